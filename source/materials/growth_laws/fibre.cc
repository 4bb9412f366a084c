// Growth along fibres given by expressions: Fg = I + (g - 1) f (x) f.
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class FibreGrowth : public ScalarFactorGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Fibre direction",
                          "0; 0; 1",
                          Patterns::Anything(),
                          "Fibre direction f for 'fibre' growth: three expressions of "
                          "x, y separated by ';' (normalised to unit length pointwise).");
      }
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        ScalarFactorGrowthLaw::parse_parameters(prm, where);
        fibre_text = prm.get("Fibre direction");
        fibre      = parse_expressions(fibre_text, 3, where, "Fibre direction");
      }
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        Tensor<1, 3> f;
        for (unsigned int i = 0; i < 3; ++i)
          f[i] = fibre->value(X, i);
        AssertThrow(f.norm() > 0,
                    ExcMessage("The fibre direction vanishes at (" + std::to_string(X[0]) + ", " +
                               std::to_string(X[1]) + "): '" + fibre_text + "'"));
        return fibre_growth(ramped_factor(X, t), f / f.norm());
      }
      std::string
      description() const override
      {
        return "fibre, g = " + factor_text() + ", f = (" + fibre_text + ")";
      }

    private:
      std::string                        fibre_text;
      std::unique_ptr<FunctionParser<2>> fibre;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          FibreGrowth,
                          "fibre",
                          "I + (g-1) f (x) f, f from 'Fibre direction'.")
  } // namespace materials
} // namespace cosmo
