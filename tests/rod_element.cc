// Unit tests of the helicoidal rod element (kinematics/rod_element.h): a
// constant-strain state is reproduced exactly whatever the element's length
// and rotation, no rigid motion changes a strain, the quaternions' scale and
// sign do not matter, the series meet their closed forms, and Sacado's
// derivatives of an element's energy agree with differences.
#include <deal.II/base/tensor.h>

#include <cosmo/kinematics/rod_element.h>
#include <cosmo/materials/energy_derivatives.h>

#include "test_tools.h"

#include <cmath>
#include <random>

using namespace dealii;
using namespace cosmo::kinematics;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  std::mt19937 rng(12345);

  double
  uniform(const double a, const double b)
  {
    return std::uniform_real_distribution<double>(a, b)(rng);
  }

  Tensor<1, 3>
  random_vector(const double scale)
  {
    Tensor<1, 3> v;
    for (unsigned int i = 0; i < 3; ++i)
      v[i] = uniform(-scale, scale);
    return v;
  }

  /// exp of the 4x4 twist matrix [[h [kappa]x, h nu], [0, 0]] by scaling
  /// and squaring of its Taylor series: independent of J_L's closed form.
  std::array<std::array<double, 4>, 4>
  twist_exponential(const Tensor<1, 3> &nu, const Tensor<1, 3> &kappa, const double h)
  {
    using M = std::array<std::array<double, 4>, 4>;
    M A{};
    const Tensor<2, 3> K = skew(kappa);
    for (unsigned int i = 0; i < 3; ++i)
      {
        for (unsigned int j = 0; j < 3; ++j)
          A[i][j] = h * K[i][j];
        A[i][3] = h * nu[i];
      }
    // Scale to a norm below 1/4: the series then converges to round-off in
    // 25 terms, and each squaring doubles the error, so use as few as needed.
    double norm = 0;
    for (const auto &row : A)
      for (const double x : row)
        norm = std::max(norm, std::abs(x));
    const unsigned int squarings = norm > 0.25 ? static_cast<unsigned int>(std::ceil(std::log2(4 * norm))) : 0;
    for (auto &row : A)
      for (auto &x : row)
        x /= double(1u << squarings);
    auto product = [](const M &a, const M &b) {
      M c{};
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int j = 0; j < 4; ++j)
          for (unsigned int k = 0; k < 4; ++k)
            c[i][j] += a[i][k] * b[k][j];
      return c;
    };
    M E{}, term{};
    for (unsigned int i = 0; i < 4; ++i)
      E[i][i] = term[i][i] = 1;
    for (unsigned int n = 1; n < 25; ++n)
      {
        term = product(term, A);
        for (auto &row : term)
          for (auto &x : row)
            x /= n;
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            E[i][j] += term[i][j];
      }
    for (unsigned int s = 0; s < squarings; ++s)
      E = product(E, E);
    return E;
  }

  /// A random quaternion of R scaled by a random factor and sign.
  Quaternion<double>
  scrambled(const Tensor<2, 3> &R)
  {
    auto         q = quaternion_of_rotation(R);
    const double f = uniform(0.5, 2.) * (uniform(0, 1) < 0.5 ? -1 : 1);
    for (auto &x : q)
      x *= f;
    return q;
  }

  // Nodes placed on H_a exp(h xi): the element's strains are xi, for
  // rotations h |kappa| up to 2.8 rad, with shear and stretch.
  void
  constant_strain_exact()
  {
    double worst = 0;
    for (unsigned int trial = 0; trial < 200; ++trial)
      {
        const double       h     = uniform(0.01, 3.);
        const Tensor<1, 3> kappa = random_vector(1.) * (uniform(0, 2.8) / h / std::sqrt(3.));
        Tensor<1, 3>       nu    = random_vector(0.3);
        nu[2] += 1;
        const Tensor<2, 3> R_a = rotation_exp(random_vector(3.));
        const Tensor<1, 3> r_a = random_vector(2.);
        const auto         E   = twist_exponential(nu, kappa, h);
        Tensor<2, 3>       R_rel, R_b;
        Tensor<1, 3>       u;
        for (unsigned int i = 0; i < 3; ++i)
          {
            u[i] = E[i][3];
            for (unsigned int j = 0; j < 3; ++j)
              R_rel[i][j] = E[i][j];
          }
        R_b                    = R_a * R_rel;
        const Tensor<1, 3> r_b = r_a + R_a * u;
        const auto e = helicoidal_strains(r_a, scrambled(R_a), r_b, scrambled(R_b), h);
        for (unsigned int i = 0; i < 3; ++i)
          {
            worst = std::max(worst, std::abs(e[i] - nu[i]) / nu.norm());
            worst = std::max(worst, std::abs(e[3 + i] - kappa[i]) / std::max(kappa.norm(), 1e-300));
          }
      }
    // Round-off of the 4x4 exponential (up to 4 squarings) and of the
    // element: measured 1e-14 to 1e-13 over these elements.
    check_close("constant strains reproduced (200 random elements)", worst, 0, 0, 1e-12);
  }

  // A rigid motion (Q, c) of both nodes changes no strain.
  void
  objectivity()
  {
    double worst = 0;
    for (unsigned int trial = 0; trial < 200; ++trial)
      {
        const double       h   = uniform(0.05, 1.);
        const Tensor<2, 3> R_a = rotation_exp(random_vector(3.)), R_b = R_a * rotation_exp(random_vector(0.8));
        const Tensor<1, 3> r_a = random_vector(1.), r_b = r_a + random_vector(h);
        const Tensor<2, 3> Q = rotation_exp(random_vector(3.));
        const Tensor<1, 3> c = random_vector(5.);
        const auto e  = helicoidal_strains(r_a, scrambled(R_a), r_b, scrambled(R_b), h);
        const auto e2 = helicoidal_strains(Tensor<1, 3>(Q * r_a + c), scrambled(Q * R_a),
                                           Tensor<1, 3>(Q * r_b + c), scrambled(Q * R_b), h);
        double scale = 0;
        for (const double x : e)
          scale = std::max(scale, std::abs(x));
        for (unsigned int i = 0; i < 6; ++i)
          worst = std::max(worst, std::abs(e[i] - e2[i]) / scale);
      }
    check_close("objectivity: rigid motions change no strain", worst, 0, 0, 1e-13);
  }

  // The series and closed forms meet where they switch, and the
  // quaternion conversions invert each other.
  void
  series_and_conversions()
  {
    using namespace cosmo::kinematics::internal;
    const double t2 = 0.5, t = std::sqrt(t2);
    check_close("gamma series at t^2 = 0.5", left_jacobian_inverse_coefficient(0.5 - 1e-15),
                (1 - 0.5 * t / std::tan(0.5 * t)) / t2, 1e-14);
    check_close("atan ratio series at s = 0.01", atan_ratio(0.01 - 1e-17), std::atan(0.1) / 0.1, 1e-15);
    double worst = 0;
    for (unsigned int trial = 0; trial < 100; ++trial)
      {
        const Tensor<2, 3> R = rotation_exp(random_vector(3.));
        const Tensor<2, 3> back = quaternion_rotation(scrambled(R));
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            worst = std::max(worst, std::abs(R[i][j] - back[i][j]));
        const Tensor<1, 3> phi = random_vector(2.);
        const Tensor<2, 3> R2  = quaternion_rotation(quaternion_of_rotation_vector(phi)), E = rotation_exp(phi);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            worst = std::max(worst, std::abs(R2[i][j] - E[i][j]));
      }
    check_close("quaternion <-> rotation round trips", worst, 0, 0, 1e-14);
  }

  // Sacado's gradient and Hessian of a coupled quadratic energy of the
  // strains against central differences (step 1e-6: truncation ~1e-12,
  // round-off ~1e-10 of the scale).
  void
  derivatives_against_differences()
  {
    std::array<double, 36> K{};
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        K[6 * a + b] = (a == b ? 3. : 0.) + 0.4 / (1. + a + b);
    const double h      = 0.3;
    auto         energy = [&](const auto &x) {
      using Number = std::decay_t<decltype(x[0])>;
      Tensor<1, 3, Number> r_a, r_b;
      Quaternion<Number>   q_a, q_b;
      for (unsigned int i = 0; i < 3; ++i)
        {
          r_a[i] = x[i];
          r_b[i] = x[7 + i];
        }
      for (unsigned int i = 0; i < 4; ++i)
        {
          q_a[i] = x[3 + i];
          q_b[i] = x[10 + i];
        }
      auto   e = helicoidal_strains(r_a, q_a, r_b, q_b, h);
      e[2] -= 1.;
      Number W = 0.;
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          W += 0.5 * K[6 * a + b] * e[a] * e[b];
      return W;
    };
    std::array<double, 14> x;
    const auto q_a = quaternion_of_rotation(rotation_exp(random_vector(1.)));
    const auto q_b = quaternion_of_rotation(rotation_exp(random_vector(1.)));
    for (unsigned int i = 0; i < 3; ++i)
      {
        x[i]     = uniform(-0.1, 0.1);
        x[7 + i] = x[i] + uniform(-0.1, 0.1);
      }
    x[9] += h;
    for (unsigned int i = 0; i < 4; ++i)
      {
        x[3 + i]  = q_a[i];
        x[10 + i] = q_b[i];
      }
    double                  W;
    std::array<double, 14>  g;
    std::array<double, 196> H;
    cosmo::materials::internal::differentiate<14>(x, energy, true, W, g, H);
    double gerr = 0, herr = 0, gscale = 0, hscale = 0;
    const double d = 1e-6;
    for (unsigned int i = 0; i < 14; ++i)
      {
        auto xp = x, xm = x;
        xp[i] += d;
        xm[i] -= d;
        double                  Wp, Wm;
        std::array<double, 14>  gp, gm;
        std::array<double, 196> unused;
        cosmo::materials::internal::differentiate<14>(xp, energy, false, Wp, gp, unused);
        cosmo::materials::internal::differentiate<14>(xm, energy, false, Wm, gm, unused);
        gerr   = std::max(gerr, std::abs((Wp - Wm) / (2 * d) - g[i]));
        gscale = std::max(gscale, std::abs(g[i]));
        for (unsigned int j = 0; j < 14; ++j)
          {
            herr   = std::max(herr, std::abs((gp[j] - gm[j]) / (2 * d) - H[14 * i + j]));
            hscale = std::max(hscale, std::abs(H[14 * i + j]));
          }
      }
    check_close("gradient against central differences", gerr / gscale, 0, 0, 1e-7);
    check_close("Hessian against central differences", herr / hscale, 0, 0, 1e-7);
  }
} // namespace

int
main()
{
  constant_strain_exact();
  objectivity();
  series_and_conversions();
  derivatives_against_differences();
  return cosmo_test::report();
}
