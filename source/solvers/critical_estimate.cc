#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_estimate.h>
#include <cosmo/solvers/critical_point.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace cosmo
{
  namespace solvers
  {
    namespace
    {
      /**
       * -J' v on the mode unknowns: the difference in the load (along the
       * tangent, lambda1 = lambda0 + delta, U1 = U0 + delta dU) of the
       * differences J v = (R(U + eps v) - R(U))/eps, with R at U0 and U1
       * computed once. Its round-off is about 1e-16 |R|/(eps delta) of the
       * internal forces: 1e-6 of them at the default steps.
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
          problem.residual(U1, R1);
          problem.set_load_parameter(lambda0);
          problem.residual(U0, R0);
          residuals = 2;
        }

        void
        vmult(const Vector<double> &v, Vector<double> &dst)
        {
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

        unsigned int residuals = 0;

      private:
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
      const unsigned int      n     = U0.size();
      auto                    solve = [&](const Vector<double> &b, Vector<double> &x) {
        problem.solve_with_jacobian(b, x);
        x.scale(mask);
        ++out.solves;
      };
      // Lanczos for K = -J0^-1 J' in the J0 inner product <x, y> = x.J0 y:
      // q_j with J0 q_j alongside (J0 K q = -J' q needs no product with J0).
      // On the mode unknowns x.J0 y is the constrained Hessian's form: a
      // solve's multipliers satisfy C x = 0, so x.(J0 x) = x_u.H x_u.
      std::vector<Vector<double>>            Q, JQ;
      std::vector<double>                    alpha, beta;
      Vector<double>                         start(n), w(n), Jw(n), theta;
      FullMatrix<double>                     S;
      std::mt19937                           random(20261206);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      for (unsigned int i = 0; i < n; ++i)
        start[i] = mask[i] * uniform(random);
      G.vmult(start, Jw);
      solve(Jw, w);
      double norm2 = masked_dot(w, Jw, mask);
      if (!(norm2 > 0))
        {
          out.message = "J0 is not positive definite on the start vector (not a stable state)";
          return out;
        }
      Q.push_back(scaled(w, 1. / std::sqrt(norm2)));
      JQ.push_back(scaled(Jw, 1. / std::sqrt(norm2)));
      for (unsigned int j = 0; j < settings.max_steps; ++j)
        {
          G.vmult(Q[j], Jw); // w = K q_j: J0 w = -J' q_j
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
          tridiagonal_eigenpairs(alpha, beta, theta, S);
          out.steps = j + 1;
          // The largest theta is 1/tau of the first critical load; its Ritz
          // pair's residual is |K y - theta y| = b |s_j| in the J0 norm.
          const unsigned int top   = theta.size() - 1;
          const double       scale = std::max(std::abs(theta[0]), std::abs(theta[top]));
          if (theta[top] > 0 && b * std::abs(S(j, top)) <= settings.tolerance * theta[top])
            {
              out.converged = true;
              break;
            }
          // (K is self-adjoint in the J0 inner product: the k-th largest
          // Ritz value is at most the k-th largest eigenvalue, and the top
          // one lies within r of an eigenvalue)
          if (settings.cluster_factor > 0 && top > 0 && theta[top] > 0)
            {
              const double r = b * std::abs(S(j, top)), second = theta[top - 1];
              if (r <= 1e-2 * theta[top] && second > (theta[top] + r) / settings.cluster_factor &&
                  second < (1 - 1e-3) * theta[top])
                {
                  out.cluster = true;
                  break;
                }
            }
          if (b <= 1e-14 * scale)
            {
              out.converged = true; // an invariant subspace: the Ritz values are exact
              break;
            }
          beta.push_back(b);
          Q.push_back(scaled(w, 1. / b));
          JQ.push_back(scaled(Jw, 1. / b));
        }
      out.residuals = G.residuals;
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
      out.mode.reinit(n);
      for (unsigned int i = 0; i < m; ++i)
        out.mode.add(S(i, m - 1), Q[i]);
      const double vmax = masked_max(out.mode, mask);
      if (vmax > 0)
        out.mode /= vmax;
      problem.set_load_parameter(lambda0);
      return out;
    }
  } // namespace solvers
} // namespace cosmo
