// The rod's element kernel (element.h): the helicoidal element's energy,
// its gradient and Hessian in (chord, q_a, q_b) by the chain rule through
// (theta, u), and the reference nested AD of the whole element.
#include <cosmo/kinematics/rod_element_derivatives.h>
#include <cosmo/materials/energy_derivatives.h>

#include "element.h"

#include <cstdlib>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      template <typename Number>
      kinematics::Quaternion<Number>
      as_numbers(const kinematics::Quaternion<double> &q)
      {
        return {{Number(q[0]), Number(q[1]), Number(q[2]), Number(q[3])}};
      }

      /**
       * The element's energy: h psi(strains) of the law at its midpoint's
       * natural state, minus the dead loads' work, plus (k/2)(|q|^2 - 1)^2 of
       * the nodes it owns. The penalty holds the quaternions' norm, which no
       * other term sees (R depends on q/|q|): the Hessian gains one positive
       * eigenvalue per node along q, where it had a zero one, so the inertia
       * is the rod's (doc/theory-rod.md 3).
       */
      template <typename Number>
      Number
      element_energy(const std::array<Number, n_ad> &    y,
                     const RodElementData &              d,
                     const materials::RodLaw &           law,
                     const materials::RodNaturalState &  natural,
                     const unsigned int                  e)
      {
        // y holds the chord r_b - r_a and the quaternions: the positions
        // enter the strains through the chord alone, and the dead loads,
        // linear in them, are added outside the differentiation.
        Tensor<1, 3, Number>           chord;
        kinematics::Quaternion<Number> q_a, q_b;
        for (unsigned int i = 0; i < 3; ++i)
          chord[i] = y[i];
        for (unsigned int i = 0; i < 4; ++i)
          {
            q_a[i] = y[3 + i];
            q_b[i] = y[7 + i];
          }
        const bool seam = d.ring && e + 1 == d.n_elements;
        const auto q_b_seen = seam ? kinematics::quaternion_product(q_b, as_numbers<Number>(d.seam)) : q_b;
        Number W = d.h * materials::grown_rod_energy(
                           law, kinematics::helicoidal_strains(Tensor<1, 3, Number>(), q_a, chord, q_b_seen, d.h), natural);
        // (returns a Number, not a Sacado expression of its local m)
        auto penalty = [&](const kinematics::Quaternion<Number> &q) -> Number {
          const Number m = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] - 1.;
          return 0.5 * d.penalty * m * m;
        };
        W += penalty(q_a);
        if (!d.ring && e + 1 == d.n_elements)
          W += penalty(q_b);
        if (e == 0 && d.spin_gauge)
          {
            // A penalty on a symmetry's orbit: zero at equilibrium, where the
            // rest of the energy does not change along the spin; the spin's
            // zero eigenvalue becomes positive and no other changes sign
            // (doc/theory-rod.md 5).
            const auto p    = kinematics::quaternion_product(q_a, as_numbers<Number>(d.reference_0_conjugate));
            Number     spin = p[1] * d.spin_axis[0];
            spin += p[2] * d.spin_axis[1];
            spin += p[3] * d.spin_axis[2];
            W += 0.5 * d.penalty * spin * spin;
          }
        return W;
      }

      /// The strain variables z = (theta, u) of an element, their first and
      /// (with_hessian) second derivatives in y = (c, q_a, q_b).
      struct StrainVariables
      {
        std::array<double, 6>                   z;
        std::array<std::array<double, n_ad>, 6> z_y{};
        std::array<std::array<double, 64>, 3>   theta_qq; ///< in (q_a, q_b), y[3..10]
        std::array<std::array<double, 49>, 3>   u_cq;     ///< in (c, q_a), y[0..6]
      };

      /// theta = log(conj(q_a) q_b s) (s: a ring's seam) and u = R(q_a)^T c
      /// with their derivatives in y = (c, q_a, q_b).
      StrainVariables
      strain_variables(const std::array<double, n_ad> &y, const RodElementData &d, const unsigned int e,
                       const bool with_hessian)
      {
        const bool seam = d.ring && e + 1 == d.n_elements;
        StrainVariables                      v;
        std::array<double, 8>                xq;
        std::array<double, 3>                th, u;
        std::array<std::array<double, 8>, 3> dth;
        std::array<std::array<double, 7>, 3> du;
        std::array<double, 7>                xu;
        std::copy(y.begin() + 3, y.end(), xq.begin());
        std::copy(y.begin(), y.begin() + 7, xu.begin());
        kinematics::relative_rotation_derivatives(xq, seam ? &d.seam : nullptr, with_hessian, th, dth, v.theta_qq);
        kinematics::chord_in_frame_derivatives(xu, with_hessian, u, du, v.u_cq);
        for (unsigned int i = 0; i < 3; ++i)
          {
            v.z[i]     = th[i];
            v.z[3 + i] = u[i];
            for (unsigned int a = 0; a < 8; ++a)
              v.z_y[i][3 + a] = dth[i][a];
            for (unsigned int a = 0; a < 7; ++a)
              v.z_y[3 + i][a] = du[i][a];
          }
        return v;
      }

      /// W_y = z_y^T W_z and W_yy = z_y^T W_zz z_y + sum_m W_z_m (z_m)_yy
      /// (the upper triangle).
      void
      pull_back_to_chord_and_quaternions(const StrainVariables &         v,
                                         const std::array<double, 6> &   gz,
                                         const std::array<double, 36> &  Hz,
                                         const bool                      with_hessian,
                                         std::array<double, n_ad> &      G,
                                         std::array<double, n_ad * n_ad> &H)
      {
        for (unsigned int a = 0; a < n_ad; ++a)
          {
            double w = 0;
            for (unsigned int m = 0; m < 6; ++m)
              w += gz[m] * v.z_y[m][a];
            G[a] = w;
          }
        if (!with_hessian)
          return;
        std::array<std::array<double, n_ad>, 6> T{}; // W_zz z_y
        for (unsigned int m = 0; m < 6; ++m)
          for (unsigned int b = 0; b < n_ad; ++b)
            for (unsigned int n = 0; n < 6; ++n)
              T[m][b] += Hz[6 * m + n] * v.z_y[n][b];
        for (unsigned int a = 0; a < n_ad; ++a)
          for (unsigned int b = a; b < n_ad; ++b)
            {
              double w = 0;
              for (unsigned int m = 0; m < 6; ++m)
                w += v.z_y[m][a] * T[m][b];
              H[n_ad * a + b] = w;
            }
        for (unsigned int i = 0; i < 3; ++i)
          {
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int b = a; b < 8; ++b)
                H[n_ad * (3 + a) + 3 + b] += gz[i] * v.theta_qq[i][8 * a + b];
            for (unsigned int a = 0; a < 7; ++a)
              for (unsigned int b = a; b < 7; ++b)
                H[n_ad * a + b] += gz[3 + i] * v.u_cq[i][7 * a + b];
          }
      }

      /// The quaternions' norm penalty of the nodes the element owns and the
      /// spin gauge (element_energy's), in closed form, added to W, G, H.
      void
      add_penalties(const std::array<double, n_ad> &y, const RodElementData &d, const unsigned int e,
                    const bool with_hessian, double &W, std::array<double, n_ad> &G,
                    std::array<double, n_ad * n_ad> &H)
      {
        // (1/2) k (|q|^2 - 1)^2 (offset 3 or 7 in y), (1/2) k s^2 of s = a . q_a.
        auto add = [&](const unsigned int o, const double m, const std::array<double, 4> &grad_m,
                       const bool quadratic) {
          W += 0.5 * d.penalty * m * m;
          for (unsigned int k = 0; k < 4; ++k)
            {
              G[o + k] += d.penalty * m * grad_m[k];
              if (with_hessian)
                for (unsigned int l = k; l < 4; ++l)
                  H[n_ad * (o + k) + o + l] +=
                    d.penalty * (grad_m[k] * grad_m[l] + (!quadratic && k == l ? 2 * m : 0.));
            }
        };
        auto add_norm_penalty = [&](const unsigned int o) {
          double                m = -1;
          std::array<double, 4> grad_m;
          for (unsigned int k = 0; k < 4; ++k)
            {
              m += y[o + k] * y[o + k];
              grad_m[k] = 2 * y[o + k];
            }
          add(o, m, grad_m, false);
        };
        add_norm_penalty(3);
        if (!d.ring && e + 1 == d.n_elements)
          add_norm_penalty(7);
        if (e == 0 && d.spin_gauge)
          {
            std::array<double, 4> a{};
            for (unsigned int k = 0; k < 4; ++k)
              {
                kinematics::Quaternion<double> unit{{0, 0, 0, 0}};
                unit[k]      = 1;
                const auto p = kinematics::quaternion_product(unit, d.reference_0_conjugate);
                for (unsigned int i = 0; i < 3; ++i)
                  a[k] += p[1 + i] * d.spin_axis[i];
              }
            double spin = 0;
            for (unsigned int k = 0; k < 4; ++k)
              spin += a[k] * y[3 + k];
            add(3, spin, a, true);
          }
      }

      /**
       * W = h g psi(e) of z = (theta, u) and its derivatives in z through
       * the strains s(z) (kinematics::helicoidal_strain_derivatives). The law
       * gives psi's gradient and Hessian at e = w (s/g - s0) (rod_law.h), so
       * W_s = h w psi_e and W_ss = h w w^T psi_ee / g; then
       *   W_z = W_s s_z,   W_zz = s_z^T W_ss s_z + sum_k W_s_k (s_k)_zz.
       * (The nested AD of the whole element, COSMO_NESTED_AD, is the
       * reference: tests/rod_validation.py 'chain_rule'.)
       */
      void
      energy_in_strain_variables(const std::array<double, 6> &z, const double h, const materials::RodLaw &law,
                                 const materials::RodNaturalState &natural, const bool with_hessian, double &W,
                                 std::array<double, 6> &gz, std::array<double, 36> &Hz)
      {
        const auto             s = kinematics::helicoidal_strain_derivatives(z, h, with_hessian);
        const auto             e = materials::elastic_rod_strains(s.strains, natural);
        std::array<double, 6>  dpsi{};
        std::array<double, 36> ddpsi{};
        double                 psi = 0;
        law.energy_derivatives_at(natural.parameter, e, with_hessian, psi, dpsi, ddpsi);
        W = h * natural.growth * psi;
        std::array<double, 6> W_s;
        for (unsigned int k = 0; k < 6; ++k)
          W_s[k] = h * natural.weights[k] * dpsi[k];
        for (unsigned int c = 0; c < 6; ++c)
          {
            double w = 0;
            for (unsigned int k = 0; k < 6; ++k)
              w += W_s[k] * s.s_z[k][c];
            gz[c] = w;
          }
        if (!with_hessian)
          return;
        std::array<std::array<double, 6>, 6> T{}; // W_ss s_z
        for (unsigned int k = 0; k < 6; ++k)
          for (unsigned int l = 0; l < 6; ++l)
            if (const double w = h * natural.weights[k] * natural.weights[l] * ddpsi[6 * k + l] / natural.growth; w != 0)
              for (unsigned int c = 0; c < 6; ++c)
                T[k][c] += w * s.s_z[l][c];
        for (unsigned int c = 0; c < 6; ++c)
          for (unsigned int r = 0; r < 6; ++r)
            {
              double w = 0;
              for (unsigned int k = 0; k < 6; ++k)
                w += s.s_z[k][c] * T[k][r];
              Hz[6 * c + r] = w;
            }
        s.add_second_derivatives(W_s, Hz);
      }

    } // namespace

    /**
     * The element's energy and its derivatives in y = (chord c, q_a, q_b) by
     * the chain rule through z = (theta, u), what nested AD of the whole
     * energy in 11 variables gives at a tenth of the Jacobian's cost
     * (benchmarks/README.md):
     *  - theta(q_a, q_b) and u(c, q_a) with their derivatives in closed
     *    form (kinematics/rod_element_derivatives.h; strain_variables());
     *  - h psi(strains(theta, u)) and its derivatives in z through the
     *    strains' (energy_in_strain_variables());
     *  - W_y = z_y^T W_z, W_yy = z_y^T W_zz z_y + sum_m W_z_m (z_m)_yy;
     *  - the quaternions' norm penalty and the spin gauge in closed form.
     * Checked against the nested AD of element_energy (COSMO_NESTED_AD,
     * tests/rod_validation.py case 'chain_rule').
     */
    void
    element_energy_derivatives(const std::array<double, n_ad> &   y,
                               const RodElementData &             d,
                               const materials::RodLaw &          law,
                               const materials::RodNaturalState & natural,
                               const unsigned int                 e,
                               const bool                         with_hessian,
                               double &                           W,
                               std::array<double, n_ad> &         G,
                               std::array<double, n_ad * n_ad> &  H)
    {
      // COSMO_NESTED_AD: nested AD in all 11 variables, the reference of
      // the chain rule (tests/rod_validation.py 'chain_rule', benchmarks).
      static const bool nested_ad = std::getenv("COSMO_NESTED_AD") != nullptr;
      if (nested_ad)
        {
          materials::internal::differentiate<n_ad>(
            y, [&](const auto &z) { return element_energy(z, d, law, natural, e); }, with_hessian, W, G, H);
          return;
        }
      const StrainVariables  v = strain_variables(y, d, e, with_hessian);
      std::array<double, 6>  gz;
      std::array<double, 36> Hz;
      energy_in_strain_variables(v.z, d.h, law, natural, with_hessian, W, gz, Hz);
      pull_back_to_chord_and_quaternions(v, gz, Hz, with_hessian, G, H);
      add_penalties(y, d, e, with_hessian, W, G, H);
      if (with_hessian)
        for (unsigned int a = 0; a < n_ad; ++a)
          for (unsigned int b = 0; b < a; ++b)
            H[n_ad * a + b] = H[n_ad * b + a];
    }

    /**
     * The dead loads' energy of element e and its gradient in the local
     * (u_a, q_a, u_b, q_b), which they change by a constant: minus the work
     * of the distributed force (its midpoint value, shared by the nodes)
     * and of the forces on free ends, in the displacements.
     */
    double
    load_energy(const std::array<double, 14> &x, const RodElementData &d, const Tensor<1, 3> &f,
                const unsigned int e, std::array<double, 14> &g)
    {
      g.fill(0.);
      double W = 0;
      for (unsigned int i = 0; i < 3; ++i)
        {
          g[i] -= 0.5 * d.h * f[i];
          g[7 + i] -= 0.5 * d.h * f[i];
          if (e == 0 && d.free_end[0])
            g[i] -= d.end_force[0][i];
          if (!d.ring && e + 1 == d.n_elements && d.free_end[1])
            g[7 + i] -= d.end_force[1][i];
          W += g[i] * x[i] + g[7 + i] * x[7 + i];
        }
      return W;
    }

    /// The differentiated variables of an element from its local
    /// (u_a, q_a, u_b, q_b): the chord (the reference's plus u_b - u_a) and
    /// the quaternions.
    std::array<double, n_ad>
    chord_variables(const std::array<double, n_local> &x, const Tensor<1, 3> &reference_chord)
    {
      std::array<double, n_ad> y;
      for (unsigned int i = 0; i < 3; ++i)
        y[i] = reference_chord[i] + (x[7 + i] - x[i]);
      for (unsigned int k = 0; k < 4; ++k)
        {
          y[3 + k] = x[3 + k];
          y[7 + k] = x[10 + k];
        }
      return y;
    }

    /// The gradient and Hessian in the 11 variables added to those in the
    /// local unknowns: u_a enters the chord with -1, u_b with +1.
    void
    spread_to_nodes(const std::array<double, n_ad> &       gy,
                    const std::array<double, n_ad * n_ad> &Hy,
                    const bool                             jacobian,
                    std::array<double, n_local> &          g,
                    std::array<double, n_local * n_local> &H)
    {
      static constexpr std::array<unsigned int, n_local> index{{0, 1, 2, 3, 4, 5, 6, 0, 1, 2, 7, 8, 9, 10}};
      static constexpr std::array<double, n_local>       sign{{-1, -1, -1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}};
      for (unsigned int a = 0; a < n_local; ++a)
        g[a] += sign[a] * gy[index[a]];
      if (jacobian)
        for (unsigned int a = 0; a < n_local; ++a)
          for (unsigned int b = 0; b < n_local; ++b)
            H[n_local * a + b] = sign[a] * sign[b] * Hy[n_ad * index[a] + index[b]];
    }

    /// The force and moment conjugate to a node's (r, q) gradient: the
    /// moment of a rotation delta_phi in the fixed axes, q -> (1, delta_phi/2) q.
    std::array<double, 6>
    nodal_load(const double *g, const kinematics::Quaternion<double> &q)
    {
      std::array<double, 6> load{};
      for (unsigned int i = 0; i < 3; ++i)
        {
          load[i] = g[i];
          kinematics::Quaternion<double> e{{0, 0, 0, 0}};
          e[i + 1]      = 1;
          const auto eq = kinematics::quaternion_product(e, q);
          for (unsigned int k = 0; k < 4; ++k)
            load[3 + i] += 0.5 * g[3 + k] * eq[k];
        }
      return load;
    }
  } // namespace rod
} // namespace cosmo
