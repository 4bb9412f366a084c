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
                                     const materials::NaghdiPlateLaw &               law,
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

        // The director d and its gradient (d1, d2), with their first and
        // (on request) second derivatives in x = z[9..14].
        Vec                                 d, d1, d2;
        std::array<Vec, n_x>                dd{}, dd1{}, dd2{};
        std::array<Vec, n_x * n_x>          ddd{}, ddd1{}, ddd2{};
        if (with_hessian)
          {
            using D1 = materials::FirstOrderAD<n_x>;
            using D2 = materials::SecondOrderAD<n_x>;
            std::array<D2, n_x> x;
            for (int a = 0; a < n_x; ++a)
              x[a] = D2(n_x, a, D1(n_x, a, z[9 + a]));
            std::array<D2, 3> q, q1, q2;
            exact_director_and_gradient(x[0], x[1], &x[2], q, q1, q2);
            for (unsigned int i = 0; i < 3; ++i)
              {
                d[i]  = q[i].val().val();
                d1[i] = q1[i].val().val();
                d2[i] = q2[i].val().val();
                for (int a = 0; a < n_x; ++a)
                  {
                    dd[a][i]  = q[i].dx(a).val();
                    dd1[a][i] = q1[i].dx(a).val();
                    dd2[a][i] = q2[i].dx(a).val();
                    for (int b = 0; b < n_x; ++b)
                      {
                        ddd[n_x * a + b][i]  = q[i].dx(a).dx(b);
                        ddd1[n_x * a + b][i] = q1[i].dx(a).dx(b);
                        ddd2[n_x * a + b][i] = q2[i].dx(a).dx(b);
                      }
                  }
              }
          }
        else
          {
            using D1 = materials::FirstOrderAD<n_x>;
            std::array<D1, n_x> x;
            for (int a = 0; a < n_x; ++a)
              x[a] = D1(n_x, a, z[9 + a]);
            std::array<D1, 3> q, q1, q2;
            exact_director_and_gradient(x[0], x[1], &x[2], q, q1, q2);
            for (unsigned int i = 0; i < 3; ++i)
              {
                d[i]  = q[i].val();
                d1[i] = q1[i].val();
                d2[i] = q2[i].val();
                for (int a = 0; a < n_x; ++a)
                  {
                    dd[a][i]  = q[i].dx(a);
                    dd1[a][i] = q1[i].dx(a);
                    dd2[a][i] = q2[i].dx(a);
                  }
              }
          }

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
              V[9 + 3 * b + c]  = d1[c] * Gi[0][b] + d2[c] * Gi[1][b];
              Vz[n_z * (3 * b + c) + 3 + c] = Gi[0][b];
              Vz[n_z * (3 * b + c) + 6 + c] = Gi[1][b];
              for (int a = 0; a < n_x; ++a)
                Vz[n_z * (9 + 3 * b + c) + 9 + a] = dd1[a][c] * Gi[0][b] + dd2[a][c] * Gi[1][b];
            }
        for (unsigned int c = 0; c < 3; ++c)
          {
            V[6 + c] = d[c];
            for (int a = 0; a < n_x; ++a)
              Vz[n_z * (6 + c) + 9 + a] = dd[a][c];
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
                  v += wV[6 + c] * ddd[ab][c];
                  for (unsigned int k = 0; k < 2; ++k)
                    v += wV[9 + 3 * k + c] * (ddd1[ab][c] * Gi[0][k] + ddd2[ab][c] * Gi[1][k]);
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
        using D1 = materials::FirstOrderAD<2>;
        using D2 = materials::SecondOrderAD<2>;
        std::array<D2, 2> x;
        for (int a = 0; a < 2; ++a)
          x[a] = D2(2, a, D1(2, a, z[9 + a]));
        const D2          no_gradient[4] = {D2(0.), D2(0.), D2(0.), D2(0.)};
        std::array<D2, 3> q, q1, q2;
        exact_director_and_gradient(x[0], x[1], no_gradient, q, q1, q2);
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
                e += Jb * a[b][i] * q[i].val().val();
                grad[3 + 3 * b + i] = Jb * q[i].val().val();
                for (int t = 0; t < 2; ++t)
                  grad[9 + t] += Jb * a[b][i] * q[i].dx(t).val();
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
                  const double v                         = Jb * q[i].dx(t).val();
                  H[n_z * (3 + 3 * b + i) + 9 + t]       = v;
                  H[n_z * (9 + t) + 3 + 3 * b + i]       = v;
                  for (int r = 0; r < 2; ++r)
                    H[n_z * (9 + t) + 9 + r] += Jb * a[b][i] * q[i].dx(t).dx(r);
                }
          }
      }
    } // namespace internal
  }   // namespace kinematics
} // namespace cosmo
