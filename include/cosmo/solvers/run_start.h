#ifndef cosmo_solvers_run_start_h
#define cosmo_solvers_run_start_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/parameters.h>
#include <cosmo/io/run_record.h>
#include <cosmo/solvers/continuation.h>

#include <string>

namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /**
     * The start of every application's run of `problem`: its directory
     * opened by `record` (claimed, or resumed with its checkpoint), the
     * postprocessors the options carry attached to the problem, and on a
     * mesh distributed over the ranks every step taken by all ranks
     * together (a failure of one rank alone ends all) with the ranks agreed
     * on whether there is a checkpoint to resume.
     */
    void
    start_run(io::RunRecord &         record,
              ContinuationProblem &   problem,
              const io::RunOptions &  options,
              const ParameterHandler &prm,
              const std::string &     output_directory,
              bool                    distributed_mesh);
  } // namespace solvers
} // namespace cosmo

#endif
