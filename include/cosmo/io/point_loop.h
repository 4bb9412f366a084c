#ifndef cosmo_io_point_loop_h
#define cosmo_io_point_loop_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/ranks.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

/**
 * The loop over the points of a study (a parameter sweep: one run per value
 * of an entry), written once for every application:
 *
 * - under mpirun each rank takes a contiguous block of the points
 *   (io/ranks.h), and rank 0 writes every rank's rows, in the points' order;
 * - after each point the table is rewritten whole (a killed study leaves a
 *   complete one) and a checkpoint written, so that `--resume DIR` goes on
 *   after the last finished point, on the same number of ranks exactly
 *   where it was, on another taking every converged point from whichever
 *   rank did it;
 * - a point that fails (io::RunFailure) or whose value the problem rejects
 *   (io::InputError) is a row marked not converged; the others still run,
 *   and the study then ends with exit status 2 or 1 naming them;
 * - an interrupt between points leaves the table and the checkpoint.
 *
 * The application gives the table's columns and the point: a function that
 * runs point k and returns its row and its line in the log.
 */
namespace cosmo
{
  namespace io
  {
    class RunLog;

    class PointLoop
    {
    public:
      /// What one point gave.
      struct Point
      {
        enum class Outcome
        {
          converged,
          failed,  ///< the run could not proceed (io::RunFailure)
          rejected ///< the problem refused the value (io::InputError)
        };
        Outcome             outcome = Outcome::converged;
        std::vector<double> row;  ///< its row (completed with NaN to the table's columns)
        std::string         line; ///< its line in the log
        /// A rejected point: what to say of it at the end (by default its value, quoted).
        std::string rejection;
      };

      /**
       * What a driver of dependent points adds (a critical curve, whose
       * next point is predicted from the previous ones); each may be empty.
       */
      struct Hooks
      {
        /**
         * A point an earlier run did (a resume on another number of ranks):
         * whether it is taken as it is (its outcome and line; the row is the
         * earlier one), or run again (none). Default: taken if converged.
         */
        std::function<std::optional<Point>(unsigned int k, const std::vector<double> &row)>
          take_done;
        /// What the driver holds after a point, written into each checkpoint
        /// and read back on a resume (also from an earlier rank's checkpoint
        /// where that rank stopped, to go on from there as it would have).
        std::function<void(CheckpointWriter &)> save_held;
        std::function<void(CheckpointReader &)> load_held;
        /**
         * Rank 0, every rank's rows gathered in the points' order, before
         * they are written: what only the whole table shows (a change of
         * the critical mode between two points run apart). With it the rows
         * are gathered also after a resume on one rank.
         */
        std::function<void(std::vector<std::vector<double>> &rows)> complete_rows;
      };

      struct Description
      {
        std::string application;     ///< e.g. "rod_cross_section"
        std::string checkpoint_kind; ///< e.g. "rod_cross_section sweep"
        std::string parameters;      ///< io::checkpoint_parameters(prm): another run's is refused
        std::string directory;       ///< the run's directory (rank 0's)
        std::string  table_file = "sweep.csv";
        /// Further names the table is written under (e.g. critical_curve.csv).
        std::vector<std::string> also_written;
        std::string  log_file   = "sweep-log.txt";
        /// "sweep" or "study", in the log.
        std::string  kind = "sweep";
        /// The end's errors: the entry named for rejected values, and what failed points are.
        std::string  rejected_entry = "Entry";
        std::string  failed_words   = "sweep points failed";
        /// The table's column that is 1 for a converged point (a resumed run
        /// on another number of ranks takes those as they are).
        unsigned int converged_column = 2;
        /// The entry the study varies and the texts of its values (for the errors).
        std::string              entry;
        std::vector<std::string> values;
      };

      /**
       * `columns`: the table's columns (no rows). `resume`: the run goes on
       * from the checkpoint in the directory, which is read here, before
       * the directory is claimed (io::open_run_directory moves what it
       * finds into previous/).
       */
      PointLoop(const Description &description,
                const CSVTable &   columns,
                bool               resume,
                const Hooks &      hooks = Hooks());

      /**
       * Runs this rank's points, `point(k)` for each not done before, then
       * gathers the ranks' rows into the directory's table (rank 0). Throws
       * io::InputError if values were rejected, io::RunFailure if points
       * failed (after the table is complete), io::Interrupted on a signal.
       */
      void
      run(RunLog &log, const std::function<Point(unsigned int k)> &point);

      /**
       * The options of one point's run: quiet (the point's log.txt has the
       * details), run whole (not resumed), and with postprocessors of its
       * own, parsed from the point's parameters, so that no point's files
       * carry another point's states. finish_point() ends them.
       */
      static RunOptions
      point_options(const RunOptions &options, ParameterHandler &prm);
      static void
      finish_point(const RunOptions &point_options, const std::string &point_directory);

      /// The directory every rank's point directories are in (rank 0's);
      /// valid from run() on.
      const std::string &
      shared_directory() const
      {
        return shared;
      }

    private:
      Description           description;
      CSVTable              table;
      bool                  resume;
      Hooks                 hooks;
      ranks::Resumed        resumed;
      std::string           shared;
      unsigned int          n_failed = 0;
      std::vector<std::string> rejected;

      /// Rank 0: every rank's rows and lines, into the table and the log.
      void
      gather(RunLog &log, const std::vector<std::string> &point_lines);
      void
      write_checkpoint(unsigned int first, unsigned int next) const;
      /// A checkpoint's payload after its header: the counters, then the held state.
      void
      read_payload(CheckpointReader &r, bool keep_counters);
      /// Takes point k if an earlier run did it; true if taken.
      bool
      take_done(unsigned int k, RunLog &log, std::vector<std::string> &point_lines);
      /// The end: rejected values (io::InputError), failed points (io::RunFailure).
      void
      report() const;
    };
  } // namespace io
} // namespace cosmo

#endif
