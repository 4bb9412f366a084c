#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/distributed/tria_base.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth_admissibility.h>

#include <cmath>
#include <utility>
#include <sstream>

namespace cosmo
{
  namespace materials
  {
    namespace
    {
      /**
       * The minimum on [0, 1] of the cubic through (0, q0), (1/3, q1), (2/3, q2),
       * (1, q3), and where it is: in s = 3 t, c = b0 + b1 s + b2 s^2 + b3 s^3
       * from the forward differences, and the minimum among the ends and the
       * roots of c' in [0, 3].
       */
      std::pair<double, double>
      cubic_minimum(const double (&q)[4])
      {
        const double d1 = q[1] - q[0], d2 = q[2] - 2 * q[1] + q[0],
                     d3 = q[3] - 3 * q[2] + 3 * q[1] - q[0];
        const double b[4] = {q[0], d1 - d2 / 2 + d3 / 3, d2 / 2 - d3 / 2, d3 / 6};
        auto c = [&b](const double s) { return b[0] + s * (b[1] + s * (b[2] + s * b[3])); };
        std::vector<double> candidates = {0., 1., 2., 3.};
        // c'(s) = b1 + 2 b2 s + 3 b3 s^2 = A s^2 + B s + C, its roots in the
        // form that stays accurate when A is round-off (a quadratic det Fg,
        // as for plate growth): q = -(B + sign(B) sqrt(B^2 - 4AC))/2, s = q/A, C/q.
        const double A = 3 * b[3], B = 2 * b[2], C = b[1];
        const double disc = B * B - 4 * A * C;
        if (disc >= 0)
          {
            const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
            if (A != 0)
              candidates.push_back(q / A);
            if (q != 0)
              candidates.push_back(C / q);
          }
        std::pair<double, double> best{INFINITY, 0.};
        for (const double s : candidates)
          if (s >= 0 && s <= 3 && c(s) < best.first)
            best = {c(s), s / 3};
        return best;
      }

      std::string
      refusal(const Point<2> &X, const double t, const double value, const GrowthEntry &entry)
      {
        std::ostringstream m;
        m << entry.quantity << " = " << value << " at (" << X[0] << ", " << X[1]
          << ") at load t = " << t
          << ": growth must be finite and keep " << entry.quantity
          << " > 0 at every vertex and quadrature point of the mesh (and of its coarser "
             "levels) for 0 <= t <= 1";
        return m.str();
      }

      /// This rank's first refusal, or "".
      std::string
      first_refusal(const std::vector<Point<2>> &                                        points,
                    const std::function<std::vector<double>(const Point<2> &, double)> &q,
                    const GrowthEntry &                                                  entry)
      {
        const double nodes[4] = {0., 1. / 3., 2. / 3., 1.};
        for (const auto &X : points)
          {
            std::vector<double> at[4];
            // t = 1 first: a law that is not finite is named at the load
            // the file gives it for (at t = 0 it ramps to 1 + 0 inf = nan).
            for (const unsigned int j : {3u, 1u, 2u, 0u})
              {
                at[j] = q(X, nodes[j]);
                for (const double v : at[j])
                  if (!(std::isfinite(v) && v > 0))
                    return refusal(X, nodes[j], v, entry);
              }
            for (unsigned int k = 0; k < at[0].size(); ++k)
              {
                const double c[4]    = {at[0][k], at[1][k], at[2][k], at[3][k]};
                const auto   minimum = cubic_minimum(c);
                if (!(minimum.first > 0))
                  return refusal(X, minimum.second, minimum.first, entry);
              }
          }
        return "";
      }
    } // namespace

    void
    check_growth_admissible(const std::vector<Point<2>> &                                        points,
                            const std::function<std::vector<double>(const Point<2> &, double)> &q,
                            const GrowthEntry &                                                  entry,
                            const MPI_Comm                                                       comm)
    {
      std::string why = first_refusal(points, q, entry);
      if (comm != MPI_COMM_SELF && Utilities::MPI::n_mpi_processes(comm) > 1)
        for (const auto &w : Utilities::MPI::all_gather(comm, why))
          if (!w.empty())
            {
              why = w;
              break;
            }
      if (!why.empty())
        throw io::InputError(entry.section, entry.entry, entry.text, why);
    }

    namespace
    {
      /**
       * `visit` every cell of every mesh the run uses: on a serial mesh the
       * cells of every level (the coarse-mesh start's meshes are its coarser
       * levels), on a distributed one this rank's active cells.
       */
      void
      for_each_cell_of_the_run(const Triangulation<2> &                                      tria,
                               const std::function<void(const Triangulation<2>::cell_iterator &)> &visit)
      {
        if (dynamic_cast<const parallel::DistributedTriangulationBase<2> *>(&tria) != nullptr)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned())
                visit(cell);
          }
        else
          for (const auto &cell : tria.cell_iterators())
            visit(cell);
      }
    } // namespace

    std::vector<Point<2>>
    growth_points(const Mapping<2> &                                                  mapping,
                  const Triangulation<2> &                                            tria,
                  const Quadrature<2> &                                               quadrature,
                  const std::function<bool(const Triangulation<2>::cell_iterator &)> &selected)
    {
      const FE_Nothing<2>   nothing;
      FEValues<2>           fev(mapping, nothing, quadrature, update_quadrature_points);
      std::vector<Point<2>> points;
      for_each_cell_of_the_run(tria, [&](const Triangulation<2>::cell_iterator &cell) {
        if (!selected(cell))
          return;
        for (const unsigned int v : cell->vertex_indices())
          points.push_back(cell->vertex(v));
        fev.reinit(cell);
        const auto &qp = fev.get_quadrature_points();
        points.insert(points.end(), qp.begin(), qp.end());
      });
      return points;
    }

    std::vector<Point<2>>
    boundary_growth_points(
      const Mapping<2> &                                                  mapping,
      const Triangulation<2> &                                            tria,
      const Quadrature<1> &                                               quadrature,
      const std::function<bool(const Triangulation<2>::face_iterator &)> &selected)
    {
      const FE_Nothing<2>   nothing;
      FEFaceValues<2>       fev(mapping, nothing, quadrature, update_quadrature_points);
      std::vector<Point<2>> points;
      for_each_cell_of_the_run(tria, [&](const Triangulation<2>::cell_iterator &cell) {
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && selected(cell->face(f)))
            {
              for (const unsigned int v : cell->face(f)->vertex_indices())
                points.push_back(cell->face(f)->vertex(v));
              fev.reinit(cell, f);
              const auto &qp = fev.get_quadrature_points();
              points.insert(points.end(), qp.begin(), qp.end());
            }
      });
      return points;
    }
  } // namespace materials
} // namespace cosmo
