// Orthotropic growth Fg = diag(g1, g2, g3).
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class OrthotropicGrowth : public BulkGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        text   = prm.get("Growth factor");
        factor = parse_expressions(text, 3, where, "Growth factor");
      }
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        Tensor<2, 3> Fg;
        for (unsigned int i = 0; i < 3; ++i)
          Fg[i][i] = growth_ramp(t, factor->value(X, i));
        return Fg;
      }
      std::string
      description() const override
      {
        return "orthotropic, (g1; g2; g3) = (" + text + ")";
      }

    private:
      std::string                        text;
      std::unique_ptr<FunctionParser<2>> factor;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          OrthotropicGrowth,
                          "orthotropic",
                          "diag(g1, g2, g3) from 'Growth factor' given as three expressions "
                          "separated by ';'.")
  } // namespace materials
} // namespace cosmo
