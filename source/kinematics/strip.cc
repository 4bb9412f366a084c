// The strip energy's derivatives by the chain rule through the plate
// measures (kinematics/strip.h, kinematics/plate_measures.h): nested AD
// only where the map is not polynomial (the director, 4 variables) and in
// the law (8 measures).
#include <cosmo/kinematics/plate_measures.h>
#include <cosmo/kinematics/strip.h>
#include <cosmo/materials/energy_derivatives.h>

namespace cosmo
{
  namespace kinematics
  {
    namespace
    {
      constexpr int n_z        = strip_local_variables;
      constexpr int n_director = 4; // theta1, theta3, theta1', theta3'
      using plate_measures::n_vectors;

      using Vec = std::array<double, 3>;

      double
      dot(const Vec &a, const Vec &b)
      {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      }

      /// q, q' and their derivatives in (theta1, theta3, theta1', theta3').
      struct Director
      {
        Vec                                            q, q1;
        std::array<Vec, n_director>                    dq, dq1;   // [a][i]
        std::array<Vec, n_director * n_director>       ddq, ddq1; // [4a + b][i]
      };

      Director
      director_of(const std::array<double, n_z> &z, const bool with_hessian)
      {
        // Outputs q (0-2), q' (3-5) of x = (theta1, theta3, theta1', theta3') = z[6..9].
        std::array<double, n_director>                              x = {{z[6], z[7], z[8], z[9]}};
        std::array<double, 6>                                       y;
        std::array<std::array<double, n_director>, 6>               dy;
        std::array<std::array<double, n_director * n_director>, 6> ddy;
        materials::internal::differentiate_map<n_director, 6>(
          x,
          [](const auto &X, auto &Y) {
            using Number = std::decay_t<decltype(X[0])>;
            std::array<Number, 3> q, q1;
            strip_director_and_derivative(X[0], X[1], X[2], X[3], q, q1);
            for (unsigned int i = 0; i < 3; ++i)
              {
                Y[i]     = q[i];
                Y[3 + i] = q1[i];
              }
          },
          with_hessian, y, dy, ddy);
        Director d{};
        for (unsigned int i = 0; i < 3; ++i)
          {
            d.q[i]  = y[i];
            d.q1[i] = y[3 + i];
            for (int a = 0; a < n_director; ++a)
              {
                d.dq[a][i]  = dy[i][a];
                d.dq1[a][i] = dy[3 + i][a];
              }
            if (with_hessian)
              for (int ab = 0; ab < n_director * n_director; ++ab)
                {
                  d.ddq[ab][i]  = ddy[i][ab];
                  d.ddq1[ab][i] = ddy[3 + i][ab];
                }
          }
        return d;
      }
    } // namespace

    void
    strip_energy_derivatives(const std::array<double, strip_local_variables> &z,
                             const double                                    eta,
                             const materials::PlateLawAt &               law,
                             const bool                                      membrane_bending,
                             const bool                                      with_hessian,
                             double &                                        W,
                             std::array<double, strip_local_variables> &     g,
                             std::array<double, strip_local_variables * strip_local_variables> &H,
                             const std::array<double, 3> &natural_curvature)
    {
      // Indices of z (strip_local_variables): u 0-2, u' 3-5, theta 6-7,
      // theta' 8-9, nu 10-12, kappa 13-15. Indices of V: a1 0-2, a2 3-5,
      // d 6-8, d1 9-11, d2 12-14.
      const Vec      y     = {{eta + z[0], z[1], z[2]}};
      const Vec      kappa = {{z[13], z[14], z[15]}};
      const Director dir   = director_of(z, with_hessian);

      // The vectors V(z), as in strip_energy().
      std::array<double, n_vectors> V;
      const Vec                     kxy = cross(kappa, y), kxq = cross(kappa, dir.q);
      for (unsigned int i = 0; i < 3; ++i)
        {
          V[i]      = (i == 0 ? 1. : 0.) + z[3 + i];
          V[3 + i]  = z[10 + i] + kxy[i];
          V[6 + i]  = dir.q[i];
          V[9 + i]  = dir.q1[i];
          V[12 + i] = kxq[i];
        }

      // Their Jacobian V_z (15 x 16).
      std::array<double, n_vectors * n_z> Vz{};
      auto set_column = [&Vz](const int first_row, const int column, const Vec &v) {
        for (unsigned int i = 0; i < 3; ++i)
          Vz[n_z * (first_row + i) + column] = v[i];
      };
      for (unsigned int j = 0; j < 3; ++j)
        {
          Vec e{};
          e[j]                      = 1;
          Vz[n_z * j + 3 + j]       = 1;                        // a1 = E1 + u'
          Vz[n_z * (3 + j) + 10 + j] = 1;                       // a2 = nu + kappa x y
          set_column(3, 13 + j, cross(e, y));
          set_column(3, j, cross(kappa, e));
          set_column(12, 13 + j, cross(e, dir.q));              // d2 = kappa x q
        }
      for (int a = 0; a < n_director; ++a)
        {
          if (a < 2)
            {
              set_column(6, 6 + a, dir.dq[a]);                  // d = q(theta)
              set_column(12, 6 + a, cross(kappa, dir.dq[a]));
            }
          set_column(9, 6 + a, dir.dq1[a]);                     // d1 = q'(theta, theta')
        }

      // w(s(V)) in V, then g = V_z^T w_V, H = V_z^T w_VV V_z ...
      plate_measures::Energy energy;
      energy.law              = &law;
      energy.membrane_bending = membrane_bending;
      if (membrane_bending)
        energy.natural_curvature = natural_curvature;
      std::array<double, n_vectors>             wV;
      std::array<double, n_vectors * n_vectors> wVV;
      plate_measures::energy_in_vectors(V, energy, with_hessian, W, wV, wVV);
      plate_measures::pull_back<n_z>(Vz, wV, wVV, with_hessian, g, H);
      if (!with_hessian)
        return;

      // ... + sum_i w_{V_i} (V_i)_zz: the bilinear terms kappa x y and
      // kappa x q, and the director's own second derivatives.
      auto add_symmetric = [&H](const int r, const int c, const double v) {
        H[n_z * r + c] += v;
        H[n_z * c + r] += v;
      };
      const Vec w_a2 = {{wV[3], wV[4], wV[5]}}, w_d = {{wV[6], wV[7], wV[8]}},
                w_d1 = {{wV[9], wV[10], wV[11]}}, w_d2 = {{wV[12], wV[13], wV[14]}};
      for (unsigned int l = 0; l < 3; ++l)
        {
          // d2/(dkappa_j du_l) of w_a2.(kappa x y) = w_a2.(e_j x e_l) = (e_l x w_a2)_j
          Vec e{};
          e[l]         = 1;
          const Vec el = cross(e, w_a2);
          for (unsigned int j = 0; j < 3; ++j)
            add_symmetric(13 + j, l, el[j]);
        }
      const Vec w_d2_x_kappa = cross(w_d2, kappa);
      for (int a = 0; a < n_director; ++a)
        {
          if (a < 2)
            {
              // d2/(dkappa_j dtheta_a) of w_d2.(kappa x q) = (q_a x w_d2)_j
              const Vec qa = cross(dir.dq[a], w_d2);
              for (unsigned int j = 0; j < 3; ++j)
                add_symmetric(13 + j, 6 + a, qa[j]);
            }
          for (int b = 0; b < n_director; ++b)
            {
              const int ab = n_director * a + b;
              double    v  = dot(w_d1, dir.ddq1[ab]);
              if (a < 2 && b < 2)
                v += dot(w_d, dir.ddq[ab]) + dot(dir.ddq[ab], w_d2_x_kappa); // w.(kappa x q_ab)
              H[n_z * (6 + a) + 6 + b] += v;
            }
        }
    }
  } // namespace kinematics
} // namespace cosmo
