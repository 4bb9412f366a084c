// The quadratic rod law behind the rod-law interface, with axial growth
// (materials/rod_law.h): the grown ring is stress-free, the resultants and
// the Hessian of the grown energy are the growth-scaled closed forms (by
// Sacado through the Taylor form the kinematics use), a full 6x6 with
// couplings gives K e, and the weights on the strains are the congruence
// D K D (the Kirchhoff penalty).
#include <cosmo/materials/energy_derivatives.h>
#include <cosmo/materials/rod_laws/quadratic.h>

#include "test_tools.h"

#include <cmath>

using namespace cosmo;
using cosmo_test::check_close;

int
main()
{
  materials::QuadraticRodLaw law;
  law.stiffness = {{3, 4, 10, 0.5, 0.7, 0.4}};
  const double             R = 2;
  materials::RodNaturalState ring;
  ring.reference_strains = {{0, 0, 1, 0, -1 / R, 0}}; // a ring of radius R in the frame of doc/specification/plate-rod.md
  ring.growth            = 1.25;
  const double g         = ring.growth;
  // The grown ring: radius g R, arc length per reference length g, so
  // nu = (0, 0, g) and kappa per reference length (0, -g/(g R), 0) = kappa0.
  std::array<double, 6> grown{{0, 0, g, 0, -1 / R, 0}};
  check_close("grown ring (radius g R) is stress-free", materials::grown_rod_energy(law, grown, ring), 0, 0, 1e-15);

  // Resultants and stiffness by AD at a general state against the closed form
  // n_k = K_k (e_k/g - e0_k) (nu), m_k = K_k (e_k - e0_k)/g (kappa).
  std::array<double, 6>  e{{0.01, -0.02, 1.3, 0.05, -0.4, 0.1}}, grad;
  std::array<double, 36> hess;
  double                 W = 0;
  materials::internal::differentiate<6>(
    e, [&](const auto &x) { return materials::grown_rod_energy(law, x, ring); }, true, W, grad, hess);
  double worst = 0, worst_K = 0, W_closed = 0;
  const auto resultants = materials::grown_rod_resultants(law, e, ring);
  for (unsigned int k = 0; k < 6; ++k)
    {
      const double ek = k < 3 ? e[k] / g - ring.reference_strains[k] : (e[k] - ring.reference_strains[k]) / g;
      const double n  = law.stiffness[k] * ek;
      W_closed += 0.5 * g * law.stiffness[k] * ek * ek;
      // the resultants the output writes are the same
      worst   = std::max({worst, std::abs(resultants[k] - n), std::abs(grad[k] - n)});
      worst_K = std::max(worst_K, std::abs(hess[7 * k] - law.stiffness[k] / g));
    }
  check_close("energy = g psi(e)", W, W_closed, 1e-14);
  check_close("resultants = K (strain/g - reference)", worst, 0, 0, 1e-14);
  check_close("stiffness = K / g", worst_K, 0, 0, 1e-14);

  // A full 6x6 (a section's couplings): the resultants are K e and the
  // Hessian is K / g; the weights w are the congruence D K D, D = diag(w).
  {
    materials::QuadraticRodLaw c = law;
    c.set_coupling(2, 3, 0.3);  // extension - out-of-plane bending (eccentric section)
    c.set_coupling(0, 5, -0.2); // shear - twist (shear centre off the line)
    c.set_coupling(1, 4, 0.1);
    std::array<double, 6> ec;
    for (unsigned int k = 0; k < 6; ++k)
      ec[k] = k < 3 ? e[k] / g - ring.reference_strains[k] : (e[k] - ring.reference_strains[k]) / g;
    materials::internal::differentiate<6>(
      e, [&](const auto &x) { return materials::grown_rod_energy(c, x, ring); }, true, W, grad, hess);
    double     worst_r = 0, worst_h = 0;
    const auto r = materials::grown_rod_resultants(c, e, ring);
    for (unsigned int i = 0; i < 6; ++i)
      {
        double Ke = c.stiffness[i] * ec[i];
        for (unsigned int j = 0; j < 6; ++j)
          if (j != i)
            Ke += c.coupling[i][j] * ec[j];
        worst_r = std::max({worst_r, std::abs(r[i] - Ke), std::abs(grad[i] - Ke)});
        // d e_i / d strain_i = 1/g for every component.
        for (unsigned int j = 0; j < 6; ++j)
          worst_h = std::max(worst_h, std::abs(hess[6 * i + j] - (i == j ? c.stiffness[i] : c.coupling[i][j]) / g));
      }
    check_close("coupled: resultants = K e (law and Sacado)", worst_r, 0, 0, 1e-14);
    check_close("coupled: Hessian = K / g", worst_h, 0, 0, 1e-14);
    // the largest of 0.3 / sqrt(10 0.5), 0.2 / sqrt(3 0.4), 0.1 / sqrt(4 0.7)
    check_close("coupled: largest coupling", c.largest_coupling(), 0.2 / std::sqrt(3 * 0.4), 1e-14);

    // Weight 2 on strain 0: its stiffness times 4, its couplings times 2.
    auto weighted       = ring;
    weighted.weights[0] = 2;
    materials::internal::differentiate<6>(
      e, [&](const auto &x) { return materials::grown_rod_energy(c, x, weighted); }, true, W, grad, hess);
    check_close("weights: diagonal times w^2", hess[0], 4 * c.stiffness[0] / g, 1e-14);
    check_close("weights: coupling times w", hess[5], 2 * c.coupling[0][5] / g, 1e-14);
    check_close("weights: symmetric", hess[30], hess[5], 0, 1e-15);
    check_close("weights: other couplings unchanged", hess[6 * 2 + 3], c.coupling[2][3] / g, 1e-14);
    const auto rw = materials::grown_rod_resultants(c, e, weighted);
    check_close("weights: resultant = Sacado's", rw[0], grad[0], 1e-14);
  }
  // The natural stiffness of the interface is the 6x6.
  {
    materials::QuadraticRodLaw c = law;
    c.set_coupling(2, 3, 0.3);
    const auto K = c.natural_stiffness();
    check_close("natural stiffness: diagonal", K[7 * 4], 0.7, 0, 0);
    check_close("natural stiffness: coupling", K[6 * 3 + 2], 0.3, 0, 0);
  }
  return cosmo_test::report();
}
