// Unit tests of the rod's penalty self-contact (assembly/self_contact.h,
// doc/theory-rod.md 9): the grid search finds exactly the pairs a search of
// all pairs finds; a pair's gradient and Hessian are the derivatives of its
// energy (central differences); the force between two strands crossing at
// right angles converges, as the nodes get closer, to the closed form of
// the double integral, (2 pi k/3) delta^3 (2a - delta).
#include <deal.II/base/tensor.h>

#include <cosmo/assembly/self_contact.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace dealii;
using cosmo::assembly::SelfContact;
using cosmo_test::check_close;

namespace
{
  Tensor<1, 3>
  point(const double x, const double y, const double z)
  {
    return Tensor<1, 3>({x, y, z});
  }

  /// A ring of n nodes wound twice round a torus (a (2,3) torus knot), tight enough to come near itself.
  std::vector<Tensor<1, 3>>
  knot(const unsigned int n)
  {
    std::vector<Tensor<1, 3>> x(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double s = 2 * M_PI * k / n;
        x[k] = point((2 + 0.6 * std::cos(3 * s)) * std::cos(2 * s), (2 + 0.6 * std::cos(3 * s)) * std::sin(2 * s),
                     0.6 * std::sin(3 * s));
      }
    return x;
  }

  void
  search_is_exhaustive()
  {
    const unsigned int n = 400;
    const auto         x = knot(n);
    for (const double ring : {0., 1.})
      {
        const double        a = 0.2, L = 40.;
        std::vector<double> w(n, L / n), s(n);
        for (unsigned int k = 0; k < n; ++k)
          s[k] = k * L / n;
        const SelfContact contact(a, 1., w, s, ring * L);
        for (const double distance : {2 * a, 3 * a})
          {
            std::vector<std::pair<unsigned int, unsigned int>> all;
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = i + 1; j < n; ++j)
                {
                  double along = s[j] - s[i];
                  if (ring > 0)
                    along = std::min(along, L - along);
                  if (along > M_PI * a * (1 + 1e-12) && (x[j] - x[i]).norm() < distance)
                    all.emplace_back(i, j);
                }
            const auto found = contact.pairs_within(x, distance);
            cosmo_test::check(std::string(ring > 0 ? "ring" : "open") + ": grid search = all pairs within " +
                                std::to_string(distance) + " (" + std::to_string(all.size()) + " pairs)",
                              found == all && !all.empty());
          }
      }
  }

  void
  derivatives()
  {
    // Two nodes 1.3a apart (far apart along the rod): the energy's central
    // differences against the gradient and Hessian. The truncation error of
    // step e is e^2/6 of the third derivative, ~ k e^2, and the round-off
    // eps E/e: the tolerances below are 1e3 times both.
    const double        a = 0.5, k = 7.;
    std::vector<double> w{0.1, 0.2}, s{0., 10.};
    const SelfContact   contact(a, k, w, s, 0.);
    std::vector<Tensor<1, 3>> x{point(0.1, 0.2, 0.3), point(0.1 + 0.5, 0.2 - 0.3, 0.3 + 0.3)};
    const auto                terms = contact.terms(x);
    cosmo_test::check("one pair in contact", terms.size() == 1);
    const double e = 1e-5;
    auto energy = [&](const std::vector<Tensor<1, 3>> &y) {
      const auto t = contact.terms(y);
      return t.empty() ? 0. : t[0].energy;
    };
    auto gradient = [&](const std::vector<Tensor<1, 3>> &y) { return contact.terms(y)[0].gradient_i; };
    double worst_g = 0, worst_h = 0;
    for (unsigned int c = 0; c < 3; ++c)
      {
        auto plus = x, minus = x;
        plus[0][c] += e;
        minus[0][c] -= e;
        worst_g = std::max(worst_g, std::abs((energy(plus) - energy(minus)) / (2 * e) - terms[0].gradient_i[c]));
        const Tensor<1, 3> dg = (gradient(plus) - gradient(minus)) / (2 * e);
        for (unsigned int d = 0; d < 3; ++d)
          worst_h = std::max(worst_h, std::abs(dg[d] - terms[0].hessian[d][c]));
        // Node j's gradient is node i's opposite (the energy depends on x_i - x_j).
        auto plus_j = x, minus_j = x;
        plus_j[1][c] += e;
        minus_j[1][c] -= e;
        worst_g = std::max(worst_g, std::abs((energy(plus_j) - energy(minus_j)) / (2 * e) + terms[0].gradient_i[c]));
      }
    const double scale = w[0] * w[1] * k;
    check_close("gradient against central differences", worst_g, 0, 0, 1e3 * scale * (e * e + 1e-16 / e));
    check_close("Hessian against central differences", worst_h, 0, 0, 1e3 * scale * (e * e + 1e-16 / e));
  }

  /// The force pressing strand 2 (along e2, at height d) on strand 1 (along e1) with nodes h apart.
  double
  crossing_force(const double a, const double k, const double d, const double h)
  {
    const int                 m = static_cast<int>(std::ceil(2.5 * a / h));
    std::vector<Tensor<1, 3>> x;
    std::vector<double>       w, s;
    for (int strand = 0; strand < 2; ++strand)
      for (int i = -m; i <= m; ++i)
        {
          x.push_back(strand == 0 ? point(i * h, 0, 0) : point(0, i * h, d));
          w.push_back(h);
          s.push_back(strand * 1e3 + i * h); // (the strands far apart along the rod)
        }
    const SelfContact contact(a, k, w, s, 0.);
    double            force = 0;
    for (const auto &t : contact.terms(x))
      force += t.i < x.size() / 2 && t.j >= x.size() / 2 ? t.gradient_i[2] : 0.;
    // (dE/dx_i = -c g^2 n with n from strand 2 down to strand 1: its z
    // component is the magnitude of the push on strand 1)
    return force;
  }

  void
  crossing_strands()
  {
    // E = (k/3) int int g^3 dA over the disc where g = 2a - sqrt(d^2 + rho^2)
    // > 0: F = -dE/dd = (2 pi k/3) delta^3 (2a - delta), delta = 2a - d.
    const double a = 1, k = 3, delta = 0.3 * a;
    const double exact = 2 * M_PI * k / 3 * std::pow(delta, 3) * (2 * a - delta);
    std::vector<double> errors;
    for (const double h : {a / 5, a / 10, a / 20})
      {
        errors.push_back(std::abs(crossing_force(a, k, 2 * a - delta, h) / exact - 1));
        std::cout << "  h = a/" << a / h << ": force / closed form - 1 = " << errors.back() << "\n";
      }
    // The integrand g^3 is C2 with a jump of its third derivative on the
    // circle g = 0: the trapezoidal rule converges at least at second order.
    cosmo_test::check("the force converges at least at second order in h",
                      errors[1] < errors[0] / 4 * 1.1 && errors[2] < errors[1] / 4 * 1.1);
    // (second order from the coarsest, h = a/5, bounds the finest's error
    // by 1/16 of it; measured 2.5e-6 against 6e-4 / 16)
    check_close("h = a/20: the force at the closed form", errors[2], 0, 0, errors[0] / 16);
  }
} // namespace

int
main()
{
  search_is_exhaustive();
  derivatives();
  crossing_strands();
  return cosmo_test::report();
}
