#ifndef cosmo_geometry_cross_section_h
#define cosmo_geometry_cross_section_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <string>

/**
 * Cross-section domains A of the rod: built-in shapes (circle, ellipse,
 * rectangle, annulus, and the two-region bilayer strip and half disc) and any
 * ASCII gmsh .msh whose physical surface tags become region (material) ids.
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

    class CrossSectionGeometry
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Build the mesh (refined) with manifolds for curved boundaries.
      void
      create_triangulation(Triangulation<2> &tria) const;

      /// Area, centroid and second moments with a mapping of degree `degree`.
      static SectionProperties
      properties(const Triangulation<2> &tria, unsigned int degree);

      std::string shape;
      double      radius = 1, semi_axis_1 = 1, semi_axis_2 = 0.5, width = 1, height = 1,
             inner_radius = 0.5, layer_fraction = 0.5;
      std::string  mesh_file;
      unsigned int refinements = 3;
      /// Shift applied to a gmsh mesh to put its centroid at the origin.
      mutable Point<2> applied_shift;
    };
  } // namespace geometry
} // namespace cosmo

#endif
