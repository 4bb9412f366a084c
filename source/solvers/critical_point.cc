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
      const unsigned int n = problem.n_unknowns();
      CriticalPoint      cp;
      cp.U       = U0;
      cp.lambda  = lambda0;

      // The border: the mode estimate on the mode unknowns, unit length.
      Vector<double> b = border;
      b.scale(mask);
      const double bn = std::sqrt(b * b);
      if (!(bn > 0))
        {
          cp.message = "no mode estimate to border the Jacobian with";
          return cp;
        }
      b /= bn;
      if (project)
        {
          project(b);
          b /= std::sqrt(b * b);
        }
      // Branch points: keep (U, lambda) on the old branch's tangent along b.
      const double beta_t = (!fold && tlambda != 0) ? (b * tU) / tlambda : 0.;

      Vector<double> &U      = cp.U;
      double &        lambda = cp.lambda;
      double &        mu     = cp.unfolding;
      Vector<double>  R(n), R0(n), Rl(n), y(n), a(n), z(n), v(n), gU(n), Rp(n), Rm(n), Upv(n),
        Umv(n);
      double          previous_update = INFINITY;
      Vector<double>  last_dU(n);
      double          last_d_lambda = 0;
      bool            nudged        = false;
      const double    U_scale         = problem.unknowns_scale(U0);

      auto fail = [&](const std::string &why) {
        cp.message = why;
        problem.set_load_parameter(lambda);
        return cp;
      };

      double previous_g = INFINITY;
      for (unsigned int it = 0;; ++it)
        {
          // (before the factorization the iterate would cost)
          io::check_interrupt();
          if (it == settings.max_iterations)
            return fail("no convergence in " + std::to_string(settings.max_iterations) +
                        " Newton iterations");
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
          const double beta = b * y;
          if (!std::isfinite(beta) || beta == 0)
            return fail("the bordered system is singular (the border is orthogonal to the mode)");
          const double g = -1. / beta;
          v              = y;
          v /= beta;
          cp.test_function = g;
          const double vv  = masked_dot(v, v, mask);
          cp.eigenvalue    = -g / vv;
          cp.mode          = v;
          cp.mode.scale(mask);
          cp.mode /= std::sqrt(vv);
          cp.iterations = it;

          // Derivatives of g by central differences of R along v.
          const double vmax = masked_max(v, mask);
          // The difference step: 1e-4 of the size at which the problem is
          // nonlinear (~eps^(1/4): truncation and round-off balanced).
          const double eps = 1e-4 * U_scale / vmax;
          Upv              = U;
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
          if (problem.load_derivative(U, lambda, Rl) != 0)
            return fail("dR/dlambda cannot be evaluated at a Newton iterate");
          if (problem.solve_with_jacobian(R, a) != 0 || problem.solve_with_jacobian(Rl, z) != 0)
            return fail("a solve with the Jacobian failed");
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
          const double A11 = -(vJv_plus - vJv_minus) / (2 * delta);
          // Block elimination with the factorization of J. dg_dlambda: dg/dlambda
          // along the branch, for the resolution (below).
          double d_lambda = 0, d_mu = 0, dg_dlambda = A11;
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
          if (std::getenv("COSMO_DEBUG_CRITICAL_POINT"))
            std::cerr << std::setprecision(15) << "    [critical point] it " << it << " lambda "
                      << lambda << " d_lambda " << d_lambda << " g " << g << " dg/dlambda "
                      << dg_dlambda << " A11 " << A11 << " gU.a " << gU * a << " gU.y "
                      << gU * y << " |R| " << cp.residual_norm << " mu " << mu << " eps " << eps
                      << "\n";

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
          if (tiny || floor || contracted)
            {
              problem.set_load_parameter(lambda);
              if (problem.residual(U, R) != 0)
                return fail("the residual cannot be evaluated at the located point");
              if (!fold)
                R.add(mu, b);
              cp.residual_norm = scaled_residual_norm(problem, R);
              cp.iterations    = it + 1;
              if (cp.residual_norm <= residual_tolerance)
                {
                  cp.converged = true;
                  return cp;
                }
            }
        }
    }
  } // namespace solvers
} // namespace cosmo
