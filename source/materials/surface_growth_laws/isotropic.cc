// Isotropic surface growth: gT = g3 = g.
#include <cosmo/materials/growth.h>
#include <cosmo/materials/surface_layer.h>

namespace cosmo
{
  namespace materials
  {
    class IsotropicSurfaceGrowth : public SurfaceGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        factor.parse(prm, where, 1);
      }
      std::array<double, 2>
      growth(const Point<2> &X, const double t) const override
      {
        const double g = factor.ramped(X, t);
        return {{g, g}};
      }
      std::string
      description() const override
      {
        return "isotropic growth g = " + factor.text();
      }

    private:
      GrowthFactors factor;
    };

    COSMO_REGISTER_PLUGIN(SurfaceGrowthLaw, IsotropicSurfaceGrowth, "isotropic", "gT = g3 = g.")
  } // namespace materials
} // namespace cosmo
