#ifndef cosmo_applications_rod_run_h
#define cosmo_applications_rod_run_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>

#include <cosmo/solvers/critical_point_study.h>

#include "rod_problem.h"

#include <memory>
#include <vector>

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

      // What a study of critical points asks of a run (solvers::CriticalPointRunOf).
      void
      start_from_critical_point(const solvers::CriticalGuess &g)
      {
        critical_guess = std::make_unique<solvers::CriticalGuess>(g);
      }
      const std::vector<solvers::EventRecord> &
      event_records() const
      {
        return problem.located_events;
      }
      unsigned int
      n_unknowns() const
      {
        return problem.n_unknowns();
      }
      const io::PhaseTimer &
      timings() const
      {
        return problem.timer;
      }
      /// The mode's direction: 1, 2 or 3 for the fixed axis its displacements lie most along.
      std::vector<double>
      classify_critical_mode(const Vector<double> &mode) const;
      /// The supports' axial force at B (along e3) at the critical point.
      std::vector<double>
      critical_point_columns(const solvers::EventRecord &e) const;
      void
      save_progress(io::CheckpointWriter &w) const;
      void
      load_progress(io::CheckpointReader &r);

      RodProblem problem;

    private:
      std::unique_ptr<solvers::CriticalGuess> critical_guess;

      /// A study's point: its critical point located from the guess, no path.
      void
      locate_from_guess();
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
