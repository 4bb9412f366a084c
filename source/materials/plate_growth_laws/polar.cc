// Polar in-plane plate growth G = g_r e_r (x) e_r + g_t e_t (x) e_t, both
// factors functions of r.
#include <cosmo/materials/growth.h>
#include <cosmo/materials/plate_growth.h>

namespace cosmo
{
  namespace materials
  {
    class PolarPlateGrowth : public PlateGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm) override
      {
        radial = parse_expression_of_r(prm.get("Radial growth factor"), "Radial growth factor");
        circumferential = parse_expression_of_r(prm.get("Circumferential growth factor"),
                                                "Circumferential growth factor");
      }
      std::array<double, 2>
      factors(const double r, const double t) const override
      {
        return {{growth_ramp(t, radial->value(Point<1>(r))),
                 growth_ramp(t, circumferential->value(Point<1>(r)))}};
      }

    private:
      std::shared_ptr<FunctionParser<1>> radial, circumferential;
    };

    COSMO_REGISTER_PLUGIN(PlateGrowthLaw,
                          PolarPlateGrowth,
                          "polar",
                          "g_r e_r (x) e_r + g_t e_t (x) e_t.")
  } // namespace materials
} // namespace cosmo
