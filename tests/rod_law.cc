// The quadratic rod law with axial growth: the grown ring is stress-free,
// the small-strain stiffnesses are the given ones, and the resultants are
// the growth-scaled ones (checked by Sacado against the closed form).
#include <cosmo/materials/energy_derivatives.h>
#include <cosmo/materials/rod_law.h>

#include "test_tools.h"

#include <cmath>

using namespace cosmo;
using cosmo_test::check_close;

int
main()
{
  materials::QuadraticRodLaw law;
  law.stiffness         = {{3, 4, 10, 0.5, 0.7, 0.4}};
  const double R        = 2;
  law.reference_strains = {{0, 0, 1, 0, -1 / R, 0}}; // a ring of radius R in the frame of doc/specification/plate-rod.md
  const double g        = 1.25;
  // The grown ring: radius g R, arc length per reference length g, so
  // nu = (0, 0, g) and kappa per reference length (0, -g/(g R), 0) = kappa0.
  std::array<double, 6> grown{{0, 0, g, 0, -1 / R, 0}};
  check_close("grown ring (radius g R) is stress-free", law.energy(grown, g), 0, 0, 1e-15);

  // Resultants and stiffness by AD at a general state against the closed form
  // n_k = K_k (e_k/g - e0_k) (nu), m_k = K_k (e_k - e0_k)/g (kappa).
  std::array<double, 6> e{{0.01, -0.02, 1.3, 0.05, -0.4, 0.1}}, grad;
  std::array<double, 36> hess;
  double                 W = 0;
  materials::internal::differentiate<6>(
    e, [&](const auto &x) { return law.energy(x, g); }, true, W, grad, hess);
  double worst = 0, worst_K = 0;
  for (unsigned int k = 0; k < 6; ++k)
    {
      const double n = k < 3 ? law.stiffness[k] * (e[k] / g - law.reference_strains[k]) :
                               law.stiffness[k] * (e[k] - law.reference_strains[k]) / g;
      // the law's own resultants (what the output writes) are the same
      worst   = std::max(worst, std::abs(law.resultants(e, g)[k] - n));
      worst   = std::max(worst, std::abs(grad[k] - n));
      worst_K = std::max(worst_K, std::abs(hess[7 * k] - law.stiffness[k] / g));
    }
  check_close("resultants = K (strain/g - reference)", worst, 0, 0, 1e-14);
  check_close("stiffness = K / g", worst_K, 0, 0, 1e-14);

  // A full 6x6 (a section's couplings): the resultants are K e and the
  // Hessian is D K D / g with D = diag(1/g for nu... ) -- here checked
  // entry by entry against Sacado, and scale_strain() is the congruence
  // D K D (D_kk = sqrt(f)).
  {
    materials::QuadraticRodLaw c = law;
    c.set_coupling(2, 3, 0.3);  // extension - out-of-plane bending (eccentric section)
    c.set_coupling(0, 5, -0.2); // shear - twist (shear centre off the line)
    c.set_coupling(1, 4, 0.1);
    std::array<double, 6> ec;
    for (unsigned int k = 0; k < 6; ++k)
      ec[k] = k < 3 ? e[k] / g - c.reference_strains[k] : (e[k] - c.reference_strains[k]) / g;
    materials::internal::differentiate<6>(
      e, [&](const auto &x) { return c.energy(x, g); }, true, W, grad, hess);
    double worst_r = 0, worst_h = 0;
    const auto r = c.resultants(e, g);
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
    materials::QuadraticRodLaw s = c;
    s.scale_strain(0, 4.);
    check_close("scale_strain: diagonal times f", s.stiffness[0], 4 * c.stiffness[0], 1e-15);
    check_close("scale_strain: coupling times sqrt(f)", s.coupling[0][5], 2 * c.coupling[0][5], 1e-15);
    check_close("scale_strain: symmetric", s.coupling[5][0], s.coupling[0][5], 0, 0);
    check_close("scale_strain: other couplings unchanged", s.coupling[2][3], c.coupling[2][3], 0, 0);
  }
  return cosmo_test::report();
}
