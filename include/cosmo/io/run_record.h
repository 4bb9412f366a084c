#ifndef cosmo_io_run_record_h
#define cosmo_io_run_record_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>

#include <functional>
#include <chrono>
#include <limits>
#include <memory>
#include <string>

/**
 * What every run of every application leaves and says, in one place
 * (doc/specification/architecture.md): the output directory with
 * parameters.prm and log.txt, progress lines on the terminal (unless
 * quiet), the exception policy and summary.json's common keys.
 *
 * The policy: bad input (io::InputError) ends the run with exit status 1
 * and no summary; any other failure of the work (io::RunFailure, a Newton
 * failure at the start, a file that cannot be written, ...) is recorded as
 * `"status": "failed"` with its message in summary.json, which is written
 * either way, and then ends the run with exit status 2 (io::RunFailure).
 * summary.json says `"status": "running"` from open() on; a run stopped by
 * SIGINT/SIGTERM (io::Interrupted, between steps) writes it with
 * `"status": "interrupted"` and ends with 128 + the signal.
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    class RunRecord
    {
    public:
      /// `application` as it calls itself (summary.json's "application").
      explicit RunRecord(const std::string &application);

      /**
       * Create `directory`, write the parameters as read (parameters.prm),
       * open log.txt and say which application and file this is.
       */
      void
      open(const std::string &directory, const ParameterHandler &prm, const RunOptions &options);

      /// A line to log.txt and (unless quiet) the terminal; before open(), the terminal only.
      void
      say(const std::string &line) const;

      /**
       * For a step line: "  [12.3 s]" (wall time since open()), with
       * ", ETA 40 s" when `fraction` (the share of the run done, e.g. t of a
       * path to t = 1) is in (0.01, 1): the remaining share at the speed so far.
       * Given the step number as well, "step 12 of ~40" before the ETA: the
       * number of steps the path takes at its mean step so far (an estimate:
       * the step length adapts).
       */
      std::string
      progress(double fraction = std::numeric_limits<double>::quiet_NaN(), unsigned int step = 0) const;

      /// say() as a function, for the library's progress callbacks.
      std::function<void(const std::string &)>
      reporter() const;

      bool
      quiet() const
      {
        return options.quiet;
      }

      void
      set_quiet(const bool q)
      {
        options.quiet = q;
      }

      /// Run `work` under the policy above (InputError passes through).
      void
      attempt(const std::function<void()> &work);

      /**
       * The ranks of a run on a distributed mesh take every step together.
       * A failure that `raised_on_all_ranks` recognises (the drivers', which
       * every rank meets at the same point) is recorded as on one process.
       * Any other is asked about among the ranks for a bounded time
       * (ranks::all_ranks_failed_within): met by every rank, it is recorded
       * as on one process (summary.json "failed", exit 2); met by this rank
       * alone (one rank's write error, say), this rank writes the run's
       * summary.json ("failed", with the message) and ends every rank
       * (io::RunFailure, then MPI_Abort with exit 2) instead of leaving the
       * others waiting in a collective call. Call on every rank.
       */
      void
      set_lockstep(const std::function<bool(const std::exception &)> &raised_on_all_ranks);

      /// Record a failure found by the caller.
      void
      fail(const std::string &message);

      bool
      failed() const
      {
        return status != "converged";
      }

      /**
       * The keys every summary.json starts with: application, version,
       * parameter_file, status ("converged" or "failed"), message; and
       * mpi_ranks, the number of ranks, under mpirun.
       */
      JSON
      summary() const;

      /**
       * Add the timings (and, given the number of converged states, the
       * factorizations, assemblies and seconds per state as
       * `work_per_state`), write `summary` to summary.json (atomically) and
       * then either say where the output is or, for a failed run, throw
       * io::RunFailure with its message (exit status 2).
       */
      void
      finish(JSON summary, const PhaseTimer &timer, unsigned int converged_states = 0) const;

      const std::string &
      directory() const
      {
        return output_directory;
      }
      /// The run continues an interrupted one (--resume): its checkpoint was read by open().
      bool
      resuming() const
      {
        return resumed;
      }
      /// A resumed run found a checkpoint of its own (rank k > 0 under mpirun may not).
      bool
      has_checkpoint() const
      {
        return has_resume_data;
      }
      /// The checkpoint of this run's application and parameters in another directory.
      CheckpointReader
      read_checkpoint_in(const std::string &directory) const;
      /// The payload of the checkpoint the run resumes from (after open(), if has_checkpoint()).
      CheckpointReader &
      checkpoint()
      {
        return resume_data;
      }
      /// Write the run's checkpoint (io/checkpoint.h) with this payload.
      void
      write_checkpoint(const CheckpointWriter &payload) const;

    private:
      std::string             application;
      RunOptions              options;
      std::string             output_directory;
      std::unique_ptr<RunLog> log;
      std::string             status = "converged";
      std::string             message;
      int                     signal = 0; ///< of an interrupted run
      std::string             parameters; ///< checkpoint_parameters() of the run
      bool                    resumed = false, has_resume_data = false;
      CheckpointReader        resume_data;
      std::chrono::steady_clock::time_point opened_at = std::chrono::steady_clock::now();
      std::function<bool(const std::exception &)> lockstep_failure;
    };
  } // namespace io
} // namespace cosmo

#endif
