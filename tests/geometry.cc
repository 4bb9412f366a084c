// Cross-sections from gmsh and the names of regions and boundary parts:
// .geo meshing (exactness on a polygon, O(h^2) convergence on a disc), the
// example geometries, the built-in shapes' names, boundary selections,
// materials by region name, and the errors for bad mesh files.
//
// usage: test_geometry <case> <tests/data directory> <example .geo directory>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cosmo/geometry/cross_section.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/ranks.h>
#include <cosmo/materials/material.h>

#include "test_tools.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>

using namespace dealii;
using namespace cosmo;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  std::string data_directory, example_directory;

  /// A geometry parsed from the body of a `Cross-section` subsection, as
  /// the application does it.
  geometry::CrossSectionGeometry
  geometry_from(const std::string &entries)
  {
    ParameterHandler prm;
    geometry::CrossSectionGeometry::declare_parameters(prm);
    prm.parse_input_from_string("subsection Cross-section\n" + entries + "\nend\n");
    geometry::CrossSectionGeometry g;
    g.parse_parameters(prm);
    return g;
  }

  geometry::CrossSectionGeometry
  gmsh_geometry(const std::string &file, const double mesh_size = 0)
  {
    return geometry_from(" set Shape = gmsh\n set Mesh file = " + file +
                         "\n set Mesh size = " + std::to_string(mesh_size) +
                         "\n set Global refinements = 0");
  }

  /// The smallest Jacobian determinant of the bilinear map of any cell: it
  /// is attained at a corner, so positive corner values mean no inverted or
  /// degenerate quadrilaterals (a positive measure alone would not).
  double
  min_corner_jacobian(const Triangulation<2> &tria)
  {
    double m = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      {
        const Point<2> v[4] = {cell->vertex(0), cell->vertex(1), cell->vertex(2), cell->vertex(3)};
        auto det = [](const Tensor<1, 2> &a, const Tensor<1, 2> &b) {
          return a[0] * b[1] - a[1] * b[0];
        };
        // lexicographic vertices: (0,0), (1,0), (0,1), (1,1)
        m = std::min({m,
                      det(v[1] - v[0], v[2] - v[0]),
                      det(v[1] - v[0], v[3] - v[1]),
                      det(v[3] - v[2], v[2] - v[0]),
                      det(v[3] - v[2], v[3] - v[1])});
      }
    return m;
  }

  double
  min_cell_measure(const Triangulation<2> &tria)
  {
    double m = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      m = std::min(m, cell->measure());
    return m;
  }

  /// Total length and number of the boundary faces `selected` accepts.
  std::pair<double, unsigned int>
  boundary_length(const Triangulation<2> &                                               tria,
                  const std::function<bool(const Triangulation<2>::face_iterator &)> &selected)
  {
    double       length = 0;
    unsigned int n      = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && selected(cell->face(f)))
          {
            length += cell->face(f)->measure();
            ++n;
          }
    return {length, n};
  }

  std::string
  names_of(const std::map<std::string, types::boundary_id> &m)
  {
    std::string s;
    for (const auto &n : m)
      s += (s.empty() ? "" : ", ") + n.first + "=" + std::to_string(n.second);
    return s;
  }

  /// The message of the io::InputError `f` throws ("" if none is thrown).
  std::string
  input_error(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (io::InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void
  check_message(const std::string &what, const std::string &message,
                const std::vector<std::string> &must_contain)
  {
    bool ok = !message.empty();
    for (const auto &s : must_contain)
      ok = ok && message.find(s) != std::string::npos;
    check(what + ": " + (message.empty() ? "(no error thrown)" : message), ok);
  }

  // (a) A rectangle meshed by gmsh is a polygon, so its area and second
  // moments are exact: they must equal the built-in rectangle's.
  void
  rectangle_geo()
  {
    const auto       gmsh = gmsh_geometry(data_directory + "/rectangle.geo");
    Triangulation<2> tria;
    gmsh.create_triangulation(tria);
    std::cout << "rectangle.geo: " << tria.n_active_cells() << " cells, " << gmsh.meshing_summary
              << "\n";
    const auto builtin = geometry_from(" set Shape = rectangle\n set Width = 2\n set Height = 1\n"
                                       " set Global refinements = 2");
    Triangulation<2> reference;
    builtin.create_triangulation(reference);
    for (const unsigned int degree : {1u, 2u})
      {
        const auto p = geometry::CrossSectionGeometry::properties(tria, degree);
        const auto q = geometry::CrossSectionGeometry::properties(reference, degree);
        const std::string d = " (mapping degree " + std::to_string(degree) + ")";
        check_close("area" + d, p.area, q.area, 1e-12);
        check_close("area = W H" + d, p.area, 2.0, 1e-12);
        check_close("I11 = int X2^2" + d, p.I11, q.I11, 1e-12);
        check_close("I22 = int X1^2" + d, p.I22, q.I22, 1e-12);
        check_close("I12 = int X1 X2" + d, p.I12, q.I12, 0, 1e-12);
        check_close("centroid X1" + d, p.centroid[0], 0, 0, 1e-12);
        check_close("centroid X2" + d, p.centroid[1], 0, 0, 1e-12);
      }
    check("boundary parts " + names_of(gmsh.boundary_part_ids()) + " = left, right, bottom, top",
          gmsh.boundary_part_ids() ==
            std::map<std::string, types::boundary_id>{{"left", 1}, {"right", 2}, {"bottom", 3}, {"top", 4}});
    check("region names: section = 1",
          gmsh.region_ids() == std::map<std::string, types::material_id>{{"section", 1}});
    check("no shift for a centred mesh", gmsh.applied_shift.norm() == 0);

    // Each named side, on both meshes: its length, and every face midpoint on it.
    const std::map<std::string, std::pair<double, std::function<bool(const Point<2> &)>>> sides = {
      {"left", {1., [](const Point<2> &c) { return std::abs(c[0] + 1) < 1e-12; }}},
      {"right", {1., [](const Point<2> &c) { return std::abs(c[0] - 1) < 1e-12; }}},
      {"bottom", {2., [](const Point<2> &c) { return std::abs(c[1] + 0.5) < 1e-12; }}},
      {"top", {2., [](const Point<2> &c) { return std::abs(c[1] - 0.5) < 1e-12; }}}};
    for (const auto *g : {&gmsh, &builtin})
      {
        const Triangulation<2> &t     = (g == &gmsh) ? tria : reference;
        const std::string       label = (g == &gmsh) ? "rectangle.geo" : "built-in rectangle";
        double                  total = 0;
        for (const auto &side : sides)
          {
            geometry::BoundarySelection s;
            s.parse(side.first, "Test", "Boundary", *g);
            const auto selected =
              boundary_length(t, [&](const auto &face) { return s.contains(face); });
            const auto on_side = boundary_length(t, [&](const auto &face) {
              return s.contains(face) && side.second.second(face->center());
            });
            total += selected.first;
            check_close(label + ": length of " + side.first, selected.first, side.second.first,
                        1e-12);
            check(label + ": all " + std::to_string(selected.second) + " faces of '" + side.first +
                    "' (" + s.description() + ") lie on that side",
                  on_side.second == selected.second && selected.second > 0);
          }
        check_close(label + ": the sides cover the boundary", total, 6, 1e-12);
      }

    // The same rectangle as a user's MSH 4.1 file (written by gmsh here):
    // its $PhysicalNames and element blocks are read as well.
    const auto dir = std::filesystem::temp_directory_path() /
                     ("cosmo-test-geometry-msh4-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string msh4    = (dir / "rectangle.msh").string();
    const std::string command = "gmsh '" + data_directory + "/rectangle.geo' -2 -format msh41 "
                                "-setnumber Mesh.RecombineAll 1 -setnumber Mesh.Algorithm 6 -o '" +
                                msh4 + "' > /dev/null 2>&1";
    check("gmsh writes an MSH 4.1 file", std::system(command.c_str()) == 0);
    const auto       g4 = gmsh_geometry(msh4);
    Triangulation<2> tria4;
    g4.create_triangulation(tria4);
    std::filesystem::remove_all(dir);
    std::cout << "rectangle.msh (MSH 4.1): " << tria4.n_active_cells() << " cells\n";
    check_close("MSH 4.1: area", geometry::CrossSectionGeometry::properties(tria4, 1).area, 2,
                1e-12);
    check("MSH 4.1: boundary parts " + names_of(g4.boundary_part_ids()),
          g4.boundary_part_ids() == gmsh.boundary_part_ids());
    check("MSH 4.1: region names", g4.region_ids() == gmsh.region_ids());
    geometry::BoundarySelection top;
    top.parse("top", "Test", "Boundary", g4);
    check_close("MSH 4.1: length of top",
                boundary_length(tria4, [&](const auto &f) { return top.contains(f); }).first, 2,
                1e-12);
  }

  // (b) A disc meshed at h, h/2, h/4: the straight-sided mesh is an
  // inscribed polygon, area error ~ (2 pi^3 / 3) R^2 / n^2, i.e. O(h^2).
  void
  circle_area_convergence()
  {
    const double        h0 = 0.2;
    std::vector<double> errors;
    for (const double h : {h0, h0 / 2, h0 / 4})
      {
        const auto       g = gmsh_geometry(data_directory + "/circle.geo", h);
        Triangulation<2> tria;
        g.create_triangulation(tria);
        const double area  = geometry::CrossSectionGeometry::properties(tria, 1).area;
        const double error = M_PI - area;
        const auto   outer = boundary_length(tria, [](const auto &) { return true; });
        std::cout << "  Mesh size " << h << ": " << tria.n_active_cells() << " cells, "
                  << outer.second << " boundary faces, area " << std::setprecision(12) << area
                  << ", error pi R^2 - area = " << std::setprecision(4) << error << "\n";
        check("inscribed polygon: area below pi R^2", error > 0);
        errors.push_back(error);
      }
    for (unsigned int i = 1; i < errors.size(); ++i)
      {
        const double rate = std::log2(errors[i - 1] / errors[i]);
        check_close("area convergence rate, h/" + std::to_string(1 << (i - 1)) + " -> h/" +
                      std::to_string(1 << i),
                    rate, 2.0, 0, 0.3);
      }
  }

  // (c) The example geometries mesh to valid quadrilaterals and carry the
  // names the parameter files use.
  void
  example_geometries()
  {
    struct Example
    {
      std::string                               file;
      std::map<std::string, types::material_id> regions;
      std::map<std::string, types::boundary_id> boundary;
      double                                    area, area_tolerance;
    };
    const double          pi = M_PI;
    std::vector<Example> examples = {
      // polygons: exact areas
      {"i_section.geo", {{"section", 1}}, {{"outer", 1}}, 0.6 - 0.52 * 0.8, 1e-12},
      {"channel.geo", {{"section", 1}}, {{"outer", 1}}, 0.5 - 0.4 * 0.8, 1e-12},
      // curved: polygonal boundaries, O(h^2)
      {"tube.geo", {{"wall", 1}}, {{"outer", 1}, {"inner", 2}}, pi * (1 - 0.64), 5e-3},
      {"filaments.geo", {{"matrix", 1}, {"filaments", 2}}, {{"outer", 1}}, pi, 5e-3}};
    for (const auto &e : examples)
      {
        const auto       g = gmsh_geometry(example_directory + "/" + e.file);
        Triangulation<2> tria;
        g.create_triangulation(tria);
        const auto p = geometry::CrossSectionGeometry::properties(tria, 1);
        std::cout << e.file << ": " << tria.n_active_cells() << " cells, " << g.meshing_summary
                  << ", shift (" << g.applied_shift << ")\n";
        check(e.file + ": has cells", tria.n_active_cells() > 0);
        check_close(e.file + ": area", p.area, e.area, e.area_tolerance);
        const double h2 = std::pow(GridTools::minimal_cell_diameter(tria), 2);
        check(e.file + ": smallest cell measure " + std::to_string(min_cell_measure(tria)) + " > 0",
              min_cell_measure(tria) > 0);
        check(e.file + ": smallest corner Jacobian / h_min^2 = " +
                std::to_string(min_corner_jacobian(tria) / h2) + " > 0 (no inverted cells)",
              min_corner_jacobian(tria) > 0);
        check(e.file + ": region names", g.region_ids() == e.regions);
        check(e.file + ": boundary parts " + names_of(g.boundary_part_ids()),
              g.boundary_part_ids() == e.boundary);
        check_close(e.file + ": centroid at the origin", p.centroid.norm(), 0, 0, 1e-12);
        // Each region name labels cells.
        for (const auto &r : e.regions)
          {
            double area = 0;
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->material_id() == r.second)
                area += cell->measure();
            check(e.file + ": region '" + r.first + "' has area " + std::to_string(area), area > 0);
            if (r.first == "filaments")
              check_close("filaments.geo: filament area 4 pi 0.15^2", area, 4 * pi * 0.0225, 2e-2);
          }
        if (e.file == "tube.geo")
          for (const auto &part : std::map<std::string, double>{{"outer", 1.0}, {"inner", 0.8}})
            {
              geometry::BoundarySelection s;
              s.parse(part.first, "Test", "Boundary", g);
              double       r_min = 10, r_max = 0;
              const auto   sel = boundary_length(tria, [&](const auto &face) {
                if (!s.contains(face))
                  return false;
                r_min = std::min(r_min, face->center().norm());
                r_max = std::max(r_max, face->center().norm());
                return true;
              });
              std::cout << "  tube '" << part.first << "': " << sel.second
                        << " faces, midpoint radii in [" << r_min << ", " << r_max << "]\n";
              check_close("tube.geo: '" + part.first + "' length 2 pi r", sel.first,
                          2 * pi * part.second, 5e-3);
              check_close("tube.geo: '" + part.first + "' smallest midpoint radius", r_min,
                          part.second, 5e-3);
              check_close("tube.geo: '" + part.first + "' largest midpoint radius", r_max,
                          part.second, 5e-3);
            }
      }
  }

  // The built-in shapes' names and ids, from the faces and cells themselves.
  void
  builtin_names()
  {
    {
      const auto g = geometry_from(" set Shape = annulus\n set Radius = 1\n set Inner radius = 0.5\n"
                                   " set Global refinements = 2");
      Triangulation<2> tria;
      g.create_triangulation(tria);
      check("annulus: outer = 0, inner = 1",
            g.boundary_part_ids() ==
              std::map<std::string, types::boundary_id>{{"outer", 0}, {"inner", 1}});
      const auto inner = boundary_length(tria, [](const auto &f) { return f->boundary_id() == 1; });
      const auto inner_by_radius =
        boundary_length(tria, [](const auto &f) {
          return f->boundary_id() == 1 && std::abs(f->vertex(0).norm() - 0.5) < 1e-12 &&
                 std::abs(f->vertex(1).norm() - 0.5) < 1e-12;
        });
      const auto outer_by_radius =
        boundary_length(tria, [](const auto &f) {
          return f->boundary_id() == 0 && std::abs(f->vertex(0).norm() - 1) < 1e-12;
        });
      const auto all = boundary_length(tria, [](const auto &) { return true; });
      check("annulus: " + std::to_string(inner.second) + " faces with id 1, all on r = 0.5",
            inner.second > 0 && inner_by_radius.second == inner.second);
      check("annulus: the other " + std::to_string(outer_by_radius.second) +
              " faces have id 0 and lie on r = 1",
            outer_by_radius.second + inner.second == all.second);
      check("annulus: region section = 1",
            g.region_ids() == std::map<std::string, types::material_id>{{"section", 1}});
    }
    for (const std::string shape : {"circle", "ellipse"})
      {
        const auto g = geometry_from(" set Shape = " + shape + "\n set Global refinements = 2");
        Triangulation<2> tria;
        g.create_triangulation(tria);
        const auto all  = boundary_length(tria, [](const auto &) { return true; });
        const auto zero = boundary_length(tria, [](const auto &f) { return f->boundary_id() == 0; });
        check(shape + ": outer = 0 on all " + std::to_string(all.second) + " boundary faces",
              g.boundary_part_ids() == std::map<std::string, types::boundary_id>{{"outer", 0}} &&
                zero.second == all.second);
      }
    {
      const auto g = geometry_from(" set Shape = bilayer\n set Width = 2\n set Height = 1\n"
                                   " set Layer fraction = 0.3\n set Global refinements = 2");
      Triangulation<2> tria;
      g.create_triangulation(tria);
      check("bilayer: regions lower = 1, upper = 2",
            g.region_ids() ==
              std::map<std::string, types::material_id>{{"lower", 1}, {"upper", 2}});
      const auto sides = g.boundary_part_ids();
      for (const auto &s : std::map<std::string, double>{{"left", 1}, {"right", 1}, {"bottom", 2}, {"top", 2}})
        {
          const types::boundary_id id = sides.at(s.first);
          check_close("bilayer: length of '" + s.first + "'",
                      boundary_length(tria, [id](const auto &f) { return f->boundary_id() == id; })
                        .first,
                      s.second, 1e-12);
        }
    }
    {
      const auto g = geometry_from(" set Shape = half disc\n set Global refinements = 2");
      Triangulation<2> tria;
      g.create_triangulation(tria);
      const auto regions = g.region_ids();
      bool       ok      = regions.size() == 2;
      for (const auto &cell : tria.active_cell_iterators())
        ok = ok && cell->material_id() == regions.at(cell->center()[0] < 0 ? "left" : "right");
      check("half disc: region 'left' (X1 < 0) = 1, 'right' = 2, on every cell",
            ok && regions.at("left") == 1 && regions.at("right") == 2);
    }
  }

  // (d) Boundary selections: by name, by arc, and the errors.
  void
  boundary_selection()
  {
    {
      const auto       g = gmsh_geometry(example_directory + "/tube.geo");
      Triangulation<2> tria;
      g.create_triangulation(tria);
      geometry::BoundarySelection outer;
      outer.parse("outer", "Surface layer 1", "Boundary", g);
      unsigned int n_selected = 0, n_wrong = 0, n_outer_by_radius = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const double r       = cell->face(f)->center().norm();
              const bool   at_R    = r > 0.9; // outer 1 vs inner 0.8
              const bool   chosen  = outer.contains(cell->face(f));
              n_selected += chosen;
              n_outer_by_radius += at_R;
              n_wrong += (chosen != at_R) || (chosen && std::abs(r - 1) > 5e-3);
            }
      check("tube 'outer' (" + outer.description() + ") selects exactly the " +
              std::to_string(n_outer_by_radius) + " faces at radius R = 1 (selected " +
              std::to_string(n_selected) + ", wrong " + std::to_string(n_wrong) + ")",
            n_wrong == 0 && n_selected == n_outer_by_radius && n_selected > 0);

      const std::string message = input_error([&]() {
        geometry::BoundarySelection s;
        s.parse("outer, xyz", "Surface layer 1", "Boundary", g);
      });
      check_message("unknown name lists the available parts", message,
                    {"Surface layer 1", "Boundary", "unknown boundary part 'xyz'",
                     "this section has: inner, outer, all, arc A B"});
      check_message("arc with A > B", input_error([&]() {
                      geometry::BoundarySelection s;
                      s.parse("arc 90 0", "Surface layer 1", "Boundary", g);
                    }),
                    {"Boundary", "A < B"});
      check_message("arc with one angle", input_error([&]() {
                      geometry::BoundarySelection s;
                      s.parse("arc 90", "Surface layer 1", "Boundary", g);
                    }),
                    {"Boundary", "arc A B"});
      geometry::BoundarySelection none;
      none.parse("", "Surface layer 1", "Boundary", g);
      check("empty specification selects nothing (" + none.description() + ")",
            none.empty() &&
              boundary_length(tria, [&](const auto &f) { return none.contains(f); }).second == 0);
      geometry::BoundarySelection all;
      all.parse("all", "Surface layer 1", "Boundary", g);
      check("'all' selects every boundary face",
            boundary_length(tria, [&](const auto &f) { return all.contains(f); }).second ==
              boundary_length(tria, [](const auto &) { return true; }).second);
    }
    {
      const auto g = geometry_from(" set Shape = circle\n set Global refinements = 3");
      Triangulation<2> tria;
      g.create_triangulation(tria);
      geometry::BoundarySelection quadrant;
      quadrant.parse("arc 0 90", "Surface layer 1", "Boundary", g);
      unsigned int n_selected = 0, n_first_quadrant = 0, n_wrong = 0, n_all = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2> c     = cell->face(f)->center();
              const bool     first = c[0] > 0 && c[1] > 0;
              const bool     in    = quadrant.contains(cell->face(f));
              ++n_all;
              n_selected += in;
              n_first_quadrant += first;
              n_wrong += (in != first);
            }
      check("circle 'arc 0 90' selects exactly the " + std::to_string(n_first_quadrant) +
              " first-quadrant faces of " + std::to_string(n_all) + " (selected " +
              std::to_string(n_selected) + ", wrong " + std::to_string(n_wrong) + ")",
            n_wrong == 0 && 4 * n_selected == n_all);
      // The same arc written across 360 degrees, and a union.
      geometry::BoundarySelection a, b, u;
      a.parse("arc -45 45", "S", "B", g);
      b.parse("arc 315 405", "S", "B", g);
      u.parse("arc 0 90, arc 180 270", "S", "B", g);
      unsigned int n_diff = 0, n_a = 0, n_u = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2> c = cell->face(f)->center();
              n_a += a.contains(cell->face(f));
              n_u += u.contains(cell->face(f));
              n_diff += a.contains(cell->face(f)) != b.contains(cell->face(f));
              n_diff += u.contains(cell->face(f)) != (c[0] * c[1] > 0);
            }
      check("'arc -45 45' = 'arc 315 405' (" + std::to_string(n_a) +
              " faces) and 'arc 0 90, arc 180 270' = quadrants 1 and 3 (" + std::to_string(n_u) +
              " faces): " + std::to_string(n_diff) + " differences",
            n_diff == 0 && 4 * n_a == n_all && 2 * n_u == n_all);
      check_message("circle: unknown name lists its parts", input_error([&]() {
                      geometry::BoundarySelection s;
                      s.parse("inner", "Surface layer 2", "Boundary", g);
                    }),
                    {"unknown boundary part 'inner'", "this section has: outer, all, arc A B"});
    }
    {
      // Arcs are half-open: on the coarse circle the face midpoints lie
      // exactly on the arc ends (0, 90, 180, 270 degrees), and adjacent arcs
      // must still split the boundary without sharing or dropping a face.
      const auto g = geometry_from(" set Shape = circle\n set Global refinements = 0");
      Triangulation<2> tria;
      g.create_triangulation(tria);
      geometry::BoundarySelection right, left;
      right.parse("arc -90 90", "S", "B", g);
      left.parse("arc 90 270", "S", "B", g);
      unsigned int n_all = 0, n_right = 0, n_left = 0, n_both = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              ++n_all;
              n_right += right.contains(cell->face(f));
              n_left += left.contains(cell->face(f));
              n_both += right.contains(cell->face(f)) && left.contains(cell->face(f));
            }
      check("coarse circle: 'arc -90 90' (" + std::to_string(n_right) + ") and 'arc 90 270' (" +
              std::to_string(n_left) + ") split its " + std::to_string(n_all) +
              " faces, sharing " + std::to_string(n_both),
            n_both == 0 && n_right + n_left == n_all && n_right == n_left);
    }
  }

  // Materials by region name: resolve_regions() with the mesh's names.
  void
  material_regions()
  {
    auto library = [](const std::string &regions1, const std::string &regions2) {
      ParameterHandler prm;
      materials::MaterialLibrary::declare_parameters(prm);
      prm.parse_input_from_string("subsection Material 1\n set Regions = " + regions1 +
                                  "\n set Name = soft\n set Young's modulus = 1\nend\n"
                                  "subsection Material 2\n set Regions = " + regions2 +
                                  "\n set Name = stiff\n set Young's modulus = 10\nend\n");
      materials::MaterialLibrary m;
      m.parse_parameters(prm);
      return m;
    };
    const std::map<std::string, types::material_id> names = {{"matrix", 1}, {"filaments", 2}};
    {
      auto m = library("matrix", "filaments");
      check_close("max_young before resolve_regions", m.max_young(), 10, 1e-14);
      check("descriptions before resolve_regions", m.descriptions().size() == 2);
      m.resolve_regions(names);
      m.check_regions({1, 2});
      check("'matrix' -> region 1 -> soft, 'filaments' -> region 2 -> stiff",
            m.material(1).name == "soft" && m.material(2).name == "stiff");
    }
    {
      auto m = library("1", "2, 7");
      check("integer ids work without resolve_regions",
            m.material(1).name == "soft" && m.material(7).name == "stiff");
      m.resolve_regions({});
      check("integer ids work after resolve_regions with no names",
            m.material(1).name == "soft" && m.material(7).name == "stiff");
    }
    check_message("unknown region name", input_error([&]() {
                    library("matrix", "fibres").resolve_regions(names);
                  }),
                  {"Material 2", "Regions", "unknown region 'fibres'", "filaments (2)",
                   "matrix (1)"});
    check_message("region given twice (by id and by name)", input_error([&]() {
                    library("1", "matrix").resolve_regions(names);
                  }),
                  {"Material 2", "Regions", "already given to Material 1"});
    check_message("not an id nor a name", input_error([&]() { library("1.5", ""); }),
                  {"Material 1", "Regions", "'1.5'"});
    check_message("uncovered region after resolve", input_error([&]() {
                    auto m = library("matrix", "");
                    m.resolve_regions(names);
                    m.check_regions({1, 2});
                  }),
                  {"no material covers region 2"});
  }

  /// A file in a fresh scratch directory.
  std::string
  scratch_file(const std::string &name, const std::string &contents)
  {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("cosmo-test-geometry-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / name) << contents;
    return (dir / name).string();
  }

  // Bad mesh files: each an io::InputError naming `Mesh file` and why.
  void
  mesh_file_errors()
  {
    auto mesh = [](const std::string &file, const std::string &program = "gmsh") {
      return input_error([&]() {
        auto g = geometry_from(" set Shape = gmsh\n set Mesh file = " + file +
                               "\n set Gmsh program = " + program +
                               "\n set Global refinements = 0");
        Triangulation<2> tria;
        g.create_triangulation(tria);
      });
    };
    // What was there when the file was parsed and is gone when it is meshed.
    auto removed_before_meshing = [](const std::string &file, const std::string &program,
                                     const std::string &removed) {
      return input_error([&]() {
        auto g = geometry_from(" set Shape = gmsh\n set Mesh file = " + file +
                               "\n set Gmsh program = " + program +
                               "\n set Global refinements = 0");
        std::filesystem::remove(removed);
        Triangulation<2> tria;
        g.create_triangulation(tria);
      });
    };
    check_message("missing .geo (at parse)", mesh("no_such_section.geo"),
                  {"Cross-section", "Mesh file", "no_such_section.geo", "cannot open"});
    const std::string vanishing_geo = scratch_file("vanishing.geo", "Point(1) = {0, 0, 0, 0.1};\n");
    check_message("missing .geo (at meshing)",
                  removed_before_meshing(vanishing_geo, "gmsh", vanishing_geo),
                  {"Mesh file", "does not exist"});
    check_message("gmsh program not found", input_error([]() {
                    geometry_from(" set Shape = gmsh\n set Mesh file = " + data_directory +
                                  "/circle.geo\n set Gmsh program = no-such-gmsh");
                  }),
                  {"Mesh file", "'no-such-gmsh' is not found"});
    const std::string vanishing_gmsh = scratch_file("vanishing-gmsh", "#!/bin/sh\nexit 0\n");
    std::filesystem::permissions(vanishing_gmsh, std::filesystem::perms::owner_all);
    check_message("gmsh program not found (at meshing)",
                  removed_before_meshing(data_directory + "/circle.geo", vanishing_gmsh,
                                         vanishing_gmsh),
                  {"Mesh file", "not found"});
    check_message("syntax error: gmsh's message is shown",
                  mesh(scratch_file("syntax.geo", "Point(1) = {0, 0, 0 0.1};\n")),
                  {"Mesh file", "syntax.geo", "gmsh failed", "syntax error"});
    check_message("open curve loop",
                  mesh(scratch_file("open.geo",
                                    "Point(1) = {0,0,0,0.2}; Point(2) = {1,0,0,0.2};\n"
                                    "Point(3) = {1,1,0,0.2}; Point(4) = {0,1,0,0.2};\n"
                                    "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4};\n"
                                    "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n")),
                  {"Mesh file", "open.geo", "gmsh"});
    check_message("no surface: no cells",
                  mesh(scratch_file("points.geo", "Point(1) = {0, 0, 0, 0.1};\n")),
                  {"Mesh file", "no 2D cells"});
    check_message("a triangle mesh",
                  mesh(scratch_file("triangles.msh",
                                    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
                                    "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                                    "$Elements\n2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n"
                                    "$EndElements\n")),
                  {"Mesh file", "2 triangles"});
    check_message("not a mesh", mesh(scratch_file("text.msh", "hello\n")),
                  {"Mesh file", "not a readable ASCII gmsh mesh"});

    // The temporary directories of these runs (and of the failed ones) are gone.
    unsigned int left = 0;
    const std::string prefix = "cosmo-gmsh-" + std::to_string(::getpid()) + "-";
    for (const auto &entry :
         std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
      left += entry.path().filename().string().rfind(prefix, 0) == 0;
    check("temporary gmsh directories removed (" + std::to_string(left) + " left)", left == 0);
    std::filesystem::remove_all(std::filesystem::path(scratch_file("x", "")).parent_path());
  }
} // namespace

int
main(int argc, char **argv)
{
  const auto mpi = cosmo::io::ranks::init_mpi(argc, argv, 1);
  const cosmo_test::Cases cases = {
    {"rectangle_geo", rectangle_geo},
    {"circle_area_convergence", circle_area_convergence},
    {"example_geometries", example_geometries},
    {"builtin_names", builtin_names},
    {"boundary_selection", boundary_selection},
    {"material_regions", material_regions},
    {"mesh_file_errors", mesh_file_errors}};
  if (argc == 4)
    {
      data_directory    = argv[2];
      example_directory = argv[3];
    }
  return cosmo_test::run_case("test_geometry", "<tests/data directory> <example .geo directory>",
                              cases, argc, argv, 4, 4);
}
