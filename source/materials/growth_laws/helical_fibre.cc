// Growth along helical fibres f = cos(a) E3 + sin(a) E_theta (active
// filaments wound about the axis): Fg = I + (g - 1) f (x) f.
#include <cosmo/materials/growth.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace materials
  {
    class HelicalFibreGrowth : public ScalarFactorGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Fibre angle",
                          "0",
                          Patterns::Double(-90, 90),
                          "Angle a (degrees) of helical fibres to the rod axis: "
                          "f = cos(a) E3 + sin(a) E_theta; positive a winds right-handed.");
      }
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        ScalarFactorGrowthLaw::parse_parameters(prm, where);
        angle = prm.get_double("Fibre angle") * M_PI / 180.;
      }
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        // E_theta is undefined on the axis; there the fibre is axial.
        Tensor<1, 3> f;
        const double r = X.norm();
        f[2]           = std::cos(angle);
        if (r > 0)
          {
            f[0] = -std::sin(angle) * X[1] / r;
            f[1] = std::sin(angle) * X[0] / r;
          }
        else
          f[2] = 1;
        return fibre_growth(ramped_factor(X, t), f);
      }
      std::string
      description() const override
      {
        std::ostringstream s;
        s << "helical fibre, g = " << factor_text() << ", angle " << angle * 180 / M_PI << " deg";
        return s.str();
      }

    private:
      double angle = 0;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          HelicalFibreGrowth,
                          "helical fibre",
                          "as fibre with f = cos(a) E3 + sin(a) E_theta, a = 'Fibre angle' (active "
                          "filaments wound about the axis).")
  } // namespace materials
} // namespace cosmo
