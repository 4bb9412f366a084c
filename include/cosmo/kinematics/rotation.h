#ifndef cosmo_kinematics_rotation_h
#define cosmo_kinematics_rotation_h

#include <deal.II/base/tensor.h>

#include <cmath>

/**
 * Rotations of the Cosserat director frame: the skew map, the exponential
 * map (Rodrigues) and its inverse, written so that they are exact and
 * differentiable by forward-mode AD at and near zero angle.
 *
 * The Rodrigues coefficients sin(t)/t and (1-cos t)/t^2 are functions of
 * t^2 = theta.theta; they are evaluated by their Taylor series for small
 * t^2, so no square root of zero is ever differentiated (the derivative of
 * sqrt at 0 is infinite and would poison every AD derivative with NaN even
 * though the rotation itself is smooth there).
 */
namespace cosmo
{
  namespace kinematics
  {
    using namespace dealii;

    /// [a]x, the skew matrix with [a]x b = a x b.
    template <typename Number>
    Tensor<2, 3, Number>
    skew(const Tensor<1, 3, Number> &a)
    {
      Tensor<2, 3, Number> A;
      A[0][1] = -a[2];
      A[0][2] = a[1];
      A[1][0] = a[2];
      A[1][2] = -a[0];
      A[2][0] = -a[1];
      A[2][1] = a[0];
      return A;
    }

    /// The axial vector of the skew part of A: axial([a]x) = a.
    template <typename Number>
    Tensor<1, 3, Number>
    axial_vector(const Tensor<2, 3, Number> &A)
    {
      Tensor<1, 3, Number> a;
      a[0] = 0.5 * (A[2][1] - A[1][2]);
      a[1] = 0.5 * (A[0][2] - A[2][0]);
      a[2] = 0.5 * (A[1][0] - A[0][1]);
      return a;
    }

    namespace internal
    {
      /// Below this t^2 the Taylor series (to t^6) is exact in double precision.
      constexpr double series_threshold = 1e-4;

      template <typename Number>
      struct RodriguesCoefficients
      {
        Number a; ///< sin(t)/t
        Number b; ///< (1-cos t)/t^2
        Number c; ///< (t - sin t)/t^3 = (1-a)/t^2
      };

      template <typename Number>
      RodriguesCoefficients<Number>
      rodrigues_coefficients(const Number &t2)
      {
        using std::cos;
        using std::sin;
        using std::sqrt;
        RodriguesCoefficients<Number> r;
        if (t2 < series_threshold)
          {
            r.a = 1. - t2 / 6. * (1. - t2 / 20. * (1. - t2 / 42.));
            r.b = 0.5 - t2 / 24. * (1. - t2 / 30. * (1. - t2 / 56.));
            r.c = 1. / 6. - t2 / 120. * (1. - t2 / 42. * (1. - t2 / 72.));
          }
        else
          {
            const Number t = sqrt(t2);
            r.a            = sin(t) / t;
            r.b            = (1. - cos(t)) / t2;
            r.c            = (1. - r.a) / t2;
          }
        return r;
      }
    } // namespace internal

    /// exp([theta]x) = I + a [theta]x + b [theta]x^2.
    namespace internal
    {
      /// I + a [theta]x + b [theta]x^2, entry by entry: plain Number
      /// arithmetic only, so Sacado's expression templates never meet
      /// dealii::Tensor's scalar products.
      template <typename Number>
      Tensor<2, 3, Number>
      identity_plus_skew_terms(const Tensor<1, 3, Number> &theta,
                               const Number &              a,
                               const Number &              b)
      {
        const Tensor<2, 3, Number> S = skew(theta);
        Tensor<2, 3, Number>       R;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            {
              Number S2 = S[i][0] * S[0][j];
              S2 += S[i][1] * S[1][j];
              S2 += S[i][2] * S[2][j];
              R[i][j] = a * S[i][j] + b * S2;
              if (i == j)
                R[i][j] += 1.;
            }
        return R;
      }

      template <typename Number>
      Number
      squared_norm(const Tensor<1, 3, Number> &v)
      {
        Number n = v[0] * v[0];
        n += v[1] * v[1];
        n += v[2] * v[2];
        return n;
      }
    } // namespace internal

    /// exp([theta]x) = I + a [theta]x + b [theta]x^2.
    template <typename Number>
    Tensor<2, 3, Number>
    rotation_exp(const Tensor<1, 3, Number> &theta)
    {
      const auto co = internal::rodrigues_coefficients<Number>(internal::squared_norm(theta));
      return internal::identity_plus_skew_terms(theta, co.a, co.b);
    }

    /**
     * Right Jacobian of the exponential map: with R = exp([theta]x),
     * d/de exp([theta + e delta]x) |_{e=0} = R [T(theta) delta]x,
     * T = I - b [theta]x + c [theta]x^2.
     */
    template <typename Number>
    Tensor<2, 3, Number>
    rotation_dexp_right(const Tensor<1, 3, Number> &theta)
    {
      const auto co = internal::rodrigues_coefficients<Number>(internal::squared_norm(theta));
      return internal::identity_plus_skew_terms(theta, Number(-co.b), co.c);
    }

    /**
     * The rotation vector theta, |theta| in [0, pi], with exp([theta]x) = R.
     * The angle is taken by atan2 of sine and cosine (well conditioned for
     * every angle); near pi the axis comes from the symmetric part of R.
     */
    template <typename Number>
    Tensor<1, 3, Number>
    rotation_log(const Tensor<2, 3, Number> &R)
    {
      using std::atan2;
      using std::sqrt;
      const Tensor<1, 3, Number> v  = axial_vector(R); // sin(t) n
      const Number               s2 = v * v;
      const Number               c  = 0.5 * (trace(R) - 1.);
      if (s2 < internal::series_threshold && c > 0.)
        {
          // t/sin(t) as a series in sin^2(t): asin(s)/s.
          const Number f =
            1. + s2 / 6. + 3. / 40. * s2 * s2 + 5. / 112. * s2 * s2 * s2;
          return f * v;
        }
      const Number t = atan2(sqrt(s2), c);
      if (c > -0.9)
        return (t / sqrt(s2)) * v;

      // Near t = pi: n n^T = (sym(R) - c I) / (1 - c); take the largest column.
      Tensor<2, 3, Number> nn;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          nn[i][j] = (0.5 * (R[i][j] + R[j][i]) - (i == j ? c : Number(0.))) / (1. - c);
      unsigned int k = 0;
      for (unsigned int i = 1; i < 3; ++i)
        if (nn[i][i] > nn[k][k])
          k = i;
      Tensor<1, 3, Number> n;
      for (unsigned int i = 0; i < 3; ++i)
        n[i] = nn[i][k] / sqrt(nn[k][k]);
      // Fix the sign of the axis with the (small but informative) skew part.
      if (n * v < 0.)
        n = -n;
      return t * n;
    }
  } // namespace kinematics
} // namespace cosmo

#endif
