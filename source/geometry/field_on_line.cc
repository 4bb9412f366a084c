#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <cosmo/geometry/field_on_line.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace cosmo
{
  namespace geometry
  {
    using namespace dealii;

    void
    value_on_line(const DoFHandler<1> &dof_handler,
                  const Vector<double> &field,
                  const double         x,
                  Vector<double> &     value)
    {
      const auto &tria = dof_handler.get_triangulation();
      double      lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const auto &cell : tria.active_cell_iterators())
        {
          lo = std::min(lo, cell->vertex(0)[0]);
          hi = std::max(hi, cell->vertex(1)[0]);
        }
      const double slack = 1e-10 * (hi - lo);
      if (!(x >= lo - slack && x <= hi + slack))
        throw std::invalid_argument("value_on_line: x = " + std::to_string(x) +
                                    " is outside the mesh [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "]");
      // The cell whose vertices bracket x, or (x outside by round-off) the
      // one nearest to it; on an interior vertex either neighbour (the
      // field is continuous there).
      auto   cell     = dof_handler.begin_active();
      double distance = std::numeric_limits<double>::infinity();
      for (auto c = dof_handler.begin_active(); c != dof_handler.end() && distance > 0; ++c)
        {
          const double d = std::max({0., c->vertex(0)[0] - x, x - c->vertex(1)[0]});
          if (d < distance)
            cell = c, distance = d;
        }
      const double x0 = cell->vertex(0)[0], x1 = cell->vertex(1)[0];
      const double xi = std::clamp((x - x0) / (x1 - x0), 0., 1.);
      const Quadrature<1> point(std::vector<Point<1>>{Point<1>(xi)});
      FEValues<1>         fev(dof_handler.get_fe(), point, update_values);
      fev.reinit(cell);
      std::vector<Vector<double>> values(1, Vector<double>(dof_handler.get_fe().n_components()));
      fev.get_function_values(field, values);
      value = values[0];
    }
  } // namespace geometry
} // namespace cosmo
