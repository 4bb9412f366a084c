// Unit tests of the growth-decomposed materials: the Sacado stress and
// tangent against central differences of the energy, frame indifference,
// and the stress-free state F = Fg.
#include <deal.II/base/parameter_handler.h>

#include <cosmo/materials/material.h>

#include "test_tools.h"

using namespace dealii;
using namespace cosmo::materials;
using cosmo_test::check_close;

int
main()
{
  const Tensor<2, 3> F({{1.1, 0.2, -0.1}, {0.05, 0.9, 0.3}, {-0.2, 0.1, 1.2}});
  // A general (non-symmetric) growth tensor: the energy is Jg W(F Fg^-1).
  const Tensor<2, 3> Fg({{1.2, 0.1, 0.0}, {0.0, 0.95, 0.05}, {0.1, 0.0, 1.3}});

  // every registered law
  for (const auto &[name, entry] : cosmo::plugins::Registry<HyperelasticLaw>::entries())
    {
      std::cout << name << "\n";
      GrowingMaterial m;
      m.law = HyperelasticLaw::create(name, 2.0, 0.3);
      EnergyDerivatives d;
      m.evaluate(F, Fg, true, d);

      // Central differences with h = 1e-5: truncation ~h^2 |W'''| ~ 1e-10,
      // round-off ~ eps |W| / h ~ 1e-11.
      const double h = 1e-5;
      for (unsigned int a = 0; a < 9; ++a)
        {
          Tensor<2, 3> Fp = F, Fm = F;
          Fp[a / 3][a % 3] += h;
          Fm[a / 3][a % 3] -= h;
          EnergyDerivatives dp, dm;
          m.evaluate(Fp, Fg, false, dp);
          m.evaluate(Fm, Fg, false, dm);
          check_close(name + " P[" + std::to_string(a) + "] vs FD of W", d.P[a],
                      (dp.energy - dm.energy) / (2 * h), 1e-8, 1e-9);
          for (unsigned int b = 0; b < 9; ++b)
            check_close(name + " C[" + std::to_string(a) + "," + std::to_string(b) + "] vs FD of P",
                        d.C[9 * b + a], (dp.P[b] - dm.P[b]) / (2 * h), 1e-7, 1e-8);
        }

      // Frame indifference: W(Q F) = W(F) for a rotation Q.
      const double       c = std::cos(0.7), s = std::sin(0.7);
      const Tensor<2, 3> Q({{c, -s, 0}, {s, c, 0}, {0, 0, 1}});
      EnergyDerivatives  dq;
      m.evaluate(Q * F, Fg, false, dq);
      check_close(name + " W(QF) = W(F)", dq.energy, d.energy, 1e-13);

      // Stress-free grown state: F = Fg gives W = 0 and P = 0.
      EnergyDerivatives d0;
      m.evaluate(Fg, Fg, false, d0);
      double pmax = 0;
      for (const double p : d0.P)
        pmax = std::max(pmax, std::abs(p));
      check_close(name + " W(Fg) = 0", d0.energy, 0, 0, 1e-14);
      check_close(name + " |P(Fg)| = 0", pmax, 0, 0, 1e-14);

      // Small-strain limit: C at F = I is the isotropic elasticity tensor
      // (lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk)).
      EnergyDerivatives dI;
      m.evaluate(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>(), true, dI);
      check_close(name + " C_1111 = lambda + 2 mu", dI.C[0], m.law->lambda + 2 * m.law->mu, 1e-13);
      check_close(name + " C_1122 = lambda", dI.C[9 * 0 + 4], m.law->lambda, 1e-13);
      check_close(name + " C_1212 = mu", dI.C[9 * 1 + 1], m.law->mu, 1e-13);
    }

  // Growth tensors from expressions.
  {
    std::cout << "growth tensors\n";
    ParameterHandler prm;
    GrowthTensor::declare_parameters(prm);
    prm.set("Growth kind", "helical fibre");
    prm.set("Growth factor", "1 + 0.5*x");
    prm.set("Fibre angle", "30");
    GrowthTensor g;
    g.parse_parameters(prm, "test");
    const Point<2>     X(0.4, 0.3);
    const Tensor<2, 3> Fg = g.value(X, 1.0);
    // f = cos(a) E3 + sin(a) E_theta; Fg f = g f and det Fg = g.
    const double       a = M_PI / 6, r = X.norm();
    const Tensor<1, 3> f({-std::sin(a) * X[1] / r, std::sin(a) * X[0] / r, std::cos(a)});
    check_close("helical fibre: det Fg = g", determinant(Fg), 1.2, 1e-14);
    check_close("helical fibre: |Fg f - g f|", (Fg * f - 1.2 * f).norm(), 0, 0, 1e-14);
    check_close("ramp t = 0.5: det Fg = 1 + 0.5 (g - 1)", determinant(g.value(X, 0.5)), 1.1, 1e-14);
  }
  return cosmo_test::report();
}
