// Isotropic in-plane plate growth G = g I, g = g(r).
#include <cosmo/materials/growth.h>
#include <cosmo/materials/plate_growth.h>

namespace cosmo
{
  namespace materials
  {
    class IsotropicPlateGrowth : public PlateGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm) override
      {
        g = parse_expression_of_r(prm.get("Radial growth factor"), "Radial growth factor");
        // Unused here, but still an expression: a typo there is reported, not ignored.
        parse_expression_of_r(prm.get("Circumferential growth factor"),
                              "Circumferential growth factor (unused with Kind = isotropic, still "
                              "checked)");
      }
      std::array<double, 2>
      factors(const double r, const double t) const override
      {
        const double gr = growth_ramp(t, g->value(Point<1>(r)));
        return {{gr, gr}};
      }

    private:
      std::shared_ptr<FunctionParser<1>> g;
    };

    COSMO_REGISTER_PLUGIN(PlateGrowthLaw,
                          IsotropicPlateGrowth,
                          "isotropic",
                          "g I with g = 'Radial growth factor'.")
  } // namespace materials
} // namespace cosmo
