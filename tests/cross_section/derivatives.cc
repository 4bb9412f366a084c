// test_cross_section: the resultants, the stiffness and the tangent against finite differences, without and with surface layers.
#include "common.h"

using namespace cross_section_test;

namespace
{

  // (n, m) against central differences of the energy Psi(e) = min_u E(u, e)
  // (each perturbed state re-solved), and K against central differences of
  // (n, m): the envelope theorem and the Schur-complement condensation.
  void
  resultants_and_stiffness_fd(const std::string &surface = "")
  {
    auto p = make_problem(section(" set Shape = ellipse\n set Semi-axes = 1, 0.7", 2) +
                          material(1, "1", 1.0, 0.3,
                                   " set Growth kind = fibre\n set Growth factor = 1 + 0.2*x - 0.1*y\n"
                                   " set Fibre direction = 0.3; 0.2*x; 1") + surface +
                          strains_block("prescribed strains", {{0.04, -0.02, 1.05, 0.2, -0.15, 0.25}}));
    const auto   s0 = p->solve();
    Vector<double> U  = p->current_solution(); // each point continued from the last
    const Strains e0 = s0.strains;
    const double  h  = 1e-4;
    std::cout << "central differences, h = " << h << ", " << p->n_field_dofs() << " DoFs\n";
    std::array<std::array<double, 6>, 6> dres;
    for (unsigned int k = 0; k < 6; ++k)
      {
        Strains ep = e0, em = e0;
        ep[k] += h;
        em[k] -= h;
        const auto sp = assembly::resolve_strains(*p, U, p->newton_settings, ep);
        const auto sm = assembly::resolve_strains(*p, U, p->newton_settings, em);
        // Truncation ~ h^2 Psi''' ~ 1e-8 relative; Newton tolerance 1e-12.
        check_close("dPsi/d" + kinematics::strain_names[k] + " = " + kinematics::resultant_names[k],
                    s0.resultants[k], (sp.energy - sm.energy) / (2 * h), 1e-6, 1e-9);
        for (unsigned int a = 0; a < 6; ++a)
          dres[a][k] = (sp.resultants[a] - sm.resultants[a]) / (2 * h);
      }
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int k = 0; k < 6; ++k)
        check_close("K(" + std::to_string(a) + "," + std::to_string(k) + ") = FD of resultants",
                    s0.stiffness(a, k), dres[a][k], 1e-6, 1e-8);
    // At a general grown and strained state (all couplings nonzero) the
    // condensed stiffness, not symmetrized anywhere, is symmetric.
    check_symmetric_positive(s0.stiffness, "general state");
  }

  // The AD tangent (bordered Jacobian) against central differences of the
  // residual, at a state that is not an equilibrium, all strains free.
  void
  tangent_fd(const std::string &surface = "")
  {
    auto p = make_problem(section(" set Shape = half disc\n set Radius = 1", 1) +
                          material(1, "1", 1.0, 0.3, " set Growth kind = axial\n set Growth factor = 1.2") +
                          material(2, "2", 2.5, 0.2, " set Growth kind = isotropic\n set Growth factor = 0.9 + 0.1*y") +
                          surface +
                          strains_block("prescribed strains", {{0.1, 0.05, 1.1, 0.3, -0.2, 0.4}}));
    p->solve();
    Vector<double>     U;
    const double       error = cosmo_test::tangent_fd_error(*p, p->current_solution(), U);
    const unsigned int n     = p->n_unknowns();
    // The threaded assembly (WorkStream) gives the residual of the serial one.
    {
      Vector<double> R1(n), R2(n);
      MultithreadInfo::set_thread_limit(1);
      p->residual(U, R1);
      MultithreadInfo::set_thread_limit(2);
      p->residual(U, R2);
      MultithreadInfo::set_thread_limit(1);
      R2 -= R1;
      check_close("threaded vs serial residual, max diff / max |R|", R2.linfty_norm() / R1.linfty_norm(), 0, 0, 1e-15);
    }
    // Measured 3.5e-10.
    check_close("max |J v - FD| / max |J v|", error, 0, 0, 1e-8);
    // A Jacobian stored at another state (the critical-point estimate's
    // products): the derivative there, to the same resolution, and the
    // factorization and blocks in place untouched.
    bool         unchanged = false;
    const double stored    = cosmo_test::stored_jacobian_error(*p, U, unchanged);
    check_close("stored Jacobian at another state: max |J v - FD| / max |J v|", stored, 0, 0, 1e-8);
    check("storing it leaves the factorization and the assembled blocks as they were (bitwise)", unchanged);
  }
} // namespace

void
cross_section_test::add_derivatives_cases(cosmo_test::Cases &cases)
{
  cases["resultants_and_stiffness_fd"] = [] { resultants_and_stiffness_fd(); };
  cases["tangent_fd"] = [] { tangent_fd(); };
  cases["surface_resultants_and_stiffness_fd"] = [] { resultants_and_stiffness_fd(general_surface); };
  cases["surface_tangent_fd"] = [] { tangent_fd(general_surface); };
}
