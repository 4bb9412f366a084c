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
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
      std::vector<unsigned int>            component(n);
      std::vector<types::global_dof_index> idx;
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

    template std::vector<types::global_dof_index>
    mirror_dofs<1>(const Mapping<1> &, const DoFHandler<1> &, unsigned int, double);
    template std::vector<types::global_dof_index>
    mirror_dofs<2>(const Mapping<2> &, const DoFHandler<2> &, unsigned int, double);
  } // namespace geometry
} // namespace cosmo
