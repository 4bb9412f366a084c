// Isotropic growth Fg = g I.
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class IsotropicGrowth : public BulkGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        text   = prm.get("Growth factor");
        factor = parse_expressions(text, 1, where, "Growth factor");
      }
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        return growth_ramp(t, factor->value(X)) * unit_symmetric_tensor<3>();
      }
      std::string
      description() const override
      {
        return "isotropic, g = " + text;
      }

    private:
      std::string                        text;
      std::unique_ptr<FunctionParser<2>> factor;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw, IsotropicGrowth, "isotropic", "g I.")
  } // namespace materials
} // namespace cosmo
