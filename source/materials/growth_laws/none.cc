// No growth: Fg = I.
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class NoGrowth : public BulkGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        // Unused, but still an expression: a typo there is reported, not ignored.
        const std::string text = prm.get("Growth factor");
        parse_expressions(text, Utilities::split_string_list(text, ';').size(),
                          where + "' (unused with Growth kind = none, still checked",
                          "Growth factor");
      }
      Tensor<2, 3>
      value(const Point<2> &, double) const override
      {
        return unit_symmetric_tensor<3>();
      }
      std::string
      description() const override
      {
        return "no growth";
      }
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw, NoGrowth, "none", "Fg = I.")
  } // namespace materials
} // namespace cosmo
