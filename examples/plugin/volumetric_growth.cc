// The example of doc/cookbook.md, "Add a growth law": growth that prescribes
// the volume ratio, Fg = J^(1/3) I with J = 1 + t (g - 1) the ramped
// 'Growth factor'. This file is the whole extension: compiled into an
// executable together with an application's main.cc (tests/CMakeLists.txt,
// rod_cross_section_cookbook), or into a shared library built against the
// installed suite (examples/plugin/CMakeLists.txt) and named in a run's
// 'Additional shared libraries', the name 'volumetric' becomes a value of
// every material's 'Growth kind'.
#include <cosmo/materials/growth.h>

#include <cmath>

namespace cosmo
{
  namespace materials
  {
    // A law with one scalar factor: ScalarFactorGrowthLaw parses the
    // common 'Growth factor' (an io::InputError names the section and entry
    // of a bad expression) and ramps it, ramped_factor(X, t) = 1 + t (g - 1).
    class VolumetricGrowth : public ScalarFactorGrowthLaw
    {
    public:
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        return std::cbrt(ramped_factor(X, t)) * unit_symmetric_tensor<3>();
      }
      std::string
      description() const override
      {
        return "volumetric, J = " + factor_text();
      }
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          VolumetricGrowth,
                          "volumetric",
                          "J^(1/3) I, the volume ratio J = det Fg from 'Growth factor' "
                          "(doc/cookbook.md).")
  } // namespace materials
} // namespace cosmo
