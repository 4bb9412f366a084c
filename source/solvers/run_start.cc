#include <cosmo/io/ranks.h>
#include <cosmo/solvers/newton.h>
#include <cosmo/solvers/run_start.h>

namespace cosmo
{
  namespace solvers
  {
    void
    start_run(io::RunRecord &         record,
              ContinuationProblem &   problem,
              const io::RunOptions &  options,
              const ParameterHandler &prm,
              const std::string &     output_directory,
              const bool              distributed_mesh)
    {
      record.open(output_directory, prm, options);
      problem.attach_postprocessors(options.postprocessors.get(), output_directory);
      if (distributed_mesh)
        {
          // Every rank takes every step: a failure of one rank alone ends all.
          record.set_lockstep(&is_driver_failure);
          io::ranks::check_checkpoints_agree(record.has_checkpoint() ? 1 : 0, "whether there is one");
        }
    }
  } // namespace solvers
} // namespace cosmo
