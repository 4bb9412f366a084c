#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_point.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace cosmo
{
  namespace solvers
  {
    double
    masked_max(const Vector<double> &v, const Vector<double> &mask)
    {
      double m = 0;
      for (unsigned int i = 0; i < v.size(); ++i)
        if (mask[i] != 0)
          m = std::max(m, std::abs(v[i]));
      return m;
    }

    double
    masked_dot(const Vector<double> &a, const Vector<double> &b, const Vector<double> &mask)
    {
      double s = 0;
      for (unsigned int i = 0; i < a.size(); ++i)
        s += mask[i] * a[i] * b[i];
      return s;
    }

    namespace
    {
      /// The border: the mode estimate on the mode unknowns, unit length (and
      /// in the fixed-point space, if project is given). False if the
      /// estimate vanishes on the mode unknowns.
      bool
      unit_border(const Vector<double> &                       border,
                  const Vector<double> &                       mask,
                  const std::function<void(Vector<double> &)> &project,
                  Vector<double> &                             b)
      {
        b = border;
        b.scale(mask);
        const double bn = std::sqrt(b * b);
        if (!(bn > 0))
          return false;
        b /= bn;
        if (project)
          {
            project(b);
            b /= std::sqrt(b * b);
          }
        return true;
      }

      /**
       * Newton on the minimally augmented system (locate_critical_point):
       * the iterate (in cp), the border b and the vectors the pieces of one
       * iteration share, each piece named for what it computes. A piece that
       * fails says why in cp.message and returns false.
       */
      struct CriticalPointNewton
      {
        CriticalPointNewton(BifurcationProblem &                         problem,
                            const bool                                   fold,
                            const Vector<double> &                       U0,
                            const double                                 lambda0,
                            const Vector<double> &                       b,
                            const Vector<double> &                       mask,
                            const Vector<double> &                       tU,
                            const double                                 tlambda,
                            const double                                 lambda_scale,
                            const double                                 residual_tolerance,
                            const CriticalPointSettings &                settings,
                            const std::function<void(Vector<double> &)> &project,
                            CriticalPoint &                              cp)
          : problem(problem)
          , fold(fold)
          , U0(U0)
          , lambda0(lambda0)
          , b(b)
          , mask(mask)
          , lambda_scale(lambda_scale)
          , residual_tolerance(residual_tolerance)
          , settings(settings)
          , project(project)
          , cp(cp)
          , U(cp.U)
          , lambda(cp.lambda)
          , mu(cp.unfolding)
          // Branch points: keep (U, lambda) on the old branch's tangent along b.
          , beta_t((!fold && tlambda != 0) ? (b * tU) / tlambda : 0.)
          , n(problem.n_unknowns())
          , R(n)
          , R0(n)
          , Rl(n)
          , y(n)
          , a(n)
          , z(n)
          , v(n)
          , gU(n)
          , Rp(n)
          , Rm(n)
          , Upv(n)
          , Umv(n)
          , last_dU(n)
          , U_scale(problem.unknowns_scale(U0))
        {}

        /// Says why Newton stopped; false.
        bool
        fail(const std::string &why)
        {
          cp.message = why;
          return false;
        }

        /// The iterate where Newton stopped, with the load parameter at it.
        CriticalPoint
        stopped()
        {
          problem.set_load_parameter(lambda);
          return cp;
        }

        /// Newton has failed when the iteration cap is reached.
        bool
        below_iteration_limit(const unsigned int it)
        {
          if (it == settings.max_iterations)
            return fail("no convergence in " + std::to_string(settings.max_iterations) +
                        " Newton iterations");
          return true;
        }

        /// J at the iterate (the caller's factorization at the first one if
        /// factorized).
        bool
        factorize(const unsigned int it, const bool factorized)
        {
          problem.set_load_parameter(lambda);
          if (it > 0 || !factorized)
            {
              ++cp.factorizations;
              if (problem.setup_jacobian(U) != 0)
                {
                  // An exactly singular J (a Newton step can land on the
                  // critical point exactly in small problems): step back by a
                  // millionth of the last update, once, and go on.
                  if (it == 0 || nudged)
                    return fail("the Jacobian cannot be set up at a Newton iterate");
                  nudged = true;
                  U.add(-1e-6, last_dU);
                  lambda -= 1e-6 * last_d_lambda;
                  problem.set_load_parameter(lambda);
                  ++cp.factorizations;
                  if (problem.setup_jacobian(U) != 0)
                    return fail("the Jacobian cannot be set up at a Newton iterate");
                }
            }
          return true;
        }

        /// R, and the test function g and the mode v of the bordered system
        /// at the iterate, as cp reports them.
        bool
        bordered_test_function(const unsigned int it)
        {
          // R0 = R(U, lambda); R = R0 + mu b, the first equation of the
          // branch-point system (R = R0 for a fold).
          if (problem.residual(U, R0) != 0)
            return fail("the residual cannot be evaluated at a Newton iterate");
          R = R0;
          if (!fold)
            R.add(mu, b);
          cp.residual_norm = scaled_residual_norm(problem, R);

          // The bordered system: g and v.
          if (problem.solve_with_jacobian(b, y) != 0)
            return fail("a solve with the Jacobian failed");
          if (project)
            project(y);
          beta = b * y;
          if (!std::isfinite(beta) || beta == 0)
            return fail("the bordered system is singular (the border is orthogonal to the mode)");
          g = -1. / beta;
          v = y;
          v /= beta;
          cp.test_function = g;
          const double vv  = masked_dot(v, v, mask);
          cp.eigenvalue    = -g / vv;
          cp.mode          = v;
          cp.mode.scale(mask);
          cp.mode /= std::sqrt(vv);
          cp.iterations = it;
          return true;
        }

        /// g_U, and eps, the difference step along v.
        bool
        test_function_gradient()
        {
          // Derivatives of g by central differences of R along v.
          const double vmax = masked_max(v, mask);
          // The difference step: 1e-4 of the size at which the problem is
          // nonlinear (~eps^(1/4): truncation and round-off balanced).
          eps = 1e-4 * U_scale / vmax;
          Upv = U;
          Upv.add(eps, v);
          Umv = U;
          Umv.add(-eps, v);
          if (problem.residual(Upv, Rp) != 0 || problem.residual(Umv, Rm) != 0)
            return fail("the residual cannot be evaluated near a Newton iterate");
          // g_U = -R_UU[v, v] (for the energy's rows; it enters only through
          // g_U.a and g_U.y, directions that do not move prescribed unknowns)
          gU = Rp;
          gU.add(-2., R0);
          gU += Rm;
          gU *= -1. / (eps * eps);
          return true;
        }

        /// a = J^-1 R and z = J^-1 R_lambda, for the block elimination.
        bool
        solves_for_elimination()
        {
          if (problem.load_derivative(U, lambda, Rl) != 0)
            return fail("dR/dlambda cannot be evaluated at a Newton iterate");
          if (problem.solve_with_jacobian(R, a) != 0 || problem.solve_with_jacobian(Rl, z) != 0)
            return fail("a solve with the Jacobian failed");
          return true;
        }

        /// A11, the derivative of g along the branch, by central differences.
        bool
        derivative_along_branch()
        {
          // dg/dlambda along the branch, A11 = g_lambda - g_U.z, as one
          // directional difference of -v.J v along (-z, 1): exact also where
          // lambda acts through prescribed unknowns (rows of R that are
          // constraints, not the energy's gradient), which g_U above misses.
          const double z_max = z.linfty_norm();
          const double delta =
            std::min(1e-5 * (std::abs(lambda) + lambda_scale),
                     z_max > 0 ? 1e-4 * U_scale / z_max : INFINITY);
          auto vJv = [&](const double sign, double &value) {
            Vector<double> Ub = U;
            Ub.add(-sign * delta, z);
            problem.set_load_parameter(lambda + sign * delta);
            Vector<double> Up = Ub, Um = Ub;
            Up.add(eps, v);
            Um.add(-eps, v);
            const int status = problem.residual(Up, Rp) + problem.residual(Um, Rm);
            Rp -= Rm;
            value = (v * Rp) / (2 * eps);
            return status;
          };
          double vJv_plus = 0, vJv_minus = 0;
          const int status = vJv(1., vJv_plus) + vJv(-1., vJv_minus);
          problem.set_load_parameter(lambda);
          if (status != 0)
            return fail("the residual cannot be evaluated near a Newton iterate");
          A11 = -(vJv_plus - vJv_minus) / (2 * delta);
          return true;
        }

        /// The Newton updates d_lambda and d_mu, and dg_dlambda.
        bool
        block_elimination()
        {
          // Block elimination with the factorization of J. dg_dlambda: dg/dlambda
          // along the branch, for the resolution (below).
          d_lambda = 0, d_mu = 0, dg_dlambda = A11;
          if (fold)
            {
              const double denominator = A11;
              if (!std::isfinite(denominator) || denominator == 0)
                return fail("the fold system is singular (g does not change along the branch)");
              d_lambda = (-g + gU * a) / denominator;
            }
          else
            {
              const double F3  = (b * U - b * U0) - beta_t * (lambda - lambda0);
              const double A12 = -(gU * y);
              const double A21 = -(b * z + beta_t), A22 = -beta;
              const double r1 = -g + gU * a, r2 = -F3 + b * a;
              const double det = A11 * A22 - A12 * A21;
              if (!std::isfinite(det) || det == 0)
                return fail("the branch-point system is singular");
              d_lambda = (r1 * A22 - A12 * r2) / det;
              d_mu     = (A11 * r2 - A21 * r1) / det;
              // Near the branch point z = J^-1 R_lambda has a component along
              // the null vector of size (phi.R_lambda)/eigenvalue: zero in exact
              // arithmetic on a symmetric branch, round-off amplified by
              // 1/eigenvalue in practice, and so is A11 = g_lambda - g_U.z. The
              // Schur complement A11 - A12 A21 / A22 (mu eliminated, the border
              // row kept) removes that component with y = J^-1 b, which carries
              // the same 1/eigenvalue: g's derivative along the branch. (A11
              // alone gave resolutions scattered over 3 decades at converged
              // points.)
              dg_dlambda = det / A22;
            }
          return true;
        }

        /// cp.resolution, then the step to the next iterate.
        bool
        take_update()
        {
          // The resolution: a perturbation dJ of the factorization moves g by
          // -v.dJ v; componentwise |dJ| <~ eps |J|, so |delta g| <~ eps
          // |v|.|J||v|, and lambda moves by that over dg/dlambda along the
          // branch.
          const double abs_form = problem.jacobian_abs_form(v);
          cp.resolution = abs_form > 0 ? std::numeric_limits<double>::epsilon() * abs_form /
                                           std::abs(dg_dlambda) :
                                         -1.;
          if (!std::isfinite(d_lambda) || !std::isfinite(d_mu))
            return fail("the Newton update is not finite");
          if (!(lambda + d_lambda >= settings.lambda_lo && lambda + d_lambda <= settings.lambda_hi))
            return fail("an iterate left the load window [" + std::to_string(settings.lambda_lo) + ", " +
                        std::to_string(settings.lambda_hi) + "] (t = " + std::to_string(lambda + d_lambda) + ")");
          // dU = -a - d_lambda z - d_mu y
          last_dU = a;
          last_dU *= -1.;
          last_dU.add(-d_lambda, z);
          last_dU.add(-d_mu, y);
          if (project)
            project(last_dU);
          U += last_dU;
          last_d_lambda = d_lambda;
          lambda += d_lambda;
          mu += d_mu;
          return true;
        }

        /// COSMO_DEBUG_CRITICAL_POINT: the iteration's figures on stderr.
        void
        print_iteration(const unsigned int it) const
        {
          if (std::getenv("COSMO_DEBUG_CRITICAL_POINT"))
            std::cerr << std::setprecision(15) << "    [critical point] it " << it << " lambda "
                      << lambda << " d_lambda " << d_lambda << " g " << g << " dg/dlambda "
                      << dg_dlambda << " A11 " << A11 << " gU.a " << gU * a << " gU.y "
                      << gU * y << " |R| " << cp.residual_norm << " mu " << mu << " eps " << eps
                      << "\n";
        }

        /// Whether the update just taken ends the iteration (cp.lambda_update
        /// its precision).
        bool
        update_accepted()
        {
          // Accepted when one of three holds (doc/theory-continuation.md 3):
          // - tiny: the update is below the tolerance;
          // - floor: after an update below the round-off level (at least the
          //   a-priori resolution: in a badly conditioned problem the updates
          //   wander there), another below it that no longer shrinks by 4:
          //   quadratic convergence has done its work, the scatter is
          //   round-off in g; precision: the larger of the two;
          // - contracted: the update is small and at most a tenth of the last
          //   one, and so is g against the last iterate's (both measure the
          //   error: a lambda update that is small only because its sign
          //   turned is not taken); the error left after it is about
          //   |d_k|^2 / |d_k-1| (the last contraction applied once more), and
          //   when that is below the tolerance the factorization that would
          //   only confirm it is saved; precision: that estimate.
          const double scale       = std::abs(lambda) + lambda_scale;
          const double tolerance =
            std::max(settings.lambda_tolerance * scale,
                     cp.resolution > 0 ? settings.resolution_fraction * cp.resolution : 0.);
          const double update      = std::abs(d_lambda);
          const double floor_level = std::max(1e-6 * scale, 4 * cp.resolution);
          const double left_after =
            std::isfinite(previous_update) ? update * update / previous_update : INFINITY;
          const bool tiny  = update <= tolerance;
          const bool floor = !tiny && previous_update <= floor_level && update <= floor_level &&
                             update > 0.25 * previous_update;
          const bool contracted = !tiny && !floor && update <= 1e-3 * scale &&
                                  update <= 0.1 * previous_update &&
                                  std::abs(g) <= 0.1 * std::abs(previous_g) &&
                                  left_after <= tolerance;
          cp.lambda_update = tiny ? update : floor ? std::max(update, previous_update) :
                             contracted ? left_after : update;
          previous_g = g;
          previous_update = std::abs(d_lambda);
          return tiny || floor || contracted;
        }

        /// The residual at the accepted iterate: cp.converged if it is
        /// below the tolerance.
        bool
        check_located_point(const unsigned int it)
        {
          problem.set_load_parameter(lambda);
          if (problem.residual(U, R) != 0)
            return fail("the residual cannot be evaluated at the located point");
          if (!fold)
            R.add(mu, b);
          cp.residual_norm = scaled_residual_norm(problem, R);
          cp.iterations    = it + 1;
          if (cp.residual_norm <= residual_tolerance)
            cp.converged = true;
          return true;
        }

        BifurcationProblem &                         problem;
        const bool                                   fold;
        const Vector<double> &                       U0;
        const double                                 lambda0;
        const Vector<double> &                       b;
        const Vector<double> &                       mask;
        const double                                 lambda_scale;
        const double                                 residual_tolerance;
        const CriticalPointSettings &                settings;
        const std::function<void(Vector<double> &)> &project;
        CriticalPoint &                              cp;
        Vector<double> &                             U;
        double &                                     lambda;
        double &                                     mu;
        const double                                 beta_t;
        const unsigned int                           n;
        Vector<double>                               R, R0, Rl, y, a, z, v, gU, Rp, Rm, Upv, Umv;
        double                                       previous_update = INFINITY;
        Vector<double>                               last_dU;
        double                                       last_d_lambda = 0;
        bool                                         nudged        = false;
        const double                                 U_scale;
        double                                       previous_g = INFINITY;
        // The current iteration's: b.y, g, the difference step, the Jacobian
        // of (g, F3) in lambda (and mu), the updates.
        double beta = 0, g = 0, eps = 0, A11 = 0, d_lambda = 0, d_mu = 0, dg_dlambda = 0;
      };
    } // namespace

    CriticalPoint
    locate_critical_point(BifurcationProblem &         problem,
                          const bool                   fold,
                          const Vector<double> &       U0,
                          const double                 lambda0,
                          const Vector<double> &       border,
                          const Vector<double> &       mask,
                          const Vector<double> &       tU,
                          const double                 tlambda,
                          const bool                   factorized,
                          const double                 lambda_scale,
                          const double                 residual_tolerance,
                          const CriticalPointSettings &settings,
                          const std::function<void(Vector<double> &)> &project)
    {
      CriticalPoint cp;
      cp.U      = U0;
      cp.lambda = lambda0;

      Vector<double> b;
      if (!unit_border(border, mask, project, b))
        {
          cp.message = "no mode estimate to border the Jacobian with";
          return cp;
        }
      CriticalPointNewton newton(problem, fold, U0, lambda0, b, mask, tU, tlambda, lambda_scale,
                                 residual_tolerance, settings, project, cp);
      for (unsigned int it = 0;; ++it)
        {
          // (before the factorization the iterate would cost)
          io::check_interrupt();
          if (!newton.below_iteration_limit(it) || !newton.factorize(it, factorized) ||
              !newton.bordered_test_function(it) || !newton.test_function_gradient() ||
              !newton.solves_for_elimination() || !newton.derivative_along_branch() ||
              !newton.block_elimination() || !newton.take_update())
            return newton.stopped();
          newton.print_iteration(it);
          if (newton.update_accepted())
            {
              if (!newton.check_located_point(it))
                return newton.stopped();
              if (cp.converged)
                return cp;
            }
        }
    }
  } // namespace solvers
} // namespace cosmo
