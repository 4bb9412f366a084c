#ifndef cosmo_materials_material_h
#define cosmo_materials_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <cosmo/materials/growth.h>
#include <cosmo/materials/hyperelastic_law.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

/**
 * A growing hyperelastic material: stored energy per reference volume
 * Jg W(F Fg^-1) (growth decomposition F = Fe Fg), and its first and second
 * derivatives with respect to F by Sacado (forward mode, nested, static size:
 * nine variables per quadrature point, which is cheaper than differentiating
 * with respect to all cell DoFs, doc/specification/rod-cross-section.md).
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /// Energy density and derivatives at one point. Row-major 3x3 / 9x9.
    struct EnergyDerivatives
    {
      double                 energy = 0;
      std::array<double, 9>  P{};  ///< dW/dF (first Piola stress of the grown body)
      std::array<double, 81> C{};  ///< d2W/dF2, C[9*a+b], a = 3i+j
      bool                   admissible = true; ///< det Fe > 0
    };

    class GrowingMaterial
    {
    public:
      std::string     name;
      std::string     section; ///< its parameter section, for error messages
      /// The registered stored energy named by 'Hyperelastic law' (shared: materials are copied).
      std::shared_ptr<const HyperelasticLaw> law;
      GrowthTensor    growth;
      double          density = 1; ///< mass per reference volume (mass properties only)

      /// Jg W(F Fg^-1) and dW/dF; second derivatives if `tangent`.
      void
      evaluate(const Tensor<2, 3> &F,
               const Tensor<2, 3> &Fg,
               bool                tangent,
               EnergyDerivatives & out) const;
    };

    /**
     * Materials by region: up to `max_materials` parameter sections
     * "Material 1" ... each naming the regions it covers, by region
     * (material) id or by region name. Names are only known once the mesh
     * exists, so parse_parameters() keeps the lists and resolve_regions()
     * maps them (integer ids are mapped already by parse_parameters()).
     */
    class MaterialLibrary
    {
    public:
      static constexpr unsigned int max_materials = 4;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Map the Regions lists to region ids with the mesh's region names
       * (CrossSectionGeometry::region_ids()); call after building the mesh.
       * Unknown names and regions given twice are an io::InputError naming
       * the material section, `Regions` and the available names.
       */
      void
      resolve_regions(const std::map<std::string, types::material_id> &names);

      /// The material of a region; throws InputError if no section covers it.
      const GrowingMaterial &
      material(types::material_id region) const;
      /// Check that every region id in `ids` is covered (clear error otherwise).
      void
      check_regions(const std::vector<types::material_id> &ids) const;

      /// Largest shear/Young modulus, to scale residual tolerances.
      double
      max_young() const;

      std::vector<std::string>
      descriptions() const;

    private:
      /// A material's `Regions` entry as given, for resolve_regions().
      struct RegionList
      {
        std::string              section;
        std::string              text;
        std::vector<std::string> items;
      };

      std::vector<GrowingMaterial>                materials;
      std::vector<RegionList>                     region_lists; ///< one per material
      std::map<types::material_id, unsigned int> region_to_material;
    };
  } // namespace materials
} // namespace cosmo

#endif
