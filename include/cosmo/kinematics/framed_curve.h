#ifndef cosmo_kinematics_framed_curve_h
#define cosmo_kinematics_framed_curve_h

#include <deal.II/base/tensor.h>

#include <vector>

/**
 * Link, twist and writhe of a closed framed polygon (doc/theory-rod.md 8):
 * the centreline of a ring through its nodes, and one unit vector m_e normal
 * to each segment e (the ribbon's edge direction). By Calugareanu, White and
 * Fuller Lk = Tw + Wr, with Lk an integer fixed by the topology; the three
 * are computed independently here, so that a test can check the relation.
 *
 * - Wr: Gauss's double integral of the polygon on itself, exactly, as the
 *   sum over pairs of non-adjacent segments of their solid angles (Klenin &
 *   Langowski, Biopolymers 54 (2000) 307).
 * - Tw: the sum over the nodes of the angle by which m turns about the next
 *   segment's tangent beyond parallel transport from the previous segment
 *   (the discrete twist of Bergou et al., SIGGRAPH 2008), over 2 pi.
 * - Lk: the same double sum between the polygon and its copy displaced by
 *   epsilon m (at the nodes, m averaged), which is an integer when epsilon is
 *   below the distance to self-contact.
 */
namespace cosmo
{
  namespace kinematics
  {
    using namespace dealii;

    /// Wr of the closed polygon through `x` (the last point joined to the first).
    double
    writhe(const std::vector<Tensor<1, 3>> &x);

    /**
     * Tw of the closed polygon `x` with the unit normals `m` of its segments
     * (m[e] on x[e] -> x[e+1]). `closure`: if not zero, the unit normal of
     * the first segment as the frame of the last one continues into it (a
     * ring closed with a turn at its seam, whose frame is continuous only up
     * to that turn); zero for a continuous frame.
     */
    double
    twist(const std::vector<Tensor<1, 3>> &x,
          const std::vector<Tensor<1, 3>> &m,
          const Tensor<1, 3> &             closure = Tensor<1, 3>());

    /**
     * Tw of an open framed polygon given by its segments' unit tangents `t`
     * and unit normals `m` (m[e] normal to t[e]): the turns of m beyond
     * parallel transport from each segment to the next, over 2 pi (a clamped
     * rod's, with its ends' frames as segments along the line of the clamps).
     */
    double
    open_twist(const std::vector<Tensor<1, 3>> &t, const std::vector<Tensor<1, 3>> &m);

    /// The Gauss linking number of two closed polygons (exact sum of solid angles).
    double
    linking_number(const std::vector<Tensor<1, 3>> &x, const std::vector<Tensor<1, 3>> &y);

    /// Lk of the ribbon: x against x + epsilon m, m of the segments averaged at the nodes.
    double
    ribbon_link(const std::vector<Tensor<1, 3>> &x, const std::vector<Tensor<1, 3>> &m, double epsilon);
  } // namespace kinematics
} // namespace cosmo

#endif
