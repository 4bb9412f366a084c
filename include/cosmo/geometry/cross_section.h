#ifndef cosmo_geometry_cross_section_h
#define cosmo_geometry_cross_section_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

/**
 * Cross-section domains A of the rod: the shapes registered by name
 * (geometry/section_shape.h; built in: circle, ellipse, rectangle, annulus,
 * the two-region bilayer and half disc, and any shape from gmsh: an ASCII
 * .msh, or a .geo that is meshed here by running the gmsh program).
 * Physical surface tags become region (material) ids, physical line tags
 * boundary ids; their names (and the built-in shapes' fixed names)
 * are available after create_triangulation(), so that materials and surface
 * layers can be given by name.
 *
 * The helical kinematics measure w from the origin and the gauge puts the
 * centreline through the centroid, so the reference centroid must be the
 * origin: built-in shapes are centred by construction, gmsh meshes are
 * shifted (and the shift is reported).
 */
namespace cosmo
{
  namespace geometry
  {
    using namespace dealii;

    struct SectionProperties
    {
      double     area = 0;
      Point<2>   centroid;
      double     I11 = 0; ///< int X2^2 dA (bending about E1)
      double     I22 = 0; ///< int X1^2 dA (bending about E2)
      double     I12 = 0; ///< int X1 X2 dA
      double     diameter = 0;
    };

    class SectionShape;

    class CrossSectionGeometry
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Build the mesh (refined) with manifolds for curved boundaries, its
       * region (material) ids and boundary ids, and the name maps below.
       * For Shape = gmsh with a .geo this runs gmsh (in a temporary
       * directory that is removed again). Throws io::InputError for a mesh
       * that cannot be made or read.
       */
      void
      create_triangulation(Triangulation<2> &tria) const;

      /**
       * Named boundary parts -> boundary id, valid after
       * create_triangulation(). gmsh: the dimension-1 physical names
       * (boundary faces on no physical line have id 0). Built-in shapes:
       * circle, ellipse, half disc `outer` = 0; annulus `outer` = 0,
       * `inner` = 1; rectangle, bilayer `left` = 0, `right` = 1,
       * `bottom` = 2, `top` = 3.
       */
      const std::map<std::string, types::boundary_id> &
      boundary_part_ids() const;

      /**
       * Named regions -> region (material) id, valid after
       * create_triangulation(). gmsh: the dimension-2 physical names.
       * Built-in shapes: `section` = 1 for single-region shapes; bilayer
       * `lower` = 1, `upper` = 2; half disc `left` = 1, `right` = 2.
       */
      const std::map<std::string, types::material_id> &
      region_ids() const;

      /// Area, centroid and second moments with a mapping of degree `degree`.
      static SectionProperties
      properties(const Triangulation<2> &tria, unsigned int degree);

      /// The registered name of the shape (`Cross-section / Shape`).
      std::string  shape;
      unsigned int refinements = 3;
      /// Shift applied to a gmsh mesh to put its centroid at the origin.
      mutable Point<2> applied_shift;
      /// How a .geo was meshed (gmsh options, number of cells), for the log.
      mutable std::string meshing_summary;

    private:
      std::shared_ptr<SectionShape> shape_model;
      // Filled by create_triangulation(), which is const like the rest of
      // the problem's use of the geometry (as applied_shift).
      mutable std::map<std::string, types::boundary_id> boundary_parts;
      mutable std::map<std::string, types::material_id> regions;
    };

    /**
     * Which boundary faces of the cross-section a boundary condition or a
     * surface layer covers, from a specification such as `outer`,
     * `all`, `arc 0 90` or `left, arc 170 190` (a comma-separated union):
     *
     * - `all`: the whole boundary;
     * - a boundary part name of the geometry (CrossSectionGeometry::
     *   boundary_part_ids(), e.g. a gmsh physical line name);
     * - `arc A B` (degrees, A < B, B - A <= 360): boundary faces whose
     *   midpoint has its polar angle about the origin (the centroid, after
     *   the gmsh shift), counterclockwise from X1, in [A, B) modulo 360 (half-open: adjacent arcs share no face).
     *
     * An empty specification selects nothing. parse() needs the names, so
     * call it after the geometry's create_triangulation().
     */
    class BoundarySelection
    {
    public:
      /// Parse `spec`; errors name `section`, `entry` and the available parts.
      void
      parse(const std::string &         spec,
            const std::string &         section,
            const std::string &         entry,
            const CrossSectionGeometry &geometry);

      /// Whether the boundary face `face` is selected (false off the boundary).
      bool
      contains(const typename Triangulation<2>::face_iterator &face) const;

      /// True if nothing is selected.
      bool
      empty() const;

      /// For the log, e.g. "outer (boundary id 0), arc 0..90 deg".
      std::string
      description() const;

    private:
      bool                                     everything = false;
      std::vector<std::pair<std::string, types::boundary_id>> parts;
      std::set<types::boundary_id>             ids;
      std::vector<std::pair<double, double>>   arcs; ///< [A, B) in degrees
    };
  } // namespace geometry
} // namespace cosmo

#endif
