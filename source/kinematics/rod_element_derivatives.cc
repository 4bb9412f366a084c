// Closed-form derivatives of the helicoidal element's maps
// (rod_element_derivatives.h): the element's Hessian by the chain rule.
#include <cosmo/kinematics/rod_element_derivatives.h>
#include <cosmo/materials/energy_derivatives.h>

namespace cosmo
{
  namespace kinematics
  {
    namespace
    {
      constexpr int levi_civita[3][3][3] = {{{0, 0, 0}, {0, 0, 1}, {0, -1, 0}},
                                            {{0, 0, -1}, {0, 0, 0}, {1, 0, 0}},
                                            {{0, 1, 0}, {-1, 0, 0}, {0, 0, 0}}};
    } // namespace

    /**
     * u = R(q)^T c and its derivatives in (c, q) in closed form. R(q) =
     * Q(q)/|q|^2 with Q quadratic in q (quaternion_rotation),
     * so u_i = q^T A_i q / n, A_i = sum_j c_j S_ji, Q_ji = q^T S_ji q,
     * n = |q|^2: with g = A_i q - u_i q,
     *   du_i/dc_j = R_ji,  du_i/dq = (2/n) g,
     *   d2u_i/dc_j dq = (2/n)(S_ji q - R_ji q),  d2u_i/dc^2 = 0,
     *   d2u_i/dq^2 = (2/n)(A_i - u_i I) - (4/n^2)(q g^T + g q^T).
     * (What nested AD of the same formula gives, at a fraction of its cost.)
     */
    void
    chord_in_frame_derivatives(const std::array<double, 7>           &x,
                               const bool                             with_hessian,
                               std::array<double, 3>                 &u,
                               std::array<std::array<double, 7>, 3>  &du,
                               std::array<std::array<double, 49>, 3> &ddu)
    {
      // S_ji by polarization of the quadratic Q (exact: integer entries).
      static const auto S = [] {
        std::array<std::array<std::array<double, 16>, 3>, 3> S{};
        auto                                                 Q = [](const Quaternion<double> &q) {
          const double n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
          auto         R = quaternion_rotation(q);
          return R * n;
        };
        for (unsigned int k = 0; k < 4; ++k)
          for (unsigned int l = 0; l < 4; ++l)
            {
              Quaternion<double> ek{{0, 0, 0, 0}}, el{{0, 0, 0, 0}}, ekl{{0, 0, 0, 0}};
              ek[k] = 1, el[l] = 1, ekl[k] += 1, ekl[l] += 1;
              const auto Qk = Q(ek), Ql = Q(el), Qkl = Q(ekl);
              for (unsigned int j = 0; j < 3; ++j)
                for (unsigned int i = 0; i < 3; ++i)
                  S[j][i][4 * k + l] = k == l ? Qk[j][i] : 0.5 * (Qkl[j][i] - Qk[j][i] - Ql[j][i]);
            }
        return S;
      }();
      const double *q = &x[3];
      const double  n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      for (unsigned int i = 0; i < 3; ++i)
        {
          std::array<double, 16>               A{};
          std::array<double, 3>                R_i; // R_ji, j = 0..2
          std::array<std::array<double, 4>, 3> Sq{};
          for (unsigned int j = 0; j < 3; ++j)
            {
              double Qji = 0;
              for (unsigned int k = 0; k < 4; ++k)
                {
                  for (unsigned int l = 0; l < 4; ++l)
                    Sq[j][k] += S[j][i][4 * k + l] * q[l];
                  Qji += q[k] * Sq[j][k];
                }
              R_i[j] = Qji / n;
              for (unsigned int kl = 0; kl < 16; ++kl)
                A[kl] += x[j] * S[j][i][kl];
            }
          u[i] = R_i[0] * x[0] + R_i[1] * x[1] + R_i[2] * x[2];
          std::array<double, 4> g;
          for (unsigned int k = 0; k < 4; ++k)
            {
              g[k]         = x[0] * Sq[0][k] + x[1] * Sq[1][k] + x[2] * Sq[2][k] - u[i] * q[k];
              du[i][3 + k] = 2 / n * g[k];
            }
          for (unsigned int j = 0; j < 3; ++j)
            du[i][j] = R_i[j];
          if (!with_hessian)
            continue;
          ddu[i].fill(0.);
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int k = 0; k < 4; ++k)
              ddu[i][7 * j + 3 + k] = ddu[i][7 * (3 + k) + j] = 2 / n * (Sq[j][k] - R_i[j] * q[k]);
          for (unsigned int k = 0; k < 4; ++k)
            for (unsigned int l = 0; l < 4; ++l)
              ddu[i][7 * (3 + k) + 3 + l] =
                  2 / n * (A[4 * k + l] - (k == l ? u[i] : 0.)) - 4 / (n * n) * (q[k] * g[l] + g[k] * q[l]);
        }
    }

    namespace
    {
      /**
       * Theta(p) = F(s) w, w = v/p0, s = |w|^2, F = 2 atan(sqrt s)/sqrt s
       * (relative_rotation_vector), and its derivatives in p = (p0, v):
       *   w_i,0 = -w_i/p0, w_i,j = delta_ij/p0, w_i,00 = 2 w_i/p0^2,
       *   w_i,0j = -delta_ij/p0^2, s_a = 2 w . w_a, s_ab = 2 (w_a . w_b + w . w_ab),
       *   Theta_i,a = F' s_a w_i + F w_i,a,
       *   Theta_i,ab = F'' s_a s_b w_i + F' (s_ab w_i + s_a w_i,b + s_b w_i,a) + F w_i,ab,
       * with F, F', F'' by AD in s alone (its series near 0).
       */
      void
      log_of_quaternion_derivatives(const std::array<double, 4>           &p,
                                    const bool                             with_hessian,
                                    std::array<double, 3>                 &theta,
                                    std::array<std::array<double, 4>, 3>  &Th_p,
                                    std::array<std::array<double, 16>, 3> &Th_pp)
      {
        const double          p0 = p[0];
        std::array<double, 3> w;
        double                s = 0;
        for (unsigned int i = 0; i < 3; ++i)
          w[i] = p[i + 1] / p0, s += w[i] * w[i];
        double                F;
        std::array<double, 1> dF, ddF{};
        materials::internal::differentiate<1>(
            std::array<double, 1>{{s}},
            [](const auto &x) {
              // (a Number, not Sacado's expression of a temporary)
              using Number = std::decay_t<decltype(x[0])>;
              return Number(2. * internal::atan_ratio(x[0]));
            },
            with_hessian, F, dF, ddF);
        auto w_a = [&](const unsigned int i, const unsigned int a) {
          return a == 0 ? -w[i] / p0 : (a == i + 1 ? 1 / p0 : 0.);
        };
        auto w_ab = [&](const unsigned int i, unsigned int a, unsigned int b) {
          if (a > b)
            std::swap(a, b);
          return a == 0 ? (b == 0 ? 2 * w[i] / (p0 * p0) : (b == i + 1 ? -1 / (p0 * p0) : 0.)) : 0.;
        };
        std::array<double, 4> s_a{};
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int i = 0; i < 3; ++i)
            s_a[a] += 2 * w[i] * w_a(i, a);
        for (unsigned int i = 0; i < 3; ++i)
          {
            theta[i] = F * w[i];
            for (unsigned int a = 0; a < 4; ++a)
              Th_p[i][a] = dF[0] * s_a[a] * w[i] + F * w_a(i, a);
          }
        if (!with_hessian)
          return;
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int b = a; b < 4; ++b)
            {
              double s_ab = 0;
              for (unsigned int j = 0; j < 3; ++j)
                s_ab += 2 * (w_a(j, a) * w_a(j, b) + w[j] * w_ab(j, a, b));
              for (unsigned int i = 0; i < 3; ++i)
                Th_pp[i][4 * a + b] = Th_pp[i][4 * b + a] =
                    ddF[0] * s_a[a] * s_a[b] * w[i] +
                    dF[0] * (s_ab * w[i] + s_a[a] * w_a(i, b) + s_a[b] * w_a(i, a)) + F * w_ab(i, a, b);
            }
      }
    } // namespace

    /**
     * theta = log(p) of p = conj(q_a) (q_b s) (s: a ring's seam) and its
     * derivatives in (q_a, q_b): p is bilinear, p_k = q_a^T T_k q_b, so
     * nested AD runs in p's 4 variables only and the chain rule adds
     *   theta_y = Theta_p p_y,
     *   theta_yy = p_y^T Theta_pp p_y + sum_k Theta_p_k (p_k)_yy,
     * with (p_k)_yy the constant T_k in the mixed (q_a, q_b) blocks.
     */
    void
    relative_rotation_derivatives(const std::array<double, 8>           &x,
                                  const Quaternion<double>              *seam,
                                  const bool                             with_hessian,
                                  std::array<double, 3>                 &theta,
                                  std::array<std::array<double, 8>, 3>  &dtheta,
                                  std::array<std::array<double, 64>, 3> &ddtheta)
    {
      // T_k[m][n] = p_k(e_m, e_n): exact (a unit quaternion's products only
      // permute signs); once for the elements without a seam.
      auto bilinear = [](const Quaternion<double> *s) {
        std::array<std::array<double, 16>, 4> T;
        for (unsigned int m = 0; m < 4; ++m)
          for (unsigned int n = 0; n < 4; ++n)
            {
              Quaternion<double> em{{0, 0, 0, 0}}, en{{0, 0, 0, 0}};
              em[m] = 1, en[n] = 1;
              const auto p = relative_quaternion(em, s ? quaternion_product(en, *s) : en);
              for (unsigned int k = 0; k < 4; ++k)
                T[k][4 * m + n] = p[k];
            }
        return T;
      };
      static const std::array<std::array<double, 16>, 4> plain = bilinear(nullptr);
      const std::array<std::array<double, 16>, 4>        T     = seam ? bilinear(seam) : plain;
      std::array<double, 4>                              p{};
      std::array<std::array<double, 8>, 4>               p_y{}; // in (q_a, q_b)
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int m = 0; m < 4; ++m)
          for (unsigned int n = 0; n < 4; ++n)
            {
              const double t = T[k][4 * m + n];
              p[k] += x[m] * t * x[4 + n];
              p_y[k][m] += t * x[4 + n];
              p_y[k][4 + n] += x[m] * t;
            }
      std::array<std::array<double, 4>, 3>  Th_p;
      std::array<std::array<double, 16>, 3> Th_pp;
      log_of_quaternion_derivatives(p, with_hessian, theta, Th_p, Th_pp);
      for (unsigned int i = 0; i < 3; ++i)
        {
          for (unsigned int a = 0; a < 8; ++a)
            {
              double w = 0;
              for (unsigned int k = 0; k < 4; ++k)
                w += Th_p[i][k] * p_y[k][a];
              dtheta[i][a] = w;
            }
          if (!with_hessian)
            continue;
          std::array<std::array<double, 8>, 4> Tp{}; // Theta_pp p_y
          for (unsigned int k = 0; k < 4; ++k)
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int l = 0; l < 4; ++l)
                Tp[k][a] += Th_pp[i][4 * k + l] * p_y[l][a];
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int b = 0; b < 8; ++b)
              {
                double w = 0;
                for (unsigned int k = 0; k < 4; ++k)
                  w += p_y[k][a] * Tp[k][b];
                ddtheta[i][8 * a + b] = w;
              }
          for (unsigned int k = 0; k < 4; ++k)
            for (unsigned int m = 0; m < 4; ++m)
              for (unsigned int n = 0; n < 4; ++n)
                {
                  const double c = Th_p[i][k] * T[k][4 * m + n];
                  ddtheta[i][8 * m + 4 + n] += c;
                  ddtheta[i][8 * (4 + n) + m] += c;
                }
        }
    }

    HelicoidalStrainDerivatives
    helicoidal_strain_derivatives(const std::array<double, 6> &z, const double h, const bool with_hessian)
    {
      // nu h = u - a/2 + gamma(|theta|^2) b, a = theta x u,
      // b = theta x a = theta (theta . u) - u |theta|^2; kappa h = theta.
      HelicoidalStrainDerivatives d;
      d.z = z, d.h = h;
      const double *th = &z[0], *u = &z[3];
      for (unsigned int i = 0; i < 3; ++i)
        d.tu += th[i] * u[i], d.t2 += th[i] * th[i];
      std::array<double, 1> dgamma, ddgamma{};
      materials::internal::differentiate<1>(
          std::array<double, 1>{{d.t2}},
          [](const auto &x) { return internal::left_jacobian_inverse_coefficient(x[0]); }, with_hessian, d.gamma,
          dgamma, ddgamma);
      d.dgamma = dgamma[0], d.ddgamma = ddgamma[0];
      const std::array<double, 3> a{
          {th[1] * u[2] - th[2] * u[1], th[2] * u[0] - th[0] * u[2], th[0] * u[1] - th[1] * u[0]}};
      for (unsigned int i = 0; i < 3; ++i)
        d.b[i] = th[i] * d.tu - u[i] * d.t2;
      for (unsigned int i = 0; i < 3; ++i)
        {
          d.strains[i]     = (u[i] - 0.5 * a[i] + d.gamma * d.b[i]) / h;
          d.strains[3 + i] = th[i] / h;
          d.s_z[3 + i][i]  = 1 / h;
          for (unsigned int k = 0; k < 3; ++k)
            {
              double a_t = 0,
                     a_u = 0; // da_i/dtheta_k = eps_ikj u_j, da_i/du_k = eps_ijk theta_j
              for (unsigned int j = 0; j < 3; ++j)
                a_t += levi_civita[i][k][j] * u[j], a_u += levi_civita[i][j][k] * th[j];
              const double b_t = (i == k ? d.tu : 0.) + th[i] * u[k] - 2 * u[i] * th[k];
              const double b_u = th[i] * th[k] - (i == k ? d.t2 : 0.);
              d.s_z[i][k]      = (-0.5 * a_t + 2 * d.dgamma * th[k] * d.b[i] + d.gamma * b_t) / h;
              d.s_z[i][3 + k]  = ((i == k ? 1. : 0.) - 0.5 * a_u + d.gamma * b_u) / h;
            }
        }
      return d;
    }

    void
    HelicoidalStrainDerivatives::add_second_derivatives(const std::array<double, 6> &c,
                                                        std::array<double, 36>      &H) const
    {
      // (nu_i h)_zz = -a_i,zz / 2 + gamma_zz b_i + gamma_z b_i,z^T + b_i,z
      // gamma_z^T + gamma b_i,zz with gamma_theta = 2 gamma' theta, gamma_theta
      // theta = 4 gamma'' theta theta^T + 2 gamma' I.
      const double *th = &z[0], *u = &z[3];
      const double  g1 = 2 * dgamma, g2 = 4 * ddgamma;
      for (unsigned int i = 0; i < 3; ++i)
        {
          const double f = c[i] / h;
          if (f == 0)
            continue;
          for (unsigned int k = 0; k < 3; ++k)
            {
              const double b_tk = (i == k ? tu : 0.) + th[i] * u[k] - 2 * u[i] * th[k];
              for (unsigned int l = 0; l < 3; ++l)
                {
                  const double b_tl = (i == l ? tu : 0.) + th[i] * u[l] - 2 * u[i] * th[l];
                  const double b_ul = th[i] * th[l] - (i == l ? t2 : 0.);
                  const double b_tt = (i == k ? u[l] : 0.) + (i == l ? u[k] : 0.) - (k == l ? 2 * u[i] : 0.);
                  H[6 * k + l] += f * ((g2 * th[k] * th[l] + (k == l ? g1 : 0.)) * b[i] + g1 * th[k] * b_tl +
                                       b_tk * g1 * th[l] + gamma * b_tt);
                  const double b_tu = (i == k ? th[l] : 0.) + (k == l ? th[i] : 0.) - (i == l ? 2 * th[k] : 0.);
                  const double m    = f * (-0.5 * levi_civita[i][k][l] + g1 * th[k] * b_ul + gamma * b_tu);
                  H[6 * k + 3 + l] += m;
                  H[6 * (3 + l) + k] += m;
                }
            }
        }
    }
  } // namespace kinematics
} // namespace cosmo
