#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <cosmo/geometry/mirror_dofs.h>

#include <array>
#include <cmath>
#include <map>

namespace cosmo
{
  namespace geometry
  {
    namespace
    {
      /// The communicator of a mesh divided over ranks; MPI_COMM_NULL for a serial one.
      template <int dim>
      MPI_Comm
      ranks_of(const DoFHandler<dim> &dof_handler)
      {
        const auto *parallel_mesh = dynamic_cast<const parallel::TriangulationBase<dim> *>(
          &dof_handler.get_triangulation());
        return parallel_mesh ? parallel_mesh->get_communicator() : MPI_COMM_NULL;
      }

      /**
       * `width` numbers per DoF, whole on every rank: `fill(i, x)` writes
       * DoF i's into x for the DoFs this rank owns (every DoF on one
       * process), and the ranks' parts are summed. Each entry has one
       * nonzero term, so the sum is exact and the same on every rank.
       */
      template <int dim, typename Fill>
      std::vector<double>
      per_dof(const DoFHandler<dim> &dof_handler, const unsigned int width, const Fill &fill)
      {
        std::vector<double> all(std::size_t(width) * dof_handler.n_dofs(), 0.);
        fill(all);
        if (const MPI_Comm comm = ranks_of(dof_handler); comm != MPI_COMM_NULL)
          MPI_Allreduce(MPI_IN_PLACE, all.data(), all.size(), MPI_DOUBLE, MPI_SUM, comm);
        return all;
      }

      /// The field component of every DoF, from its owner's cells.
      template <int dim>
      std::vector<double>
      dof_components(const DoFHandler<dim> &dof_handler)
      {
        return per_dof(dof_handler, 1, [&](std::vector<double> &c) {
          const IndexSet                       owned = dof_handler.locally_owned_dofs();
          std::vector<types::global_dof_index> idx;
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                idx.resize(cell->get_fe().n_dofs_per_cell());
                cell->get_dof_indices(idx);
                for (unsigned int i = 0; i < idx.size(); ++i)
                  if (owned.is_element(idx[i]))
                    c[idx[i]] = cell->get_fe().system_to_component_index(i).first;
              }
        });
      }

      /// The support point of every DoF (the map variant of deal.II's, which gives a rank
      /// its own and its neighbours' DoFs).
      template <int dim>
      std::vector<Point<dim>>
      dof_support_points(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler)
      {
        const std::vector<double> all = per_dof(dof_handler, dim, [&](std::vector<double> &x) {
          std::map<types::global_dof_index, Point<dim>> mine;
          DoFTools::map_dofs_to_support_points(mapping, dof_handler, mine);
          const IndexSet owned = dof_handler.locally_owned_dofs();
          for (const auto &[i, p] : mine)
            if (owned.is_element(i))
              for (unsigned int d = 0; d < dim; ++d)
                x[dim * i + d] = p[d];
        });
        std::vector<Point<dim>> points(dof_handler.n_dofs());
        for (types::global_dof_index i = 0; i < points.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            points[i][d] = all[dim * i + d];
        return points;
      }
    } // namespace

    template <int dim>
    std::vector<types::global_dof_index>
    mirror_dofs(const Mapping<dim> &    mapping,
                const DoFHandler<dim> &dof_handler,
                const unsigned int     axis,
                const double           length_scale)
    {
      const types::global_dof_index n         = dof_handler.n_dofs();
      const std::vector<Point<dim>> points    = dof_support_points(mapping, dof_handler);
      const std::vector<double>     component = dof_components(dof_handler);
      const double scale = 1e-7 * length_scale;
      using Key          = std::pair<std::array<long long, dim>, unsigned int>;
      auto key           = [&](const Point<dim> &p, const double c) {
        Key k;
        for (unsigned int d = 0; d < dim; ++d)
          k.first[d] = std::llround(p[d] / scale);
        k.second = static_cast<unsigned int>(c);
        return k;
      };
      std::map<Key, types::global_dof_index> at;
      for (types::global_dof_index i = 0; i < n; ++i)
        at[key(points[i], component[i])] = i;
      std::vector<types::global_dof_index> mirror(n);
      for (types::global_dof_index i = 0; i < n; ++i)
        {
          Point<dim> p = points[i];
          p[axis]      = -p[axis];
          const auto it = at.find(key(p, component[i]));
          if (it == at.end())
            return {};
          mirror[i] = it->second;
        }
      return mirror;
    }

    template <int dim>
    double
    reflection_parity(const DoFHandler<dim> &                     dof_handler,
                      const std::vector<types::global_dof_index> &mirror,
                      const Vector<double> &                      mode,
                      const std::vector<double> &                 component_signs)
    {
      if (mirror.empty() || mirror.size() != dof_handler.n_dofs() || mode.size() < mirror.size())
        return NAN;
      const std::vector<double> component = dof_components(dof_handler);
      double                    cross = 0, square = 0;
      for (types::global_dof_index i = 0; i < mirror.size(); ++i)
        {
          const unsigned int c    = static_cast<unsigned int>(component[i]);
          const double       sign = c < component_signs.size() ? component_signs[c] : 0.;
          if (sign != 0)
            {
              cross += sign * mode[i] * mode[mirror[i]];
              square += mode[i] * mode[i];
            }
        }
      return square > 0 ? cross / square : NAN;
    }

    template std::vector<types::global_dof_index>
    mirror_dofs<1>(const Mapping<1> &, const DoFHandler<1> &, unsigned int, double);
    template std::vector<types::global_dof_index>
    mirror_dofs<2>(const Mapping<2> &, const DoFHandler<2> &, unsigned int, double);
    template double
    reflection_parity<1>(const DoFHandler<1> &, const std::vector<types::global_dof_index> &,
                         const Vector<double> &, const std::vector<double> &);
    template double
    reflection_parity<2>(const DoFHandler<2> &, const std::vector<types::global_dof_index> &,
                         const Vector<double> &, const std::vector<double> &);
  } // namespace geometry
} // namespace cosmo
