#ifndef cosmo_io_point_loop_h
#define cosmo_io_point_loop_h

#include <cosmo/io/output.h>
#include <cosmo/io/ranks.h>

#include <functional>
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
      };

      struct Description
      {
        std::string application;     ///< e.g. "rod_cross_section"
        std::string checkpoint_kind; ///< e.g. "rod_cross_section sweep"
        std::string parameters;      ///< io::checkpoint_parameters(prm): another run's is refused
        std::string directory;       ///< the run's directory (rank 0's)
        std::string  table_file = "sweep.csv";
        std::string  log_file   = "sweep-log.txt";
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
      PointLoop(const Description &description, const CSVTable &columns, bool resume);

      /**
       * Runs this rank's points, `point(k)` for each not done before, then
       * gathers the ranks' rows into the directory's table (rank 0). Throws
       * io::InputError if values were rejected, io::RunFailure if points
       * failed (after the table is complete), io::Interrupted on a signal.
       */
      void
      run(RunLog &log, const std::function<Point(unsigned int k)> &point);

      /// The directory every rank's point directories are in (rank 0's).
      const std::string &
      shared_directory() const
      {
        return shared;
      }

    private:
      Description           description;
      CSVTable              table;
      bool                  resume;
      ranks::Resumed        resumed;
      std::string           shared;
      unsigned int          n_failed = 0;
      std::vector<std::string> rejected;

      /// Rank 0: every rank's rows and lines, into the table and the log.
      void
      gather(RunLog &log, const std::vector<std::string> &point_lines);
      void
      write_checkpoint(unsigned int first, unsigned int next) const;
    };
  } // namespace io
} // namespace cosmo

#endif
