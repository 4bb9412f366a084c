// The annulus between an inner and an outer radius (a tube).
#include <deal.II/grid/grid_generator.h>

#include <cosmo/geometry/section_shape.h>
#include <cosmo/io/parameters.h>

namespace cosmo
{
  namespace geometry
  {
    class AnnulusSection : public SectionShape
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Inner radius", "0.5", Patterns::Double(0), "Annulus inner radius.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        radius       = get_positive_length(prm, "Radius");
        inner_radius = prm.get_double("Inner radius");
        if (!(inner_radius > 0 && inner_radius < radius))
          throw io::InputError("Cross-section", "Inner radius", prm.get("Inner radius"),
                               "must lie between 0 and Radius = " + prm.get("Radius"));
        check_section_length(inner_radius, "Inner radius", prm.get("Inner radius"));
      }

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        GridGenerator::hyper_shell(tria, Point<2>(), inner_radius, radius, 0, true);
        tria.refine_global(refinements);
        const double r_mid = (inner_radius + radius) / 2;
        return label_builtin_mesh(tria, {{"section", 1}}, nullptr, {{"outer", 0}, {"inner", 1}},
                                  [r_mid](const Point<2> &c) {
                                    return types::boundary_id(c.norm() < r_mid ? 1 : 0);
                                  });
      }

    private:
      double radius = 1, inner_radius = 0.5;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          AnnulusSection,
                          "annulus",
                          "the annulus between `Inner radius` and `Radius`; region `section` "
                          "= 1, boundary parts `outer` = 0 and `inner` = 1.")
  } // namespace geometry
} // namespace cosmo
