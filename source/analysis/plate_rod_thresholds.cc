#include <cosmo/analysis/plate_rod_thresholds.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cosmo
{
  namespace analysis
  {
    double
    PlateRod::plate_D() const
    {
      return young * thickness * thickness * thickness / (12 * (1 - poisson * poisson));
    }

    double
    PlateRod::edge_stiffness() const
    {
      return radius * young * thickness / (1 - poisson);
    }

    PrebuckledState
    prebuckled_state(const PlateRod &p, const double ep, const double er)
    {
      // Plate: u_r = a r, N = E h/(1 - v) (a - ep) (equi-biaxial, plane
      // stress). Rim: hoop strain a - er, T = EA (a - er). Rim equilibrium
      // under the plate's edge load: T = -N R. Hence a is the stiffness-
      // weighted mean of the two growth strains.
      const double k = p.edge_stiffness();
      PrebuckledState s;
      s.radial_strain  = (p.rod_EA * er + k * ep) / (p.rod_EA + k);
      s.membrane_force = k / p.radius * (s.radial_strain - ep);
      s.hoop_force     = p.rod_EA * (s.radial_strain - er);
      return s;
    }

    double
    axisymmetric_load_factor(const double poisson, const double rho)
    {
      if (!(rho >= 0))
        throw std::invalid_argument("rotational restraint rho must be >= 0");
      auto f = [&](const double x) {
        return x * std::cyl_bessel_j(0., x) - (1 - poisson - rho) * std::cyl_bessel_j(1., x);
      };
      // f > 0 near 0 (f ~ x (1 + v + rho)/2) and f(j_{1,1}) = j_{1,1} J0(j_{1,1}) < 0.
      double a = 1e-8, b = 3.8317059702075125;
      for (int i = 0; i < 200 && b - a > 1e-15 * b; ++i)
        {
          const double m = 0.5 * (a + b);
          (f(m) > 0 ? a : b) = m;
        }
      const double x = 0.5 * (a + b);
      return x * x;
    }

    namespace
    {
      /// Lame relation: the mismatch that produces the hoop force T
      /// (T = EA k Delta / (EA + k), prebuckled_state).
      double
      mismatch_from_hoop_force(const PlateRod &p, const double T)
      {
        const double k = p.edge_stiffness();
        return T * (p.rod_EA + k) / (p.rod_EA * k);
      }
    } // namespace

    double
    axisymmetric_critical_mismatch(const PlateRod &p)
    {
      const double D   = p.plate_D();
      const double rho = p.rod_EI1 / (p.radius * D);
      const double P   = axisymmetric_load_factor(p.poisson, rho) * D / (p.radius * p.radius);
      // -N = P with N = -T / R, T the hoop force of the rim.
      return mismatch_from_hoop_force(p, P * p.radius);
    }

    double
    planar_critical_mismatch_soft_plate(const PlateRod &p, const unsigned int n)
    {
      if (n < 2)
        throw std::invalid_argument("lobe number n >= 2");
      const double T = -(double(n) * n - 1) * p.rod_EI2 / (p.radius * p.radius);
      return mismatch_from_hoop_force(p, T);
    }
    namespace
    {
      /**
       * The first sign change of f on the geometric grid x0, x0 q, x0 q^2, ...
       * (f(x0) > 0), up to x_max, refined by bisection to round-off. Throws
       * std::domain_error with `what` if f stays positive.
       */
      template <typename F>
      double
      first_root(const F &f, const double x0, const double q, const double x_max, const std::string &what)
      {
        if (!(f(x0) > 0))
          throw std::domain_error(what + ": the flat state is not stable at vanishing load");
        double a = x0, b = x0 * q;
        while (f(b) > 0)
          {
            a = b, b *= q;
            if (b > x_max)
              throw std::domain_error(what + ": no root of the stability determinant below " +
                                      std::to_string(x_max));
          }
        for (int i = 0; i < 200 && b - a > 4 * std::numeric_limits<double>::epsilon() * b; ++i)
          {
            const double m = 0.5 * (a + b);
            (f(m) > 0 ? a : b) = m;
          }
        return 0.5 * (a + b);
      }

      /**
       * Planar stability matrix for the rim displacement
       * u_r = A cos(n th), u_t = B sin(n th), in P = (A + B)/2, M = (A - B)/2:
       * second variation = pi [a P^2 + 2 b P M + c M^2]. Returns a c - b^2 and
       * c (both positive while the flat state is stable).
       */
      void
      planar_matrix(const PlateRod &p, const unsigned int n, const double T, double &det, double &c_out)
      {
        const double R   = p.radius;
        const double Eh  = p.young * p.thickness;
        const double v   = p.poisson;
        const double lam = Eh * v / (1 - v * v), mu = Eh / (2 * (1 + v));
        const double N   = -T / R;
        const double nn  = n;
        // Disc, mode r^{n+1} (P) and r^{n-1} (M) parts of the Navier solution
        // of (mu + N) lap u + (lambda + mu) grad div u = 0:
        const double FP = 2 * (mu + N) * (lam + mu) / (lam + 3 * mu + 2 * N) + N;
        const double FM = N + 2 * mu;
        // Ring: EA (A + n B)^2 + (EI2 n^2/R^2 + T) (n A + B)^2, over 2R.
        const double s = p.rod_EI2 * nn * nn / (R * R) + T;
        const double a = (nn + 1) * (nn + 1) * (p.rod_EA + s) / (2 * R) + (nn + 1) * FP;
        const double c = (nn - 1) * (nn - 1) * (p.rod_EA + s) / (2 * R) + (nn - 1) * FM;
        const double b = (nn * nn - 1) * (s - p.rod_EA) / (2 * R);
        det            = a * c - b * b;
        c_out          = c;
      }
    } // namespace

    double
    planar_critical_hoop_force(const PlateRod &p, const unsigned int n)
    {
      if (n < 2)
        throw std::invalid_argument("lobe number n >= 2");
      const double scale = p.rod_EA + p.young * p.thickness * p.radius + p.rod_EI2 / (p.radius * p.radius);
      // f(t) > 0 while the 2x2 matrix at T = -t is positive definite.
      auto f = [&](const double t) {
        double det, c;
        planar_matrix(p, n, -t, det, c);
        return c > 0 ? det : std::min(det, c);
      };
      const double t = first_root(f, 1e-14 * scale, 1.05, 1e14 * scale, "planar_critical_hoop_force");
      return -t;
    }

    double
    planar_critical_mismatch(const PlateRod &p, const unsigned int n)
    {
      return mismatch_from_hoop_force(p, planar_critical_hoop_force(p, n));
    }

    double
    bessel_i_chi(const unsigned int n, const double x)
    {
      if (!(x > 0))
        throw std::invalid_argument("bessel_i_chi: x > 0");
      const double nu = n;
      if (x <= std::max(500., 4 * (nu + 1) * (nu + 1)))
        {
          // h = I_{n+1}/I_n by the continued fraction h = 1/(2(n+1)/x + 1/(2(n+2)/x + ...))
          // (modified Lentz); it converges after ~x + 20 terms and never overflows.
          const double tiny = 1e-300;
          double       fr = tiny, C = fr, Dl = 0;
          for (int k = 1; k < 10000000; ++k)
            {
              const double bk = 2 * (nu + k) / x;
              Dl              = bk + Dl;
              if (Dl == 0)
                Dl = tiny;
              C = bk + 1 / C;
              if (C == 0)
                C = tiny;
              Dl               = 1 / Dl;
              const double del = C * Dl;
              fr *= del;
              if (std::abs(del - 1) < 1e-16)
                break;
            }
          // fr = 1/(b1 + 1/(b2 + ...)) = h
          return x / fr;
        }
      // Large x: Hankel expansion I_m(x) ~ e^x/sqrt(2 pi x) sum_k (-1)^k a_k(m)/x^k; the
      // exponential cancels in the ratio.
      auto series = [&](const double m) {
        double sum = 1, term = 1;
        for (int k = 1; k < 60; ++k)
          {
            const double next = -term * (4 * m * m - (2 * k - 1) * (2 * k - 1)) / (8 * k * x);
            if (std::abs(next) >= std::abs(term) || std::abs(next) < 1e-17 * std::abs(sum))
              {
                sum += std::abs(next) < std::abs(term) ? next : 0;
                break;
              }
            term = next;
            sum += term;
          }
        return sum;
      };
      return x * series(nu) / series(nu + 1);
    }

    double
    out_of_plane_determinant(const double v, const double e1, const double g, const unsigned int n, const double x)
    {
      const double nn  = n;
      const double chi = bessel_i_chi(n, x);
      return chi * (nn * (nn - 1) * (e1 + g) + 2 * nn * (1 - v)) +
             nn * (nn + 1) * (e1 * g * (nn * nn - 1) + (1 - v) * (e1 + g) - (1 - v) * (1 - v)) -
             x * x * (chi - (1 - v) + e1 + g * nn * nn);
    }

    double
    out_of_plane_load_parameter(const double v, const double e1, const double g, const unsigned int n)
    {
      if (n < 2)
        throw std::invalid_argument("lobe number n >= 2 (n = 0, 1 are stable under rim compression)");
      if (!(e1 >= 0 && g >= 0))
        throw std::invalid_argument("rim stiffness ratios must be >= 0");
      // The 2x2 stability matrix has the diagonal entry chi - (1 - v) + e1 + g n^2 > 0 for
      // all x, so it is positive definite exactly while the determinant is.
      auto f = [&](const double x) { return out_of_plane_determinant(v, e1, g, n, x); };
      return first_root(f, 1e-6, 1.02, 1e9, "out_of_plane_load_parameter");
    }

    double
    out_of_plane_critical_mismatch(const PlateRod &p, const unsigned int n)
    {
      const double D = p.plate_D();
      const double x =
        out_of_plane_load_parameter(p.poisson, p.rod_EI1 / (p.radius * D), p.rod_GJ / (p.radius * D), n);
      // N = D x^2/R^2 = -T/R.
      return mismatch_from_hoop_force(p, -D * x * x / p.radius);
    }

    LobedThreshold
    first_planar(const PlateRod &p, const unsigned int n_max, const unsigned int n_step)
    {
      if (n_max < 2 || n_step < 1)
        throw std::invalid_argument("n_max >= 2, n_step >= 1");
      LobedThreshold first{0, -std::numeric_limits<double>::infinity(), false};
      for (unsigned int n = std::max(2u, n_step); n <= n_max; n += n_step)
        {
          const double d = planar_critical_mismatch(p, n);
          if (d > first.mismatch)
            first = {n, d, n + n_step > n_max};
        }
      return first;
    }

    LobedThreshold
    first_out_of_plane(const PlateRod &p, const unsigned int n_max, const unsigned int n_step)
    {
      if (n_max < 2 || n_step < 1)
        throw std::invalid_argument("n_max >= 2, n_step >= 1");
      LobedThreshold first{0, -std::numeric_limits<double>::infinity(), false};
      for (unsigned int n = std::max(2u, n_step); n <= n_max; n += n_step)
        {
          const double d = out_of_plane_critical_mismatch(p, n);
          if (d > first.mismatch)
            first = {n, d, n + n_step > n_max};
        }
      return first;
    }
  } // namespace analysis
} // namespace cosmo
