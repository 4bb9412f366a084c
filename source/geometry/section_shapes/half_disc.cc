// The disc of radius R in two regions, X1 < 0 and X1 > 0 (a bimaterial rod).
#include <deal.II/grid/grid_generator.h>

#include <cosmo/geometry/section_shape.h>
#include <cosmo/io/parameters.h>

namespace cosmo
{
  namespace geometry
  {
    class HalfDiscSection : public SectionShape
    {
    public:
      void
      parse_parameters(ParameterHandler &prm) override
      {
        radius = get_positive_length(prm, "Radius");
      }

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        // The coarse ball's cells straddle X1 = 0; one refinement makes it a mesh line.
        if (refinements == 0)
          throw io::InputError("Cross-section", "Global refinements", "0",
                               "a half disc needs at least 1 refinement so that X1 = 0 "
                               "is a mesh line");
        GridGenerator::hyper_ball(tria, Point<2>(), radius);
        tria.refine_global(refinements);
        return label_builtin_mesh(
          tria, {{"left", 1}, {"right", 2}},
          [](const Point<2> &c) { return types::material_id(c[0] < 0 ? 1 : 2); },
          {{"outer", 0}}, nullptr);
      }

    private:
      double radius = 1;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          HalfDiscSection,
                          "half disc",
                          "the disc of radius `Radius` in two regions, `left` = 1 for X1 < 0 "
                          "and `right` = 2 for X1 > 0; boundary part `outer` = 0.")
  } // namespace geometry
} // namespace cosmo
