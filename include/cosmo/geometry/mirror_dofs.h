#ifndef cosmo_geometry_mirror_dofs_h
#define cosmo_geometry_mirror_dofs_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <vector>

/**
 * The DoFs of a mirror-symmetric mesh paired by the reflection x_axis -> -x_axis:
 * for every DoF the DoF of the same vector component at the mirrored support
 * point. Used where a problem's symmetry acts on its unknowns: the full disc's
 * reflection y -> -y (plate_rod's fixed-point space at double eigenvalues) and
 * the width-wise parity of the strip's modes. Support points are matched to
 * 1e-7 of length_scale (the mesh's vertices are mirror images to round-off).
 */
namespace cosmo
{
  namespace geometry
  {
    using namespace dealii;

    /// mirror[i]: the DoF DoF i maps to; empty if some DoF has no mirror image
    /// (the mesh is not symmetric). The element must be primitive.
    template <int dim>
    std::vector<types::global_dof_index>
    mirror_dofs(const Mapping<dim> &    mapping,
                const DoFHandler<dim> &dof_handler,
                unsigned int           axis,
                double                 length_scale);

    /**
     * The parity of a mode (a vector over the DoFs of dof_handler, or longer:
     * entries past n_dofs() are ignored) under the reflection that `mirror`
     * (mirror_dofs()) represents: sum s_c m_i m_mirror(i) / sum m_i^2 over
     * the DoFs whose component c has a sign s_c = +-1 in `component_signs`
     * (0 or beyond its size: left out). The sign is how component c
     * transforms: -1 for the displacement normal to the mirror, +1 for the
     * others. +1: the mode is its own mirror image (symmetric), -1: minus it
     * (antisymmetric), in between: mixed. NaN if `mirror` is empty (the mesh
     * is not symmetric) or the mode vanishes on those DoFs.
     */
    template <int dim>
    double
    reflection_parity(const DoFHandler<dim> &                     dof_handler,
                      const std::vector<types::global_dof_index> &mirror,
                      const Vector<double> &                      mode,
                      const std::vector<double> &                 component_signs);
  } // namespace geometry
} // namespace cosmo

#endif
