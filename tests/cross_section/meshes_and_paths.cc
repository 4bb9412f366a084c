// test_cross_section: gmsh sections, arclength paths, the coarse-mesh start, solving again after a path.
#include "common.h"

using namespace cross_section_test;

namespace
{

  // A gmsh mesh (ASCII .msh, physical surfaces 7 and 9, not centred) is
  // shifted to its centroid and its regions carry their own materials.
  // Poisson 0: the composite section's small-strain stiffness is exact in
  // beam theory, EA = sum E_i A_i, coupling int E X2, EI1 = int E X2^2, and
  // the fields are polynomials in the FE space (round-off agreement).
  void
  gmsh_section()
  {
    const double E7 = 1, E9 = 3, W = 1, h = 0.25; // layers [-h, 0], [0, h] after the shift
    auto p = make_problem("subsection Cross-section\n set Shape = gmsh\n set Mesh file = " + data_directory +
                          "/offset_bilayer.msh\n set Global refinements = 1\nend\n" +
                          material(1, "7", E7, 0.0) + material(2, "9", E9, 0.0) +
                          strains_block("prescribed strains", reference_strains));
    const auto  s = p->solve();
    const auto &K = s.stiffness;
    std::cout << "gmsh bilayer, " << p->n_field_dofs() << " DoFs\n";
    check_close("area", p->get_discretization().properties().area, W * 2 * h, 1e-13);
    check_close("EA = sum E_i A_i", K(2, 2), (E7 + E9) * W * h, 1e-10);
    check_close("stretch-bending coupling int E X2", K(2, 3), (E9 - E7) * W * h * h / 2, 1e-10);
    check_close("EI1 = int E X2^2", K(3, 3), (E7 + E9) * W * h * h * h / 3, 1e-10);
    check_close("EI2 = int E X1^2", K(4, 4), (E7 + E9) * h * W * W * W / 12, 1e-10);
  }

  // The shared arclength driver on part 1: with linear axial growth every
  // state of the path is the exact natural state kappa2 = -g1 t (anchor 2),
  // so the arclength path must lie on it, stay stable and find no event.
  void
  arclength_linear_growth()
  {
    auto p = make_problem(section(" set Shape = circle\n set Radius = 1", 2) +
                          material(1, "1", 1.0, 0.3, " set Growth kind = axial\n set Growth factor = 1 + 0.3*x") +
                          strains_block("natural shape", reference_strains) +
                          "subsection Path following\n set Method = arclength\nend\n"
                          "subsection Arclength continuation\n set Parameter range = 0, 1\n"
                          " set Initial step = 0.1\n set Maximum step = 0.3\nend\n");
    p->solve();
    double       worst = 0, t_max = 0;
    unsigned int unstable = 0;
    for (const auto &pt : p->path())
      {
        worst = std::max({worst, std::abs(pt.strains[4] + 0.3 * pt.t), std::abs(pt.strains[2] - 1)});
        unstable += pt.n_negative != 0;
        t_max = std::max(t_max, pt.t);
      }
    std::cout << p->path().size() << " states up to t = " << t_max << "\n";
    check_close("every state on kappa2 = -0.3 t, nu3 = 1", worst, 0, 0, 1e-9);
    check("the path reaches t = 1", t_max >= 1);
    check("stable everywhere, no event (" + std::to_string(unstable) + " unstable, " +
            std::to_string(p->events().size()) + " events)",
          unstable == 0 && p->events().empty());
  }

  // A section given as a gmsh .geo (meshed by the application) reproduces the
  // built-in section of the same shape: the 2 x 1 rectangle, unstructured
  // quadrilaterals against the built-in structured mesh. Both converge to the
  // same closed forms; their difference is discretization error.
  void
  gmsh_geo_section()
  {
    const double E = 1.0, poisson = 0.25, G = E / (2 * (1 + poisson)), W = 2, H = 1;
    auto builtin = make_problem(section(" set Shape = rectangle\n set Width = 2\n set Height = 1", 4) +
                                material(1, "1", E, poisson) +
                                strains_block("prescribed strains", reference_strains));
    auto geo = make_problem("subsection Cross-section\n set Shape = gmsh\n set Mesh file = " +
                            data_directory + "/rectangle.geo\n set Mesh size = 0.2\n set Global refinements = 0\nend\n" +
                            material(1, "section", E, poisson) +
                            strains_block("prescribed strains", reference_strains));
    const auto Kb = builtin->solve().stiffness;
    const auto Kg = geo->solve().stiffness;
    std::cout << "built-in rectangle " << builtin->n_field_dofs() << " DoFs, gmsh .geo "
              << geo->n_field_dofs() << " DoFs\n";
    // Stretch: the exact field is linear, in the isoparametric space of any
    // straight-sided mesh: round-off on both.
    check_close(".geo: EA = E W H", Kg(2, 2), E * W * H, 1e-10);
    // Bending at this Poisson ratio comes out exact too (measured 1e-15).
    // Shear and torsion need cubic and singular fields: measured 7e-7 and
    // 9e-6 (shear), 8e-6 (torsion) on the .geo mesh, 6e-6 apart from the
    // built-in mesh.
    const std::array<double, 6> exact = {5. / 6 * G * W * H, 5. / 6 * G * W * H, E * W * H,
                                         E * W * H * H * H / 12, E * H * W * W * W / 12,
                                         G * rectangle_torsion_constant(W, H)};
    for (unsigned int k = 0; k < 6; ++k)
      {
        check_close(".geo: K_" + kinematics::strain_names[k] + " against its closed form", Kg(k, k), exact[k], 2e-5);
        check_close(".geo against built-in: K_" + kinematics::strain_names[k], Kg(k, k), Kb(k, k), 2e-5);
      }
    check_close(".geo: max off-diagonal / EA", off_diagonal_max(Kg) / Kg(2, 2), 0, 0, 1e-5);
    check_symmetric_positive(Kg, ".geo rectangle");
  }
  // resolve() after a run along 'Path' waypoints goes to the strains it is
  // given, not to the path's end (the waypoints must be cleared: a latent
  // bug in which the requested strains were silently ignored). Prescribed
  // strain rows are linear: Newton meets them to round-off, ~eps, so 1e-14
  // absolute on strains of order 1 is 50x the resolution.
  void
  resolve_after_path()
  {
    std::string strains = strains_block("prescribed strains", reference_strains);
    strains.insert(strains.rfind("end\n"), " set Path = 0,0,1,0.05,0,0; 0,0,1,0.05,0,0.05\n");
    auto p = make_problem(section(" set Shape = rectangle\n set Width = 1\n set Height = 0.5", 2) +
                          material(1, "1", 1., 0.3) + strains);
    const auto end = p->solve();
    Vector<double> U   = p->current_solution();
    check_close("the path ends at its last waypoint: kappa3", end.strains[5], 0.05, 0, 1e-14);
    const Strains requested = {0, 0, 1.01, 0.02, -0.01, 0.03};
    const auto    s         = assembly::resolve_strains(*p, U, p->newton_settings, requested);
    for (unsigned int k = 0; k < 6; ++k)
      check_close("resolve goes to the requested " + kinematics::strain_names[k], s.strains[k],
                  requested[k], 0, 1e-14);
  }
  // Nested iteration ('Coarse-mesh start'): the first step solved on the section refined once
  // and twice less, interpolated, starts Newton on the full mesh. The converged state is the
  // full mesh's, so it must equal the state reached from the reference state to Newton's
  // resolution, in fewer iterations on the full mesh. A growth quadratic in X2, so that the
  // natural state is not in the FE space (with 1 + 0.3 X1 it is, u = 0, and the interpolated
  // coarse state would already be the answer).
  void
  coarse_mesh_start()
  {
    auto run = [](const unsigned int levels) {
      auto p = make_problem(section(" set Shape = circle", 3) +
                            material(1, "1", 1.0, 0.3,
                                     " set Growth kind = axial\n set Growth factor = 1 + 0.3*x + 0.3*y*y") +
                            strains_block("natural shape", reference_strains) +
                            "subsection Nonlinear solver\n set Coarse-mesh start = " +
                            std::to_string(levels) +
                            "\nend\nsubsection Continuation\n set Initial step = 1\n set Maximum step = 1\nend\n");
      const auto s = p->solve();
      return std::make_pair(s, p->newton_iterations());
    };
    const auto [direct, n_direct] = run(0);
    const auto [nested, n_nested] = run(2);
    std::cout << "Newton iterations on the full mesh: " << n_direct << " from the reference state, "
              << n_nested << " from the coarser meshes\n";
    check("the coarse-mesh start saves at least two Newton iterations", n_nested + 2 <= n_direct);
    // Both end below Newton's relative tolerance 1e-12 (make_problem): the strains, O(1), agree
    // to the state's resolution, about 1e-12 times the condition of the 6x6 stiffness (~10);
    // measured 1e-13 to 1e-12 (where the direct start's fourth iteration stops, 8.3e-13).
    for (unsigned int k = 0; k < 6; ++k)
      check_close("strain " + kinematics::strain_names[k], nested.strains[k], direct.strains[k], 0,
                  1e-10);
    check_close("not the trivial state: kappa2 != -0.3 (quadratic growth)", std::abs(direct.strains[4] + 0.3),
                0.0137, 0.05);
    double dK = 0, K = 0;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        {
          dK = std::max(dK, std::abs(nested.stiffness(i, j) - direct.stiffness(i, j)));
          K  = std::max(K, std::abs(direct.stiffness(i, j)));
        }
    check_close("stiffness, max difference / max entry", dK / K, 0, 0, 1e-9);
  }
} // namespace

void
cross_section_test::add_meshes_and_paths_cases(cosmo_test::Cases &cases)
{
  cases["gmsh_section"] = gmsh_section;
  cases["gmsh_geo_section"] = gmsh_geo_section;
  cases["arclength_linear_growth"] = arclength_linear_growth;
  cases["resolve_after_path"] = resolve_after_path;
  cases["coarse_mesh_start"] = coarse_mesh_start;
}
