// The ellipse with semi-axes a (along X1) and b (along X2).
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cosmo/geometry/section_shape.h>
#include <cosmo/io/parameters.h>

#include <cmath>

namespace cosmo
{
  namespace geometry
  {
    namespace
    {
      /**
       * The boundary of an ellipse x = a r cos(p), y = b r sin(p), as a chart
       * in (r, p): new boundary points stay on r = 1. Periodic in p.
       */
      class EllipseManifold : public ChartManifold<2, 2, 2>
      {
      public:
        EllipseManifold(const double a, const double b)
          : ChartManifold<2, 2, 2>(Tensor<1, 2>({0., 2 * M_PI}))
          , a(a)
          , b(b)
        {}
        std::unique_ptr<Manifold<2, 2>>
        clone() const override
        {
          return std::make_unique<EllipseManifold>(a, b);
        }
        Point<2>
        pull_back(const Point<2> &x) const override
        {
          const double u = x[0] / a, v = x[1] / b;
          double       p = std::atan2(v, u);
          if (p < 0)
            p += 2 * M_PI;
          return Point<2>(std::sqrt(u * u + v * v), p);
        }
        Point<2>
        push_forward(const Point<2> &c) const override
        {
          return Point<2>(a * c[0] * std::cos(c[1]), b * c[0] * std::sin(c[1]));
        }

      private:
        double a, b;
      };
    } // namespace

    class EllipseSection : public SectionShape
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Semi-axes", "1, 0.5", Patterns::List(Patterns::Double(0), 2, 2),
                          "Ellipse semi-axes a (along X1), b (along X2).");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        const auto ab = io::get_double_list(prm, "Semi-axes", 2, "Cross-section");
        a             = ab[0];
        b             = ab[1];
        if (!(a > 0 && b > 0))
          throw io::InputError("Cross-section", "Semi-axes", prm.get("Semi-axes"),
                               "two positive numbers");
        check_section_length(a, "Semi-axes", prm.get("Semi-axes"));
        check_section_length(b, "Semi-axes", prm.get("Semi-axes"));
        check_aspect_ratio(a, b, "Semi-axes", prm.get("Semi-axes"));
      }

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        // The unit ball stretched, its boundary on the ellipse's chart and
        // the interior a transfinite interpolation of it.
        GridGenerator::hyper_ball(tria, Point<2>(), 1.0);
        const double a = this->a, b = this->b;
        GridTools::transform([a, b](const Point<2> &p) { return Point<2>(a * p[0], b * p[1]); },
                             tria);
        tria.set_manifold(0, EllipseManifold(a, b));
        TransfiniteInterpolationManifold<2> interior;
        interior.initialize(tria);
        tria.set_manifold(1, interior);
        tria.refine_global(refinements);
        return label_builtin_mesh(tria, {{"section", 1}}, nullptr, {{"outer", 0}}, nullptr);
      }

    private:
      double a = 1, b = 0.5;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          EllipseSection,
                          "ellipse",
                          "the ellipse of `Semi-axes` a (along X1) and b (along X2); region "
                          "`section` = 1, boundary part `outer` = 0.")
  } // namespace geometry
} // namespace cosmo
