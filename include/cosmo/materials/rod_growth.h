#ifndef cosmo_materials_rod_growth_h
#define cosmo_materials_rod_growth_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/base/plugins.h>

#include <array>
#include <memory>
#include <string>

/**
 * The growth of a rod (the plate's rim): its axial growth factor g, which
 * makes the stress-free rod g times longer (materials/rod_law.h), and the
 * change of its stress-free curvature from growth through its section, both
 * at the load t. Implementations register themselves by name
 * (COSMO_REGISTER_PLUGIN), one file each in source/materials/rod_growth_laws/;
 * the names are the values of 'Rim rod / Growth kind'.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    class RodGrowthLaw
    {
    public:
      virtual ~RodGrowthLaw() = default;
      /// Reads its entries in `section` (entered; named in its errors).
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &section) = 0;
      /// The axial growth factor at load t (1 at t = 0).
      virtual double
      factor(double t) const = 0;
      /// The change of the stress-free curvature at load t (zero at t = 0), per unit length.
      virtual std::array<double, 3>
      natural_curvature(double t) const = 0;
      /// The growth factor at t = 1 (the closed forms' uniform growth).
      double
      final_factor() const
      {
        return factor(1.);
      }
    };

    /// The entry 'Growth kind' (the registered rod growth laws) and every
    /// law's entries, in the entered section.
    void
    declare_rod_growth_parameters(ParameterHandler &prm);
    /// The law selected in the entered section `section`'s 'Growth kind', its entries read.
    std::unique_ptr<RodGrowthLaw>
    create_rod_growth(ParameterHandler &prm, const std::string &section);
  } // namespace materials

  namespace plugins
  {
    // One registry of rod growth laws per process (instantiated in source/materials/rod_growth.cc).
    extern template class Registry<materials::RodGrowthLaw>;
  } // namespace plugins
} // namespace cosmo

#endif
