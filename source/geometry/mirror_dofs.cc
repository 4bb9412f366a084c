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
    template <int dim>
    std::vector<types::global_dof_index>
    mirror_dofs(const Mapping<dim> &    mapping,
                const DoFHandler<dim> &dof_handler,
                const unsigned int     axis,
                const double           length_scale)
    {
      const types::global_dof_index n = dof_handler.n_dofs();
      std::vector<Point<dim>>       points(n);
      std::vector<unsigned int>            component(n);
      std::vector<types::global_dof_index> idx;
      const auto *parallel_mesh = dynamic_cast<const parallel::TriangulationBase<dim> *>(
        &dof_handler.get_triangulation());
      if (parallel_mesh == nullptr)
        DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
      else
        {
          // A mesh divided over ranks: each rank places its own DoFs, and
          // every rank gets all of them (a sum in which each entry has one
          // nonzero term, so exact and the same on every rank).
          std::map<types::global_dof_index, Point<dim>> mine;
          DoFTools::map_dofs_to_support_points(mapping, dof_handler, mine);
          const IndexSet      owned = dof_handler.locally_owned_dofs();
          std::vector<double> all((dim + 1) * n, 0.);
          for (const auto &[i, p] : mine)
            if (owned.is_element(i))
              for (unsigned int d = 0; d < dim; ++d)
                all[(dim + 1) * i + d] = p[d];
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                idx.resize(cell->get_fe().n_dofs_per_cell());
                cell->get_dof_indices(idx);
                for (unsigned int i = 0; i < idx.size(); ++i)
                  if (owned.is_element(idx[i]))
                    all[(dim + 1) * idx[i] + dim] = cell->get_fe().system_to_component_index(i).first;
              }
          MPI_Allreduce(MPI_IN_PLACE, all.data(), all.size(), MPI_DOUBLE, MPI_SUM,
                        parallel_mesh->get_communicator());
          for (types::global_dof_index i = 0; i < n; ++i)
            {
              for (unsigned int d = 0; d < dim; ++d)
                points[i][d] = all[(dim + 1) * i + d];
              component[i] = static_cast<unsigned int>(all[(dim + 1) * i + dim]);
            }
        }
      if (parallel_mesh == nullptr)
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          idx.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(idx);
          for (unsigned int i = 0; i < idx.size(); ++i)
            component[idx[i]] = cell->get_fe().system_to_component_index(i).first;
        }
      const double scale = 1e-7 * length_scale;
      using Key          = std::pair<std::array<long long, dim>, unsigned int>;
      auto key           = [&](const Point<dim> &p, const unsigned int c) {
        Key k;
        for (unsigned int d = 0; d < dim; ++d)
          k.first[d] = std::llround(p[d] / scale);
        k.second = c;
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
      std::vector<double>                  sign(dof_handler.n_dofs(), 0.);
      std::vector<types::global_dof_index> idx;
      const auto *parallel_mesh = dynamic_cast<const parallel::TriangulationBase<dim> *>(
        &dof_handler.get_triangulation());
      const IndexSet owned = dof_handler.locally_owned_dofs();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          idx.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(idx);
          for (unsigned int i = 0; i < idx.size(); ++i)
            if (owned.is_element(idx[i]))
            {
              const unsigned int c = cell->get_fe().system_to_component_index(i).first;
              sign[idx[i]]         = c < component_signs.size() ? component_signs[c] : 0.;
            }
        }
      // (a mesh divided over ranks: each DoF's sign from its owner, a sum of one term)
      if (parallel_mesh != nullptr)
        MPI_Allreduce(MPI_IN_PLACE, sign.data(), sign.size(), MPI_DOUBLE, MPI_SUM,
                      parallel_mesh->get_communicator());
      double cross = 0, square = 0;
      for (types::global_dof_index i = 0; i < mirror.size(); ++i)
        if (sign[i] != 0)
          {
            cross += sign[i] * mode[i] * mode[mirror[i]];
            square += mode[i] * mode[i];
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
