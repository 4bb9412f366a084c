#ifndef cosmo_materials_growth_admissibility_h
#define cosmo_materials_growth_admissibility_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <string>
#include <vector>

/**
 * One admissibility check of a growth law, applied wherever the law is
 * evaluated (doc/theory-rod-cross-section.md, "Admissible growth"): every growth law of every
 * application (bulk and surface growth of a section, the plate's growth, the
 * rim's) is refused before the run starts if it is not finite, or makes
 * det Fg (a surface factor, ...) <= 0, at any vertex or quadrature point of
 * any mesh the run uses, anywhere on the ramp t in [0, 1].
 *
 * Why every mesh: a law singular at the origin, 1 + 0.1/(x^2 + y^2), was
 * caught on the coarse-mesh start's mesh (a quadrature point at (0, 0)) but
 * not on the fine one, and the run went on to a "converged" state on a path
 * with 6 negative eigenvalues.
 *
 * Why along the ramp: every factor ramps linearly, 1 + t (g - 1), so Fg is
 * linear in t and det Fg a cubic with det Fg(0) = 1. Its value at t = 1 alone
 * does not decide (diag(-1, -1, 1) has det 1 but crosses 0 at t = 1/2); the
 * cubic through t = 0, 1/3, 2/3, 1 is det Fg on the whole ramp, and its
 * minimum on [0, 1] does.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /// Where a law comes from, for the message: the file's section, entry and its text.
    struct GrowthEntry
    {
      std::string section, entry, text;
      /// What must stay positive, e.g. "det Fg" or "the surface factors (gT, g3)".
      std::string quantity = "det Fg";
    };

    /**
     * The quantities q(X, t) that must stay positive (det Fg, or each factor
     * of a surface law), each a polynomial of degree <= 3 in t. At each
     * point: q at t = 0, 1/3, 2/3, 1 must be finite and the cubic through
     * them positive on [0, 1] (sampled at 64 points). Otherwise io::InputError
     * naming entry.section, entry.entry, entry.text, the point, t and the
     * value. On a distributed mesh (comm with more than one rank) each rank
     * checks its points and all ranks refuse together, with the first
     * rank's message.
     */
    void
    check_growth_admissible(
      const std::vector<Point<2>> &                                           points,
      const std::function<std::vector<double>(const Point<2> &, double)> &q,
      const GrowthEntry &                                                     entry,
      MPI_Comm comm = MPI_COMM_SELF);

    /**
     * Every vertex and quadrature point of the cells of `tria` for which
     * `selected` is true: on a serial mesh the cells of every level (the
     * coarse-mesh start's meshes are its coarser levels), on a distributed
     * one this rank's active cells.
     */
    std::vector<Point<2>>
    growth_points(const Mapping<2> &                                             mapping,
                  const Triangulation<2> &                                       tria,
                  const Quadrature<2> &                                          quadrature,
                  const std::function<bool(const Triangulation<2>::cell_iterator &)> &selected);

    /// The same on the boundary faces for which `selected` is true (surface growth).
    std::vector<Point<2>>
    boundary_growth_points(
      const Mapping<2> &                                             mapping,
      const Triangulation<2> &                                       tria,
      const Quadrature<1> &                                          quadrature,
      const std::function<bool(const Triangulation<2>::face_iterator &)> &selected);
  } // namespace materials
} // namespace cosmo

#endif
