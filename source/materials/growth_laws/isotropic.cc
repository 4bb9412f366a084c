// Isotropic growth Fg = g I.
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class IsotropicGrowth : public ScalarFactorGrowthLaw
    {
    public:
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        return ramped_factor(X, t) * unit_symmetric_tensor<3>();
      }
      std::string
      description() const override
      {
        return "isotropic, g = " + factor_text();
      }
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw, IsotropicGrowth, "isotropic", "g I.")
  } // namespace materials
} // namespace cosmo
