// The plate's linear isotropic law (materials::LinearIsotropicPlateLaw)
// behind the plate-law interface: its energy, resultants and stiffnesses
// against the closed forms of doc/specification/strip.md, its own gradient
// and Hessian against central differences of its energy, the energy half the
// work of the resultants, and the Taylor form the kinematics evaluate on
// Sacado numbers (PlateLawAt) giving the law's own derivatives.
#include <cosmo/materials/energy_derivatives.h>
#include <cosmo/materials/plate_laws/linear_isotropic.h>

#include "test_tools.h"

#include <cmath>

using namespace cosmo;
using cosmo_test::check_close;
using materials::PlatePart;

int
main()
{
  materials::LinearIsotropicPlateLaw linear;
  linear.young_modulus = 2.5;
  linear.poisson_ratio = 0.35;
  const double h       = 0.03;
  const materials::PlateLawAt law(linear, h);
  // membrane (11, 22, 12), bending (11, 22, 12), shear (1, 2)
  const std::array<double, 8> x{{0.012, -0.004, 0.007, 0.8, 0.3, -0.45, 0.02, -0.03}};
  materials::PlateStrains<double> s{{{x[0], x[1], x[2]}}, {{x[3], x[4], x[5]}}, {{x[6], x[7]}}};

  // The closed forms: C, D, G and the energy.
  const double v = 0.35, E = 2.5, C = E * h / (1 - v * v), D = C * h * h / 12, G = E / (2 * (1 + v));
  auto quadratic = [v](const double *a) {
    const double tr = a[0] + a[1];
    return v * tr * tr + (1 - v) * (a[0] * a[0] + a[1] * a[1] + 2 * a[2] * a[2]);
  };
  const double W_mb = 0.5 * C * quadratic(&x[0]) + 0.5 * D * quadratic(&x[3]);
  const double W_s  = 0.5 * (5. / 6) * G * h * (x[6] * x[6] + x[7] * x[7]);
  // round-off: a few ulps of sums of terms of the same sign
  check_close("W_mb closed form", law.membrane_bending_energy(s), W_mb, 1e-14);
  check_close("W_s closed form", law.shear_energy(s), W_s, 1e-14);
  check_close("C = E h / (1 - v^2)", law.membrane_stiffness(), C, 1e-14);
  check_close("D = C h^2 / 12", law.bending_stiffness(), D, 1e-14);

  // N = C ((v tr e) I + (1 - v) e), M likewise with D, Q = ks G h gamma.
  const auto r = law.resultants(s);
  double     worst = 0, scale = 0;
  for (unsigned int k = 0; k < 3; ++k)
    {
      const double tre = x[0] + x[1], trk = x[3] + x[4];
      const double N = C * ((k < 2 ? v * tre : 0) + (1 - v) * x[k]);
      const double M = D * ((k < 2 ? v * trk : 0) + (1 - v) * x[3 + k]);
      worst          = std::max({worst, std::abs(r.membrane[k] - N), std::abs(r.bending[k] - M)});
      scale          = std::max({scale, std::abs(N), std::abs(M)});
    }
  for (unsigned int k = 0; k < 2; ++k)
    worst = std::max(worst, std::abs(r.shear[k] - (5. / 6) * G * h * x[6 + k]));
  check_close("N, M, Q closed forms", worst / scale, 0, 0, 1e-14);
  const double work = 0.5 * (r.membrane[0] * x[0] + r.membrane[1] * x[1] + 2 * r.membrane[2] * x[2] +
                             r.bending[0] * x[3] + r.bending[1] * x[4] + 2 * r.bending[2] * x[5]);
  check_close("W_mb = 1/2 (N : e + M : k)", work, W_mb, 1e-14);

  // The law's gradient and Hessian against central differences of its
  // energy. The energy is quadratic, so the differences are exact but for
  // round-off: eps |W| / step ~ 1e-16 * 1e-3 / 1e-4 ~ 1e-15 absolute in
  // the gradient, relative to |dW| ~ 1e-3 about 1e-12 (tolerance 1e-9).
  for (const PlatePart part : {PlatePart::membrane_and_bending, PlatePart::transverse_shear})
    {
      double                 W = 0;
      std::array<double, 8>  dW, dWp, dWm;
      std::array<double, 64> H, Hp;
      law.derivatives(x, part, true, W, dW, H);
      double worst_g = 0, worst_H = 0, scale_g = 0, scale_H = 0;
      for (unsigned int k = 0; k < 8; ++k)
        {
          const double step = 1e-4;
          auto         xp = x, xm = x;
          xp[k] += step;
          xm[k] -= step;
          double Wp = 0, Wm = 0;
          law.derivatives(xp, part, true, Wp, dWp, Hp);
          law.derivatives(xm, part, true, Wm, dWm, Hp);
          worst_g = std::max(worst_g, std::abs((Wp - Wm) / (2 * step) - dW[k]));
          scale_g = std::max(scale_g, std::abs(dW[k]));
          for (unsigned int l = 0; l < 8; ++l)
            {
              worst_H = std::max(worst_H, std::abs((dWp[l] - dWm[l]) / (2 * step) - H[8 * l + k]));
              scale_H = std::max(scale_H, std::abs(H[8 * l + k]));
            }
        }
      const std::string name = part == PlatePart::transverse_shear ? "shear" : "membrane-bending";
      check_close(name + ": dW against differences", worst_g / scale_g, 0, 0, 1e-9);
      check_close(name + ": ddW against differences", worst_H / scale_H, 0, 0, 1e-9);
    }

  // The Taylor form on Sacado numbers: AD of membrane_bending_energy gives
  // the law's own gradient and Hessian (the kinematics rely on it).
  {
    std::array<double, 8>  g, dW;
    std::array<double, 64> Hd, H;
    double                 W = 0, W0 = 0;
    materials::internal::differentiate<8>(
      x,
      [&](const auto &y) {
        using Number = std::decay_t<decltype(y[0])>;
        materials::PlateStrains<Number> t{{{y[0], y[1], y[2]}}, {{y[3], y[4], y[5]}}, {{y[6], y[7]}}};
        Number w = law.membrane_bending_energy(t);
        w += law.shear_energy(t);
        return w;
      },
      true, W, g, Hd);
    double worst_t = std::abs(W - W_mb - W_s) / (W_mb + W_s);
    for (const PlatePart part : {PlatePart::membrane_and_bending, PlatePart::transverse_shear})
      {
        law.derivatives(x, part, true, W0, dW, H);
        for (unsigned int k = 0; k < 8; ++k)
          {
            // the parts' measures do not overlap: each entry is one part's
            if (dW[k] != 0)
              worst_t = std::max(worst_t, std::abs(g[k] - dW[k]) / std::abs(dW[k]));
            for (unsigned int l = 0; l < 8; ++l)
              if (H[8 * k + l] != 0)
                worst_t = std::max(worst_t, std::abs(Hd[8 * k + l] - H[8 * k + l]) / std::abs(H[8 * k + l]));
          }
      }
    check_close("Taylor form on Sacado numbers = the law's derivatives", worst_t, 0, 0, 1e-13);
  }
  return cosmo_test::report();
}
