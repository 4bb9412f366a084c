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
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          idx.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(idx);
          for (unsigned int i = 0; i < idx.size(); ++i)
            {
              const unsigned int c = cell->get_fe().system_to_component_index(i).first;
              sign[idx[i]]         = c < component_signs.size() ? component_signs[c] : 0.;
            }
        }
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
