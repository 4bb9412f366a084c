#ifndef cosmo_applications_rod_run_h
#define cosmo_applications_rod_run_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>

#include "rod_problem.h"

/**
 * The run of the rod application: the start (the reference state solved at
 * the path's start), the path with its events and checkpoints, summary.json.
 */
namespace cosmo
{
  namespace rod
  {
    class RodRun
    {
    public:
      void
      parse_parameters(ParameterHandler &prm)
      {
        problem.parse_parameters(prm);
      }
      void
      run(const io::RunOptions &options, const ParameterHandler &prm);
      void
      save_progress(io::CheckpointWriter &w) const;
      void
      load_progress(io::CheckpointReader &r);

      RodProblem problem;

    private:
      void
      solve_start();
      /// io::InputError if an element of the start turns past the largest rotation.
      void
      check_start() const;
      void
      follow_path();
      void
      finish_run();
      /// summary.json's record of located event k.
      io::JSON
      event_json(unsigned int k);
    };

    void
    run_rod(ParameterHandler &prm, const io::RunOptions &options);
  } // namespace rod
} // namespace cosmo

#endif
