// The example of doc/cookbook.md, "Add a growth law": growth that prescribes
// the volume ratio, Fg = J^(1/3) I with J = 1 + t (g - 1) the ramped
// 'Growth factor'. This file is the whole extension: compiled into an
// executable together with an application's main.cc (tests/CMakeLists.txt,
// rod_cross_section_cookbook), the name 'volumetric' becomes a value of every
// material's 'Growth kind'.
#include <cosmo/materials/growth.h>

#include <cmath>

namespace cosmo
{
  namespace materials
  {
    class VolumetricGrowth : public BulkGrowthLaw
    {
    public:
      /// Its own entries (none: it uses the common 'Growth factor').
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
        return std::cbrt(growth_ramp(t, factor->value(X))) * unit_symmetric_tensor<3>();
      }
      std::string
      description() const override
      {
        return "volumetric, J = " + text;
      }

    private:
      std::string                        text;
      std::unique_ptr<FunctionParser<2>> factor;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          VolumetricGrowth,
                          "volumetric",
                          "J^(1/3) I, the volume ratio J = det Fg from 'Growth factor' "
                          "(doc/cookbook.md).")
  } // namespace materials
} // namespace cosmo
