#ifndef cosmo_geometry_section_shape_h
#define cosmo_geometry_section_shape_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <cosmo/base/plugins.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

/**
 * The shape of a rod's cross-section A, one implementation per file in
 * source/geometry/section_shapes/, registered by name (the values of
 * `Cross-section / Shape`, doc/cookbook.md). A shape reads its dimensions,
 * checks them, and builds the refined mesh with its region (material) ids,
 * its boundary ids and the names of both, which materials, surface layers
 * and boundary selections use.
 */
namespace cosmo
{
  namespace geometry
  {
    using namespace dealii;

    /// What a shape's mesh carries besides its cells.
    struct SectionMesh
    {
      /// Named regions -> region (material) id.
      std::map<std::string, types::material_id> regions;
      /// Named boundary parts -> boundary id.
      std::map<std::string, types::boundary_id> boundary_parts;
      /// How the mesh was made (e.g. gmsh's options and cell count), for the log; may be empty.
      std::string meshing_summary;
      /**
       * The helical kinematics measure w from the origin, and the gauge puts
       * the centreline through the centroid: a shape not centred by
       * construction (a mesh from a file) is shifted by CrossSectionGeometry.
       */
      bool centred_by_construction = true;
    };

    class SectionShape
    {
    public:
      virtual ~SectionShape() = default;

      /**
       * Its own entries in `Cross-section` (none by default): the entries
       * several shapes use (Radius, Width, Height, Global refinements) are
       * declared by CrossSectionGeometry.
       */
      static void
      declare_parameters(ParameterHandler &)
      {}

      /// Reads and checks its dimensions; `Cross-section` is entered.
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;

      /**
       * The mesh refined `refinements` times, with manifolds for curved
       * boundaries, region ids and boundary ids set. Throws io::InputError
       * for a mesh that cannot be made.
       */
      virtual SectionMesh
      create_triangulation(Triangulation<2> &tria, unsigned int refinements) const = 0;
    };

    /**
     * The labels of a built-in shape on its refined mesh: every cell in
     * region 1 (named `section`) unless `region_of` is given (its value at
     * the cell centre), and every boundary face labelled by `boundary_of` at
     * its centre (0, `outer`, by default). From the refined mesh, so they do
     * not depend on how GridGenerator colours its coarse mesh.
     */
    SectionMesh
    label_builtin_mesh(Triangulation<2> &                                         tria,
                       const std::map<std::string, types::material_id> &          regions,
                       const std::function<types::material_id(const Point<2> &)> &region_of,
                       const std::map<std::string, types::boundary_id> &          boundary_parts,
                       const std::function<types::boundary_id(const Point<2> &)> &boundary_of);

    /// A positive number read from `entry` of `Cross-section` (entered), else io::InputError.
    double
    get_positive_length(ParameterHandler &prm, const std::string &entry);

    /// io::InputError naming 'Cross-section/entry' unless 1e-6 <= length <= 1e6.
    void
    check_section_length(double length, const std::string &entry, const std::string &text);

    /// io::InputError naming 'Cross-section/entry' unless max(a, b) <= 1e3 min(a, b).
    void
    check_aspect_ratio(double a, double b, const std::string &entry, const std::string &text);
  } // namespace geometry

  namespace plugins
  {
    extern template class Registry<geometry::SectionShape>;
  } // namespace plugins
} // namespace cosmo

#endif
