// No surface growth: Fsg = I.
#include <cosmo/materials/growth.h>
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
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        // Unused, but still an expression: a typo there is reported, not ignored.
        const std::string text = prm.get("Growth factor");
        parse_expressions(text, Utilities::split_string_list(text, ';').size(),
                          where + "' (unused with Growth kind = none, still checked",
                          "Growth factor");
      }
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
