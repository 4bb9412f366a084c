#ifndef cosmo_geometry_field_on_line_h
#define cosmo_geometry_field_on_line_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

/**
 * Point values of a finite-element field on a 1D mesh without a point
 * search. VectorTools::point_value finds the cell around a point with a
 * tolerance, and a point on the mesh's end by round-off (eta = w/2 on a
 * mesh of 1500 cells whose last vertex is w/2 - 1 ulp) is found in no cell:
 * deal.II then throws its generic "not locally owned" text. Here the cell
 * is the one whose vertices bracket x, and the reference point
 * (x - x0)/(x1 - x0) is clamped to [0, 1]: a point within round-off of an
 * end is evaluated at that end, for every cell count.
 */
namespace cosmo
{
  namespace geometry
  {
    /**
     * The field's components at x on a 1D mesh (the mapping is the linear
     * one of a line). x outside [first vertex, last vertex] by more than
     * 1e-10 of the mesh's length is an error (std::invalid_argument).
     */
    void
    value_on_line(const dealii::DoFHandler<1> &   dof_handler,
                  const dealii::Vector<double> &  field,
                  double                          x,
                  dealii::Vector<double> &        value);
  } // namespace geometry
} // namespace cosmo

#endif
