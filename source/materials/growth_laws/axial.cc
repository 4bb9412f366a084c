// Axial growth Fg = I + (g - 1) E3 (x) E3: the rod lengthens.
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class AxialGrowth : public BulkGrowthLaw
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
        Tensor<1, 3> E3;
        E3[2] = 1;
        return fibre_growth(growth_ramp(t, factor->value(X)), E3);
      }
      std::string
      description() const override
      {
        return "axial, g = " + text;
      }

    private:
      std::string                        text;
      std::unique_ptr<FunctionParser<2>> factor;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          AxialGrowth,
                          "axial",
                          "I + (g-1) E3 (x) E3 (growth along the rod axis).")
  } // namespace materials
} // namespace cosmo
