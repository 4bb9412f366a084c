// Part 3 benchmark: wall time per continuation step and per stability
// evaluation of the growing plate bounded by a rod, full disc against the
// quarter sector, at two mesh sizes; time from the flat state to the
// located critical growth, with the event located by Newton on the
// augmented system and, for comparison, by bisection of the stability count
// (factorizations spent between detection and location). Run from the build
// directory:
//   ./benchmark_plate_rod_growth [max refinements = 5]
//   ./benchmark_plate_rod_growth assembly [refinements = 4] [residuals = 50] [Jacobians = 6]
// The second form times the assemblies alone (the quarter sector, at the flat
// state at t = 0.5 plus a smooth perturbation of every unknown), to profile them.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/ranks.h>

#include "run.h"

#include <chrono>
#include <iomanip>
#include <cmath>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace cosmo;

namespace
{
  /// The dome example's plate and rim (closed-form critical t = 0.226) on a sector of 90 degrees.
  std::string
  dome_parameters(const std::string &domain, const unsigned int refinements, const std::string &location)
  {
    std::ostringstream t;
    t << "subsection Plate growth\n set Kind = isotropic\n set Radial growth factor = 1.0004\nend\n"
      << "subsection Rim rod\n set Stiffnesses = 0.1, 0.1, 0.1, 1e-6, 1e-6, 1e-6\nend\n"
      << "subsection Mesh\n set Domain = " << domain << "\n set Sector angle = 90\n"
      << " set Global refinements = " << refinements << "\nend\n"
      << "subsection Growth path\n set Stop at first event = true\nend\n"
      << "subsection Arclength continuation\n set Initial step = 0.05\n set Maximum step = 0.1\n"
      << " set Parameter range = 0, 1\n set Event tolerance = 1e-6\n set Event location = "
      << location << "\nend\n";
    return t.str();
  }

  /// Seconds per residual and per Jacobian assembly (with its factorization apart) at a
  /// state with every field nonzero: the flat state at t = 0.5 plus a smooth perturbation.
  int
  time_assemblies(const unsigned int refinements, const unsigned int calls, const unsigned int jacobians)
  {
    ParameterHandler prm;
    plate_rod::PlateRodProblem::declare_parameters(prm);
    prm.parse_input_from_string(dome_parameters("sector", refinements, "newton"));
    plate_rod::PlateRodRun run;
    run.parse_parameters(prm);
    plate_rod::PlateRodProblem &p = run.get_problem();
    p.set_quiet(true);
    p.setup_system();
    run.solve_flat_state(0.5);
    Vector<double> U = p.current_solution(), R(p.n_unknowns());
    for (unsigned int i = 0; i < U.size(); ++i)
      U[i] += 1e-3 * std::sin(0.37 * i);
    using clock = std::chrono::steady_clock;
    auto start = clock::now();
    // (each call at another state: the problem keeps its last residuals)
    for (unsigned int k = 0; k < calls; ++k)
      {
        U[k % U.size()] += 1e-12;
        p.residual(U, R);
      }
    const double residual =
      std::chrono::duration<double>(clock::now() - start).count() / std::max(1u, calls);
    for (unsigned int k = 0; k < jacobians; ++k)
      p.setup_jacobian(U);
    const auto &tm  = p.timings();
    auto        per = [&](const std::string &phase) {
      return tm.calls(phase) ? tm.seconds(phase) / tm.calls(phase) * 1e3 : 0.;
    };
    std::cout << p.n_unknowns() << " DoFs: residual " << residual * 1e3 << " ms, Jacobian assembly "
              << per("assembly (Jacobian)") << " ms, factorization " << per("factorization")
              << " ms (|R| "
              << R.l2_norm() << ")" << std::endl;
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  const auto mpi = cosmo::io::ranks::init_mpi(argc, argv);
  if (argc > 1 && std::string(argv[1]) == "assembly")
    return time_assemblies(argc > 2 ? std::stoi(argv[2]) : 4, argc > 3 ? std::stoi(argv[3]) : 50,
                           argc > 4 ? std::stoi(argv[4]) : 6);
  const unsigned int               max_refinements = argc > 1 ? std::stoi(argv[1]) : 5;
  std::cout << "domain     location   refs     DoFs  steps  t_critical        resolution  event "
               "factorizations  to critical [s]  per step [s]  Jacobian [s]  factorization [s]  "
               "smallest eig. [s]\n";
  for (const unsigned int k : {4u, max_refinements})
    for (const std::string domain : {"sector", "full disc"})
      for (const std::string location : {"newton", "bisection"})
      {
        ParameterHandler prm;
        plate_rod::PlateRodProblem::declare_parameters(prm);
        prm.parse_input_from_string(dome_parameters(domain, k, location));
        plate_rod::PlateRodRun p;
        p.parse_parameters(prm);
        p.get_problem().set_quiet(true);
        const auto start = std::chrono::steady_clock::now();
        p.get_problem().setup_system();
        p.solve_flat_state(0.);
        p.follow_branches();
        const double total =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto & tm   = p.timings();
        auto         per  = [&](const std::string &phase) {
          return tm.calls(phase) ? tm.seconds(phase) / tm.calls(phase) : 0.;
        };
        const unsigned int steps = p.get_problem().path().size();
        const solvers::BifurcationProblem::Event *e =
          p.event_records().empty() ? nullptr : &p.event_records()[0].event;
        std::cout << std::left << std::setw(11) << domain << std::setw(10) << location << std::right
                  << std::setw(5) << k << std::setw(9) << p.n_unknowns() << std::setw(7) << steps
                  << std::setw(18) << std::setprecision(12) << (e ? e->lambda : NAN)
                  << std::setprecision(3) << std::setw(12)
                  << (e ? solvers::event_resolution(*e) : NAN) << std::setw(22)
                  << (e ? e->factorizations : 0) << std::setw(17) << total << std::setw(14)
                  << total / std::max(1u, steps) << std::setw(14) << per("assembly (Jacobian)")
                  << std::setw(19) << per("factorization") << std::setw(19)
                  << per("stability (smallest eigenvalue)") << std::endl;
        std::cout << "    phases:";
        for (const auto &phase : tm.phases())
          std::cout << "  " << phase << " " << tm.seconds(phase) << " s / " << tm.calls(phase);
        std::cout << std::endl;
      }
}
