#ifndef cosmo_solvers_critical_estimate_h
#define cosmo_solvers_critical_estimate_h

#include <deal.II/lac/vector.h>

#include <string>

/**
 * The first critical load ahead of a stable state from one eigenproblem
 * (doc/theory-continuation.md 10): along the path the Hessian is, to first
 * order in the load, J(lambda0 + tau) = J0 + tau J', J' = dJ/dlambda along
 * the tangent (the state moving with it); it becomes singular first at the
 * smallest tau > 0 with J0 v = -tau J' v. For a state that does not move
 * with the load in the directions the Hessian depends on (a flat plate's
 * von Karman prestress, a straight column, the trivial state of a
 * bifurcation problem) J is linear in lambda and the estimate is the
 * critical load itself; otherwise it is the linear prediction, which
 * Newton on the augmented system then corrects (critical_point.h).
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    class BifurcationProblem;

    struct CriticalEstimateSettings
    {
      /// Lanczos steps at most (each two residuals and one solve).
      unsigned int max_steps = 40;
      /// The largest Ritz value converged when its residual estimate
      /// |beta_m s_m| is below this fraction of it.
      double tolerance = 1e-8;
      /// The load step of the difference for J' (times 1 + |lambda0|).
      double load_step = 1e-4;
      /// The state step of the differences J v (times the problem's
      /// unknowns_scale over |v|_inf).
      double state_step = 1e-6;
      /// Stop once the second critical load is certain to lie less than
      /// this factor as far as the first (the caller refuses such a
      /// cluster): the top Ritz pair's residual r below 1/100 of its value
      /// theta_1, and the next Ritz value, a lower bound of its eigenvalue,
      /// above (theta_1 + r)/factor and not within 1e-3 of theta_1 (a
      /// double eigenvalue in the making). 0: never.
      double cluster_factor = 0;
    };

    struct CriticalEstimate
    {
      /// A critical point ahead: a positive eigenvalue theta = 1/tau of
      /// -J0^-1 J' (none: J' does not destabilize, to first order).
      bool           found  = false;
      double         lambda = 0; ///< lambda0 + tau
      Vector<double> U;          ///< U0 + tau dU, the tangent's prediction there
      Vector<double> mode;       ///< the Ritz vector, masked, unit max-norm
      /// dU/dlambda there: dU, or dU + tau d2U from the second-order estimate
      Vector<double> tangent;
      /// The next Ritz value's tau (the second critical load's estimate;
      /// +inf if none): how well separated the first is.
      double       next_lambda = 0;
      /// (jacobians: assembled for products, where the problem stores them)
      unsigned int steps = 0, residuals = 0, jacobians = 0, solves = 0;
      bool         converged = false; ///< the Ritz residual below the tolerance
      /// Stopped early: the next critical load less than cluster_factor as far.
      bool         cluster = false;
      std::string  message;
    };

    /**
     * The estimate from a state (U0, lambda0) at which the problem's
     * Jacobian is factorized and positive definite on the mode unknowns
     * (mask), dU = dU/dlambda the path's tangent there (J0 dU = -dR/dlambda).
     * Lanczos on K = -J0^-1 J', self-adjoint in the J0 inner product,
     * with full reorthogonalization; J0 q is carried along the recurrence
     * (J0 K q = -J' q), so that only J' products (two residuals: a
     * difference in the state and one in the load) and solves with J0's
     * factorization are needed. The problem's load is left at lambda0.
     */
    CriticalEstimate
    estimate_first_critical_point(BifurcationProblem             &problem,
                                  const Vector<double>           &U0,
                                  double                          lambda0,
                                  const Vector<double>           &dU,
                                  const Vector<double>           &mask,
                                  const CriticalEstimateSettings &settings = CriticalEstimateSettings());

    /**
     * The second-order estimate, where the linear one is far off (a
     * twisted strip's Hessian depends on the twist to second order: its
     * linear estimates cluster at a ninth of the threshold). Along the
     * path to second order, U(tau) = U0 + tau dU + tau^2/2 d2U (d2U from
     * one more solve with J0), the Hessian is J0 + tau J1 + tau^2 J2; the
     * estimate is the smallest tau > 0 of the quadratic eigenproblem
     * (J0 + tau J1 + tau^2 J2) v = 0. With mu = 1/tau it is the largest
     * real mu > 0 of the linearization
     *   [w; v] -> [-J0^-1 (J1 w + J2 v); w],  w = mu v,
     * found by Arnoldi with J0's factorization: each step three residuals
     * (the products J1 w + J2 v by differences of J(U(t)) along the path
     * at t = -h, 0, h) and one solve. `tau_scale` sets the load's scale (the
     * differences' step h = min(1e-2 (1 + |lambda0|), tau_scale/4), and
     * the linearization's balance). As the linear estimate: J0 factorized
     * and positive definite on the mask, the load left at lambda0.
     */
    CriticalEstimate
    estimate_first_critical_point_second_order(BifurcationProblem             &problem,
                                               const Vector<double>           &U0,
                                               double                          lambda0,
                                               const Vector<double>           &dU,
                                               const Vector<double>           &mask,
                                               double                          tau_scale,
                                               const CriticalEstimateSettings &settings = CriticalEstimateSettings());

    /// What refine_critical_estimate() did.
    struct EstimateRefinement
    {
      /// The estimate replaced by the refined one (else left as it was).
      bool refined = false;
      /// states converged (Newton iterations on the eigenvalue), Newton
      /// steps on the states, GMRES steps, Lanczos steps, solves with the
      /// start's factorization, residuals, Jacobians assembled
      unsigned int evaluations = 0, newton = 0, krylov = 0, lanczos = 0, solves = 0, residuals = 0, jacobians = 0;
      std::string  message;
    };

    /**
     * A second-order estimate refined with the start's factorization J0
     * alone (no other factorization): Newton on mu(t), the smallest
     * eigenvalue of the pencil J(t) v = mu J0 v on the mask along the path,
     * until |mu| <= 1e-4, and its last step taken along the tangent
     * without converging onto it (Newton on the augmented system does, its
     * guess's load ~1e-8 off). At each load the path's state is converged by
     * Newton whose steps are GMRES preconditioned with J0 (J0^-1 J is
     * near the identity but for the few modes the load softens), mu by
     * Lanczos on J0^-1 (J0 - J) from the last mode, its rate by
     * Hellmann-Feynman, v.J' v / v.J0 v along the tangent (GMRES again).
     * `estimate` gets the load, the state predicted along the tangent
     * there, the mode and the series' tangent where it converges, else
     * stays as it was. Not at a fold (the mode along dR/dlambda), where mu
     * ~ sqrt(t_c - t) and Newton on it steps past the fold. J0 must be the
     * factorization in place, positive definite on the mask; the load is
     * left at lambda0.
     */
    EstimateRefinement
    refine_critical_estimate(BifurcationProblem   &problem,
                             const Vector<double> &U0,
                             double                lambda0,
                             const Vector<double> &dU,
                             const Vector<double> &mask,
                             CriticalEstimate     &estimate);
  } // namespace solvers
} // namespace cosmo

#endif
