#ifndef cosmo_kinematics_strip_h
#define cosmo_kinematics_strip_h

#include <cosmo/kinematics/rotation.h>
#include <cosmo/materials/plate_law.h>

#include <array>

/**
 * The helical Cauchy-Born kinematics of a strip (doc/specification/strip.md): a plate whose
 * mid-surface and director are phi(eta, s) = r(s) + R(s) y(eta) and
 * d = R(s) q(eta), with the helix (r, R) of uniform rod strains (nu, kappa).
 * In the rod frame d phi/ds -> nu + kappa x y, d phi/d eta -> y',
 * dd/ds -> kappa x q, dd/d eta -> q'; the plate strains depend on eta alone.
 */
namespace cosmo
{
  namespace kinematics
  {
    /// Local variables at a point of the width line: u (0-2), u' (3-5),
    /// theta1, theta3 (6, 7), their derivatives (8, 9), the strains (10-15);
    /// y = eta E1 + u, q = exp([theta]x) E2 with theta = (theta1, 0, theta3).
    constexpr int strip_local_variables = 16;

    /// The director q = exp([theta]x) E2 of the thickness line, theta = (theta1, 0, theta3).
    inline Tensor<1, 3>
    strip_director(const double theta1, const double theta3)
    {
      Tensor<1, 3> theta;
      theta[0]            = theta1;
      theta[2]            = theta3;
      const Tensor<2, 3> Q = rotation_exp(theta);
      return Tensor<1, 3>({Q[0][1], Q[1][1], Q[2][1]});
    }

    /// a x b of 3-vectors stored as arrays (the strip's kinematics, any number type).
    template <typename Number>
    std::array<Number, 3>
    cross(const std::array<Number, 3> &a, const std::array<Number, 3> &b)
    {
      std::array<Number, 3> c;
      c[0] = a[1] * b[2] - a[2] * b[1];
      c[1] = a[2] * b[0] - a[0] * b[2];
      c[2] = a[0] * b[1] - a[1] * b[0];
      return c;
    }

    /**
     * The director q = R E2 of the thickness line and its derivative along
     * the width q' = R (omega x E2), with R = exp([theta]x), theta = (theta1,
     * 0, theta3), and omega = T(theta) theta' (the right trivialization,
     * rotation_dexp_right). The only transcendental part of the strip's
     * kinematics: strip_energy_derivatives() differentiates it in its own
     * four variables.
     */
    template <typename Number>
    void
    strip_director_and_derivative(const Number &         theta1,
                                  const Number &         theta3,
                                  const Number &         dtheta1,
                                  const Number &         dtheta3,
                                  std::array<Number, 3> &q,
                                  std::array<Number, 3> &q1)
    {
      Tensor<1, 3, Number> theta;
      theta[0]                     = theta1;
      theta[2]                     = theta3;
      const Tensor<2, 3, Number> R = rotation_exp(theta);
      const Tensor<2, 3, Number> T = rotation_dexp_right(theta);
      std::array<Number, 3>      omega;
      for (unsigned int i = 0; i < 3; ++i)
        {
          q[i]     = R[i][1];
          omega[i] = T[i][0] * dtheta1;
          omega[i] += T[i][2] * dtheta3;
        }
      const std::array<Number, 3> w = {{-omega[2], Number(0.), omega[0]}}; // omega x E2
      for (unsigned int i = 0; i < 3; ++i)
        {
          q1[i] = R[i][0] * w[0];
          q1[i] += R[i][2] * w[2];
        }
    }

    /**
       * The plate energy density at one point of the width line, as a
       * function of the local variables z (doc/specification/strip.md, helical Cauchy-Born
       * kinematics): y = eta E1 + u, Fp = [y' | nu + kappa x y],
       * q = exp([theta]x) E2, grad d = [q' | kappa x q]; the bending
       * measures are taken relative to the plate's natural curvature
       * (k11, k22, k12 in the (eta, s) frame; zero for a flat plate).
       */
      template <typename Number>
      Number
      strip_energy(const std::array<Number, strip_local_variables> &z,
                   const double                       eta,
                   const materials::PlateLawAt &  law,
                   const bool                         membrane_bending,
                   const std::array<double, 3> &      natural_curvature = {{0., 0., 0.}})
      {
        using V = std::array<Number, 3>;
        const V y  = {{eta + z[0], z[1], z[2]}};
        const V y1 = {{1. + z[3], z[4], z[5]}};
        const V nu = {{z[10], z[11], z[12]}}, kappa = {{z[13], z[14], z[15]}};
        V q, q1;
        strip_director_and_derivative(z[6], z[7], z[8], z[9], q, q1);
        V b = cross(kappa, y);
        for (unsigned int i = 0; i < 3; ++i)
          b[i] += nu[i];
        const V    q2 = cross(kappa, q);
        auto       s  = materials::plate_strains(y1, b, q, q1, q2);
        for (unsigned int k = 0; k < 3; ++k)
          s.bending[k] -= natural_curvature[k];
        return membrane_bending ? law.membrane_bending_energy(s) : law.shear_energy(s);
      }

    /**
     * Value W, gradient g and (if with_hessian) Hessian H (row-major) of
     * strip_energy() in its 16 local variables: what nested forward AD of
     * strip_energy in 16 variables gives (materials::internal::differentiate),
     * by the chain rule W = w(s(V(z))) instead, at a sixth of the cost
     * (benchmarks/README.md):
     *  - V = (a1, a2, d, d1, d2), the five vectors plate_strains() takes;
     *    V(z) is linear or bilinear in z but for the director (q, q'), which
     *    is differentiated by AD in its four variables (theta, theta');
     *  - s(V), the eight plate measures, each a dot product of two of the
     *    vectors: the gradient by first-order AD, the (constant) Hessians
     *    once by nested AD, so plate_strains() stays the one formula;
     *  - w(s), the law, by nested AD in the eight measures.
     * Then g = V_z^T w_V, H = V_z^T w_VV V_z + sum_i w_{V_i} (V_i)_zz.
     * The natural curvature is taken off the bending measures, as in strip_energy().
     * Checked against the nested AD of strip_energy (tests/kinematics.cc).
     */
    void
    strip_energy_derivatives(const std::array<double, strip_local_variables> &z,
                             double                                          eta,
                             const materials::PlateLawAt &               law,
                             bool                                            membrane_bending,
                             bool                                            with_hessian,
                             double &                                        W,
                             std::array<double, strip_local_variables> &     g,
                             std::array<double, strip_local_variables * strip_local_variables> &H,
                             const std::array<double, 3> &natural_curvature = {{0., 0., 0.}});

  } // namespace kinematics
} // namespace cosmo

#endif
