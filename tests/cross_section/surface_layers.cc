// test_cross_section: surface layers: small strain, growth of the surface (stretch and curvature).
#include "common.h"

using namespace cross_section_test;

namespace
{

  // ---------------------------------------------------------------------
  // Anchor 5: surface elasticity and surface growth (doc: theory, section 7).

  // Small-strain stiffness of a circle with a surface layer (tau0 = 0):
  // EA and GJ in closed form for any moduli, EI exactly when Poisson = 0 =
  // lambda_s, and to first order in the layer (error ~ mu_s^2) otherwise.
  void
  surface_small_strain()
  {
    const double E = 2.0, R = 1.5;
    auto stiffness = [&](const double poisson, const double lambda_s, const double mu_s) {
      auto p = make_problem(section(" set Shape = circle\n set Radius = 1.5", 3) +
                            material(1, "1", E, poisson) +
                            (mu_s > 0 ? surface_layer(1, "all", 0, lambda_s, mu_s) : "") +
                            strains_block("prescribed strains", reference_strains));
      return p->solve().stiffness;
    };
    for (const double poisson : {0.0, 0.3})
      for (const double lambda_s : {0.0, 0.08})
        {
          const double mu_s = 0.05;
          const double mu = E / (2 * (1 + poisson)), lambda = E * poisson / ((1 + poisson) * (1 - 2 * poisson));
          const auto   K  = stiffness(poisson, lambda_s, mu_s);
          const auto   K0 = stiffness(poisson, 0, 0);
          std::ostringstream tag;
          tag << "Poisson " << poisson << ", lambda_s " << lambda_s << ", mu_s " << mu_s;
          std::cout << tag.str() << "\n";
          // Uniform contraction u_r = a r with the Young-Laplace condition
          // sigma_rr(R) = -sigma_s_thetatheta / R (doc 7.2).
          const double a = -(lambda + lambda_s / R) / (2 * lambda + 2 * mu + (lambda_s + 2 * mu_s) / R);
          const double EA = M_PI * R * R * (2 * lambda * a + lambda + 2 * mu) +
                            2 * M_PI * R * (lambda_s * a + lambda_s + 2 * mu_s);
          // Q2 mapping of the circle: 3e-6 (area), 6e-6 (I) geometric error.
          check_close("  EA with layer (exact)", K(2, 2), EA, 1e-5);
          check_close("  GJ = mu pi R^4/2 + 2 pi mu_s R^3 (exact)", K(5, 5),
                      mu * M_PI * std::pow(R, 4) / 2 + 2 * M_PI * mu_s * std::pow(R, 3), 1e-5);
          const double Es  = (lambda_s + 2 * mu_s) * (1 + poisson * poisson) - 2 * lambda_s * poisson;
          const double dEI = Es * M_PI * std::pow(R, 3); // first order: Es int X1^2 dS
          if (poisson == 0 && lambda_s == 0)
            {
              check_close("  EI1 = E I + 2 mu_s pi R^3 (exact)", K(3, 3), E * M_PI * std::pow(R, 4) / 4 + dEI, 1e-5);
              check_close("  EI2 = E I + 2 mu_s pi R^3 (exact)", K(4, 4), E * M_PI * std::pow(R, 4) / 4 + dEI, 1e-5);
              continue;
            }
          // First-order perturbation: the increment is the layer's energy on
          // the unperturbed (Saint-Venant) field, hoop strain -nu eps_zz.
          // Its error is second order in the layer: halving mu_s and
          // lambda_s divides it by 4 (asymptotically; third-order terms give
          // 3.7 at the first halving, so the rate is taken between the
          // quarter and the eighth layer).
          double err[4];
          for (unsigned int level = 0; level < 4; ++level)
            {
              const double f = 1. / (1u << level);
              const auto   Kf = level == 0 ? K : stiffness(poisson, f * lambda_s, f * mu_s);
              err[level]      = Kf(3, 3) - K0(3, 3) - f * dEI;
            }
          std::cout << "  EI increment " << K(3, 3) - K0(3, 3) << ", first order " << dEI
                    << ", second-order remainder at 1, 1/2, 1/4, 1/8 of the layer " << err[0]
                    << ", " << err[1] << ", " << err[2] << ", " << err[3] << ": ratios "
                    << err[0] / err[1] << ", " << err[1] / err[2] << ", " << err[2] / err[3] << "\n";
          check_close("  EI increment, first order in the layer", K(3, 3) - K0(3, 3), dEI, 0.05);
          check_close("  remainder ratio 1/4 : 1/8 (second order: 4)", err[2] / err[3], 4, 0.05);
          check_close("  EI1 = EI2 (isotropy)", K(4, 4), K(3, 3), 1e-10);
        }
  }

  /// Natural strains of a circle with surface layers (Poisson nu, R = 1, E = 1).
  Strains
  natural_strains(const double poisson, const std::string &layers)
  {
    auto p = make_problem(section(" set Shape = circle\n set Radius = 1", 3) +
                          material(1, "1", 1.0, poisson) + layers +
                          strains_block("natural shape", reference_strains));
    const auto s = p->solve();
    check_close("  multipliers vanish at the natural state", max_abs(s.multipliers), 0, 0, 1e-9);
    return s.strains;
  }

  // Stretch of a circle whose whole lateral surface grows isotropically
  // (g = 1 + delta), and whose surface is under tension tau0 (no growth):
  // linear closed forms of doc 7.3. The nonlinear remainder is even in
  // delta (tau0) to leading order, so the odd part (e(+) - e(-))/2 must
  // match the linear answer to O(delta^2).
  void
  surface_growth_stretch()
  {
    const double poisson = 0.3, R = 1, mu = 1 / (2 * (1 + poisson)),
                 lambda = poisson / ((1 + poisson) * (1 - 2 * poisson)), lambda_s = 0.1, mu_s = 0.1;
    // [a11 a12; a21 a22] (a, eps) = (b1, b2), a = radial strain of the section.
    const double a11 = 2 * lambda + 2 * mu + (lambda_s + 2 * mu_s) / R, a12 = lambda + lambda_s / R;
    const double a21 = 2 * lambda * R * R + 2 * R * lambda_s,
                 a22 = (lambda + 2 * mu) * R * R + 2 * R * (lambda_s + 2 * mu_s);
    auto eps_of = [&](const double b1, const double b2) {
      return (a11 * b2 - a21 * b1) / (a11 * a22 - a12 * a21);
    };
    const double delta = 0.01, tau0 = 0.01;
    {
      std::cout << "isotropic surface growth g = 1 +- " << delta << " on the whole boundary\n";
      auto growth = [&](double d) {
        std::ostringstream g;
        g << " set Growth kind = isotropic\n set Growth factor = " << std::setprecision(17) << 1 + d;
        return surface_layer(1, "all", 0, lambda_s, mu_s, g.str());
      };
      const Strains ep = natural_strains(poisson, growth(delta)), em = natural_strains(poisson, growth(-delta));
      const double  eps_lin = eps_of((2 * lambda_s + 2 * mu_s) * delta / R, 2 * R * (2 * lambda_s + 2 * mu_s) * delta);
      std::cout << "  nu3 - 1 = " << ep[2] - 1 << " (+delta), " << em[2] - 1 << " (-delta), linear " << eps_lin << "\n";
      check_close("  odd part of the natural stretch", (ep[2] - em[2]) / 2, eps_lin, 1e-3);
      check_close("  even part is O(delta^2)", (ep[2] + em[2]) / 2 - 1, 0, 0, 10 * delta * std::abs(eps_lin));
      double others = 0;
      for (unsigned int k : {0u, 1u, 3u, 4u, 5u})
        others = std::max({others, std::abs(ep[k]), std::abs(em[k])});
      check_close("  no shear, bending or twist", others, 0, 0, 1e-10);
    }
    {
      std::cout << "surface tension tau0 = +- " << tau0 << " on the whole boundary\n";
      const Strains ep = natural_strains(poisson, surface_layer(1, "all", tau0, lambda_s, mu_s));
      const Strains em = natural_strains(poisson, surface_layer(1, "all", -tau0, lambda_s, mu_s));
      const double  eps_lin = eps_of(-tau0 / R, -2 * R * tau0);
      std::cout << "  nu3 - 1 = " << ep[2] - 1 << " (+tau0), " << em[2] - 1 << " (-tau0), linear " << eps_lin << "\n";
      check_close("  odd part of the natural stretch (Laplace pressure + axial tension)", (ep[2] - em[2]) / 2, eps_lin, 1e-3);
    }
  }

  // Curvature from axial surface growth g3 = 1 + delta on the half X1 > 0 of
  // the boundary (layer 1, 'arc -90 90'), the other half the same layer
  // without growth (layer 2): at Poisson 0 and lambda_s = 0 the linear
  // solution has no in-plane field and is a composite beam (doc 7.4).
  void
  surface_growth_curvature()
  {
    const double R = 1, mu = 0.5, mu_s = 0.1, delta = 0.01;
    auto layers = [&](double d) {
      std::ostringstream g;
      g << " set Growth kind = tangential and axial\n set Growth factor = 1; " << std::setprecision(17) << 1 + d;
      return surface_layer(1, "arc -90 90", 0, 0, mu_s, g.str()) + surface_layer(2, "arc 90 270", 0, 0, mu_s);
    };
    const Strains ep = natural_strains(0.0, layers(delta)), em = natural_strains(0.0, layers(-delta));
    const double  EA = 2 * mu * M_PI * R * R + 4 * M_PI * R * mu_s;
    const double  EI = 2 * mu * M_PI * std::pow(R, 4) / 4 + 2 * M_PI * mu_s * std::pow(R, 3);
    const double  N  = 2 * mu_s * delta * M_PI * R, M = 2 * mu_s * delta * 2 * R * R;
    std::cout << "axial surface growth 1 +- " << delta << " on X1 > 0: kappa2 = " << ep[4] << ", "
              << em[4] << "; nu3 - 1 = " << ep[2] - 1 << ", " << em[2] - 1 << "\n";
    check_close("odd part of kappa2 = -M*/EI", (ep[4] - em[4]) / 2, -M / EI, 1e-3);
    check_close("odd part of nu3 - 1 = N*/EA", (ep[2] - em[2]) / 2, N / EA, 1e-3);
    double others = 0;
    for (unsigned int k : {0u, 1u, 3u, 5u})
      others = std::max({others, std::abs(ep[k]), std::abs(em[k])});
    check_close("no kappa1, twist or shear (symmetry about X2 = 0)", others, 0, 0, 1e-10);
  }
} // namespace

void
cross_section_test::add_surface_layers_cases(cosmo_test::Cases &cases)
{
  cases["surface_small_strain"] = surface_small_strain;
  cases["surface_growth_stretch"] = surface_growth_stretch;
  cases["surface_growth_curvature"] = surface_growth_curvature;
}
