// Surface growth with separate factors along the boundary (gT) and along
// the rod's axis (g3).
#include <cosmo/materials/growth.h>
#include <cosmo/materials/surface_layer.h>

namespace cosmo
{
  namespace materials
  {
    class TangentialAxialSurfaceGrowth : public SurfaceGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        factors.parse(prm, where, 2);
      }
      std::array<double, 2>
      growth(const Point<2> &X, const double t) const override
      {
        return {{factors.ramped(X, t, 0), factors.ramped(X, t, 1)}};
      }
      std::string
      description() const override
      {
        return "growth (gT; g3) = (" + factors.text() + ")";
      }

    private:
      GrowthFactors factors;
    };

    COSMO_REGISTER_PLUGIN(SurfaceGrowthLaw,
                          TangentialAxialSurfaceGrowth,
                          "tangential and axial",
                          "separate factors 'gT; g3'.")
  } // namespace materials
} // namespace cosmo
