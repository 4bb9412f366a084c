// Unit tests of the kinematics module: rotations and the uniform-strain helix.
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/base/quadrature_lib.h>

#include <cosmo/assembly/assumed_shear.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/kinematics/plate_model.h>
#include <cosmo/kinematics/rod_element_derivatives.h>
#include <cosmo/kinematics/rotation.h>
#include <cosmo/kinematics/strip.h>
#include <cosmo/materials/energy_derivatives.h>
#include <cosmo/materials/plate_laws/linear_isotropic.h>

#include <Sacado.hpp>

#include "test_tools.h"

#include <random>

using namespace dealii;
using namespace cosmo::kinematics;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  double
  max_abs(const Tensor<2, 3> &A)
  {
    double m = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        m = std::max(m, std::abs(A[i][j]));
    return m;
  }

  // Orthogonality and det = 1 of an exponential, and log(exp(theta)) = theta.
  void
  exp_log_round_trip()
  {
    std::cout << "rotation exp/log round trip\n";
    const Tensor<1, 3> axis = Tensor<1, 3>({0.3, -0.5, 0.8}) / Tensor<1, 3>({0.3, -0.5, 0.8}).norm();
    for (const double angle : {0.0, 1e-12, 1e-7, 1e-3, 9.9e-3, 1.01e-2, 0.5, 2.0, 3.0,
                               M_PI - 1e-4, M_PI - 1e-9})
      {
        const Tensor<1, 3> theta = angle * axis;
        const Tensor<2, 3> R     = rotation_exp(theta);
        check_close("|R^T R - I|, angle " + std::to_string(angle),
                    max_abs(transpose(R) * R - unit_symmetric_tensor<3>()), 0, 0, 1e-15);
        check_close("det R, angle " + std::to_string(angle), determinant(R), 1, 1e-14);
        // Near pi the log is ill-conditioned by nature (the axis sign is fixed
        // by a tiny skew part): the error there is eps / (pi - angle).
        const double tol = 1e-14 + 4e-16 / std::max(1e-12, M_PI - angle);
        check_close("|log(exp(theta)) - theta|, angle " + std::to_string(angle),
                    (rotation_log(R) - theta).norm(), 0, 0, tol);
      }
  }

  // The AD derivative of exp is finite at zero angle and matches both the
  // closed-form right Jacobian and central differences everywhere.
  void
  exp_derivative()
  {
    std::cout << "derivative of the exponential map\n";
    using AD = Sacado::Fad::DFad<double>;
    std::mt19937                           gen(42);
    std::uniform_real_distribution<double> dist(-1, 1);
    for (const double scale : {0.0, 1e-6, 1e-2, 0.7, 2.5})
      {
        Tensor<1, 3> theta({dist(gen), dist(gen), dist(gen)});
        theta *= scale;
        Tensor<1, 3, AD> theta_ad;
        for (unsigned int i = 0; i < 3; ++i)
          theta_ad[i] = AD(3, i, theta[i]);
        Tensor<2, 3, AD>   R_ad = rotation_exp(theta_ad);
        const Tensor<2, 3> R    = rotation_exp(theta);
        const Tensor<2, 3> T    = rotation_dexp_right(theta);
        for (unsigned int k = 0; k < 3; ++k)
          {
            Tensor<1, 3> dk;
            dk[k] = 1;
            // Closed form: dR/dtheta_k = R [T e_k]x.
            const Tensor<2, 3> dR_exact = R * skew(Tensor<1, 3>(T * dk));
            const double       h        = 1e-6;
            const Tensor<2, 3> dR_fd =
              (rotation_exp(Tensor<1, 3>(theta + h * dk)) - rotation_exp(Tensor<1, 3>(theta - h * dk))) /
              (2 * h);
            Tensor<2, 3> dR_ad;
            bool         finite = true;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                {
                  dR_ad[i][j] = R_ad[i][j].dx(k);
                  finite      = finite && std::isfinite(dR_ad[i][j]);
                }
            const std::string tag = " (|theta| = " + std::to_string(theta.norm()) + ", k = " +
                                    std::to_string(k) + ")";
            check("AD derivative finite" + tag, finite);
            check_close("|dR_AD - R[T e_k]x|" + tag, max_abs(dR_ad - dR_exact), 0, 0, 1e-14);
            // Central differences: truncation h^2 ~ 1e-12, round-off eps/h ~ 1e-10.
            check_close("|dR_FD - R[T e_k]x|" + tag, max_abs(dR_fd - dR_exact), 0, 0, 1e-9);
          }
      }
  }

  // The closed-form helix against RK4 integration of R' = R [kappa]x, r' = R nu.
  void
  helix_against_integration()
  {
    std::cout << "uniform-strain helix against numerical integration\n";
    const std::vector<std::array<double, 6>> cases = {
      {{0.1, -0.2, 1.1, 0.4, -0.7, 1.3}}, // general
      {{0.0, 0.0, 1.0, 0.0, -0.3, 0.0}},  // planar circle
      {{0.05, 0.0, 0.9, 1e-9, 0, 2e-9}},  // nearly straight (series branch)
      {{0.0, 0.0, 1.0, 0.0, 0.0, 0.0}}};  // straight
    for (const auto &c : cases)
      {
        const RodStrains e(c);
        const double     L = 2.0;
        const unsigned   n = 4000;
        const double     h = L / n;
        Tensor<2, 3>     R = unit_symmetric_tensor<3>();
        Tensor<1, 3>     r;
        const Tensor<2, 3> K = skew(e.kappa);
        // RK4 on the matrix ODE (R, r); the error is ~ h^4 |kappa|^5 ~ 1e-14.
        auto rhs = [&](const Tensor<2, 3> &Rs, Tensor<2, 3> &dR, Tensor<1, 3> &dr) {
          dR = Rs * K;
          dr = Rs * e.nu;
        };
        for (unsigned int s = 0; s < n; ++s)
          {
            Tensor<2, 3> k1R, k2R, k3R, k4R;
            Tensor<1, 3> k1r, k2r, k3r, k4r;
            rhs(R, k1R, k1r);
            rhs(R + 0.5 * h * k1R, k2R, k2r);
            rhs(R + 0.5 * h * k2R, k3R, k3r);
            rhs(R + h * k3R, k4R, k4r);
            R += h / 6 * (k1R + 2 * k2R + 2 * k3R + k4R);
            r += h / 6 * (k1r + 2 * k2r + 2 * k3r + k4r);
          }
        const std::string tag = " (kappa = " + std::to_string(e.kappa.norm()) + ")";
        check_close("|R(L) - R_RK4|" + tag, max_abs(helix_rotation(e.kappa, L) - R), 0, 0, 1e-11);
        check_close("|r(L) - r_RK4|" + tag, (helix_position(e.nu, e.kappa, L) - r).norm(), 0, 0, 1e-11);

        // Helix geometry: every centreline point is at distance `radius`
        // from the axis through the centre, and advances pitch per turn.
        const HelixGeometry g = helix_geometry(e);
        if (g.radius > 0 && g.handedness != 0)
          {
            // Spatial axis at s = 0 is kappa/|kappa|; the centre of the
            // circle traced by r lies at r(0) + radius * (principal normal).
            const double       k    = e.kappa.norm();
            const Tensor<1, 3> a    = e.kappa / k;
            const Tensor<1, 3> vper = e.nu - (e.nu * a) * a;
            const Tensor<1, 3> c    = cross_product_3d(a, vper) / (k); // centre offset
            double             dmax = 0;
            for (double s = 0; s < 3; s += 0.25)
              {
                const Tensor<1, 3> x   = helix_position(e.nu, e.kappa, s) - c;
                const Tensor<1, 3> rad = x - (x * a) * a;
                dmax = std::max(dmax, std::abs(rad.norm() - g.radius));
              }
            check_close("distance of centreline to helix axis = radius (relative)", dmax / g.radius, 0, 0, 1e-12);
            const double s_turn = 2 * M_PI / k;
            const double adv    = (helix_position(e.nu, e.kappa, s_turn) * a);
            check_close("axial advance per turn = pitch", std::abs(adv), g.pitch, 1e-12);
            check("handedness = sign(nu . kappa)",
                  g.handedness == ((e.nu * e.kappa) > 0 ? 1 : -1));
          }
      }
  }
  /// The largest difference of b from a over the largest entry of a.
  double
  relative(const double *a, const double *b, const int n)
  {
    double d = 0, m = 1e-300;
    for (int i = 0; i < n; ++i)
      {
        d = std::max(d, std::abs(a[i] - b[i]));
        m = std::max(m, std::abs(a[i]));
      }
    return d / m;
  }

  /**
   * A plate law no built-in law is: a full 6 x 6 quadratic form in the
   * membrane and bending measures (membrane-bending couplings, as of an
   * unsymmetric laminate) plus a quartic stiffening, and a quartic shear.
   * The kinematics must take it as they take the linear isotropic law: the
   * chain rule through the measures and the nested AD of the law's Taylor
   * form (materials::PlateLawAt) must agree for it too.
   */
  class CoupledQuarticLaw : public cosmo::materials::PlateLaw
  {
  public:
    void
    parse_parameters(ParameterHandler &) override
    {}
    double
    young() const override
    {
      return 1;
    }
    double
    poisson() const override
    {
      return 0.3;
    }
    void
    energy_derivatives(const std::array<double, 8> &s,
                       const double                 h,
                       const cosmo::materials::PlatePart part,
                       const bool                   with_hessian,
                       double &                     W,
                       std::array<double, 8> &      dW,
                       std::array<double, 64> &     ddW) const override
    {
      dW.fill(0.);
      ddW.fill(0.);
      const bool         shear = part == cosmo::materials::PlatePart::transverse_shear;
      const unsigned int first = shear ? 6 : 0, n = shear ? 2 : 6;
      // W = 1/2 s.A s + c/4 (s.s)^2 over the part's measures, A = h (I + B^T B / 4).
      double ss = 0;
      for (unsigned int i = 0; i < n; ++i)
        ss += s[first + i] * s[first + i];
      const double c = 0.7 * h;
      W              = 0.25 * c * ss * ss;
      for (unsigned int i = 0; i < n; ++i)
        {
          for (unsigned int j = 0; j < n; ++j)
            {
              const double A = h * ((i == j ? 1. : 0.) + 0.25 * coupling(i, j));
              W += 0.5 * s[first + i] * A * s[first + j];
              dW[first + i] += A * s[first + j];
              if (with_hessian)
                ddW[8 * (first + i) + first + j] =
                  A + c * ((i == j ? ss : 0.) + 2 * s[first + i] * s[first + j]);
            }
          dW[first + i] += c * ss * s[first + i];
        }
    }

  private:
    // (B^T B)_ij with B_kl = sin(k + 2 l + 1): dense, symmetric, positive semi-definite.
    static double
    coupling(const unsigned int i, const unsigned int j)
    {
      double x = 0;
      for (unsigned int k = 0; k < 6; ++k)
        x += std::sin(k + 2. * i + 1) * std::sin(k + 2. * j + 1);
      return x;
    }
  };

  // The strip energy's chain-rule derivatives (strip_energy_derivatives)
  // against the nested AD of strip_energy in all 16 variables, at random
  // states with large rotations, at theta = 0 exactly (the exponential's
  // series branch), with and without a natural curvature, and for both
  // parts of the energy. The two differ only
  // by the order of the floating-point operations: measured at most 5e-16
  // of each quantity's largest entry; the tolerance 1e-12 is well above
  // that and far below any error of the formulas (a wrong term is O(1)).
  void
  strip_chain_rule(const cosmo::materials::PlateLaw &plate_law, const std::string &name)
  {
    std::cout << "strip energy (" << name << "): chain rule against nested AD in 16 variables\n";
    constexpr int                    N = strip_local_variables;
    const cosmo::materials::PlateLawAt law(plate_law, 0.03);
    std::mt19937                           gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    double                                 worst[3] = {0, 0, 0};
    for (unsigned int sample = 0; sample < 40; ++sample)
      {
        std::array<double, N> z;
        const double          scales[N] = {0.1, 0.1, 0.1, 0.3, 0.3, 0.3, 1.2, 1.2, 2, 2,
                                  0.2, 0.2, 0.2, 1.5, 1.5, 1.5};
        for (int a = 0; a < N; ++a)
          z[a] = scales[a] * u(gen);
        if (sample % 5 == 0)
          z[6] = z[7] = 0;
        const double eta = 0.5 * u(gen);
        // A natural curvature (a saddle, a bilayer) on every other sample.
        const std::array<double, 3> kbar =
          sample % 2 ? std::array<double, 3>{{1.3 * u(gen), 1.3 * u(gen), 1.3 * u(gen)}} :
                       std::array<double, 3>{{0., 0., 0.}};
        for (const bool membrane_bending : {true, false})
          for (const bool hessian : {true, false})
            {
              double                    W0, W1;
              std::array<double, N>     g0, g1;
              std::array<double, N * N> H0{}, H1{};
              cosmo::materials::internal::differentiate<N>(
                z, [&](const auto &x) { return strip_energy(x, eta, law, membrane_bending, kbar); },
                hessian, W0, g0, H0);
              strip_energy_derivatives(z, eta, law, membrane_bending, hessian, W1, g1, H1, kbar);
              worst[0] = std::max(worst[0], relative(&W0, &W1, 1));
              worst[1] = std::max(worst[1], relative(g0.data(), g1.data(), N));
              if (hessian)
                worst[2] = std::max(worst[2], relative(H0.data(), H1.data(), N * N));
            }
      }
    check_close("energy, largest relative difference", worst[0], 0, 0, 1e-12);
    check_close("gradient, largest difference / largest entry", worst[1], 0, 0, 1e-12);
    check_close("Hessian, largest difference / largest entry", worst[2], 0, 0, 1e-12);
  }
  // The rod element's maps in closed form (rod_element_derivatives.h)
  // against the nested AD of the formulas they replace: u = R(q)^T c in
  // (c, q), theta = log(conj(q_a) q_b s) with and without a seam, and the
  // strains s(theta, u) contracted with a random c. Random non-unit
  // quaternions, relative rotations up to ~2.5 rad, theta = 0 exactly on
  // some samples (the series of gamma and of atan(t)/t). Same arithmetic in another order: 1e-12
  // of the largest entry, as the plate's.
  void
  rod_element_maps()
  {
    std::cout << "rod element maps: closed forms against nested AD\n";
    namespace ad = cosmo::materials::internal;
    std::mt19937                           gen(11);
    std::uniform_real_distribution<double> r(-1, 1);
    double                                 worst[3] = {0, 0, 0};
    // (differences over max(largest entry, 1): theta = 0 is a value of the
    // samples, the quantities are of order one)
    auto scaled_difference = [](const double *a, const double *b, const int n) {
      double d = 0, m = 1;
      for (int i = 0; i < n; ++i)
        d = std::max(d, std::abs(a[i] - b[i])), m = std::max(m, std::abs(a[i]));
      return d / m;
    };
    for (unsigned int sample = 0; sample < 60; ++sample)
      {
        std::array<double, 7> xu;
        for (auto &x : xu)
          x = r(gen);
        xu[3] += 1.5; // (a quaternion away from zero, not of unit norm)
        std::array<double, 3>                 u0, u1;
        std::array<std::array<double, 7>, 3>  du0, du1;
        std::array<std::array<double, 49>, 3> ddu0, ddu1;
        ad::differentiate_map<7, 3>(
          xu,
          [](const auto &x, auto &out) {
            using Number = std::decay_t<decltype(x[0])>;
            const auto R = quaternion_rotation(Quaternion<Number>{{x[3], x[4], x[5], x[6]}});
            for (unsigned int i = 0; i < 3; ++i)
              out[i] = R[0][i] * x[0] + R[1][i] * x[1] + R[2][i] * x[2];
          },
          true, u0, du0, ddu0);
        chord_in_frame_derivatives(xu, true, u1, du1, ddu1);
        for (unsigned int i = 0; i < 3; ++i)
          worst[0] = std::max({worst[0], scaled_difference(&u0[i], &u1[i], 1), scaled_difference(du0[i].data(), du1[i].data(), 7),
                               scaled_difference(ddu0[i].data(), ddu1[i].data(), 49)});
        std::array<double, 8> xq;
        for (auto &x : xq)
          x = 0.6 * r(gen);
        xq[0] += 1.2, xq[4] += 1.1;
        if (sample % 7 == 0) // theta = 0 exactly (the series of atan(t)/t)
          for (unsigned int k = 0; k < 4; ++k)
            xq[4 + k] = 0.9 * xq[k];
        const Quaternion<double> seam{{std::cos(0.4), 0, 0, std::sin(0.4)}};
        for (const Quaternion<double> *s : {(const Quaternion<double> *)nullptr, &seam})
          {
            std::array<double, 3>                 t0, t1;
            std::array<std::array<double, 8>, 3>  dt0, dt1;
            std::array<std::array<double, 64>, 3> ddt0, ddt1;
            ad::differentiate_map<8, 3>(
              xq,
              [s](const auto &x, auto &out) {
                using Number = std::decay_t<decltype(x[0])>;
                const Quaternion<Number> a{{x[0], x[1], x[2], x[3]}}, b{{x[4], x[5], x[6], x[7]}};
                Quaternion<Number>       bs = b;
                if (s)
                  bs = quaternion_product(b, Quaternion<Number>{{(*s)[0], (*s)[1], (*s)[2], (*s)[3]}});
                const auto t = relative_rotation_vector(relative_quaternion(a, bs));
                for (unsigned int i = 0; i < 3; ++i)
                  out[i] = t[i];
              },
              true, t0, dt0, ddt0);
            relative_rotation_derivatives(xq, s, true, t1, dt1, ddt1);
            for (unsigned int i = 0; i < 3; ++i)
              worst[1] = std::max({worst[1], scaled_difference(&t0[i], &t1[i], 1), scaled_difference(dt0[i].data(), dt1[i].data(), 8),
                                   scaled_difference(ddt0[i].data(), ddt1[i].data(), 64)});
          }
        std::array<double, 6> z, c;
        for (unsigned int k = 0; k < 6; ++k)
          z[k] = (k < 3 ? 1.5 : 1.) * r(gen), c[k] = r(gen);
        if (sample % 6 == 0)
          z[0] = z[1] = z[2] = 0;
        const double          h = 0.3;
        double                W0;
        std::array<double, 6> g0, g1{};
        std::array<double, 36> H0, H1{};
        ad::differentiate<6>(
          z,
          [&](const auto &x) {
            using Number = std::decay_t<decltype(x[0])>;
            Tensor<1, 3, Number> t, u;
            for (unsigned int i = 0; i < 3; ++i)
              t[i] = x[i], u[i] = x[3 + i];
            const auto e = helicoidal_strains_of(t, u, h);
            Number     w = c[0] * e[0];
            for (unsigned int k = 1; k < 6; ++k)
              w += c[k] * e[k];
            return w;
          },
          true, W0, g0, H0);
        const auto d  = helicoidal_strain_derivatives(z, h, true);
        double     W1 = 0;
        for (unsigned int k = 0; k < 6; ++k)
          {
            W1 += c[k] * d.strains[k];
            for (unsigned int a = 0; a < 6; ++a)
              g1[a] += c[k] * d.s_z[k][a];
          }
        d.add_second_derivatives(c, H1);
        worst[2] = std::max({worst[2], scaled_difference(&W0, &W1, 1), scaled_difference(g0.data(), g1.data(), 6),
                             scaled_difference(H0.data(), H1.data(), 36)});
      }
    check_close("u = R(q)^T c: value and derivatives, largest difference / largest entry", worst[0], 0, 0, 1e-12);
    check_close("theta(q_a, q_b), with and without a seam", worst[1], 0, 0, 1e-12);
    check_close("strains s(theta, u) contracted: value, s_z, s_zz", worst[2], 0, 0, 1e-12);
  }

  // The Cosserat plate energy's chain-rule derivatives
  // (exact_plate_energy_derivatives) against the nested AD of plate_energy
  // in its 15 local variables: random states with large rotations, theta = 0
  // exactly (the exponential's series branch), anisotropic growth G with
  // det G != 1 and a natural curvature, both parts of the energy (the shear
  // with a factor); and the covariant shear strain of the assumed shear
  // (exact_covariant_shear_derivatives) against the nested AD of
  // covariant_shear_strain. The two differ only by the order of the
  // floating-point operations; the tolerance is that of the strip's test
  // above.
  void
  plate_chain_rule(const cosmo::materials::PlateLaw &plate_law, const std::string &name)
  {
    std::cout << "Cosserat plate energy (" << name << "): chain rule against nested AD in 15 variables\n";
    constexpr int                    N = plate_local_variables;
    const cosmo::materials::PlateLawAt law(plate_law, 0.03);
    auto model    = cosmo::plugins::Registry<PlateModel>::create("cosserat");
    std::mt19937                           gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    double                                 worst[3]       = {0, 0, 0};
    bool                                   has_chain_rule = true;
    double                                 worst_shear[3] = {0, 0, 0};
    for (unsigned int sample = 0; sample < 40; ++sample)
      {
        std::array<double, N> z;
        const double          scales[N] = {0.1, 0.1, 0.1, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3,
                                  1.2, 1.2, 2, 2, 2, 2};
        for (int a = 0; a < N; ++a)
          z[a] = scales[a] * u(gen);
        if (sample % 5 == 0)
          z[9] = z[10] = 0;
        const PlateGrowthAtPoint g = sample % 2 ?
          PlateGrowthAtPoint::of({{{{1.1 + 0.1 * u(gen), 0.05 * u(gen)}}, {{0.05 * u(gen), 0.9 + 0.1 * u(gen)}}}}) :
          PlateGrowthAtPoint();
        PlateGrowthAtPoint gk = g;
        gk.natural_curvature  = {{0.3 * u(gen), 0.3 * u(gen), 0.1 * u(gen)}};
        for (const PlateGrowthAtPoint &growth : {g, gk})
          for (const bool membrane_bending : {true, false})
            for (const bool hessian : {true, false})
              {
                const double              factor = membrane_bending ? 1 : 7.5;
                double                    W0, W1;
                std::array<double, N>     g0, g1;
                std::array<double, N * N> H0{}, H1{};
                // As the assembly: in the 12 (8) variables the energy depends on.
                auto energy_of = [&](const auto &x) {
                  using Number = std::decay_t<decltype(x[0])>;
                  std::array<Number, N> y;
                  for (int k = 0; k < N; ++k)
                    y[k] = k >= 3 && k < 3 + int(x.size()) ? x[k - 3] : Number(z[k]);
                  return plate_energy(y, growth, law, *model, membrane_bending, factor);
                };
                if (membrane_bending)
                  cosmo::materials::internal::differentiate_subset<12>(z, 3, energy_of, hessian, W0, g0, H0);
                else
                  cosmo::materials::internal::differentiate_subset<8>(z, 3, energy_of, hessian, W0, g0, H0);
                has_chain_rule &= model->plate_energy_derivatives(z, growth, law, membrane_bending,
                                                                  factor, hessian, W1, g1, H1);
                worst[0] = std::max(worst[0], relative(&W0, &W1, 1));
                worst[1] = std::max(worst[1], relative(g0.data(), g1.data(), N));
                if (hessian)
                  worst[2] = std::max(worst[2], relative(H0.data(), H1.data(), N * N));
              }
        // The covariant shear strain at a tying point (assumed_shear.h), with
        // a distorted cell's Jacobian.
        Tensor<2, 2> J;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            J[i][j] = (i == j ? 0.3 : 0.) + 0.1 * u(gen);
        for (const unsigned int c : {0u, 1u})
          for (const bool hessian : {true, false})
            {
              double                    e0, e1;
              std::array<double, N>     g0, g1;
              std::array<double, N * N> H0{}, H1{};
              cosmo::materials::internal::differentiate_subset<8>(
                z, 3,
                [&](const auto &x) {
                  using Number = std::decay_t<decltype(x[0])>;
                  std::array<Number, N> y;
                  for (int k = 0; k < N; ++k)
                    y[k] = k >= 3 && k < 11 ? x[k - 3] : Number(z[k]);
                  return covariant_shear_strain(y, *model, J, c);
                },
                hessian, e0, g0, H0);
              has_chain_rule &=
                model->covariant_shear_strain_derivatives(z, J, c, hessian, e1, g1, H1);
              worst_shear[0] = std::max(worst_shear[0], std::abs(e0 - e1) / std::max(std::abs(e0), 1e-300));
              for (int i = 0; i < N; ++i)
                worst_shear[1] = std::max(worst_shear[1], std::abs(g0[i] - g1[i]));
              if (hessian)
                for (int i = 0; i < N * N; ++i)
                  worst_shear[2] = std::max(worst_shear[2], std::abs(H0[i] - H1[i]));
            }
      }
    check("the cosserat model has its chain rules", has_chain_rule);
    // The shear's entries are O(|J|) = O(0.3): absolute differences.
    check_close("covariant shear strain, largest relative difference", worst_shear[0], 0, 0, 1e-12);
    check_close("its gradient, largest difference", worst_shear[1], 0, 0, 1e-12);
    check_close("its Hessian, largest difference", worst_shear[2], 0, 0, 1e-12);
    check_close("energy, largest relative difference", worst[0], 0, 0, 1e-12);
    check_close("gradient, largest difference / largest entry", worst[1], 0, 0, 1e-12);
    check_close("Hessian, largest difference / largest entry", worst[2], 0, 0, 1e-12);
  }
  // The assumed shear's reduction (assembly/assumed_shear.h), for p = 1, 2,
  // 3 and both tyings: (a) it reproduces every field of its space, e_0 in
  // Q_{p-1,p} and e_1 in Q_{p,p-1}; (b) edge tying: on the edge xi_1 = 0
  // the reduced e_0 (the tangential strain there) depends on that edge's
  // tying points only, so it is continuous from cell to cell; interior
  // tying has not this property; (c) edge tying of e_0 = xi_1^(p+1) (not in
  // the space): the edge values and the moments against P_{p-2} in xi_1 are
  // kept (the canonical interpolation).
  void
  assumed_shear_reduction()
  {
    // (d) For a strain of degree p in both directions (the covariant strain
    // of the linear plate's discrete fields on a parallelogram) the two
    // tyings give the same reduced strain.
    {
      std::mt19937                           gen(5);
      std::uniform_real_distribution<double> u(-1., 1.);
      for (const unsigned int p : {1u, 2u, 3u})
        {
          const cosmo::assembly::AssumedShear edges(p, true), interior(p, false);
          std::vector<double>                 a((p + 1) * (p + 1) * 2);
          for (auto &x : a)
            x = u(gen);
          auto field = [&](const unsigned int c, const Point<2> &x) {
            double e = 0;
            for (unsigned int i = 0; i <= p; ++i)
              for (unsigned int j = 0; j <= p; ++j)
                e += a[c * (p + 1) * (p + 1) + i * (p + 1) + j] * std::pow(x[0], i) * std::pow(x[1], j);
            return e;
          };
          const QGauss<2> q(p + 2);
          auto reduced = [&](const cosmo::assembly::AssumedShear &shear, const unsigned int i,
                             const unsigned int c) {
            const FullMatrix<double> N = shear.interpolation(q);
            double                   e = 0;
            for (unsigned int k = 0; k < shear.n_tying_points(); ++k)
              if (shear.component(k) == c)
                e += N(i, k) * field(c, shear.tying_points().point(shear.location_of(k)));
            return e;
          };
          double worst = 0;
          for (unsigned int i = 0; i < q.size(); ++i)
            for (const unsigned int c : {0u, 1u})
              worst = std::max(worst, std::abs(reduced(edges, i, c) - reduced(interior, i, c)));
          check_close("p = " + std::to_string(p) +
                        ": edge and interior tying of a degree-p strain agree, largest difference",
                      worst, 0, 0, 1e-12);
        }
    }
    std::mt19937                           gen(11);
    std::uniform_real_distribution<double> u(-1., 1.);
    for (const unsigned int p : {1u, 2u, 3u})
      for (const bool edges : {true, false})
        {
          const cosmo::assembly::AssumedShear shear(p, edges);
          const auto &                        tying = shear.tying_points();
          const std::string what = "p = " + std::to_string(p) + (edges ? ", edge" : ", interior") + " tying: ";
          // The tied strains and their distinct locations (edge tying: e_0
          // and e_1 share the p x p interior points).
          check(what + std::to_string(shear.n_tying_points()) + " tied strains at " +
                  std::to_string(tying.size()) + " locations",
                edges ? shear.n_tying_points() == (p == 1 ? 4 : 2 * p * (p + 2)) &&
                          tying.size() == (p == 1 ? 4 : 4 * p + p * p) :
                        shear.n_tying_points() == 2 * p * (p + 1) &&
                          tying.size() == 2 * p * (p + 1));
          // (a) random fields of the space.
          std::vector<double> a(2 * p * (p + 1));
          for (auto &x : a)
            x = u(gen);
          auto field = [&](const unsigned int c, const Point<2> &x) {
            double       e = 0;
            unsigned int m = 0;
            for (unsigned int i = 0; i < p; ++i) // degree < p along xi_c
              for (unsigned int j = 0; j <= p; ++j, ++m)
                e += a[c * p * (p + 1) + m] * std::pow(x[c], i) * std::pow(x[1 - c], j);
            return e;
          };
          const QGauss<2>          q(p + 2);
          const FullMatrix<double> N = shear.interpolation(q);
          double                   worst = 0;
          for (unsigned int i = 0; i < q.size(); ++i)
            for (const unsigned int c : {0u, 1u})
              {
                double e = 0;
                for (unsigned int k = 0; k < shear.n_tying_points(); ++k)
                  if (shear.component(k) == c)
                    e += N(i, k) * field(c, tying.point(shear.location_of(k)));
                worst = std::max(worst, std::abs(e - field(c, q.point(i))));
              }
          check_close(what + "a field of the space reproduced, largest error", worst, 0, 0, 1e-12);
          // (b) on the edge xi_1 = 0: the weights of e_0's tying points off it.
          std::vector<Point<2>> edge_points;
          for (unsigned int i = 0; i < 5; ++i)
            edge_points.emplace_back(0.1 + 0.2 * i, 0.);
          const FullMatrix<double> Ne = shear.interpolation(Quadrature<2>(edge_points));
          double                   off_edge = 0;
          for (unsigned int i = 0; i < edge_points.size(); ++i)
            for (unsigned int k = 0; k < shear.n_tying_points(); ++k)
              if (shear.component(k) == 0 && tying.point(shear.location_of(k))[1] != 0.)
                off_edge = std::max(off_edge, std::abs(Ne(i, k)));
          if (edges)
            check_close(what + "tangential strain on an edge from that edge only", off_edge, 0, 0, 1e-13);
          else
            check(what + "the interior tying's edge strain depends on interior points", off_edge > 1e-3);
          // (c) the canonical interpolation of xi_1^(p+1), on the line xi_0 = 0.5
          if (edges)
            {
              const QGauss<1>       line(p + 3);
              std::vector<Point<2>> points = {Point<2>(0.5, 0.), Point<2>(0.5, 1.)};
              for (const auto &x : line.get_points())
                points.emplace_back(0.5, x[0]);
              const FullMatrix<double> Nl = shear.interpolation(Quadrature<2>(points));
              auto                     reduced = [&](const unsigned int i) {
                double e = 0;
                for (unsigned int k = 0; k < shear.n_tying_points(); ++k)
                  if (shear.component(k) == 0)
                    e += Nl(i, k) * std::pow(tying.point(shear.location_of(k))[1], p + 1);
                return e;
              };
              double worst_c = std::max(std::abs(reduced(0) - 0.), std::abs(reduced(1) - 1.));
              for (unsigned int r = 0; r + 2 <= p; ++r)
                {
                  double moment = 0;
                  for (unsigned int g = 0; g < line.size(); ++g)
                    moment += line.weight(g) * std::pow(line.point(g)[0], r) *
                              (reduced(2 + g) - std::pow(line.point(g)[0], p + 1));
                  worst_c = std::max(worst_c, std::abs(moment));
                }
              check_close(what + "edge values and moments of xi_1^(p+1) kept, largest error", worst_c, 0, 0, 1e-13);
            }
        }
  }
} // namespace

int
main()
{
  exp_log_round_trip();
  exp_derivative();
  helix_against_integration();
  const cosmo::materials::LinearIsotropicPlateLaw linear;
  const CoupledQuarticLaw                         coupled;
  strip_chain_rule(linear, "linear isotropic");
  strip_chain_rule(coupled, "coupled quartic");
  plate_chain_rule(linear, "linear isotropic");
  plate_chain_rule(coupled, "coupled quartic");
  assumed_shear_reduction();
  rod_element_maps();
  return cosmo_test::report();
}
