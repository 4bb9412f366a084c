// The plate's linear law (materials::NaghdiPlateLaw): the membrane force and
// bending moment it gives the output are the derivatives of the energy the
// assembly differentiates (checked by Sacado), and the energy is half their
// work on the strains.
#include <cosmo/materials/energy_derivatives.h>
#include <cosmo/materials/plate_law.h>

#include "test_tools.h"

#include <cmath>

using namespace cosmo;
using cosmo_test::check_close;

int
main()
{
  materials::NaghdiPlateLaw law;
  law.young     = 2.5;
  law.poisson   = 0.35;
  law.thickness = 0.03;
  // membrane (11, 22, 12), then bending (11, 22, 12)
  const std::array<double, 6> x{{0.012, -0.004, 0.007, 0.8, 0.3, -0.45}};
  std::array<double, 6>       grad;
  std::array<double, 36>      hess;
  double                      W = 0;
  materials::internal::differentiate<6>(
    x,
    [&](const auto &y) {
      using Number = std::decay_t<decltype(y[0])>;
      materials::PlateStrains<Number> s;
      for (unsigned int k = 0; k < 3; ++k)
        {
          s.membrane[k] = y[k];
          s.bending[k]  = y[3 + k];
        }
      s.shear = {{Number(0.), Number(0.)}};
      return law.membrane_bending_energy(s);
    },
    false, W, grad, hess);
  const auto N = law.membrane_force({{x[0], x[1], x[2]}});
  const auto M = law.bending_moment({{x[3], x[4], x[5]}});
  // dW/de_12 counts the off-diagonal pair: N_12 = 1/2 dW/de_12.
  double worst = 0, scale = 0;
  for (unsigned int k = 0; k < 3; ++k)
    {
      const double f = k == 2 ? 0.5 : 1.;
      worst          = std::max({worst, std::abs(N[k] - f * grad[k]), std::abs(M[k] - f * grad[3 + k])});
      scale          = std::max({scale, std::abs(N[k]), std::abs(M[k])});
    }
  // round-off of O(1e-16) relative to the largest resultant
  check_close("N, M = dW/de, dW/dk (12: half)", worst / scale, 0, 0, 1e-14);
  const double work = 0.5 * (N[0] * x[0] + N[1] * x[1] + 2 * N[2] * x[2] + M[0] * x[3] +
                             M[1] * x[4] + 2 * M[2] * x[5]);
  check_close("W = 1/2 (N : e + M : k)", work, W, 1e-14);
  check_close("D = C h^2 / 12", law.bending_stiffness(),
              law.young * std::pow(law.thickness, 3) / (12 * (1 - law.poisson * law.poisson)), 1e-14);
  return cosmo_test::report();
}
