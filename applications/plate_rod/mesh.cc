// The mesh of part 3 (the disc, the sector stretched or mirrored) and the
// constraints on its DoFs (mirror edges, gauges, the rim rotation off the
// rim): PlateRodDiscretization::make_mesh and make_constraints.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cosmo/io/resources.h>

#include "discretization.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace cosmo
{
  namespace plate_rod
  {
    namespace
    {
      /// The sector 0 <= theta <= pi/n of radius R: the quarter disc (3 cells; the half
      /// disc for n = 1) refined, then stretched in angle onto [0, pi/n] (circles stay circles).
      void
      stretched_sector(Triangulation<2> &tria, const unsigned int n, const double R,
                       const std::function<void()> &refine)
      {
        if (n == 1)
          {
            // The half disc y >= 0 (half_hyper_ball is x >= 0): no degenerate apex cell.
            GridGenerator::half_hyper_ball(tria, Point<2>(), R);
            GridTools::rotate(M_PI / 2, tria);
          }
        else
          GridGenerator::quarter_hyper_ball(tria, Point<2>(), R);
        refine();
        if (n > 2)
          {
            const double s = 2. / n;
            GridTools::transform(
              [s](const Point<2> &p) {
                const double r = p.norm(), a = std::atan2(p[1], p[0]);
                return Point<2>(r * std::cos(s * a), r * std::sin(s * a));
              },
              tria);
          }
      }

      /**
       * The sector pi/n as two mirror images of the (refined) mesh of the
       * sector pi/(2n), joined along theta = pi/(2n): the same discretization
       * on both halves, so that the states of the sector pi/n symmetric about
       * that line are exactly those of the sector pi/(2n) (a comparison of the
       * two symmetry reductions to round-off, not to the discretization error).
       */
      void
      mirrored_sector(Triangulation<2> &tria, const unsigned int n, const double R,
                      const std::function<void(Triangulation<2> &)> &refine)
      {
        Triangulation<2> half, flat;
        stretched_sector(half, 2 * n, R, [&]() { refine(half); });
        GridGenerator::flatten_triangulation(half, flat);
        const double          phi = M_PI / (2 * n);
        const Tensor<1, 2>    e({std::cos(phi), std::sin(phi)});
        std::vector<Point<2>> vertices = flat.get_vertices();
        const unsigned int    nv       = vertices.size();
        for (unsigned int v = 0; v < nv; ++v)
          vertices.push_back(Point<2>(2 * (vertices[v] * e) * e - vertices[v]));
        std::vector<CellData<2>> cells;
        for (const auto &cell : flat.active_cell_iterators())
          {
            CellData<2> c(4), m(4);
            for (unsigned int v = 0; v < 4; ++v)
              c.vertices[v] = cell->vertex_index(v);
            // The image of a cell has the opposite orientation: swap 0 <-> 1, 2 <-> 3.
            const unsigned int order[4] = {1, 0, 3, 2};
            for (unsigned int v = 0; v < 4; ++v)
              m.vertices[v] = c.vertices[order[v]] + nv;
            cells.push_back(c);
            cells.push_back(m);
          }
        SubCellData                subcells;
        std::vector<unsigned int>  unused;
        GridTools::delete_duplicated_vertices(vertices, cells, subcells, unused, 1e-10 * R);
        GridTools::consistently_order_cells(cells);
        tria.create_triangulation(vertices, cells, subcells);
      }
    } // namespace

    void
    PlateRodDiscretization::make_mesh()
    {
      this->triangulation.set_distributed(parameters.distributed_mesh);
      // The same coarse mesh and refinements on one process and on a distributed mesh.
      Triangulation<2> &triangulation = this->triangulation.get();
      triangulation.clear();
      // 6 fields of degree p: about 6 p^2 unknowns per cell; refused before refining what
      // cannot fit (io/resources.h).
      const unsigned int degree = parameters.degree, refinements = parameters.refinements;
      const double       radius = parameters.radius;
      auto               refine = [=](Triangulation<2> &tria) {
        const boost::signals2::scoped_connection guard(
          io::guard_refinement(tria, 6. * degree * degree, degree, "Mesh", "Global refinements",
                               std::to_string(refinements)));
        tria.refine_global(refinements);
      };
      if (parameters.domain == "sector" && parameters.sector_mesh == "mirrored")
        mirrored_sector(triangulation, parameters.sector_n, radius, refine);
      else if (parameters.domain == "sector")
        stretched_sector(triangulation, parameters.sector_n, radius, [&]() { refine(triangulation); });
      else
        {
          GridGenerator::hyper_ball(triangulation, Point<2>(), radius);
          refine(triangulation);
        }
      // Straight cells inside, the rim on the exact circle (MappingQ(p) bends
      // the cells next to it).
      triangulation.reset_all_manifolds();
      triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto   face = cell->face(f);
              const double r0 = face->vertex(0).norm(), r1 = face->vertex(1).norm();
              if (std::abs(r0 - radius) < 1e-8 * radius && std::abs(r1 - radius) < 1e-8 * radius)
                {
                  face->set_boundary_id(rim_id);
                  face->set_manifold_id(0);
                }
              else
                face->set_boundary_id(std::abs(face->center()[1]) < 1e-10 * radius ?
                                        mirror_first :
                                        mirror_second);
            }
      triangulation.set_manifold(0, SphericalManifold<2>(Point<2>()));
      mapping = std::make_unique<MappingQ<2>>(degree);
    }

    namespace
    {
      /// The sector's mirror edges (boundary mirror_first: m = E2; mirror_second: the edge
      /// at pi/n): m.u = 0 and theta parallel to m (m.d = 0), and the rim's alpha = 0 there.
      void
      add_mirror_constraints(const DoFHandler<2> &       dof_handler,
                             const FiniteElement<2> &    fe,
                             const unsigned int          sector_n,
                             AffineConstraints<double> &constraints)
      {
        // Mirror planes with normal m: m.u = 0 and theta parallel to m (m.d = 0).
        const double phi = M_PI / sector_n, c = std::cos(phi), s = std::sin(phi);
        std::vector<types::global_dof_index> fd(fe.n_dofs_per_face());
        auto constrain = [&constraints](const types::global_dof_index slave,
                                        const types::global_dof_index master,
                                        const double                  w) {
          if (constraints.is_constrained(slave))
            return;
          constraints.add_line(slave);
          if (master != numbers::invalid_dof_index && w != 0)
            constraints.add_entry(slave, master, w);
        };
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                (cell->face(f)->boundary_id() == mirror_first ||
                 cell->face(f)->boundary_id() == mirror_second))
              {
                cell->face(f)->get_dof_indices(fd);
                std::map<unsigned int, std::array<types::global_dof_index, 6>> nodes;
                for (unsigned int i = 0; i < fd.size(); ++i)
                  {
                    const auto ci                     = fe.face_system_to_component_index(i);
                    nodes[ci.second][ci.first]        = fd[i];
                  }
                const bool first = cell->face(f)->boundary_id() == mirror_first;
                for (const auto &[node, d] : nodes)
                  {
                    (void)node;
                    constrain(d[5], numbers::invalid_dof_index, 0); // the rim end: alpha = 0
                    if (first)
                      {
                        // m = E2: u2 = 0, theta1 = 0.
                        constrain(d[1], numbers::invalid_dof_index, 0);
                        constrain(d[3], numbers::invalid_dof_index, 0);
                      }
                    else if (std::abs(c) >= std::abs(s))
                      {
                        // m = (-s, c): u2 = (s/c) u1;  c theta1 + s theta2 = 0.
                        constrain(d[1], d[0], s / c);
                        constrain(d[3], d[4], -s / c);
                      }
                    else
                      {
                        constrain(d[0], d[1], c / s);
                        constrain(d[4], d[3], -c / s);
                      }
                  }
              }
      }

      /// The rim's in-plane rotation alpha lives on the rim: zero elsewhere. (A cell with a DoF
      /// on the rim has its rim face there, so every rank that knows such a DoF sees it is on
      /// the rim.)
      void
      constrain_alpha_off_rim(const DoFHandler<2> &       dof_handler,
                              const FiniteElement<2> &    fe,
                              AffineConstraints<double> &constraints)
      {
        std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
        std::set<types::global_dof_index>    all_alpha, rim_alpha;
        std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int k = 0; k < cell_dofs.size(); ++k)
                if (fe.system_to_component_index(k).first == 5)
                  all_alpha.insert(cell_dofs[k]);
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
                  {
                    cell->face(f)->get_dof_indices(face_dofs);
                    for (unsigned int k = 0; k < face_dofs.size(); ++k)
                      if (fe.face_system_to_component_index(k).first == 5)
                        rim_alpha.insert(face_dofs[k]);
                  }
            }
        for (const auto i : all_alpha)
          if (!rim_alpha.count(i) && !constraints.is_constrained(i))
            constraints.add_line(i);
      }
    } // namespace

    void
    PlateRodDiscretization::make_constraints()
    {
      constraints.clear();
      const bool   sector = parameters.domain == "sector";
      const double radius = parameters.radius;
      // In-plane only: u3, theta1, theta2 = 0 everywhere, first (the mirror
      // conditions below then find those DoFs constrained already).
      // On a distributed mesh each rank makes the constraints of the DoFs of
      // the cells it knows (its own and their neighbours): every constraint
      // here ties DoFs of one node, so the ranks that know a DoF agree on it.
      std::vector<types::global_dof_index> cell_dofs(fe->n_dofs_per_cell());
      if (parameters.in_plane_only)
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int k = 0; k < cell_dofs.size(); ++k)
                {
                  const unsigned int c = fe->system_to_component_index(k).first;
                  if (c >= 2 && c <= 4 && !constraints.is_constrained(cell_dofs[k]))
                    constraints.add_line(cell_dofs[k]);
                }
            }
      // The apex: no translation, director E3 (the gauge of the full disc; on a sector with
      // n >= 2 the mirrors imply all but u3 = 0, the one gauge left there).
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).norm() < 1e-10 * radius)
            for (unsigned int c = 0; c < 5; ++c)
              {
                const auto i = cell->vertex_dof_index(v, c);
                if (!constraints.is_constrained(i))
                  constraints.add_line(i);
              }
      if (!sector)
        {
          // Rotation about E3: u2 = 0 at the rim point (R, 0) (modes cos(n theta) keep it).
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial())
            for (const unsigned int v : cell->vertex_indices())
              if ((cell->vertex(v) - Point<2>(radius, 0)).norm() < 1e-8 * radius)
                {
                  const auto i = cell->vertex_dof_index(v, 1);
                  if (!constraints.is_constrained(i))
                    constraints.add_line(i);
                }
        }
      else
        {
          add_mirror_constraints(dof_handler, *fe, parameters.sector_n, constraints);
        }
      constrain_alpha_off_rim(dof_handler, *fe, constraints);
      constraints.close();
    }
  } // namespace plate_rod
} // namespace cosmo
