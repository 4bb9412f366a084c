// Benchmark (issue "part 2"): states per second of the strip along a twist
// path at zero axial force (stiffness at every state), at about 200 and 800
// field DoFs, and the wall time per phase. Release build.
//   benchmark_strip_twist
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/ranks.h>

#include "strip_problem.h"

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
  std::cout << "strip w = 1, h = 0.02, twist to kappa3 = 0.8 at zero axial force, 40 states, Q2\n"
            << std::setw(7) << "cells" << std::setw(7) << "DoFs" << std::setw(9) << "states"
            << std::setw(10) << "Newton" << std::setw(11) << "assembly" << std::setw(11)
            << "factorize" << std::setw(9) << "solves" << std::setw(11) << "total [s]"
            << std::setw(13) << "states/s" << "\n";
  for (const unsigned int cells : {20u, 80u})
    {
      ParameterHandler prm;
      strip::StripProblem::declare_parameters(prm);
      prm.parse_input_from_string(
        "subsection Strip\n set Width = 1\n set Thickness = 0.02\n set Number of cells = " +
        std::to_string(cells) +
        "\nend\nsubsection Rod strains\n set Mode = prescribed strains\n set Strains = 0, 0, 1, 0, 0, 0.8\n"
        " set Free strains = nu3\nend\n"
        "subsection Continuation\n set Initial step = 0.025\n set Maximum step = 0.025\nend\n");
      strip::StripProblem problem;
      problem.parse_parameters(prm);
      problem.set_quiet(true);
      const auto start = std::chrono::steady_clock::now();
      problem.setup_system();
      problem.solve();
      const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const auto & t      = problem.timings();
      const double states = problem.path().size();
      std::cout << std::setw(7) << cells << std::setw(7) << problem.n_field_dofs() << std::setw(9)
                << states << std::setw(10) << t.calls("factorization") << std::setw(11)
                << std::setprecision(3) << t.seconds("assembly (Jacobian)") + t.seconds("assembly (residual)")
                << std::setw(11) << t.seconds("factorization") << std::setw(9) << t.seconds("solve")
                << std::setw(11) << total << std::setw(13) << states / total << "\n";
    }
}
