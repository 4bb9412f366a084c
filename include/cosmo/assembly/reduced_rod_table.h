#ifndef cosmo_assembly_reduced_rod_table_h
#define cosmo_assembly_reduced_rod_table_h

#include <deal.II/lac/vector.h>

#include <cosmo/assembly/constitutive_table.h>
#include <cosmo/assembly/reduced_rod_problem.h>
#include <cosmo/io/run_record.h>
#include <cosmo/solvers/newton.h>

#include <string>

namespace cosmo
{
  namespace assembly
  {
    /**
     * The state of `problem` at these prescribed strains (at t = 1), by
     * Newton from U, which ends there: a point of a constitutive table, or
     * of a finite-difference check of the stiffness. Clears a 'Path' (its
     * last waypoint would otherwise win at t = 1).
     */
    ReducedRodState
    resolve_strains(ReducedRodProblem &            problem,
                    Vector<double> &               U,
                    const solvers::NewtonSettings &newton,
                    const std::array<double, 6> &  strains);

    /**
     * The constitutive table of a reduced rod around its current state (at
     * t = 1, in U): each point prescribes its strains to the problem and
     * solves by Newton from the neighbour's state, and its condensed state
     * (energy, resultants, stiffness) is the table's entry; `last` is the
     * last point's. The description gets the problem's free strains and
     * held resultants; the files go into `directory`, with the run's
     * checkpoints and --resume (ConstitutiveTable::run_in).
     */
    void
    run_constitutive_table(const ConstitutiveTable &      table,
                           ReducedRodProblem &            problem,
                           Vector<double> &               U,
                           const solvers::NewtonSettings &newton,
                           ReducedRodState &              last,
                           io::RunRecord &                record,
                           const std::string &            directory,
                           TableDescription               description);
  } // namespace assembly
} // namespace cosmo

#endif
