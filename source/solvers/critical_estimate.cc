#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_estimate.h>
#include <cosmo/solvers/critical_point.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <complex>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace cosmo
{
  namespace solvers
  {
    namespace
    {
      /// COSMO_ESTIMATE_BY_RESIDUALS: the products by differences of
      /// residuals even where the problem stores Jacobians (a serial run
      /// compared with a distributed one: tests/mpi_distributed_section.sh).
      bool
      by_residuals()
      {
        static const bool set = std::getenv("COSMO_ESTIMATE_BY_RESIDUALS") != nullptr;
        return set;
      }

      /**
       * -J' v on the mode unknowns: the difference in the load (along the
       * tangent, lambda1 = lambda0 + delta, U1 = U0 + delta dU) of J v, with
       * the problem's Jacobians assembled at both (store_jacobian), else
       * with the differences J v = (R(U + eps v) - R(U))/eps, R at U0 and
       * U1 computed once: round-off about 1e-16 |R|/(eps delta) of the
       * internal forces, 1e-6 of them at the default steps.
       */
      class LoadDerivativeOfHessian
      {
      public:
        LoadDerivativeOfHessian(BifurcationProblem             &problem,
                                const Vector<double>           &U0,
                                const double                    lambda0,
                                const Vector<double>           &dU,
                                const Vector<double>           &mask,
                                const CriticalEstimateSettings &settings)
            : problem(problem), U0(U0), U1(U0), lambda0(lambda0),
              delta(settings.load_step * (1 + std::abs(lambda0))),
              state_step(settings.state_step * problem.unknowns_scale(U0)), mask(mask)
        {
          U1.add(delta, dU);
          problem.set_load_parameter(lambda0 + delta);
          stored = !by_residuals() && problem.store_jacobian(U1, 1);
          problem.set_load_parameter(lambda0);
          stored = stored && problem.store_jacobian(U0, 0);
          if (stored)
            {
              jacobians = 2;
              return;
            }
          problem.set_load_parameter(lambda0 + delta);
          problem.residual(U1, R1);
          problem.set_load_parameter(lambda0);
          problem.residual(U0, R0);
          residuals = 2;
        }

        ~LoadDerivativeOfHessian()
        {
          problem.release_stored_jacobians();
        }

        void
        vmult(const Vector<double> &v, Vector<double> &dst)
        {
          if (stored)
            {
              // (the assembled J at both loads: no difference in the state)
              Vector<double> y0;
              problem.stored_jacobian_vmult(1, v, dst);
              problem.stored_jacobian_vmult(0, v, y0);
              dst -= y0;
              dst *= -1. / delta;
              dst.scale(mask);
              return;
            }
          const double   vmax = masked_max(v, mask);
          const double   eps  = state_step / (vmax > 0 ? vmax : 1.);
          Vector<double> U(U1), R(U1.size());
          U.add(eps, v);
          problem.set_load_parameter(lambda0 + delta);
          problem.residual(U, R);
          R -= R1;
          dst = R;
          U   = U0;
          U.add(eps, v);
          problem.set_load_parameter(lambda0);
          problem.residual(U, R);
          R -= R0;
          dst -= R;
          dst *= -1. / (eps * delta);
          dst.scale(mask);
          residuals += 2;
        }

        unsigned int residuals = 0, jacobians = 0;

      private:
        bool                  stored = false;
        BifurcationProblem   &problem;
        const Vector<double> &U0;
        Vector<double>        U1, R0, R1;
        const double          lambda0, delta, state_step;
        const Vector<double> &mask;
      };

      Vector<double>
      scaled(const Vector<double> &v, const double factor)
      {
        Vector<double> out(v);
        out *= factor;
        return out;
      }

      /// The eigenvalues (ascending) and eigenvectors of the symmetric tridiagonal (alpha, beta).
      void
      tridiagonal_eigenpairs(const std::vector<double> &alpha,
                             const std::vector<double> &beta,
                             Vector<double>            &theta,
                             FullMatrix<double>        &S)
      {
        const unsigned int       m = alpha.size();
        LAPACKFullMatrix<double> T(m, m);
        for (unsigned int i = 0; i < m; ++i)
          {
            T(i, i) = alpha[i];
            if (i + 1 < m)
              T(i, i + 1) = T(i + 1, i) = beta[i];
          }
        T.compute_eigenvalues_symmetric(-1e300, 1e300, 0., theta, S);
      }

      /**
       * The Hessian along the path to second order,
       * J(U(t), lambda0 + t) = J0 + t J1 + t^2 J2 + O(t^3) with U(t) = U0 +
       * t dU + t^2/2 d2U: the products J1 w + J2 v from J(U(t)) at t = -h,
       * 0, h (J1 the central difference, J2 half the second one). Those
       * are the problem's assembled Jacobians where it stores them
       * (round-off ~1e-16 |J|/h^2: 1e-12 at h = 1e-2), else differences
       * J(U(t)) x = (R(U(t) + eps x) - R(U(t)))/eps, five residuals a
       * product. The differences carry eps/2 R''[x, x]: on the 90-cell
       * strip (membrane stiffness 1e4 times the bending one) a rough x's
       * product was 0.4 % off the assembled one, which moved the estimate
       * from 0.757 to 0.628 (the threshold: 0.608, by luck closer).
       */
      class PathHessianSeries
      {
      public:
        PathHessianSeries(BifurcationProblem             &problem,
                          const Vector<double>           &U0,
                          const double                    lambda0,
                          const Vector<double>           &dU,
                          const Vector<double>           &mask,
                          const double                    h,
                          const CriticalEstimateSettings &settings)
            : problem(problem), lambda0(lambda0), h(h),
              state_step(settings.state_step * problem.unknowns_scale(U0)), mask(mask), U(3, U0), R(3)
        {
          // d2U: d^2/dt^2 R(U0 + t dU + t^2/2 d2U, lambda0 + t) = 0 at t = 0
          for (int k = 0; k < 3; ++k)
            {
              U[k].add((k - 1) * h, dU);
              residual(k, U[k], R[k]);
            }
          Vector<double> r2(R[2]);
          r2.add(-2., R[1]);
          r2 += R[0];
          r2 /= h * h;
          d2U.reinit(U0.size());
          failed = failed || problem.solve_with_jacobian(r2, d2U) != 0;
          d2U *= -1.;
          for (int k : {0, 2})
            U[k].add(0.5 * h * h, d2U);
          stored = !by_residuals();
          for (int k = 0; k < 3 && stored; ++k)
            {
              problem.set_load_parameter(lambda0 + (k - 1) * h);
              stored = problem.store_jacobian(U[k], k);
              jacobians += stored ? 1 : 0;
            }
          if (!stored)
            for (int k : {0, 2})
              residual(k, U[k], R[k]);
        }

        ~PathHessianSeries()
        {
          problem.release_stored_jacobians();
        }

        /// y = J1 w + J2 v on the mask
        void
        vmult(const Vector<double> &w, const Vector<double> &v, Vector<double> &y)
        {
          // One state step per vector at every t: the differences' own
          // error eps/2 R''[x, x] then cancels in the differences across t
          // (with a step per combination it would not, and swamp J2).
          y.reinit(w.size());
          add_differences(w, {{-1. / (2 * h), 0., 1. / (2 * h)}}, y);
          add_differences(v, {{1. / (2 * h * h), -1. / (h * h), 1. / (2 * h * h)}}, y);
          y.scale(mask);
        }

        /// U(tau) and its tangent dU + tau d2U
        void
        state(const double tau, const Vector<double> &dU, Vector<double> &Ut, Vector<double> &tangent) const
        {
          Ut = U[1];
          Ut.add(tau, dU, 0.5 * tau * tau, d2U);
          tangent = dU;
          tangent.add(tau, d2U);
        }

        unsigned int residuals = 0, jacobians = 0;
        /// A residual along the path could not be evaluated (an inadmissible
        /// state within h of the start): the model is void.
        bool failed = false;

      private:
        bool stored = false; ///< J(U(t_k)) assembled (else differences of residuals)
        /// y += sum_k c_k J(U(t_k)) x
        void
        add_differences(const Vector<double> &x, const std::array<double, 3> &c, Vector<double> &y)
        {
          const double xmax = masked_max(x, mask);
          if (!(xmax > 0))
            return;
          Vector<double> Ux(x.size()), Rx(x.size());
          if (stored)
            {
              for (int k = 0; k < 3; ++k)
                if (c[k] != 0)
                  {
                    problem.stored_jacobian_vmult(k, x, Rx);
                    y.add(c[k], Rx);
                  }
              return;
            }
          const double eps = state_step / xmax;
          for (int k = 0; k < 3; ++k)
            if (c[k] != 0)
              {
                Ux = U[k];
                Ux.add(eps, x);
                residual(k, Ux, Rx);
                Rx -= R[k];
                y.add(c[k] / eps, Rx);
              }
        }

        void
        residual(const int k, const Vector<double> &x, Vector<double> &r)
        {
          r.reinit(x.size());
          problem.set_load_parameter(lambda0 + (k - 1) * h);
          failed = failed || problem.residual(x, r) != 0;
          ++residuals;
        }

        BifurcationProblem         &problem;
        const double                lambda0, h, state_step;
        const Vector<double>       &mask;
        std::vector<Vector<double>> U, R;
        Vector<double>              d2U;
      };

      /// The eigenvalues of the leading m x m block of H; nu the largest real
      /// positive one and next the one below (0: none).
      std::vector<std::complex<double>>
      ritz_values(const FullMatrix<double> &H, const unsigned int m, double &nu, double &next)
      {
        LAPACKFullMatrix<double> Hm(m, m);
        for (unsigned int r = 0; r < m; ++r)
          for (unsigned int c = 0; c < m; ++c)
            Hm(r, c) = H(r, c);
        Hm.compute_eigenvalues();
        std::vector<std::complex<double>> theta(m);
        nu = next = 0;
        for (unsigned int i = 0; i < m; ++i)
          {
            const std::complex<double> e = theta[i] = Hm.eigenvalue(i);
            if (!(e.real() > 0 && std::abs(e.imag()) <= 1e-8 * e.real()))
              continue;
            if (e.real() > nu)
              {
                next = nu;
                nu   = e.real();
              }
            else if (e.real() > next)
              next = e.real();
          }
        return theta;
      }

      /// |e_m^T y| of the unit right eigenvector y of H (m x m) for its
      /// eigenvalue theta, real or complex (the Arnoldi residual over b):
      /// inverse iteration on the real form [[H - a, b], [-b, H - a]] of H -
      /// (a + ib).
      double
      ritz_last_component(const FullMatrix<double> &H, const unsigned int m, const std::complex<double> theta)
      {
        // (shifted off theta by 1e-10 |theta|: a purely imaginary theta too)
        const double             a = theta.real() + 1e-10 * std::abs(theta), c = theta.imag();
        LAPACKFullMatrix<double> A(2 * m, 2 * m);
        for (unsigned int i = 0; i < m; ++i)
          {
            for (unsigned int j = 0; j < m; ++j)
              A(i, j) = A(m + i, m + j) = H(i, j);
            A(i, i) -= a;
            A(m + i, m + i) -= a;
            A(i, m + i) = c;
            A(m + i, i) = -c;
          }
        try
          {
            A.compute_lu_factorization();
          }
        catch (std::exception &)
          {
            return 0; // exactly singular: theta is an eigenvalue of H to round-off
          }
        Vector<double> y(2 * m);
        for (unsigned int i = 0; i < 2 * m; ++i)
          y[i] = 1. + 0.1 * i / m;
        for (unsigned int pass = 0; pass < 2; ++pass)
          {
            A.solve(y);
            y /= y.l2_norm();
          }
        return std::hypot(y[m - 1], y[2 * m - 1]);
      }

      /// The right eigenvector of the Hessenberg matrix H (m x m) for its
      /// real eigenvalue nu: two steps of inverse iteration (the shift
      /// 1e-10 of nu off it; 1e-8 where that is singular to the last bit;
      /// empty if that is too).
      Vector<double>
      hessenberg_eigenvector(const FullMatrix<double> &H, const unsigned int m, const double nu)
      {
        LAPACKFullMatrix<double> A(m, m);
        for (const double shift : {1e-10, 1e-8})
          {
            for (unsigned int i = 0; i < m; ++i)
              for (unsigned int j = 0; j < m; ++j)
                A(i, j) = H(i, j) - (i == j ? nu * (1 + shift) : 0.);
            try
              {
                A.compute_lu_factorization();
                break;
              }
            catch (std::exception &)
              {
                if (shift == 1e-8)
                  return Vector<double>(); // (the caller: not converged)
              }
          }
        Vector<double> y(m);
        for (unsigned int i = 0; i < m; ++i)
          y[i] = 1. + 0.1 * i / m;
        for (unsigned int pass = 0; pass < 2; ++pass)
          {
            A.solve(y);
            y /= y.l2_norm();
          }
        return y;
      }
    } // namespace

    namespace
    {
      /// What pencil_lanczos() leaves: the Ritz values (ascending), their
      /// vectors' coefficients S in the basis Q.
      struct LanczosRun
      {
        std::vector<Vector<double>> Q;
        Vector<double>              theta;
        FullMatrix<double>          S;
        unsigned int                steps = 0, solves = 0;
        bool converged = false, cluster = false, definite = true;

        /// the Ritz vector of the largest Ritz value, unit max-norm on the mask
        Vector<double>
        top_vector(const Vector<double> &mask) const
        {
          const unsigned int m = theta.size();
          Vector<double>     y(Q[0].size());
          for (unsigned int i = 0; i < m; ++i)
            y.add(S(i, m - 1), Q[i]);
          const double vmax = masked_max(y, mask);
          if (vmax > 0)
            y /= vmax;
          return y;
        }
      };

      /**
       * Lanczos for the largest eigenvalues of K = J0^-1 B (B symmetric;
       * J0 the factorization in place, positive definite on the mask) in
       * the J0 inner product <x, y> = x.J0 y, from `start`: q_j with J0 q_j
       * alongside (J0 K q = B q needs no product with J0). `apply(q, J0 q,
       * B q)`. On the mode unknowns x.J0 y is the constrained Hessian's
       * form: a solve's multipliers satisfy C x = 0, so x.(J0 x) = x_u.H x_u.
       */
      LanczosRun
      pencil_lanczos(BifurcationProblem                                                                &problem,
                     const Vector<double>                                                              &mask,
                     const CriticalEstimateSettings                                                    &settings,
                     const std::function<void(const Vector<double> &, const Vector<double> &, Vector<double> &)> &apply,
                     const Vector<double>                                                              &start)
      {
        LanczosRun                 run;
        auto                       &Q = run.Q;
        std::vector<Vector<double>> JQ;
        std::vector<double>         alpha, beta;
        const unsigned int          n = start.size();
        Vector<double>              w(n), Jw(n), none;
        auto                        solve = [&](const Vector<double> &b, Vector<double> &x) {
          problem.solve_with_jacobian(b, x);
          x.scale(mask);
          ++run.solves;
        };
        apply(start, none, Jw);
        solve(Jw, w);
        const double norm2 = masked_dot(w, Jw, mask);
        if (!(norm2 > 0))
          {
            run.definite = false;
            return run;
          }
        Q.push_back(scaled(w, 1. / std::sqrt(norm2)));
        JQ.push_back(scaled(Jw, 1. / std::sqrt(norm2)));
        for (unsigned int j = 0; j < settings.max_steps; ++j)
          {
            apply(Q[j], JQ[j], Jw); // w = K q_j: J0 w = B q_j
            solve(Jw, w);
            // Full reorthogonalization, twice (twice is enough: Kahan); the
            // coefficient on q_j is alpha_j.
            double a = 0;
            for (unsigned int pass = 0; pass < 2; ++pass)
              for (unsigned int i = 0; i <= j; ++i)
                {
                  const double c = masked_dot(w, JQ[i], mask);
                  w.add(-c, Q[i]);
                  Jw.add(-c, JQ[i]);
                  if (i == j)
                    a += c;
                }
            alpha.push_back(a);
            const double b = std::sqrt(std::max(0., masked_dot(w, Jw, mask)));
            tridiagonal_eigenpairs(alpha, beta, run.theta, run.S);
            run.steps = j + 1;
            // The largest theta's Ritz pair's residual is |K y - theta y| =
            // b |s_j| in the J0 norm.
            const auto        &theta = run.theta;
            const unsigned int top   = theta.size() - 1;
            const double       scale = std::max(std::abs(theta[0]), std::abs(theta[top]));
            if (theta[top] > 0 && b * std::abs(run.S(j, top)) <= settings.tolerance * theta[top])
              {
                run.converged = true;
                break;
              }
            // (K is self-adjoint in the J0 inner product: the k-th largest
            // Ritz value is at most the k-th largest eigenvalue, and the top
            // one lies within r of an eigenvalue)
            if (settings.cluster_factor > 0 && top > 0 && theta[top] > 0)
              {
                const double r = b * std::abs(run.S(j, top)), second = theta[top - 1];
                if (r <= 1e-2 * theta[top] && second > (theta[top] + r) / settings.cluster_factor &&
                    second < (1 - 1e-3) * theta[top])
                  {
                    run.cluster = true;
                    break;
                  }
              }
            if (b <= 1e-14 * scale)
              {
                run.converged = true; // an invariant subspace: the Ritz values are exact
                break;
              }
            beta.push_back(b);
            Q.push_back(scaled(w, 1. / b));
            JQ.push_back(scaled(Jw, 1. / b));
          }
        return run;
      }
    } // namespace

    CriticalEstimate
    estimate_first_critical_point(BifurcationProblem             &problem,
                                  const Vector<double>           &U0,
                                  const double                    lambda0,
                                  const Vector<double>           &dU,
                                  const Vector<double>           &mask,
                                  const CriticalEstimateSettings &settings)
    {
      CriticalEstimate        out;
      LoadDerivativeOfHessian G(problem, U0, lambda0, dU, mask, settings);
      const unsigned int      n = U0.size();
      // K = -J0^-1 J': its largest eigenvalue is 1/tau of the first critical load
      Vector<double>                         start(n);
      std::mt19937                           random(20261206);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      for (unsigned int i = 0; i < n; ++i)
        start[i] = mask[i] * uniform(random);
      const LanczosRun run = pencil_lanczos(
        problem, mask, settings,
        [&](const Vector<double> &q, const Vector<double> &, Vector<double> &y) { G.vmult(q, y); }, start);
      out.steps     = run.steps;
      out.solves    = run.solves;
      out.converged = run.converged;
      out.cluster   = run.cluster;
      out.residuals = G.residuals;
      out.jacobians = G.jacobians;
      if (!run.definite)
        {
          out.message = "J0 is not positive definite on the start vector (not a stable state)";
          return out;
        }
      const Vector<double> &theta = run.theta;
      if (theta.size() == 0 || !(theta[theta.size() - 1] > 0))
        {
          out.message = "no positive eigenvalue of -J0^-1 J': the load does not destabilize to first order";
          return out;
        }
      const unsigned int m   = theta.size();
      const double       tau = 1. / theta[m - 1];
      out.found              = true;
      out.lambda             = lambda0 + tau;
      out.next_lambda =
          m > 1 && theta[m - 2] > 0 ? lambda0 + 1. / theta[m - 2] : std::numeric_limits<double>::infinity();
      out.U = U0;
      out.U.add(tau, dU);
      out.tangent = dU;
      out.mode    = run.top_vector(mask);
      problem.set_load_parameter(lambda0);
      return out;
    }

    CriticalEstimate
    estimate_first_critical_point_second_order(BifurcationProblem             &problem,
                                               const Vector<double>           &U0,
                                               const double                    lambda0,
                                               const Vector<double>           &dU,
                                               const Vector<double>           &mask,
                                               const double                    tau_scale,
                                               const CriticalEstimateSettings &settings)
    {
      CriticalEstimate   out;
      const unsigned int n = U0.size(), max_steps = settings.max_steps;
      // nu = tau_scale/tau: the linearization in these units is balanced
      // where the critical load is about tau_scale away
      const double      scale = tau_scale > 0 ? tau_scale : 1.;
      const double      h     = std::min(1e-2 * (1 + std::abs(lambda0)), 0.25 * scale);
      PathHessianSeries G(problem, U0, lambda0, dU, mask, h, settings);
      out.solves = 1;
      // Arnoldi on [w; v] -> [-J0^-1 (J1 scale w + J2 scale^2 v); w],
      // modified Gram-Schmidt twice, in the Euclidean product on the mask
      std::vector<Vector<double>>            W, V;
      FullMatrix<double>                     H(max_steps + 1, max_steps);
      std::mt19937                           random(20261207);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      Vector<double>                         w(n), v(n), y(n), sw(n), sv(n);
      auto dot = [&](const Vector<double> &a1, const Vector<double> &b1, const Vector<double> &a2,
                     const Vector<double> &b2) { return masked_dot(a1, a2, mask) + masked_dot(b1, b2, mask); };
      for (unsigned int i = 0; i < n; ++i)
        {
          w[i] = mask[i] * uniform(random);
          v[i] = mask[i] * uniform(random);
        }
      double norm = std::sqrt(dot(w, v, w, v));
      W.push_back(scaled(w, 1. / norm));
      V.push_back(scaled(v, 1. / norm));
      double nu = 0, next = 0;
      Vector<double> ritz;
      for (unsigned int j = 0; j < max_steps; ++j)
        {
          sw.equ(scale, W[j]);
          sv.equ(scale * scale, V[j]);
          if (G.failed)
            break;
          G.vmult(sw, sv, y);
          problem.solve_with_jacobian(y, w);
          ++out.solves;
          w *= -1.;
          w.scale(mask);
          v = W[j];
          for (unsigned int pass = 0; pass < 2; ++pass)
            for (unsigned int i = 0; i <= j; ++i)
              {
                const double c = dot(w, v, W[i], V[i]);
                w.add(-c, W[i]);
                v.add(-c, V[i]);
                H(i, j) += c;
              }
          const double b = std::sqrt(dot(w, v, w, v));
          H(j + 1, j)    = b;
          out.steps      = j + 1;
          const unsigned int m = j + 1;
          const auto theta = ritz_values(H, m, nu, next);
          if (nu > 0)
            {
              ritz = hessenberg_eigenvector(H, m, nu);
              // Converged: nu, and every Ritz value larger in modulus.
              // Arnoldi finds the outer eigenvalues first, and an outer one
              // not yet converged may still become a larger real mu: the
              // 135-cell strip stopped at its second root (0.892) 21 steps
              // before its first (0.756) emerged.
              bool converged = ritz.size() == m && b * std::abs(ritz[m - 1]) <= settings.tolerance * nu;
              for (const auto &t : theta)
                if (converged && std::abs(t) > nu * (1 + 1e-8))
                  converged = b * ritz_last_component(H, m, t) <= settings.tolerance * std::abs(t);
              if (converged)
                {
                  out.converged = true;
                  break;
                }
            }
          if (b <= 1e-14 * H.frobenius_norm())
            {
              out.converged = nu > 0; // an invariant subspace: the Ritz values are exact
              break;
            }
          W.push_back(scaled(w, 1. / b));
          V.push_back(scaled(v, 1. / b));
        }
      out.residuals = G.residuals;
      out.jacobians = G.jacobians;
      problem.set_load_parameter(lambda0);
      if (G.failed)
        {
          out.message = "a residual along the path to second order cannot be evaluated";
          return out;
        }
      if (!(nu > 0) || ritz.size() == 0)
        {
          out.message = "no real positive eigenvalue of the second-order model: the load does not destabilize";
          return out;
        }
      const double tau = scale / nu;
      out.found        = true;
      out.lambda       = lambda0 + tau;
      out.next_lambda  = next > 0 ? lambda0 + scale / next : std::numeric_limits<double>::infinity();
      G.state(tau, dU, out.U, out.tangent);
      out.mode.reinit(n);
      for (unsigned int i = 0; i < ritz.size(); ++i)
        out.mode.add(ritz[i], V[i]);
      const double vmax = masked_max(out.mode, mask);
      if (vmax > 0)
        out.mode /= vmax;
      return out;
    }
  } // namespace solvers
} // namespace cosmo

namespace cosmo
{
  namespace solvers
  {
    namespace
    {
      /// y = J(U) x at the problem's current load: the Jacobian assembled at
      /// U into `slot` where the problem stores Jacobians, else central
      /// differences of the residual (two a product).
      class JacobianAt
      {
      public:
        JacobianAt(BifurcationProblem &problem, const unsigned int slot, const double state_step)
            : problem(&problem), slot(slot), state_step(state_step)
        {}

        void
        set(const Vector<double> &at)
        {
          U      = at;
          failed = false;
          stored = !by_residuals() && problem->store_jacobian(U, slot);
          jacobians += stored ? 1 : 0;
        }

        void
        vmult(Vector<double> &y, const Vector<double> &x) const
        {
          y.reinit(x.size());
          if (stored)
            {
              problem->stored_jacobian_vmult(slot, x, y);
              return;
            }
          const double xmax = x.linfty_norm();
          if (!(xmax > 0))
            return;
          const double   eps = state_step / xmax;
          Vector<double> Up(U), Um(U), Rm(x.size());
          Up.add(eps, x);
          Um.add(-eps, x);
          if (problem->residual(Up, y) != 0 || problem->residual(Um, Rm) != 0)
            failed = true;
          y -= Rm;
          y /= 2 * eps;
          residuals += 2;
        }

        mutable unsigned int residuals = 0;
        unsigned int         jacobians = 0;
        mutable bool         failed    = false;

      private:
        BifurcationProblem *problem;
        unsigned int        slot;
        double              state_step;
        Vector<double>      U;
        bool                stored = false;
      };

      /// The start's factorization as GMRES's preconditioner.
      struct StartFactorization
      {
        BifurcationProblem  *problem;
        mutable unsigned int solves = 0;
        void
        vmult(Vector<double> &dst, const Vector<double> &src) const
        {
          problem->solve_with_jacobian(src, dst);
          ++solves;
        }
      };
    } // namespace

    namespace
    {
      /**
       * The refinement's pieces, with the start's factorization J0 in
       * place throughout (refine_critical_estimate()): the path's state at
       * a load, the smallest eigenvalue of the pencil (J, J0) there and its
       * rate along the path.
       */
      class PencilAlongPath
      {
      public:
        PencilAlongPath(BifurcationProblem   &problem,
                        const Vector<double> &U0,
                        const double          lambda0,
                        const Vector<double> &mask,
                        EstimateRefinement   &out)
            : problem(problem), U0(U0), lambda0(lambda0), scale(problem.unknowns_scale(U0)), mask(mask), out(out),
              J0(problem, 0, 1e-6 * scale), J(problem, 1, 1e-6 * scale), P{&problem}
        {
          problem.set_load_parameter(lambda0);
          J0.set(U0);
        }

        ~PencilAlongPath()
        {
          problem.release_stored_jacobians();
          problem.set_load_parameter(lambda0);
          out.residuals += J.residuals + J0.residuals;
          out.jacobians = J.jacobians + J0.jacobians;
          out.solves += P.solves;
        }

        /// R(U, lambda0 + t) = 0 by Newton from U, each step by GMRES
        /// preconditioned with J0 (whose spectrum over J's is clustered at
        /// 1 but for the few modes the load softens); J stays stored at
        /// the last iterate.
        bool
        converge_state(const double t, Vector<double> &U)
        {
          problem.set_load_parameter(lambda0 + t);
          const unsigned int n = U.size();
          Vector<double>     R(n), step(n);
          double             last = INFINITY;
          for (unsigned int k = 0; k < 8; ++k)
            {
              if (problem.residual(U, R) != 0)
                return false;
              ++out.residuals;
              J.set(U);
              R *= -1.;
              step = 0.;
              if (!gmres(R, step))
                return false;
              U += step;
              ++out.newton;
              if (J.failed)
                return false;
              // Converged: the step at round-off, or no longer decreasing
              // near it (next to the critical point the residual's
              // round-off is amplified along the nearly singular mode). J
              // stays the last iterate's where the step was below 1e-9,
              // which moves mu by as little.
              const double size = masked_max(step, mask);
              if (size <= 1e-9 * scale || (k > 0 && size <= 1e-6 * scale && size > 0.25 * last))
                {
                  if (size > 1e-9 * scale)
                    J.set(U);
                  return true;
                }
              last = size;
            }
          return false;
        }

        /// The smallest eigenvalue mu of J(U) v = mu J0 v on the mask (J
        /// stored at U by converge_state()): 1 minus the largest of J0^-1
        /// (J0 - J), by Lanczos from v, which gets its eigenvector.
        /// `tolerance` bounds the Ritz residual; mu's error is about its
        /// square over the gap to the next eigenvalue. NaN if it fails.
        double
        smallest_eigenvalue(const double t, Vector<double> &v, const double tolerance)
        {
          CriticalEstimateSettings lanczos;
          lanczos.tolerance = tolerance;
          lanczos.max_steps = 40;
          const unsigned int n = v.size();
          Vector<double>     J0q(n), Jq(n), start(v);
          // The last mode with a random part of 1e-4 (not for the last
          // run, from the mode already found): a start of one symmetry
          // keeps Lanczos in it (the section's second-order mode at growth
          // 1.3, unconverged, was symmetric, and Lanczos from it found a
          // symmetric eigenvalue, 0.4, above the critical mode's).
          const double                           vmax = masked_max(v, mask);
          std::mt19937                           random(20261207);
          std::uniform_real_distribution<double> uniform(-1., 1.);
          for (unsigned int i = 0; i < n && tolerance > 1e-8; ++i)
            start[i] += 1e-4 * (vmax > 0 ? vmax : 1.) * mask[i] * uniform(random);
          const LanczosRun run = pencil_lanczos(
            problem, mask, lanczos,
            [&](const Vector<double> &q, const Vector<double> &J0q_known, Vector<double> &y) {
              if (J0q_known.size() == n)
                J0q = J0q_known;
              else
                {
                  problem.set_load_parameter(lambda0);
                  J0.vmult(J0q, q);
                }
              problem.set_load_parameter(lambda0 + t);
              J.vmult(Jq, q);
              y = J0q;
              y -= Jq;
              y.scale(mask); // (the multipliers' rows: C q in both)
            },
            start);
          out.solves += run.solves;
          out.lanczos += run.steps;
          // (a residual of a difference product that could not be evaluated)
          if (!run.definite || run.theta.size() == 0 || !run.converged || J.failed || J0.failed)
            return NAN;
          v = run.top_vector(mask);
          return 1 - run.theta[run.theta.size() - 1];
        }

        /// The path's tangent at (U, lambda0 + t), J(U) stored: J T =
        /// -dR/dlambda by GMRES from the guess T.
        bool
        tangent(const double t, const Vector<double> &U, Vector<double> &T)
        {
          Vector<double> dR(U.size());
          problem.set_load_parameter(lambda0 + t);
          if (problem.load_derivative(U, lambda0 + t, dR) != 0)
            return false;
          dR *= -1.;
          return gmres(dR, T);
        }

        /// Whether the mode v has a component along dR/dlambda at the
        /// start (|v.dR| above 1e-4 |v| |dR| on the mask): a fold, not a
        /// branch point, as the location classifies it.
        bool
        along_load(const Vector<double> &v)
        {
          Vector<double> dR(v.size());
          problem.set_load_parameter(lambda0);
          if (problem.load_derivative(U0, lambda0, dR) != 0)
            return true; // (unknown: not refined)
          out.residuals += 2;
          return std::abs(masked_dot(v, dR, mask)) > 1e-4 * std::sqrt(masked_dot(dR, dR, mask) * masked_dot(v, v, mask));
        }

        /// d mu/dt = v.J' v / v.J0 v along the tangent T at (U, lambda0 +
        /// t), J' by a central difference in the load of v.J v, each by
        /// central differences of the residual along v (4 residuals).
        double
        eigenvalue_rate(const double t, const Vector<double> &U, const Vector<double> &T, const Vector<double> &mode)
        {
          Vector<double> v = mode;
          problem.complete_mode(v); // (the unknowns constraints determine: a state the residual takes)
          const double vmax = masked_max(v, mask), d = 1e-3 * std::max(std::abs(t), 1e-3);
          if (!(vmax > 0))
            return NAN;
          const double   eps = 1e-5 * scale / vmax;
          const unsigned n   = U.size();
          Vector<double> Up(n), Rp(n), Rm(n), J0v(n);
          auto           form = [&](const double s) {
            problem.set_load_parameter(lambda0 + t + s);
            double f = 0;
            for (const double e : {eps, -eps})
              {
                Up = U;
                Up.add(s, T, e, v);
                if (problem.residual(Up, e > 0 ? Rp : Rm) != 0)
                  return double(NAN);
              }
            out.residuals += 2;
            Rp -= Rm;
            f = masked_dot(v, Rp, mask) / (2 * eps);
            return f;
          };
          const double rate = (form(d) - form(-d)) / (2 * d);
          problem.set_load_parameter(lambda0);
          J0.vmult(J0v, v);
          return rate / masked_dot(v, J0v, mask);
        }

      private:
        /// J x = b (J stored) by GMRES preconditioned with J0, from x, to
        /// 1e-10 of |b - J x|; next to the critical point the residual's
        /// round-off sets a floor, and a reduction by 1e-4 will do.
        bool
        gmres(const Vector<double> &b, Vector<double> &x)
        {
          Vector<double> r(b.size());
          J.vmult(r, x);
          r.sadd(-1., 1., b);
          const double                                r0 = r.l2_norm();
          SolverControl                               control(100, 1e-10 * r0);
          SolverGMRES<Vector<double>>::AdditionalData data(50, true);
          SolverGMRES<Vector<double>>                 solver(control, data);
          try
            {
              solver.solve(J, x, b, P);
            }
          catch (SolverControl::NoConvergence &e)
            {
              if (!(e.last_residual <= 1e-4 * r0))
                return false;
            }
          out.krylov += control.last_step();
          return !J.failed;
        }

        BifurcationProblem   &problem;
        const Vector<double> &U0;
        const double          lambda0, scale;
        const Vector<double> &mask;
        EstimateRefinement   &out;
        JacobianAt            J0, J;
        StartFactorization    P;
      };
    } // namespace

    EstimateRefinement
    refine_critical_estimate(BifurcationProblem   &problem,
                             const Vector<double> &U0,
                             const double          lambda0,
                             const Vector<double> &dU,
                             const Vector<double> &mask,
                             CriticalEstimate     &estimate)
    {
      EstimateRefinement out;
      const double       tau = estimate.lambda - lambda0;
      if (!(tau > 0) || estimate.tangent.size() != U0.size())
        {
          out.message = "no estimate ahead to refine";
          return out;
        }
      // From the second-order series' state and tangent at the estimate
      // (U0 + t dU + t^2/2 d2U, dU + t d2U), then each state's guess along
      // the tangent there.
      double         t = tau, mu = NAN;
      Vector<double> U = estimate.U, T = estimate.tangent, v = estimate.mode;
      {
        PencilAlongPath pencil(problem, U0, lambda0, mask, out);
        // Newton on mu(t), the rate by Hellmann-Feynman (v.J' v / v.J0 v
        // along the path's tangent). The Ritz residual 1e-6 makes mu's
        // error ~1e-12 over its gap; the last one 1e-9: the mode is the
        // location's border (1e-4 off pinned a branch point 240
        // resolutions off, doc/theory-continuation.md 10).
        for (unsigned int it = 0; it < 8; ++it)
          {
            if (!pencil.converge_state(t, U))
              {
                out.message = "the state at t = " + std::to_string(lambda0 + t) + " does not converge";
                break;
              }
            ++out.evaluations;
            mu = pencil.smallest_eigenvalue(t, v, 1e-6);
            if (!std::isfinite(mu))
              {
                out.message = "the smallest eigenvalue fails";
                break;
              }
            // A fold (the mode along dR/dlambda, the location's test):
            // there mu ~ sqrt(t_c - t), and Newton on it steps past the
            // fold, where the path has no state.
            if (out.evaluations == 1 && pencil.along_load(v))
              {
                out.message = "a fold: Newton on the smallest eigenvalue would step past it";
                break;
              }
            if (!pencil.tangent(t, U, T))
              {
                out.message = "the tangent fails";
                break;
              }
            const double rate = pencil.eigenvalue_rate(t, U, T, v);
            if (!(rate < 0))
              {
                out.message = "the smallest eigenvalue's rate fails";
                break;
              }
            const double dt = -mu / rate;
            if (!(t + dt > 0 && t + dt < 4 * tau))
              {
                out.message = "Newton on the smallest eigenvalue leaves the window";
                break;
              }
            t += dt;
            U.add(dt, T); // (the next state's guess: the tangent's, off by dt^2)
            // The last step is not converged onto: Newton on the augmented
            // system does that from the tangent's guess, its load ~dt^2
            // off. A state next to the critical point would carry the
            // round-off its solves amplify along the mode (by 1/mu), and
            // that drift, pinned by the location's border row, moved the
            // section's located loads up to 68 resolutions (states down to
            // |mu| <= 1e-7), and 6 under a 1e-14 change of the input; at
            // |mu| >= 1e-4 it is about 1e-16 * 1e4.
            if (std::abs(mu) <= 1e-4)
              {
                out.refined = std::isfinite(pencil.smallest_eigenvalue(t - dt, v, 1e-9));
                break;
              }
          }
      }
      if (!out.refined)
        {
          if (out.message.empty())
            out.message = "Newton on the smallest eigenvalue does not converge";
          return out;
        }
      // The tangent handed on is the second-order series' at the refined
      // load, dU + t d2U, as the unrefined estimate's (the solved one
      // located the same points): a fallback short of the estimate
      // rebuilds the series from it (converge_short_of_estimate()).
      Vector<double> d2U = estimate.tangent;
      d2U -= dU;
      d2U /= tau;
      estimate.lambda  = lambda0 + t;
      estimate.U       = U;
      estimate.mode    = v;
      estimate.tangent = dU;
      estimate.tangent.add(t, d2U);
      return out;
    }
  } // namespace solvers
} // namespace cosmo
