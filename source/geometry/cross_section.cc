#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <deal.II/distributed/tria_base.h>

#include <cosmo/geometry/cross_section.h>
#include <cosmo/solvers/replicated_vector.h>
#include <cosmo/geometry/section_shape.h>
#include <cosmo/io/parameters.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <regex>
#include <sstream>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<geometry::SectionShape>;
  } // namespace plugins

  namespace geometry
  {
    void
    CrossSectionGeometry::declare_parameters(ParameterHandler &prm)
    {
      using Shapes = plugins::Registry<SectionShape>;
      prm.enter_subsection("Cross-section");
      prm.declare_entry("Shape",
                        "circle",
                        Patterns::Selection(Shapes::names()),
                        "The section's shape (the registered shapes, "
                        "source/geometry/section_shapes/); the names of its regions and "
                        "boundary parts are usable for Regions and boundary selections. " +
                          Shapes::documentation());
      // The dimensions several shapes use; a shape's own entries are its own.
      prm.declare_entry("Radius", "1", Patterns::Double(0), "Outer radius (length unit).");
      prm.declare_entry("Width", "1", Patterns::Double(0), "Extent along X1 (rectangle, bilayer).");
      prm.declare_entry("Height", "1", Patterns::Double(0), "Extent along X2 (rectangle, bilayer).");
      prm.declare_entry("Global refinements", "3", Patterns::Integer(0, 10),
                        "Uniform refinements of the coarse mesh (each quarters the cells).");
      Shapes::declare_parameters(prm);
      prm.leave_subsection();
    }

    void
    check_section_length(const double       length,
                         const std::string &entry,
                         const std::string &text)
    {
      if (!(length >= 1e-6 && length <= 1e6))
        throw io::InputError("Cross-section", entry, text,
                             "a length from 1e-6 to 1e6 (in the length unit of the moduli)");
    }

    void
    check_aspect_ratio(const double a, const double b, const std::string &entry, const std::string &text)
    {
      if (!(std::max(a, b) <= 1e3 * std::min(a, b)))
        throw io::InputError("Cross-section", entry, text,
                             "extents within a ratio of 1e3 of each other (a thinner section "
                             "is a strip: the strip application)");
    }

    void
    CrossSectionGeometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cross-section");
      shape       = prm.get("Shape");
      refinements = prm.get_integer("Global refinements");
      // Lengths a mesh of double-precision vertices can carry: the section's
      // moments grow as L^4 (L^6 for warping) and the mapping's inversion works
      // to ~1e-12 of a cell; 1e300 ended in a NaN area or a crash.
      for (const std::string entry : {"Radius", "Width", "Height"})
        check_section_length(prm.get_double(entry), entry, prm.get(entry));
      check_aspect_ratio(prm.get_double("Width"), prm.get_double("Height"), "Height",
                         prm.get("Height") + "' with 'Width' = '" + prm.get("Width"));
      shape_model = plugins::Registry<SectionShape>::create(shape);
      shape_model->parse_parameters(prm);
      prm.leave_subsection();
    }

    void
    CrossSectionGeometry::create_triangulation(Triangulation<2> &tria) const
    {
      AssertThrow(shape_model, ExcMessage("create_triangulation() before parse_parameters()"));
      tria.clear();
      const SectionMesh mesh = shape_model->create_triangulation(tria, refinements);
      boundary_parts         = mesh.boundary_parts;
      regions                = mesh.regions;
      meshing_summary        = mesh.meshing_summary;
      applied_shift          = Point<2>();
      if (!mesh.centred_by_construction)
        {
          const SectionProperties p = properties(tria, 1);
          if (p.centroid.norm() > 1e-12 * p.diameter)
            {
              applied_shift = -p.centroid;
              GridTools::shift(Tensor<1, 2>(applied_shift), tria);
            }
        }
    }

    SectionMesh
    label_builtin_mesh(Triangulation<2> &                                         tria,
                       const std::map<std::string, types::material_id> &          regions,
                       const std::function<types::material_id(const Point<2> &)> &region_of,
                       const std::map<std::string, types::boundary_id> &          boundary_parts,
                       const std::function<types::boundary_id(const Point<2> &)> &boundary_of)
    {
      // Every level, not only the active cells: a coarser level is the mesh
      // of the coarse-mesh start, labelled as that mesh would be (the growth
      // check, materials/growth_admissibility.h, visits every level).
      for (const auto &cell : tria.cell_iterators())
        {
          cell->set_material_id(region_of ? region_of(cell->center()) : types::material_id(1));
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              cell->face(f)->set_boundary_id(boundary_of ? boundary_of(cell->face(f)->center()) :
                                                           types::boundary_id(0));
        }
      SectionMesh mesh;
      mesh.regions        = regions;
      mesh.boundary_parts = boundary_parts;
      return mesh;
    }

    double
    get_positive_length(ParameterHandler &prm, const std::string &entry)
    {
      const double v = prm.get_double(entry);
      if (!(v > 0))
        throw io::InputError("Cross-section", entry, prm.get(entry), "must be positive");
      return v;
    }


    const std::map<std::string, types::boundary_id> &
    CrossSectionGeometry::boundary_part_ids() const
    {
      return boundary_parts;
    }

    const std::map<std::string, types::material_id> &
    CrossSectionGeometry::region_ids() const
    {
      return regions;
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
      // A mesh divided over ranks: each rank integrates its own cells, the sums are added on
      // rank 0 and sent to all (the same bits on every rank: the centroid shifts the mesh).
      const auto *parallel_mesh = dynamic_cast<const parallel::TriangulationBase<2> *>(&tria);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
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
      if (parallel_mesh == nullptr)
        {
          p.centroid = Point<2>(mx / p.area, my / p.area);
          p.diameter = GridTools::diameter(tria);
          return p;
        }
      std::vector<double> sums = {p.area, mx, my, p.I22, p.I11, p.I12};
      solvers::sum_on_all_ranks(sums, parallel_mesh->get_communicator());
      p.area     = sums[0];
      p.I22      = sums[3];
      p.I11      = sums[4];
      p.I12      = sums[5];
      p.centroid = Point<2>(sums[1] / p.area, sums[2] / p.area);
      // The diameter from the boundary vertices of every rank's cells (the
      // farthest pair of points of a mesh lies on its boundary).
      std::vector<double> mine;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  mine.push_back(cell->face(f)->vertex(v)[0]);
                  mine.push_back(cell->face(f)->vertex(v)[1]);
                }
      const auto all = Utilities::MPI::all_gather(parallel_mesh->get_communicator(), mine);
      std::vector<Point<2>> boundary;
      for (const auto &r : all)
        for (std::size_t k = 0; k + 1 < r.size(); k += 2)
          boundary.emplace_back(r[k], r[k + 1]);
      double d2 = 0;
      for (std::size_t i = 0; i < boundary.size(); ++i)
        for (std::size_t j = i + 1; j < boundary.size(); ++j)
          d2 = std::max(d2, boundary[i].distance_square(boundary[j]));
      p.diameter = std::sqrt(d2);
      return p;
    }


    void
    BoundarySelection::parse(const std::string &         spec,
                             const std::string &         section,
                             const std::string &         entry,
                             const CrossSectionGeometry &geometry)
    {
      everything = false;
      parts.clear();
      ids.clear();
      arcs.clear();
      const auto &names     = geometry.boundary_part_ids();
      auto        available = [&names]() {
        std::string list;
        for (const auto &n : names)
          list += n.first + ", ";
        return list + "all, arc A B";
      };
      for (const std::string &item : Utilities::split_string_list(spec, ','))
        {
          if (item.empty())
            continue;
          if (item == "all")
            everything = true;
          else if (item.rfind("arc", 0) == 0 &&
                   (item.size() == 3 || std::isspace(static_cast<unsigned char>(item[3]))))
            {
              std::istringstream s(item.substr(3));
              double             a = 0, b = 0;
              std::string        rest;
              if (!(s >> a >> b) || (s >> rest))
                throw io::InputError(section, entry, spec,
                                     "'" + item +
                                       "': expected 'arc A B' with two angles in degrees");
              if (!(a < b && b - a <= 360))
                throw io::InputError(section, entry, spec,
                                     "'" + item + "': 'arc A B' needs A < B and B - A <= 360 "
                                                  "(degrees, counterclockwise from X1)");
              arcs.emplace_back(a, b);
            }
          else
            {
              const auto it = names.find(item);
              if (it == names.end())
                throw io::InputError(section, entry, spec,
                                     "unknown boundary part '" + item +
                                       "'; this section has: " + available());
              parts.emplace_back(it->first, it->second);
              ids.insert(it->second);
            }
        }
    }

    bool
    BoundarySelection::contains(const typename Triangulation<2>::face_iterator &face) const
    {
      if (!face->at_boundary())
        return false;
      if (everything || ids.count(face->boundary_id()))
        return true;
      if (arcs.empty())
        return false;
      const Point<2> c     = face->center();
      const double   theta = std::atan2(c[1], c[0]) * 180 / M_PI;
      // Half-open [A, B): a midpoint exactly on an arc end (0 or 90 degrees
      // on a symmetric mesh) belongs to the arc that starts there, so that
      // 'arc -90 90' and 'arc 90 270' split the boundary without sharing a
      // face. The tolerance keeps round-off from moving it across.
      const double tolerance = 1e-9;
      for (const auto &arc : arcs)
        {
          double d = std::fmod(theta - arc.first, 360.);
          if (d < 0)
            d += 360;
          if (d >= 360 - tolerance || d < arc.second - arc.first - tolerance)
            return true;
        }
      return false;
    }

    bool
    BoundarySelection::empty() const
    {
      return !everything && parts.empty() && arcs.empty();
    }

    std::string
    BoundarySelection::description() const
    {
      if (everything)
        return "the whole boundary";
      std::ostringstream s;
      for (const auto &p : parts)
        s << (s.tellp() > 0 ? ", " : "") << p.first << " (boundary id "
          << static_cast<unsigned int>(p.second) << ")";
      for (const auto &a : arcs)
        s << (s.tellp() > 0 ? ", " : "") << "arc " << a.first << ".." << a.second << " deg";
      return empty() ? std::string("none") : s.str();
    }
  } // namespace geometry
} // namespace cosmo
