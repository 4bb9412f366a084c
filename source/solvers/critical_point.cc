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
    namespace
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
      weighted_max_norm(BifurcationProblem &problem, const Vector<double> &R)
      {
        Vector<double> w;
        problem.residual_weights(w);
        double m = 0;
        for (unsigned int i = 0; i < R.size(); ++i)
          m = std::max(m, std::abs(w[i] * R[i]));
        return m;
      }
    } // namespace

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
      cp.is_fold = fold;
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
      Vector<double>  R(n), Rl(n), y(n), a(n), z(n), v(n), gU(n), Rp(n), Rm(n), Upv(n), Umv(n);
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

      for (unsigned int it = 0;; ++it)
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
          if (problem.residual(U, R) != 0)
            return fail("the residual cannot be evaluated at a Newton iterate");
          const Vector<double> R0 = R; // without the unfolding term
          if (!fold)
            R.add(mu, b);
          cp.residual_norm = weighted_max_norm(problem, R);

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

          if (it >= settings.max_iterations)
            return fail("no convergence in " + std::to_string(settings.max_iterations) +
                        " Newton iterations");

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
          const double z_max = std::max(masked_max(z, mask), z.linfty_norm());
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
          // Block elimination with the factorization of J.
          double d_lambda = 0, d_mu = 0;
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
            }
          // The resolution: a perturbation dJ of the factorization moves g by
          // -v.dJ v; componentwise |dJ| <~ eps |J|, so |delta g| <~ eps
          // |v|.|J||v|, and lambda moves by that over dg/dlambda along the
          // branch (A11 = g_lambda - g_U.z).
          cp.dg_dlambda          = A11;
          const double abs_form = problem.jacobian_abs_form(v);
          cp.resolution = abs_form > 0 ? std::numeric_limits<double>::epsilon() * abs_form /
                                           std::abs(cp.dg_dlambda) :
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
          cp.lambda_update = std::abs(d_lambda);
          if (std::getenv("COSMO_DEBUG_CRITICAL_POINT"))
            std::cerr << std::setprecision(15) << "    [critical point] it " << it << " lambda "
                      << lambda << " d_lambda " << d_lambda << " g " << g << " dg/dlambda "
                      << A11 << " gU.a " << gU * a << " gU.y "
                      << gU * y << " |R| " << cp.residual_norm << " mu " << mu << " eps " << eps
                      << "\n";
          cp.lambda_history.push_back(lambda);

          // Converged: a tiny update, or the round-off floor -- after a small
          // update (quadratic convergence has done its work) one that no
          // longer shrinks: the scatter of lambda is then round-off in g,
          // |delta g| / |dg/dlambda| with |delta g| ~ eps |J|, and the
          // precision reported is the larger of the two last updates.
          const double scale = std::abs(lambda) + lambda_scale;
          const bool   tiny  = cp.lambda_update <= settings.lambda_tolerance * scale;
          // (the floor is at least the a-priori resolution: in a badly
          // conditioned problem the updates wander at that level)
          const double floor_level = std::max(1e-6 * scale, 4 * cp.resolution);
          const bool   floor       = previous_update <= floor_level &&
                             cp.lambda_update > 0.25 * previous_update;
          // Or contracted: once the updates shrink superlinearly (this one
          // at most a tenth of the last and small), the error left after it
          // is about |d_k|^2 / |d_k-1| (the last contraction applied once
          // more; for quadratic convergence it is smaller still). Accepting
          // then saves the factorization that would only confirm it.
          const double left_after =
            previous_update > 0 && std::isfinite(previous_update) ?
              cp.lambda_update * cp.lambda_update / previous_update :
              INFINITY;
          const bool contracted = !tiny && !floor && cp.lambda_update <= 1e-3 * scale &&
                                  cp.lambda_update <= 0.1 * previous_update &&
                                  left_after <= settings.lambda_tolerance * scale;
          if (floor)
            cp.lambda_update = std::max(cp.lambda_update, previous_update);
          else if (contracted)
            cp.lambda_update = left_after; // the estimated error, reported as the precision
          previous_update = std::abs(d_lambda);
          if (tiny || floor || contracted)
            {
              problem.set_load_parameter(lambda);
              if (problem.residual(U, R) != 0)
                return fail("the residual cannot be evaluated at the located point");
              if (!fold)
                R.add(mu, b);
              cp.residual_norm = weighted_max_norm(problem, R);
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
