#ifndef cosmo_solvers_critical_point_h
#define cosmo_solvers_critical_point_h

#include <deal.II/lac/vector.h>

#include <cosmo/solvers/continuation.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

/**
 * Location of critical points (folds and simple branch points) of
 * R(U, lambda) = 0 by Newton on a minimally augmented system (Govaerts,
 * Numerical Methods for Bifurcations of Dynamical Equilibria, SIAM 2000,
 * ch. 3-4; the "minimally augmented" turning-point formulation of Trilinos
 * LOCA). doc/theory-continuation.md derives what is solved here.
 *
 * The test function g(U, lambda) is defined, with a fixed border b (unit,
 * on the mode unknowns), by the bordered system
 *
 *     [ J    b ] [v]   [0]
 *     [ b^T  0 ] [g] = [1],        J = dR/dU,
 *
 * i.e. g = -1/(b^T J^-1 b), v = -g J^-1 b: one extra solve with the
 * factorization of J the Newton step makes anyway. g is smooth, vanishes
 * exactly where J is singular (v is then its null vector), and the bordered
 * matrix stays regular there as long as b^T phi != 0. For the Hessian of an
 * energy (J symmetric) its derivatives are
 *
 *     g_U = -R_UU[v, v],      g_lambda = -v^T R_Ulambda v,
 *
 * evaluated by central differences of R (four residuals and two for the
 * second directional derivative; they only enter the Newton matrix, so
 * their truncation error changes the rate, never the located point).
 *
 * - fold: Newton on (R = 0, g = 0) in (U, lambda);
 * - branch point (a symmetry-breaking pitchfork, where the fold system is
 *   singular: g_U.phi = 0 and R_lambda is in the range of J): the unfolded
 *   system R + mu b = 0, g = 0, b.(U - U0) = beta (lambda - lambda0) in
 *   (U, lambda, mu). Its Jacobian is regular at a simple branch point with
 *   dg/dlambda != 0 along the branch; beta = b.t_U / t_lambda keeps (U,
 *   lambda) on the old branch's tangent in the mode direction, so on a
 *   branch that the symmetry fixes (b.t_U = 0) the solution has mu = 0 up to
 *   round-off (mu is reported: it measures how far the point is from an
 *   exact branch point).
 *
 * Every linear solve is a block elimination with the problem's own
 * factorization of J (one factorization per Newton iteration; the first
 * iteration reuses the factorization at the starting point).
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    class BifurcationProblem;

    /// sum_i mask_i a_i b_i: the dot product on the mode unknowns.
    double
    masked_dot(const Vector<double> &a, const Vector<double> &b, const Vector<double> &mask);

    /// max |v_i| over the mode unknowns (mask_i != 0).
    double
    masked_max(const Vector<double> &v, const Vector<double> &mask);

    struct CriticalPointSettings
    {
      unsigned int max_iterations = 10;
      /// Converged when |d lambda| <= tolerance (|lambda| + lambda_scale), at
      /// the round-off floor, or when the error estimated after a
      /// superlinearly contracted update, |d_k|^2 / |d_k-1|, is below it.
      double lambda_tolerance = 1e-13;
      /// ... or below this fraction of the point's round-off resolution R
      /// (section 4 of doc/theory-continuation.md): the located lambda
      /// scatters by R/12 to R/26 between BLAS thread counts and inputs
      /// perturbed at 1e-14, so iterating below R/10 chases round-off. 0: off
      /// (events keep the absolute tolerance alone).
      double resolution_fraction = 0;
      /// Newton fails as soon as an iterate's load leaves [lambda_lo,
      /// lambda_hi]: a guess it runs away from (an estimate's wrong mode)
      /// costs one factorization, not max_iterations.
      double lambda_lo = -std::numeric_limits<double>::infinity();
      double lambda_hi = std::numeric_limits<double>::infinity();
    };

    /**
     * The located point (U, lambda, unfolding, residual_norm: after the last
     * update) and what the last factorization gave, at the iterate before
     * it (mode, test_function, eigenvalue, resolution, and the problem's
     * inertia): the two differ by the last update, which is below the
     * tolerance or the round-off floor, or (a contracted update) at most a
     * tenth of the one before and below 1e-3 of the scale of lambda.
     */
    struct CriticalPoint
    {
      bool           converged = false;
      Vector<double> U;
      double         lambda = 0;
      double         unfolding = 0;        ///< mu (branch points), 0 at an exact branch point
      Vector<double> mode;                 ///< v / |v| (masked Euclidean norm)
      double         test_function = 0;    ///< g at the located point
      double         eigenvalue = 0;       ///< Rayleigh quotient v.Jv / v.v = -g / v.v
      double         residual_norm = 0;    ///< weighted max-norm of R at the located point
      /// The precision of lambda: the last update, the larger of the last two
      /// at the round-off floor, or the error estimated after a contracted one
      double         lambda_update = 0;
      /// eps |v|.|J||v| / |dg/dlambda|: the round-off resolution of lambda (-1 if unknown)
      double         resolution = -1;
      unsigned int   iterations = 0;
      unsigned int   factorizations = 0;
      std::string    message;              ///< why it did not converge
    };

    /**
     * Newton on the augmented system from (U0, lambda0). border: the mode
     * estimate (masked, any length); (tU, tlambda): the branch tangent at the
     * start (branch points). If factorized is true, the problem's current
     * factorization is J(U0, lambda0) and is reused for the first iteration.
     * residual_tolerance: the weighted max-norm R must reach. project (if
     * given) keeps the iterates in a fixed-point space of the symmetry, where
     * a double eigenvalue is simple (it projects every Newton update). Never throws
     * for a failed iteration: returns converged = false with the message.
     */
    CriticalPoint
    locate_critical_point(BifurcationProblem &          problem,
                          bool                          fold,
                          const Vector<double> &        U0,
                          double                        lambda0,
                          const Vector<double> &        border,
                          const Vector<double> &        mask,
                          const Vector<double> &        tU,
                          double                        tlambda,
                          bool                          factorized,
                          double                        lambda_scale,
                          double                        residual_tolerance,
                          const CriticalPointSettings & settings = CriticalPointSettings(),
                          const std::function<void(Vector<double> &)> &project = {});
  } // namespace solvers
} // namespace cosmo

#endif
