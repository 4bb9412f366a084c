// Benchmark (issue "part 1"): natural shape of the unit disc with axial
// growth g = 1 + 0.3 X1 (neo-Hookean, Poisson 0.3, Q2) at three mesh sizes,
// printing DoFs, Newton iterations and wall time per phase. Release build.
//   benchmark_natural_shape_disc [max refinement, default 5]
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/ranks.h>

#include "cross_section_problem.h"

#include <chrono>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace cosmo;

int
main(int argc, char **argv)
{
  // All cores for the assembly (as the application does).
  const auto mpi = cosmo::io::ranks::init_mpi(argc, argv);
  const unsigned int max_ref = argc > 1 ? std::atoi(argv[1]) : 5;
  std::cout << "natural shape of the unit disc, axial growth g = 1 + 0.3 X1, Q2\n"
            << std::setw(6) << "ref" << std::setw(9) << "DoFs" << std::setw(8) << "Newton"
            << std::setw(11) << "setup" << std::setw(11) << "assembly" << std::setw(11)
            << "factorize" << std::setw(11) << "solves" << std::setw(11) << "total [s]"
            << std::setw(14) << "kappa2 error" << "\n";
  for (unsigned int ref = 3; ref <= max_ref; ++ref)
    {
      const auto       start = std::chrono::steady_clock::now();
      ParameterHandler prm;
      rod::CrossSectionProblem::declare_parameters(prm);
      prm.parse_input_from_string("subsection Cross-section\n set Shape = circle\n set Global refinements = " +
                                  std::to_string(ref) +
                                  "\nend\nsubsection Material 1\n set Growth kind = axial\n"
                                  " set Growth factor = 1 + 0.3*x\nend\n"
                                  "subsection Rod strains\n set Mode = natural shape\nend\n"
                                  "subsection Continuation\n set Initial step = 1\n set Maximum step = 1\nend\n"
                                  "subsection Output\n set Stiffness at every step = false\nend\n");
      rod::CrossSectionProblem problem;
      problem.parse_parameters(prm);
      std::cout.setstate(std::ios::failbit); // silence the per-step lines
      const auto t0 = std::chrono::steady_clock::now();
      problem.setup_system();
      const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto   state = problem.solve();
      std::cout.clear();
      const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const auto &T = problem.timings();
      std::cout << std::setw(6) << ref << std::setw(9) << problem.n_field_dofs() + 12 << std::setw(8)
                << problem.newton_iterations() << std::fixed << std::setprecision(3) << std::setw(11)
                << setup << std::setw(11)
                << T.seconds("assembly (residual)") + T.seconds("assembly (Jacobian)") << std::setw(11)
                << T.seconds("factorization") << std::setw(11) << T.seconds("solve") << std::setw(11)
                << total << std::scientific << std::setprecision(2) << std::setw(14)
                << std::abs(state.strains[4] + 0.3) << std::defaultfloat << "\n";
      std::cout << "       per phase: residual assembly " << T.calls("assembly (residual)") << " x "
                << T.seconds("assembly (residual)") / std::max(1u, T.calls("assembly (residual)"))
                << " s, Jacobian assembly " << T.calls("assembly (Jacobian)") << " x "
                << T.seconds("assembly (Jacobian)") / std::max(1u, T.calls("assembly (Jacobian)"))
                << " s, factorization " << T.calls("factorization") << " x "
                << T.seconds("factorization") / std::max(1u, T.calls("factorization")) << " s\n";
      // The factorization against the machine: its flops (MUMPS's count)
      // over its time; the FMA peak of one core is 16 double flops per cycle (AVX2).
      const auto & solver = problem.bordered_system().solver();
      const double flops  = solver.factorization_flops();
      std::cout << "       factorization: " << std::setprecision(3) << flops / 1e9 << " GFlop, "
                << solver.factor_entries() / 1e6 << " M entries in the factors, "
                << flops / 1e9 / (T.seconds("factorization") / std::max(1u, T.calls("factorization")))
                << " GFlop/s\n";
    }
}
