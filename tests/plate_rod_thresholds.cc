// The closed forms of part 3 (analysis/plate_rod_thresholds.h) against their
// classical limits and their own defining equations.
#include <cosmo/analysis/plate_rod_thresholds.h>

#include "test_tools.h"

#include <cmath>

using namespace cosmo;
using cosmo_test::check;
using cosmo_test::check_close;

int
main()
{
  // Axisymmetric buckling of a disc under uniform radial compression:
  // simply supported (rho = 0) 4.198 D/R^2 at v = 0.3 (root of
  // x J0 = (1 - v) J1, x = 2.0489), clamped (rho -> inf) j_{1,1}^2 = 14.682.
  check_close("simply supported disc, v = 0.3: x^2", analysis::axisymmetric_load_factor(0.3, 0),
              2.04885 * 2.04885, 1e-4);
  check_close("clamped disc: j_{1,1}^2", analysis::axisymmetric_load_factor(0.3, 1e12),
              3.8317059702075125 * 3.8317059702075125, 1e-9);
  // Poisson 0: the root of the defining equation itself.
  const double x0 = std::sqrt(analysis::axisymmetric_load_factor(0.0, 0));
  check_close("v = 0: root satisfies x J0(x) = J1(x)", x0 * std::cyl_bessel_j(0., x0) - std::cyl_bessel_j(1., x0), 0, 0, 1e-12);
  // The rim's rolling stiffness moves the threshold monotonically between the limits.
  double previous = 0;
  bool   monotone = true;
  for (const double rho : {0., 0.1, 1., 10., 100., 1e4})
    {
      const double l = analysis::axisymmetric_load_factor(0.3, rho);
      monotone       = monotone && l > previous && l < 14.6820;
      previous       = l;
    }
  check("load factor increases with the rim's rolling stiffness, between 4.198 and 14.682", monotone);

  // Pre-buckled state: equilibrium T = -N R and compatibility; rigid and
  // floppy rim limits.
  analysis::PlateRod p;
  p.radius = 1, p.thickness = 0.01, p.young = 1, p.poisson = 0.3, p.rod_EA = 0.02;
  const auto s = analysis::prebuckled_state(p, 0.01, 0.0);
  check_close("rim equilibrium T = -N R", s.hoop_force, -s.membrane_force * p.radius, 1e-12);
  check_close("plate law N = E h/(1-v) (a - ep)", s.membrane_force,
              p.young * p.thickness / (1 - p.poisson) * (s.radial_strain - 0.01), 1e-12);
  p.rod_EA      = 1e12;
  const auto sr = analysis::prebuckled_state(p, 0.01, 0.0);
  check_close("rigid rim: no radial strain", sr.radial_strain, 0, 0, 1e-12);
  check_close("rigid rim: N = -E h ep/(1-v)", sr.membrane_force, -p.young * p.thickness * 0.01 / (1 - p.poisson), 1e-9);
  p.rod_EA      = 1e-12;
  const auto sf = analysis::prebuckled_state(p, 0.01, 0.0);
  check_close("floppy rim: free growth, no force", sf.membrane_force, 0, 0, 1e-12);

  // Critical mismatch: with a rigid, non-rolling rim the clamped plate
  // buckles at N = -14.68 D/R^2.
  p.rod_EA = 1e12, p.rod_EI1 = 1e12;
  const double D = p.plate_D();
  check_close("rigid rim: Delta_cr = 14.68 D (1 - v)/(E h R^2)", analysis::axisymmetric_critical_mismatch(p),
              3.8317059702075125 * 3.8317059702075125 * D * (1 - p.poisson) / (p.young * p.thickness), 1e-6);
  // Soft plate: the ring under pressure, T_cr = -3 EI/R^2 for n = 2, with a
  // rigid plate edge compliance k -> inf the mismatch is T/EA.
  p.rod_EA = 0.02, p.rod_EI2 = 1e-4, p.young = 1e12;
  check_close("stiff plate, n = 2: Delta = -3 EI2/(R^2 EA)", analysis::planar_critical_mismatch_soft_plate(p, 2),
              -3 * p.rod_EI2 / p.rod_EA, 1e-9);
  return cosmo_test::report();
}
