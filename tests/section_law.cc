// The law of part-1 sections (materials/rod_laws/section.h) and its
// interpolation (base/monotone_cubic.h): the monotone cubic is exact at its
// nodes and for linear data, C1 across the nodes, its derivative that of
// its values, and it neither overshoots nor loses monotonicity; the law
// reads a sweep.csv with a hole and a comma in the value's header, gives
// the interpolated natural strains and stiffness, refuses a p outside the
// family and a sweep not at a natural shape.
#include <deal.II/base/parameter_handler.h>

#include <cosmo/base/monotone_cubic.h>
#include <cosmo/io/parameters.h>
#include <cosmo/materials/rod_laws/section.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace cosmo;
using dealii::ParameterHandler;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  void
  monotone_cubic()
  {
    const std::vector<double> x{0, 0.3, 0.45, 1, 1.7};
    // Linear data: the cubic is the line (every slope is the secant).
    std::vector<double> line;
    for (const double v : x)
      line.push_back(2 - 3 * v);
    const base::MonotoneCubic l(x, line);
    double worst = 0;
    for (double v = 0; v <= 1.7; v += 0.01)
      worst = std::max({worst, std::abs(l.value(v) - (2 - 3 * v)), std::abs(l.derivative(v) + 3)});
    check_close("linear data reproduced (value and slope)", worst, 0, 0, 1e-14);

    // Monotone, unevenly spaced data with a steep step.
    const std::vector<double> y{0, 0.1, 1, 1.05, 3};
    const base::MonotoneCubic c(x, y);
    double at_nodes = 0, jump = 0, fd = 0, decrease = 0, overshoot = 0, previous = c.value(0);
    for (unsigned int i = 0; i < x.size(); ++i)
      at_nodes = std::max(at_nodes, std::abs(c.value(x[i]) - y[i]));
    // C1: the slope from either side of an interior node (1e-9 away; the
    // second derivative is bounded by ~100 here).
    for (unsigned int i = 1; i + 1 < x.size(); ++i)
      jump = std::max(jump, std::abs(c.derivative(x[i] - 1e-9) - c.derivative(x[i] + 1e-9)));
    for (double v = 0.005; v < 1.7; v += 0.005)
      {
        // Central differences away from the nodes (the second derivative
        // jumps there): truncation h^2 |third derivative| / 6 ~ 3e-10 (below
        // 2e3 on the shortest interval), round-off ~1e-10.
        const double h = 1e-6;
        if (std::none_of(x.begin(), x.end(), [&](double n) { return std::abs(v - n) < 2 * h; }))
          fd = std::max(fd, std::abs((c.value(v + h) - c.value(v - h)) / (2 * h) - c.derivative(v)));
        decrease       = std::max(decrease, previous - c.value(v));
        overshoot      = std::max({overshoot, c.value(v) - 3, -c.value(v)});
        previous       = c.value(v);
      }
    check_close("exact at the nodes", at_nodes, 0, 0, 1e-15);
    check_close("C1 across the nodes (slope jump)", jump, 0, 0, 1e-6);
    check_close("derivative = central difference of the value", fd, 0, 0, 1e-8);
    // (round-off of the Hermite sums of values up to 3: a few 1e-16)
    check_close("monotone data stay monotone (largest decrease)", std::max(decrease, 0.), 0, 0, 1e-14);
    check_close("no overshoot beyond the data's range", std::max(overshoot, 0.), 0, 0, 1e-14);
  }

  /// A sweep.csv of rod_cross_section's columns: kappa2 = -p, nu3 = 1 + p^2,
  /// K = diag(1, 1, 3 + p, 0.8 + p^2, 0.8, 0.6) with K_nu3_kappa2 = 0.2 p.
  std::string
  write_sweep(const std::string &name, const bool stressed)
  {
    const std::array<std::string, 6> e{{"nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"}};
    std::ofstream out(name);
    // (a template with a comma in the value's header, as sweep.csv writes it)
    out << "point,value [Material 1/Growth factor = max(1, 1 + {}*x)],converged,energy [E L^2]";
    for (const auto &s : e)
      out << "," << s << " [1]";
    for (const auto &s : {"n1", "n2", "n3", "m1", "m2", "m3"})
      out << "," << s << " [E L^2]";
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = a; b < 6; ++b)
        out << ",K_" << e[a] << "_" << e[b];
    out << ",n_negative_eigenvalues\n";
    const std::vector<double> p{0, 0.1, 0.2, 0.3, 0.4};
    for (unsigned int i = 0; i < p.size(); ++i)
      {
        const double q = p[i];
        out << i << "," << q << "," << (i == 2 ? 0 : 1) << ",0";
        for (const double v : {0., 0., 1 + q * q, 0., -q, 0.})
          out << "," << v;
        for (unsigned int k = 0; k < 6; ++k)
          out << "," << (stressed && k == 4 ? 0.1 : 0.);
        std::array<double, 36> K{};
        const std::array<double, 6> d{{1, 1, 3 + q, 0.8 + q * q, 0.8, 0.6}};
        for (unsigned int k = 0; k < 6; ++k)
          K[7 * k] = d[k];
        K[6 * 2 + 4] = 0.2 * q;
        for (unsigned int a = 0; a < 6; ++a)
          for (unsigned int b = a; b < 6; ++b)
            out << "," << (i == 2 ? NAN : K[6 * a + b]);
        out << ",0\n";
      }
    return name;
  }

  materials::SectionRodLaw
  law_of(const std::string &file, const std::string &parameter)
  {
    ParameterHandler prm;
    materials::SectionRodLaw::declare_parameters(prm);
    prm.set("Section file", file);
    prm.set("Section parameter", parameter);
    materials::SectionRodLaw law;
    law.parse_parameters(prm, "Rod/Material");
    return law;
  }

  void
  section_law()
  {
    const auto dir = std::filesystem::temp_directory_path() / ("cosmo_section_law_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto law = law_of(write_sweep((dir / "sweep.csv").string(), false), "0.4*s*t");
    check_close("the family's range (the hole at p = 0.2 left out)", law.range().second, 0.4, 0);
    check("description names 4 sections and the hole",
          law.description().find("family of 4") != std::string::npos &&
            law.description().find("1 unconverged") != std::string::npos);
    // kappa2 = -p is linear: exact between members, hole or not.
    const auto m = law.member_at(0.25);
    check_close("kappa2(0.25) = -0.25 (linear data)", m.strains[4], -0.25, 1e-14);
    check_close("K_nu3_kappa2(0.25) = 0.05 (linear data)", m.stiffness[6 * 2 + 4], 0.05, 1e-14);
    check_close("symmetric: K_kappa2_nu3 = K_nu3_kappa2", m.stiffness[6 * 4 + 2], m.stiffness[6 * 2 + 4], 0);
    check_close("p(s, t) = 0.4 s t at (0.5, 0.5)", law.parameter_at(0.5, 0.5), 0.1, 1e-15);
    // The energy is 1/2 e.K(p)e: its gradient K e.
    std::array<double, 6>  e{{0.01, -0.02, 0.03, 0.1, -0.2, 0.05}}, dW;
    std::array<double, 36> ddW;
    double                 W = 0;
    law.energy_derivatives_at(0.1, e, true, W, dW, ddW);
    const double n3 = (3 + 0.1) * e[2] + 0.2 * 0.1 * e[4];
    check_close("n3 = K_33 e3 + K_35 e5 at a member", dW[2], n3, 1e-14);
    bool refused = false;
    try
      {
        law.member_at(0.41);
      }
    catch (materials::LawRangeError &error)
      {
        refused = std::string(error.what()).find("[0, 0.4]") != std::string::npos;
      }
    check("p = 0.41 outside [0, 0.4]: LawRangeError naming the range", refused);
    bool stressed = false;
    try
      {
        law_of(write_sweep((dir / "stressed.csv").string(), true), "0");
      }
    catch (io::InputError &error)
      {
        stressed = std::string(error.what()).find("natural shape") != std::string::npos;
      }
    check("a sweep with resultants is refused (not a natural shape)", stressed);
    std::filesystem::remove_all(dir);
  }
} // namespace

int
main()
{
  monotone_cubic();
  section_law();
  return cosmo_test::report();
}
