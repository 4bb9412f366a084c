// doc/cookbook.md, "Add a section shape": the equilateral triangle of side a,
// centred on its centroid, one file registered as `equilateral triangle`.
#include <deal.II/grid/grid_generator.h>

#include <cosmo/geometry/section_shape.h>

#include <cmath>

namespace cosmo
{
  namespace geometry
  {
    class EquilateralTriangleSection : public SectionShape
    {
    public:
      // Its own entry, in `Cross-section` beside the shared ones.
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Side", "1", Patterns::Double(0), "Equilateral triangle: side a.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        side = get_positive_length(prm, "Side");
      }

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        // Vertices at distance a/sqrt(3) from the centroid (the origin), one on
        // the X2 axis: the shape is symmetric about X2. GridGenerator::simplex
        // splits the triangle into three quadrilaterals.
        const double          r = side / std::sqrt(3.);
        std::vector<Point<2>> vertices;
        for (const double angle : {90., 210., 330.})
          vertices.emplace_back(r * std::cos(angle * M_PI / 180), r * std::sin(angle * M_PI / 180));
        GridGenerator::simplex(tria, vertices);
        tria.refine_global(refinements);
        // One region, one boundary part (the defaults of label_builtin_mesh).
        return label_builtin_mesh(tria, {{"section", 1}}, nullptr, {{"outer", 0}}, nullptr);
      }

    private:
      double side = 1;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          EquilateralTriangleSection,
                          "equilateral triangle",
                          "the equilateral triangle of side `Side` centred on its centroid; "
                          "region `section` = 1, boundary part `outer` = 0.")
  } // namespace geometry
} // namespace cosmo
