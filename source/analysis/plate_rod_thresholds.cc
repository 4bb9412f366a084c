#include <cosmo/analysis/plate_rod_thresholds.h>

#include <cmath>
#include <stdexcept>

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

    double
    axisymmetric_critical_mismatch(const PlateRod &p)
    {
      const double D   = p.plate_D();
      const double rho = p.rod_EI1 / (p.radius * D);
      const double P   = axisymmetric_load_factor(p.poisson, rho) * D / (p.radius * p.radius);
      // -N = P with N = -(k EA / (R (EA + k))) Delta.
      const double k = p.edge_stiffness();
      return P * p.radius * (p.rod_EA + k) / (k * p.rod_EA);
    }

    double
    planar_critical_mismatch_soft_plate(const PlateRod &p, const unsigned int n)
    {
      if (n < 2)
        throw std::invalid_argument("lobe number n >= 2");
      const double T = -(double(n) * n - 1) * p.rod_EI2 / (p.radius * p.radius);
      // T = EA (a - er) with a from prebuckled_state: T = EA k Delta / (EA + k).
      const double k = p.edge_stiffness();
      return T * (p.rod_EA + k) / (p.rod_EA * k);
    }
  } // namespace analysis
} // namespace cosmo
