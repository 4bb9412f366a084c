#include <cosmo/assembly/reduced_rod_table.h>

namespace cosmo
{
  namespace assembly
  {
    ReducedRodState
    resolve_strains(ReducedRodProblem &            problem,
                    Vector<double> &               U,
                    const solvers::NewtonSettings &newton,
                    const std::array<double, 6> &  strains)
    {
      problem.set_target_strains(strains);
      problem.set_load_parameter(1.);
      solvers::newton_solve(problem, U, newton);
      return problem.condensed_state(U);
    }

    void
    run_constitutive_table(const ConstitutiveTable &      table,
                           ReducedRodProblem &            problem,
                           Vector<double> &               U,
                           const solvers::NewtonSettings &newton,
                           ReducedRodState &              last,
                           io::RunRecord &                record,
                           const std::string &            directory,
                           TableDescription               description)
    {
      description.free_strains    = problem.free_strains();
      description.held_resultants = problem.resultants_at(1.);
      // A point: Newton at its prescribed strains from the last converged state.
      const auto resolve = [&](const std::array<double, 6> &strains) {
        last = resolve_strains(problem, U, newton, strains);
        return last;
      };
      table.run_in(record, U, problem.get_target_strains(), problem.strains_of(U), resolve, directory,
                   description);
    }
  } // namespace assembly
} // namespace cosmo
