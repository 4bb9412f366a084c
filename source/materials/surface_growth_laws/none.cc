// No surface growth: Fsg = I.
#include <cosmo/materials/surface_layer.h>

namespace cosmo
{
  namespace materials
  {
    class NoSurfaceGrowth : public SurfaceGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &, const std::string &) override
      {}
      std::array<double, 2>
      growth(const Point<2> &, double) const override
      {
        return {{1., 1.}};
      }
      std::string
      description() const override
      {
        return "no growth";
      }
    };

    COSMO_REGISTER_PLUGIN(SurfaceGrowthLaw, NoSurfaceGrowth, "none", "Fsg = I.")
  } // namespace materials
} // namespace cosmo
