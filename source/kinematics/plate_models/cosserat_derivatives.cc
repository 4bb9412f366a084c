// The Cosserat plate energy's derivatives by the chain rule through the
// plate measures (kinematics/plate_measures.h): nested AD only in the
// director (six variables) and in the law (eight measures), instead of
// nested AD of the whole energy in twelve.
#include <cosmo/kinematics/plate_measures.h>
#include <cosmo/kinematics/plate_models/cosserat.h>
#include <cosmo/materials/energy_derivatives.h>

namespace cosmo
{
  namespace kinematics
  {
    namespace internal
    {
      void
      exact_plate_energy_derivatives(const std::array<double, plate_local_variables> &z,
                                     const PlateGrowthAtPoint &                      g,
                                     const materials::PlateLawAt &               law,
                                     const bool                                      membrane_bending,
                                     const double                                    shear_scale,
                                     const bool                                      with_hessian,
                                     double &                                        W,
                                     std::array<double, plate_local_variables> &     grad,
                                     std::array<double, plate_local_variables * plate_local_variables> &H)
      {
        constexpr int n_z = plate_local_variables;
        constexpr int n_x = 6; // theta1, theta2 (z 9, 10), dtheta/dX1 (11, 12), dtheta/dX2 (13, 14)
        using plate_measures::n_vectors;
        using Vec = std::array<double, 3>;
        const auto &Gi = g.G_inv;

        // The director d and its gradient (d1, d2) (outputs 0-2, 3-5, 6-8),
        // with their first and (on request) second derivatives in x = z[9..14].
        std::array<double, n_x>                       x;
        std::copy(z.begin() + 9, z.begin() + 15, x.begin());
        std::array<double, 9>                         y;
        std::array<std::array<double, n_x>, 9>        dy;
        std::array<std::array<double, n_x * n_x>, 9>  ddy;
        materials::internal::differentiate_map<n_x, 9>(
          x,
          [](const auto &X, auto &Y) {
            using Number = std::decay_t<decltype(X[0])>;
            std::array<Number, 3> q, q1, q2;
            exact_director_and_gradient(X[0], X[1], &X[2], q, q1, q2);
            for (unsigned int i = 0; i < 3; ++i)
              {
                Y[i]     = q[i];
                Y[3 + i] = q1[i];
                Y[6 + i] = q2[i];
              }
          },
          with_hessian, y, dy, ddy);
        // d(i) = y[i], d1(i) = y[3 + i], d2(i) = y[6 + i]; likewise dy, ddy.

        // V = (e1, e2, d, f1, f2), the arguments of plate_strains() in
        // grown_plate_strains(): e_b = sum_i a_i G^-1_ib, f_b = sum_i d_i G^-1_ib,
        // with a1 = E1 + du/dX1 (z 3-5), a2 = E2 + du/dX2 (z 6-8).
        std::array<double, n_vectors>       V;
        std::array<double, n_vectors * n_z> Vz{};
        const Vec                           a1 = {{1. + z[3], z[4], z[5]}}, a2 = {{z[6], 1. + z[7], z[8]}};
        for (unsigned int b = 0; b < 2; ++b)
          for (unsigned int c = 0; c < 3; ++c)
            {
              V[3 * b + c]      = a1[c] * Gi[0][b] + a2[c] * Gi[1][b];
              V[9 + 3 * b + c]  = y[3 + c] * Gi[0][b] + y[6 + c] * Gi[1][b];
              Vz[n_z * (3 * b + c) + 3 + c] = Gi[0][b];
              Vz[n_z * (3 * b + c) + 6 + c] = Gi[1][b];
              for (int a = 0; a < n_x; ++a)
                Vz[n_z * (9 + 3 * b + c) + 9 + a] = dy[3 + c][a] * Gi[0][b] + dy[6 + c][a] * Gi[1][b];
            }
        for (unsigned int c = 0; c < 3; ++c)
          {
            V[6 + c] = y[c];
            for (int a = 0; a < n_x; ++a)
              Vz[n_z * (6 + c) + 9 + a] = dy[c][a];
          }

        // w(s(V)) in V, then g = V_z^T w_V, H = V_z^T w_VV V_z ...
        plate_measures::Energy energy;
        energy.law               = &law;
        energy.membrane_bending  = membrane_bending;
        energy.factor            = membrane_bending ? g.det_G : g.det_G * shear_scale;
        energy.natural_curvature = g.natural_curvature;
        std::array<double, n_vectors>             wV;
        std::array<double, n_vectors * n_vectors> wVV;
        plate_measures::energy_in_vectors(V, energy, with_hessian, W, wV, wVV);
        plate_measures::pull_back<n_z>(Vz, wV, wVV, with_hessian, grad, H);
        if (!with_hessian)
          return;

        // ... + sum_i w_{V_i} (V_i)_zz: only the director's part of V is not linear in z.
        for (int a = 0; a < n_x; ++a)
          for (int b = 0; b < n_x; ++b)
            {
              const int ab = n_x * a + b;
              double    v  = 0;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  v += wV[6 + c] * ddy[c][ab];
                  for (unsigned int k = 0; k < 2; ++k)
                    v += wV[9 + 3 * k + c] * (ddy[3 + c][ab] * Gi[0][k] + ddy[6 + c][ab] * Gi[1][k]);
                }
              H[n_z * (9 + a) + 9 + b] += v;
            }
      }

      void
      exact_covariant_shear_derivatives(const std::array<double, plate_local_variables> &z,
                                        const Tensor<2, 2> &                            jacobian,
                                        const unsigned int                              c,
                                        const bool                                      with_hessian,
                                        double &                                        e,
                                        std::array<double, plate_local_variables> &     grad,
                                        std::array<double, plate_local_variables * plate_local_variables> &H)
      {
        constexpr int n_z = plate_local_variables;
        using Vec         = std::array<double, 3>;
        // d = R(theta) E3 with its derivatives in theta = z[9, 10] (nested AD in two variables).
        // The two shear strains tied at one location share theta, and the assembly asks for
        // them one after the other: the last director is kept (per thread) and reused when
        // theta is bitwise the same and the order asked for the same (first- and second-order
        // AD need not round alike; so the numbers never depend on which thread assembled what
        // before), which gives the same numbers (12 evaluations per Q2 cell instead of 16).
        struct Director
        {
          bool                                 valid = false, hessian = false;
          double                               theta[2];
          std::array<double, 3>                d;
          std::array<std::array<double, 2>, 3> dd;
          std::array<std::array<double, 4>, 3> ddd;
        };
        thread_local Director last;
        if (!(last.valid && last.theta[0] == z[9] && last.theta[1] == z[10] &&
              last.hessian == with_hessian))
          {
            materials::internal::differentiate_map<2, 3>(
              {{z[9], z[10]}},
              [](const auto &X, auto &Y) {
                using Number = std::decay_t<decltype(X[0])>;
                const Number no_gradient[4] = {Number(0.), Number(0.), Number(0.), Number(0.)};
                std::array<Number, 3> q1, q2;
                exact_director_and_gradient(X[0], X[1], no_gradient, Y, q1, q2);
              },
              with_hessian, last.d, last.dd, last.ddd);
            last.valid    = true;
            last.hessian  = with_hessian;
            last.theta[0] = z[9];
            last.theta[1] = z[10];
          }
        const auto &d = last.d;
        const auto &dd = last.dd;
        const auto &ddd = last.ddd;
        // e = sum_b J_bc a_b . d (covariant_shear_strain() of the shear a_b . d), with
        // a1 = E1 + du/dX1 (z 3-5), a2 = E2 + du/dX2 (z 6-8).
        const Vec a[2] = {{{1. + z[3], z[4], z[5]}}, {{z[6], 1. + z[7], z[8]}}};
        e              = 0;
        grad.fill(0.);
        for (unsigned int b = 0; b < 2; ++b)
          {
            const double Jb = jacobian[b][c];
            for (unsigned int i = 0; i < 3; ++i)
              {
                e += Jb * a[b][i] * d[i];
                grad[3 + 3 * b + i] = Jb * d[i];
                for (int t = 0; t < 2; ++t)
                  grad[9 + t] += Jb * a[b][i] * dd[i][t];
              }
          }
        if (!with_hessian)
          return;
        H.fill(0.);
        for (unsigned int b = 0; b < 2; ++b)
          {
            const double Jb = jacobian[b][c];
            for (unsigned int i = 0; i < 3; ++i)
              for (int t = 0; t < 2; ++t)
                {
                  const double v                         = Jb * dd[i][t];
                  H[n_z * (3 + 3 * b + i) + 9 + t]       = v;
                  H[n_z * (9 + t) + 3 + 3 * b + i]       = v;
                  for (int r = 0; r < 2; ++r)
                    H[n_z * (9 + t) + 9 + r] += Jb * a[b][i] * ddd[i][2 * t + r];
                }
          }
      }
    } // namespace internal
  }   // namespace kinematics
} // namespace cosmo
