// The disc of radius R.
#include <deal.II/grid/grid_generator.h>

#include <cosmo/geometry/section_shape.h>

namespace cosmo
{
  namespace geometry
  {
    class CircleSection : public SectionShape
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
        GridGenerator::hyper_ball(tria, Point<2>(), radius);
        tria.refine_global(refinements);
        return label_builtin_mesh(tria, {{"section", 1}}, nullptr, {{"outer", 0}}, nullptr);
      }

    private:
      double radius = 1;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          CircleSection,
                          "circle",
                          "the disc of radius `Radius`; region `section` = 1, boundary part "
                          "`outer` = 0.")
  } // namespace geometry
} // namespace cosmo
