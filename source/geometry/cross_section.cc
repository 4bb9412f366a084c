#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cosmo/geometry/cross_section.h>
#include <cosmo/io/parameters.h>

#include <cmath>
#include <fstream>

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

      unsigned int
      repetitions(const double length, const double cell)
      {
        return std::max(1, static_cast<int>(std::lround(length / cell)));
      }
    } // namespace

    void
    CrossSectionGeometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cross-section");
      prm.declare_entry("Shape",
                        "circle",
                        Patterns::Selection(
                          "circle|ellipse|rectangle|annulus|bilayer|half disc|gmsh"),
                        "circle (Radius), ellipse (Semi-axes, along X1 and X2), "
                        "rectangle (Width along X1, Height along X2), annulus (Radius, "
                        "Inner radius), bilayer (rectangle; region 1 below, region 2 "
                        "above X2 = -Height/2 + Layer fraction*Height), half disc (circle; "
                        "region 1 for X1 < 0, region 2 for X1 > 0), gmsh (Mesh file). "
                        "Built-in single-region shapes are region 1.");
      prm.declare_entry("Radius", "1", Patterns::Double(0), "Outer radius (length unit).");
      prm.declare_entry("Semi-axes", "1, 0.5", Patterns::List(Patterns::Double(0), 2, 2),
                        "Ellipse semi-axes a (along X1), b (along X2).");
      prm.declare_entry("Width", "1", Patterns::Double(0), "Extent along X1 (rectangle, bilayer).");
      prm.declare_entry("Height", "1", Patterns::Double(0), "Extent along X2 (rectangle, bilayer).");
      prm.declare_entry("Inner radius", "0.5", Patterns::Double(0), "Annulus inner radius.");
      prm.declare_entry("Layer fraction", "0.5", Patterns::Double(0, 1),
                        "Bilayer: thickness fraction of the lower layer (region 1).");
      prm.declare_entry("Mesh file", "", Patterns::Anything(),
                        "ASCII gmsh .msh (format 2 or 4) of the section, read when "
                        "Shape = gmsh; physical surface tags are the region ids. A "
                        "relative path is relative to the working directory.");
      prm.declare_entry("Global refinements", "3", Patterns::Integer(0, 10),
                        "Uniform refinements of the coarse mesh (each quarters the cells).");
      prm.leave_subsection();
    }

    void
    CrossSectionGeometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cross-section");
      shape       = prm.get("Shape");
      radius      = prm.get_double("Radius");
      const auto ab = io::get_double_list(prm, "Semi-axes", 2, "Cross-section");
      semi_axis_1 = ab[0];
      semi_axis_2 = ab[1];
      width          = prm.get_double("Width");
      height         = prm.get_double("Height");
      inner_radius   = prm.get_double("Inner radius");
      layer_fraction = prm.get_double("Layer fraction");
      mesh_file      = prm.get("Mesh file");
      refinements    = prm.get_integer("Global refinements");
      auto positive  = [&](const std::string &entry, double v) {
        if (!(v > 0))
          throw io::InputError("Cross-section", entry, prm.get(entry), "must be positive");
      };
      if (shape == "circle" || shape == "half disc" || shape == "annulus")
        positive("Radius", radius);
      if (shape == "rectangle" || shape == "bilayer")
        {
          positive("Width", width);
          positive("Height", height);
        }
      if (shape == "ellipse" && !(semi_axis_1 > 0 && semi_axis_2 > 0))
        throw io::InputError("Cross-section", "Semi-axes", prm.get("Semi-axes"),
                             "two positive numbers");
      if (shape == "annulus" && !(inner_radius > 0 && inner_radius < radius))
        throw io::InputError("Cross-section", "Inner radius", prm.get("Inner radius"),
                             "must lie between 0 and Radius = " + prm.get("Radius"));
      if (shape == "bilayer" && !(layer_fraction > 0 && layer_fraction < 1))
        throw io::InputError("Cross-section", "Layer fraction", prm.get("Layer fraction"),
                             "must lie strictly between 0 and 1");
      if (shape == "gmsh")
        {
          std::ifstream in(mesh_file);
          if (!in)
            throw io::InputError("Cross-section", "Mesh file", mesh_file,
                                 "cannot open this file (an ASCII gmsh .msh is expected)");
        }
      prm.leave_subsection();
    }

    void
    CrossSectionGeometry::create_triangulation(Triangulation<2> &tria) const
    {
      tria.clear();
      if (shape == "circle" || shape == "half disc")
        {
          GridGenerator::hyper_ball(tria, Point<2>(), radius);
        }
      else if (shape == "ellipse")
        {
          GridGenerator::hyper_ball(tria, Point<2>(), 1.0);
          const double a = semi_axis_1, b = semi_axis_2;
          GridTools::transform([a, b](const Point<2> &p) { return Point<2>(a * p[0], b * p[1]); },
                               tria);
          tria.set_manifold(0, EllipseManifold(a, b));
          TransfiniteInterpolationManifold<2> interior;
          interior.initialize(tria);
          tria.set_manifold(1, interior);
        }
      else if (shape == "annulus")
        {
          GridGenerator::hyper_shell(tria, Point<2>(), inner_radius, radius, 0, true);
        }
      else if (shape == "rectangle" || shape == "bilayer")
        {
          // Nearly square cells; the bilayer interface is a mesh line.
          const double cell = std::min(width, height) /
                              (shape == "bilayer" ? 2. : 1.);
          std::vector<std::vector<double>> steps(2);
          const unsigned int nx = repetitions(width, cell);
          steps[0].assign(nx, width / nx);
          if (shape == "rectangle")
            {
              const unsigned int ny = repetitions(height, cell);
              steps[1].assign(ny, height / ny);
            }
          else
            steps[1] = {layer_fraction * height, (1 - layer_fraction) * height};
          GridGenerator::subdivided_hyper_rectangle(tria, steps,
                                                    Point<2>(-width / 2, -height / 2),
                                                    Point<2>(width / 2, height / 2));
        }
      else if (shape == "gmsh")
        {
          GridIn<2> grid_in(tria);
          std::ifstream in(mesh_file);
          try
            {
              grid_in.read_msh(in);
            }
          catch (std::exception &e)
            {
              throw io::InputError("Cross-section", "Mesh file", mesh_file,
                                   std::string("not a readable ASCII gmsh mesh: ") + e.what());
            }
        }

      // Region ids: everything is region 1 unless the shape has two regions.
      if (shape != "gmsh")
        for (const auto &cell : tria.active_cell_iterators())
          cell->set_material_id(1);
      tria.refine_global(refinements);
      if (shape == "bilayer")
        {
          const double y_interface = -height / 2 + layer_fraction * height;
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_material_id(cell->center()[1] < y_interface ? 1 : 2);
        }
      else if (shape == "half disc")
        {
          if (refinements == 0)
            throw io::InputError("Cross-section", "Global refinements", "0",
                                 "a half disc needs at least 1 refinement so that X1 = 0 "
                                 "is a mesh line");
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_material_id(cell->center()[0] < 0 ? 1 : 2);
        }

      applied_shift = Point<2>();
      if (shape == "gmsh")
        {
          const SectionProperties p = properties(tria, 1);
          if (p.centroid.norm() > 1e-12 * p.diameter)
            {
              applied_shift = -p.centroid;
              GridTools::shift(Tensor<1, 2>(applied_shift), tria);
            }
        }
    }

    SectionProperties
    CrossSectionGeometry::properties(const Triangulation<2> &tria, const unsigned int degree)
    {
      SectionProperties  p;
      MappingQ<2>        mapping(std::max(1u, degree));
      const QGauss<2>    quadrature(std::max(1u, degree) + 1);
      // Geometry only: a scalar Q1 element would do, FE_Nothing avoids DoFs.
      const FE_Nothing<2> fe;
      FEValues<2>        fe_values(mapping, fe, quadrature, update_quadrature_points | update_JxW_values);
      double             mx = 0, my = 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<2> &x  = fe_values.quadrature_point(q);
              const double    dA = fe_values.JxW(q);
              p.area += dA;
              mx += x[0] * dA;
              my += x[1] * dA;
              p.I22 += x[0] * x[0] * dA;
              p.I11 += x[1] * x[1] * dA;
              p.I12 += x[0] * x[1] * dA;
            }
        }
      p.centroid = Point<2>(mx / p.area, my / p.area);
      p.diameter = GridTools::diameter(tria);
      return p;
    }
  } // namespace geometry
} // namespace cosmo
