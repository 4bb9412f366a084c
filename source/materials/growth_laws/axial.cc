// Axial growth Fg = I + (g - 1) E3 (x) E3: the rod lengthens.
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class AxialGrowth : public ScalarFactorGrowthLaw
    {
    public:
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        return fibre_growth(ramped_factor(X, t), Tensor<1, 3>({0., 0., 1.}));
      }
      std::string
      description() const override
      {
        return "axial, g = " + factor_text();
      }
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          AxialGrowth,
                          "axial",
                          "I + (g-1) E3 (x) E3 (growth along the rod axis).")
  } // namespace materials
} // namespace cosmo
