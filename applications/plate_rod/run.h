#ifndef cosmo_applications_plate_rod_run_h
#define cosmo_applications_plate_rod_run_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_point_study.h>

#include "plate_rod_problem.h"

#include <memory>
#include <vector>

/**
 * The run of part 3 on its problem (plate_rod_problem.h): the run's
 * directory and log, the closed forms, then the flat state at the start of
 * the growth path and the branches from it, or a critical point continued
 * from a guess (a study's next point); the path's checkpoint after every
 * converged step and the summary at the end. The problem is what the
 * drivers see (the state, its system, what each step and event leaves); the
 * run is the sequence around it, and what a critical-point study asks of a
 * run (solvers::CriticalPointRunOf).
 */
namespace cosmo
{
  namespace plate_rod
  {
    using namespace dealii;

    class PlateRodRun
    {
    public:
      /// The problem's parameters (PlateRodProblem::parse_parameters).
      void
      parse_parameters(ParameterHandler &prm)
      {
        problem.parse_parameters(prm);
      }
      /**
       * A critical point to start from instead of a path from t: run() then
       * locates the critical point by Newton on the augmented system from
       * this guess (the next point of a critical curve) and reports it as
       * the first event. The guess must have the problem's DoFs.
       */
      void
      start_from_critical_point(const solvers::CriticalGuess &g)
      {
        critical_guess = std::make_unique<solvers::CriticalGuess>(g);
      }
      /// The application: the flat state at the start of the path, then the branches.
      void
      run(const io::RunOptions &options, const ParameterHandler &prm);
      /// Solve the flat state at the load parameter t from the current solution.
      void
      solve_flat_state(double t);
      /// Follow the growth path by arclength continuation from the current solution.
      std::vector<solvers::EventRecord>
      follow_branches();

      /// The problem's located events, unknowns and timings (for the study).
      const std::vector<solvers::EventRecord> &
      event_records() const
      {
        return problem.event_records();
      }
      unsigned int
      n_unknowns() const
      {
        return problem.n_unknowns();
      }
      const io::PhaseTimer &
      timings() const
      {
        return problem.timings();
      }
      /// The study's mode columns (critical_point_study.h): mode_number, mode_out_of_plane.
      std::vector<double>
      classify_critical_mode(const Vector<double> &mode) const;
      /// The study's further columns: mismatch_critical, closed_form_mismatch.
      std::vector<double>
      critical_point_columns(const solvers::EventRecord &e) const;

      /// The problem the run drives (the tests and the benchmarks).
      PlateRodProblem &
      get_problem()
      {
        return problem;
      }
      const PlateRodProblem &
      get_problem() const
      {
        return problem;
      }

      /// What the run has written and found so far, for its checkpoint (solvers::PathCheckpoints).
      void
      save_progress(io::CheckpointWriter &w) const;
      /// Restore it (its postprocessors rewrite steps.csv and the PVD files as they were then).
      void
      load_progress(io::CheckpointReader &r);

    private:
      PlateRodProblem                         problem;
      std::unique_ptr<solvers::CriticalGuess> critical_guess;

      void
      locate_from_guess();
      /// The path's summary in the log, summary.json (with the closed forms), the run's end.
      void
      finish_run(const io::JSON &closed);
    };

    /// The application's entry: a critical-point study, or one run.
    void
    run_plate_rod(ParameterHandler &prm, const io::RunOptions &options);
  } // namespace plate_rod
} // namespace cosmo

#endif
