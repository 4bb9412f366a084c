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
      parse_parameters(ParameterHandler &) override
      {}
      std::array<double, 2>
      factors(double, double) const override
      {
        return {{1., 1.}};
      }
    };

    COSMO_REGISTER_PLUGIN(PlateGrowthLaw, NoPlateGrowth, "none", "G = I.")
  } // namespace materials
} // namespace cosmo
