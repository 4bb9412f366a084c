#ifndef cosmo_kinematics_rod_element_h
#define cosmo_kinematics_rod_element_h

#include <deal.II/base/tensor.h>

#include <cosmo/kinematics/rotation.h>

#include <array>
#include <cmath>

/**
 * The two-node helicoidal (SE(3)) element of a special Cosserat rod
 * (doc/theory-rod.md 2-3): nodes carry a position r and a rotation, the
 * rotation as a quaternion q in R^4 (any nonzero q; R depends on q/|q|
 * only). The element's strains are constant: the logarithm of the nodes'
 * relative motion H_a^-1 H_b = (R_a^T R_b, R_a^T (r_b - r_a)) divided by
 * the element's reference length h,
 *
 *   kappa h = theta = log(R_a^T R_b),   nu h = J_L(theta)^-1 R_a^T (r_b - r_a),
 *
 * J_L the left Jacobian of SO(3) (the mean of exp(sigma [theta]x) over
 * sigma in [0, 1]; J_L(kappa h) nu h is kinematics::helix_position). A state of constant strains -- any helix, with shear
 * and stretch -- is therefore reproduced exactly on any mesh, and a rigid
 * motion of both nodes changes no strain (H_a^-1 H_b is invariant).
 *
 * Every function is written for Sacado numbers: series below small
 * arguments, so that no square root of zero is differentiated (as
 * rotation.h). The relative rotation must stay below pi per element (its
 * quaternion's scalar part nonzero): relative_rotation_admissible() says so.
 */
namespace cosmo
{
  namespace kinematics
  {
    using namespace dealii;

    template <typename Number>
    using Quaternion = std::array<Number, 4>; ///< (scalar, vector)

    /// a b, the product of quaternions (the rotation of b, then of a).
    template <typename Number>
    Quaternion<Number>
    quaternion_product(const Quaternion<Number> &a, const Quaternion<Number> &b)
    {
      return {{a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
               a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
               a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
               a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]}};
    }

    /// conj(a) b: the rotation from a's frame to b's, in a's frame (unnormalized).
    template <typename Number>
    Quaternion<Number>
    relative_quaternion(const Quaternion<Number> &a, const Quaternion<Number> &b)
    {
      return quaternion_product(Quaternion<Number>{{a[0], -a[1], -a[2], -a[3]}}, b);
    }

    /// R(q) = I + 2/|q|^2 (q0 [v]x + [v]x^2): a rational function of q, no normalization.
    template <typename Number>
    Tensor<2, 3, Number>
    quaternion_rotation(const Quaternion<Number> &q)
    {
      const Number               n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      Tensor<1, 3, Number>       v;
      for (unsigned int i = 0; i < 3; ++i)
        v[i] = q[i + 1];
      const Number               a = 2. * q[0] / n2, b = 2. / n2;
      return internal::identity_plus_skew_terms(v, a, b);
    }

    /// The unit quaternion of a turn by 2 pi `turns` about the body axis d3 (a ring's seam).
    inline std::array<double, 4>
    twist_quaternion(const double turns)
    {
      return {{std::cos(M_PI * turns), 0, 0, std::sin(M_PI * turns)}};
    }

    /// The unit quaternion of exp([phi]x) (any angle; data, not unknowns).
    inline Quaternion<double>
    quaternion_of_rotation_vector(const Tensor<1, 3> &phi)
    {
      const double t = phi.norm();
      const double s = t < 1e-8 ? 0.5 - t * t / 48. : std::sin(0.5 * t) / t;
      return {{std::cos(0.5 * t), s * phi[0], s * phi[1], s * phi[2]}};
    }

    /// A unit quaternion of the rotation R (Shepperd's method: the largest pivot).
    Quaternion<double>
    quaternion_of_rotation(const Tensor<2, 3> &R);

    namespace internal
    {
      /// a x b in plain Number arithmetic (as rotation.h: no Tensor products on Sacado numbers).
      template <typename Number>
      Tensor<1, 3, Number>
      cross(const Tensor<1, 3, Number> &a, const Tensor<1, 3, Number> &b)
      {
        Tensor<1, 3, Number> c;
        c[0] = a[1] * b[2] - a[2] * b[1];
        c[1] = a[2] * b[0] - a[0] * b[2];
        c[2] = a[0] * b[1] - a[1] * b[0];
        return c;
      }

      /// atan(sqrt(s))/sqrt(s), by its series below s = 0.01 (9 terms: exact to 1e-18).
      template <typename Number>
      Number
      atan_ratio(const Number &s)
      {
        using std::atan;
        using std::sqrt;
        if (s < 0.01)
          {
            Number r = 1. / 17.;
            for (int k = 7; k >= 0; --k)
              r = 1. / (2 * k + 1) - s * r;
            return r;
          }
        const Number t = sqrt(s);
        return atan(t) / t;
      }

      /**
       * gamma(t^2) = (1 - (t/2) cot(t/2)) / t^2, the coefficient of [theta]x^2
       * in J_L^-1 = I - [theta]x / 2 + gamma [theta]x^2. Below t^2 = 0.5 its
       * series sum |B_2n| t^(2n-2) / (2n)! (8 terms; the ratio of successive
       * terms is about t^2 / (2 pi)^2 < 0.013, so the remainder is below
       * 1e-17); above it the closed form (t < 2 pi).
       */
      template <typename Number>
      Number
      left_jacobian_inverse_coefficient(const Number &t2)
      {
        using std::cos;
        using std::sin;
        using std::sqrt;
        if (t2 < 0.5)
          {
            // |B_2n| / (2n)!, n = 1 ... 8.
            static constexpr double c[8] = {1. / 12.,
                                            1. / 720.,
                                            1. / 30240.,
                                            1. / 1209600.,
                                            1. / 47900160.,
                                            691. / 1307674368000.,
                                            1. / 74724249600.,
                                            3617. / 10670622842880000.};
            Number g = c[7];
            for (int k = 6; k >= 0; --k)
              g = c[k] + t2 * g;
            return g;
          }
        const Number t = sqrt(t2);
        return (1. - 0.5 * t * cos(0.5 * t) / sin(0.5 * t)) / t2;
      }
    } // namespace internal

    /**
     * theta = log(R(p)) for a relative quaternion p (unnormalized) whose
     * rotation is below pi: theta = 2 atan(|w|)/|w| w with w = v/p0, which
     * does not change under p -> -p or a scaling of p.
     */
    template <typename Number>
    Tensor<1, 3, Number>
    relative_rotation_vector(const Quaternion<Number> &p)
    {
      Tensor<1, 3, Number> w;
      for (unsigned int i = 0; i < 3; ++i)
        w[i] = p[i + 1] / p[0];
      const Number f = 2. * internal::atan_ratio(internal::squared_norm(w));
      for (unsigned int i = 0; i < 3; ++i)
        w[i] *= f;
      return w;
    }

    /// Whether the relative rotation of p is below `limit` (< pi): |p0| > cos(limit/2) |p|.
    inline bool
    relative_rotation_admissible(const Quaternion<double> &p, const double limit)
    {
      const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
      return std::abs(p[0]) > std::cos(0.5 * limit) * n;
    }

    /**
     * The strains (nu1, nu2, nu3, kappa1, kappa2, kappa3) of the helicoidal
     * element between nodes (r_a, q_a) and (r_b, q_b) of reference length h,
     * in the director frame (the frame of a, which for a constant-strain
     * element is every frame's: the strains are the same in all).
     */
    template <typename Number>
    std::array<Number, 6>
    helicoidal_strains_of(const Tensor<1, 3, Number> &theta, const Tensor<1, 3, Number> &u, const double h);

    template <typename Number>
    std::array<Number, 6>
    helicoidal_strains(const Tensor<1, 3, Number> &r_a,
                       const Quaternion<Number> &  q_a,
                       const Tensor<1, 3, Number> &r_b,
                       const Quaternion<Number> &  q_b,
                       const double                h)
    {
      const Tensor<1, 3, Number> theta = relative_rotation_vector(relative_quaternion(q_a, q_b));
      const Tensor<2, 3, Number> R_a   = quaternion_rotation(q_a);
      Tensor<1, 3, Number>       u; // R_a^T (r_b - r_a)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          u[i] += R_a[j][i] * (r_b[j] - r_a[j]);
      return helicoidal_strains_of(theta, u, h);
    }

    /**
     * The strains from the relative rotation vector theta = log(R_a^T R_b)
     * and the chord in a's frame u = R_a^T (r_b - r_a): kappa h = theta,
     * nu h = J_L(theta)^-1 u (what helicoidal_strains() computes; apart, so
     * that the element's derivatives can go through (theta, u), the rod
     * application's chain rule).
     */
    template <typename Number>
    std::array<Number, 6>
    helicoidal_strains_of(const Tensor<1, 3, Number> &theta, const Tensor<1, 3, Number> &u, const double h)
    {
      // J_L^-1 u = u - theta x u / 2 + gamma theta x (theta x u).
      const Number               g  = internal::left_jacobian_inverse_coefficient(internal::squared_norm(theta));
      const Tensor<1, 3, Number> tu = internal::cross(theta, u);
      const Tensor<1, 3, Number> ttu = internal::cross(theta, tu);
      std::array<Number, 6>      e;
      for (unsigned int i = 0; i < 3; ++i)
        {
          e[i]     = (u[i] - 0.5 * tu[i] + g * ttu[i]) / h;
          e[i + 3] = theta[i] / h;
        }
      return e;
    }
  } // namespace kinematics
} // namespace cosmo

#endif
