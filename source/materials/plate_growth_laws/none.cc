// No plate growth: G = I.
#include <cosmo/materials/plate_growth.h>

namespace cosmo
{
  namespace materials
  {
    class NoPlateGrowth : public PlateGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm) override
      {
        // Unused, but still expressions: a typo there is reported, not ignored.
        for (const std::string entry : {"Radial growth factor", "Circumferential growth factor"})
          parse_expression_of_r(prm.get(entry), entry + " (unused with Kind = none, still checked)");
      }
      std::array<double, 2>
      factors(double, double) const override
      {
        return {{1., 1.}};
      }
    };

    COSMO_REGISTER_PLUGIN(PlateGrowthLaw, NoPlateGrowth, "none", "G = I.")
  } // namespace materials
} // namespace cosmo
