// The closed forms of part 3 (analysis/plate_rod_thresholds.h) against their
// classical limits and their own defining equations.
#include <cosmo/analysis/plate_rod_thresholds.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
  // ---------------------------------------------------------------------
  // Lobed thresholds for Delta < 0 (doc/theory-plate-rod.md, sections 3, 4).
  // ---------------------------------------------------------------------
  // Reference numbers: scripts/check_lobed_thresholds.py (/usr/bin/python3),
  // section 5 of its output: the closed forms transcribed in python (scipy
  // brentq, exponentially scaled Bessel functions) and confirmed there by
  // independent Ritz discretizations in r (P1 elements for the planar disc
  // mode, C1 Hermite elements for the deflection, ring energy added at the
  // rim, linear eigenproblem K0 + T K1): planar to 3e-10, out-of-plane to
  // 1.2e-7 (Richardson-extrapolated).
  analysis::PlateRod q;
  q.radius = 1, q.thickness = 0.01, q.young = 1, q.poisson = 0.3;
  q.rod_EA = 1e-3, q.rod_EI1 = 1e-8, q.rod_EI2 = 1e-8, q.rod_GJ = 1e-8;
  check_close("planar n = 2 vs python", analysis::planar_critical_mismatch(q, 2), -6.840474313172e+00, 1e-9);
  check_close("planar n = 5 vs python", analysis::planar_critical_mismatch(q, 5), -1.551211080499e+00, 1e-9);
  check_close("out-of-plane n = 2 vs python", analysis::out_of_plane_critical_mismatch(q, 2), -2.964977125427e-04,
              1e-9);
  check_close("out-of-plane n = 3 vs python", analysis::out_of_plane_critical_mismatch(q, 3), -4.840140633153e-04,
              1e-9);
  {
    const auto fo = analysis::first_out_of_plane(q);
    const auto fp = analysis::first_planar(q);
    check("slender rim: out-of-plane saddle n = 2 first", fo.n == 2 && !fo.at_n_max && fo.mismatch > fp.mismatch);
    check("slender rim: planar minimum beyond n = 12 (wrinkling)", fp.n == 12 && fp.at_n_max);
    const auto fp200 = analysis::first_planar(q, 200);
    check_close("slender rim: planar first over n <= 200 is n = 66", fp200.n, 66, 0);
    check_close("slender rim: planar first mismatch vs python", fp200.mismatch, -1.411654757759e-01, 1e-9);
    // A sector pi/3 admits n = 3, 6, ...: its first planar mode is the best multiple of 3,
    // found by the same scan (n_step) the application's closed forms use.
    const auto fp3 = analysis::first_planar(q, 200, 3);
    double     best = -1e300;
    for (unsigned int n = 3; n <= 200; n += 3)
      best = std::max(best, analysis::planar_critical_mismatch(q, n));
    check("sector pi/3: planar first among multiples of 3", fp3.n % 3 == 0 && fp3.mismatch == best);
    check("sector pi/3: no better than the full disc", fp3.mismatch <= fp200.mismatch);
    const auto fo2 = analysis::first_out_of_plane(q, 12, 2);
    check("sector pi/2: out-of-plane n = 2 first (as the full disc)", fo2.n == 2 && fo2.mismatch == fo.mismatch);
  }
  // Rod 100x stiffer: the saddle stays first.
  {
    analysis::PlateRod s = q;
    s.rod_EA *= 100, s.rod_EI1 *= 100, s.rod_EI2 *= 100, s.rod_GJ *= 100;
    const auto fo = analysis::first_out_of_plane(s);
    check_close("stiff rim: out-of-plane n = 2 vs python", fo.mismatch, -3.094286979438e-04, 1e-9);
    check("stiff rim: out-of-plane n = 2 first", fo.n == 2 && fo.mismatch > analysis::first_planar(s, 40).mismatch);
    check_close("stiff rim: planar n = 3 vs python", analysis::planar_critical_mismatch(s, 3), -3.218775760347e-01,
                1e-9);
  }

  // Planar, soft plate (E h -> 0 at fixed T) with an inextensible rim: the plate's
  // initial-stress term N |grad u|^2/2 alone resists, T_cr = -n^2 (n^2-1)/(n^2-n-1) EI2/R^2
  // (12 for n = 2, not the hydrostatic 3: see the doc).
  {
    analysis::PlateRod s;
    s.radius = 1, s.thickness = 1e-3, s.young = 1e-12, s.rod_EA = 1e8, s.rod_EI2 = 1;
    for (const unsigned int n : {2u, 3u, 4u})
      check_close("soft plate, planar n = " + std::to_string(n) + ": T R^2/EI2", analysis::planar_critical_hoop_force(s, n),
                  -double(n * n) * (n * n - 1) / (n * n - n - 1.), 1e-6);
    // Plate stiffness raises the threshold monotonically; rigid plate: |T_cr| grows like
    // E h R (python, section 4: T_cr/(E h R) = -0.573558 at E h R = 1e4, n = 2, EA = 1,
    // EI2 = 1e-3), i.e. no planar lobing within small strain.
    s.thickness = 1e-2, s.rod_EA = 1, s.rod_EI2 = 1e-3;
    bool   monotone = true;
    double prev     = 0;
    for (const double E : {1e-6, 1e-4, 1e-2, 1., 1e2, 1e4, 1e6})
      {
        s.young        = E;
        const double T = analysis::planar_critical_hoop_force(s, 2);
        monotone       = monotone && T < prev;
        prev           = T;
      }
    check("planar |T_cr| grows with the plate stiffness", monotone);
    check_close("planar, rigid plate: T_cr/(E h R) vs python", prev / (1e6 * 1e-2), -0.573558, 2e-6);
    // A stiffer rim in bending raises |Delta_cr|.
    s.young = 1;
    const double d1 = analysis::planar_critical_mismatch(s, 3);
    s.rod_EI2 *= 10;
    check("planar |Delta_cr| grows with EI2", analysis::planar_critical_mismatch(s, 3) < d1);
  }

  // Out-of-plane: vanishing plate bending (D -> 0 at fixed T): the membrane N |grad w|^2/2
  // and the ring, T_cr = -n (n+1) (n^2-1) EI1 GJ / (R^2 (EI1 + n^2 GJ)) (Timoshenko's
  // (n^2-1)^2 EI1/(R^2 (n^2 + EI1/GJ)) for a dead in-plane load, times n/(n-1)).
  {
    analysis::PlateRod s;
    s.radius = 1, s.thickness = 1e-4, s.young = 1, s.rod_EA = 1e12, s.rod_EI1 = 1, s.rod_GJ = 0.5;
    for (const unsigned int n : {2u, 3u})
      {
        const double T = analysis::out_of_plane_critical_mismatch(s, n) * s.rod_EA * s.edge_stiffness() /
                         (s.rod_EA + s.edge_stiffness());
        check_close("membrane limit, out-of-plane n = " + std::to_string(n) + ": T", T,
                    -double(n) * (n + 1) * (n * n - 1) * 0.5 / (1 + n * n * 0.5), 1e-6);
      }
  }
  // The root satisfies its determinant (sign change across it), and the free-rim limit
  // e1 = g = 0 (python: x = 1.620..., T = -2.4043590221e-07 for h = 0.01).
  for (const unsigned int n : {2u, 3u, 7u})
    {
      const double x  = analysis::out_of_plane_load_parameter(0.3, 0.5, 2.0, n);
      const double dm = analysis::out_of_plane_determinant(0.3, 0.5, 2.0, n, x * (1 - 1e-9));
      const double dp = analysis::out_of_plane_determinant(0.3, 0.5, 2.0, n, x * (1 + 1e-9));
      check("out-of-plane n = " + std::to_string(n) + ": determinant changes sign at the root", dm > 0 && dp < 0);
    }
  {
    const double D = q.plate_D();
    const double x = analysis::out_of_plane_load_parameter(0.3, 0, 0, 2);
    check_close("free rim (e1 = g = 0), n = 2: T vs python", -D * x * x, -2.4043590221e-07, 1e-9);
  }
  // Monotone in the rim's stiffness ratios; rigid rim -> no out-of-plane lobing.
  {
    bool   monotone = true;
    double prev     = 0;
    for (const double e : {0., 0.1, 1., 10., 100., 1e4})
      {
        const double x = analysis::out_of_plane_load_parameter(0.3, e, e, 2);
        monotone       = monotone && x > prev;
        prev           = x;
      }
    check("out-of-plane load grows with EI1 = GJ", monotone);
    const double x1 = analysis::out_of_plane_load_parameter(0.3, 10, 1, 3);
    check("out-of-plane load grows with GJ alone", analysis::out_of_plane_load_parameter(0.3, 10, 2, 3) > x1);
    check("out-of-plane load grows with EI1 alone", analysis::out_of_plane_load_parameter(0.3, 20, 1, 3) > x1);
  }
  // chi = x I_n/I_{n+1}: against std::cyl_bessel_i, continuous across the large-x switch.
  for (const unsigned int n : {2u, 5u, 12u})
    for (const double x : {1e-3, 0.7, 8., 60., 300.})
      check_close("chi(" + std::to_string(n) + ", " + std::to_string(x) + ")", analysis::bessel_i_chi(n, x),
                  x * std::cyl_bessel_i(double(n), x) / std::cyl_bessel_i(double(n + 1), x), 1e-12);
  check_close("chi continuous at the Hankel switch", analysis::bessel_i_chi(2, 500 * (1 + 1e-12)),
              analysis::bessel_i_chi(2, 500), 1e-11);
  check_close("chi small-x limit 2(n+1)", analysis::bessel_i_chi(3, 1e-8), 8, 1e-12);
  {
    bool thrown = false;
    try
      {
        analysis::out_of_plane_critical_mismatch(q, 1);
      }
    catch (const std::invalid_argument &)
      {
        thrown = true;
      }
    check("n = 1 rejected", thrown);
  }
  return cosmo_test::report();
}
