// The strip energy's derivatives by the chain rule through the plate
// measures (kinematics/strip.h): nested AD only where the map is not
// polynomial (the director, 4 variables) and in the law (8 measures).
#include <cosmo/kinematics/strip.h>
#include <cosmo/materials/energy_derivatives.h>

namespace cosmo
{
  namespace kinematics
  {
    namespace
    {
      constexpr int n_z        = strip_local_variables;
      constexpr int n_measures = 8;  // membrane (11, 22, 12), bending (11, 22, 12), shear (1, 2)
      constexpr int n_vectors  = 15; // a1, a2, d, d1, d2 (plate_strains' arguments)
      constexpr int n_director = 4;  // theta1, theta3, theta1', theta3'

      using Vec = std::array<double, 3>;

      double
      dot(const Vec &a, const Vec &b)
      {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      }

      /// C += A B for row-major A (M x K), B (K x N), skipping the zeros of A
      /// (V_z and the law's Hessian are mostly zeros).
      template <int M, int K, int N>
      void
      add_product(const std::array<double, M * K> &A,
                  const std::array<double, K * N> &B,
                  std::array<double, M * N> &      C)
      {
        for (int i = 0; i < M; ++i)
          for (int l = 0; l < K; ++l)
            if (A[K * i + l] != 0)
              for (int j = 0; j < N; ++j)
                C[N * i + j] += A[K * i + l] * B[N * l + j];
      }

      /// The eight measures of plate_strains() from V = (a1, a2, d, d1, d2).
      template <typename Number>
      std::array<Number, n_measures>
      measures_of(const std::array<Number, n_vectors> &V)
      {
        auto part = [&V](const int k) {
          return std::array<Number, 3>{{V[3 * k], V[3 * k + 1], V[3 * k + 2]}};
        };
        const auto s = materials::plate_strains(part(0), part(1), part(2), part(3), part(4));
        return {{s.membrane[0], s.membrane[1], s.membrane[2], s.bending[0], s.bending[1],
                 s.bending[2], s.shear[0], s.shear[1]}};
      }

      template <typename Number>
      materials::PlateStrains<Number>
      strains_of(const std::array<Number, n_measures> &x)
      {
        materials::PlateStrains<Number> s;
        for (unsigned int k = 0; k < 3; ++k)
          {
            s.membrane[k] = x[k];
            s.bending[k]  = x[3 + k];
          }
        s.shear[0] = x[6];
        s.shear[1] = x[7];
        return s;
      }

      /**
       * The Hessians of the measures in V. Each measure is a dot product of
       * two of the vectors (plus a constant), so they do not depend on V:
       * computed once, by nested AD of plate_strains() at V = 0, so that
       * the measures are written in one place only. (If plate_strains()
       * ever stopped being bilinear, the comparison with the nested AD of
       * strip_energy in tests/kinematics.cc would fail.)
       */
      const std::array<std::array<double, n_vectors * n_vectors>, n_measures> &
      measure_hessians()
      {
        static const auto hessians = []() {
          using D1 = materials::FirstOrderAD<n_vectors>;
          using D2 = materials::SecondOrderAD<n_vectors>;
          std::array<D2, n_vectors> V;
          for (int a = 0; a < n_vectors; ++a)
            V[a] = D2(n_vectors, a, D1(n_vectors, a, 0.));
          const auto s = measures_of(V);
          std::array<std::array<double, n_vectors * n_vectors>, n_measures> h;
          for (int k = 0; k < n_measures; ++k)
            for (int a = 0; a < n_vectors; ++a)
              for (int b = 0; b < n_vectors; ++b)
                h[k][n_vectors * a + b] = s[k].dx(a).dx(b);
          return h;
        }();
        return hessians;
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
        Director d{};
        if (with_hessian)
          {
            using D1 = materials::FirstOrderAD<n_director>;
            using D2 = materials::SecondOrderAD<n_director>;
            std::array<D2, n_director> x;
            for (int a = 0; a < n_director; ++a)
              x[a] = D2(n_director, a, D1(n_director, a, z[6 + a]));
            std::array<D2, 3> q, q1;
            strip_director_and_derivative(x[0], x[1], x[2], x[3], q, q1);
            for (unsigned int i = 0; i < 3; ++i)
              {
                d.q[i]  = q[i].val().val();
                d.q1[i] = q1[i].val().val();
                for (int a = 0; a < n_director; ++a)
                  {
                    d.dq[a][i]  = q[i].dx(a).val();
                    d.dq1[a][i] = q1[i].dx(a).val();
                    for (int b = 0; b < n_director; ++b)
                      {
                        d.ddq[n_director * a + b][i]  = q[i].dx(a).dx(b);
                        d.ddq1[n_director * a + b][i] = q1[i].dx(a).dx(b);
                      }
                  }
              }
          }
        else
          {
            using D1 = materials::FirstOrderAD<n_director>;
            std::array<D1, n_director> x;
            for (int a = 0; a < n_director; ++a)
              x[a] = D1(n_director, a, z[6 + a]);
            std::array<D1, 3> q, q1;
            strip_director_and_derivative(x[0], x[1], x[2], x[3], q, q1);
            for (unsigned int i = 0; i < 3; ++i)
              {
                d.q[i]  = q[i].val();
                d.q1[i] = q1[i].val();
                for (int a = 0; a < n_director; ++a)
                  {
                    d.dq[a][i]  = q[i].dx(a);
                    d.dq1[a][i] = q1[i].dx(a);
                  }
              }
          }
        return d;
      }
    } // namespace

    void
    strip_energy_derivatives(const std::array<double, strip_local_variables> &z,
                             const double                                    eta,
                             const materials::NaghdiPlateLaw &               law,
                             const bool                                      membrane_bending,
                             const bool                                      with_hessian,
                             double &                                        W,
                             std::array<double, strip_local_variables> &     g,
                             std::array<double, strip_local_variables * strip_local_variables> &H)
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

      // The measures and their gradient in V (first-order AD).
      std::array<double, n_measures>             s;
      std::array<double, n_measures * n_vectors> sV;
      {
        using D1 = materials::FirstOrderAD<n_vectors>;
        std::array<D1, n_vectors> X;
        for (int a = 0; a < n_vectors; ++a)
          X[a] = D1(n_vectors, a, V[a]);
        const auto m = measures_of(X);
        for (int k = 0; k < n_measures; ++k)
          {
            s[k] = m[k].val();
            for (int a = 0; a < n_vectors; ++a)
              sV[n_vectors * k + a] = m[k].dx(a);
          }
      }

      // The law in the measures.
      std::array<double, n_measures>              ws;
      std::array<double, n_measures * n_measures> wss;
      materials::internal::differentiate<n_measures>(
        s,
        [&](const auto &x) {
          const auto strains = strains_of(x);
          return membrane_bending ? law.membrane_bending_energy(strains) : law.shear_energy(strains);
        },
        with_hessian,
        W,
        ws,
        wss);

      // w_V and the gradient g = V_z^T w_V.
      std::array<double, n_vectors> wV{};
      for (int k = 0; k < n_measures; ++k)
        for (int a = 0; a < n_vectors; ++a)
          wV[a] += ws[k] * sV[n_vectors * k + a];
      g.fill(0.);
      for (int a = 0; a < n_vectors; ++a)
        if (wV[a] != 0)
          for (int c = 0; c < n_z; ++c)
            g[c] += Vz[n_z * a + c] * wV[a];
      if (!with_hessian)
        return;

      // w_VV = s_V^T w_ss s_V + sum_k w_{s_k} s_k,VV.
      const auto &                                sVV = measure_hessians();
      std::array<double, n_vectors * n_vectors>   wVV{};
      std::array<double, n_measures * n_vectors>  wss_sV{};
      add_product<n_measures, n_measures, n_vectors>(wss, sV, wss_sV);
      for (int k = 0; k < n_measures; ++k)
        for (int a = 0; a < n_vectors; ++a)
          {
            const double ska = sV[n_vectors * k + a];
            for (int b = 0; b < n_vectors; ++b)
              wVV[n_vectors * a + b] += ska * wss_sV[n_vectors * k + b] + ws[k] * sVV[k][n_vectors * a + b];
          }

      // H = V_z^T w_VV V_z ...
      std::array<double, n_vectors * n_z> wVV_Vz{};
      add_product<n_vectors, n_vectors, n_z>(wVV, Vz, wVV_Vz);
      H.fill(0.);
      for (int a = 0; a < n_vectors; ++a)
        for (int r = 0; r < n_z; ++r)
          if (Vz[n_z * a + r] != 0)
            for (int c = 0; c < n_z; ++c)
              H[n_z * r + c] += Vz[n_z * a + r] * wVV_Vz[n_z * a + c];

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
