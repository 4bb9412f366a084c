#ifndef cosmo_io_run_directory_h
#define cosmo_io_run_directory_h

#include <mpi.h>

#include <stdexcept>
#include <string>

/**
 * What keeps a run's output directory its own (README.md, the table of what
 * a run does with its directory):
 *
 * - a lock: a second run into a directory in use ends at once (exit 1) with
 *   the other run's pid;
 * - a manifest (`.cosmo-files`, every file the run writes, appended as it is
 *   written): the next run into the directory moves exactly those files into
 *   `previous/` before it writes, so a directory never mixes two runs and no
 *   file of the user's is touched;
 * - a rollback: a run rejected as bad input before it wrote any result
 *   removes what it wrote and moves the earlier run's files back;
 * - signals: SIGINT and SIGTERM are recorded, not acted on at once; the
 *   drivers ask (check_interrupt()) between steps, so the file being written
 *   is finished, summary.json says "interrupted", and the exit status is
 *   128 + the signal (130, 143). A second signal ends the process at once.
 */
namespace cosmo
{
  namespace io
  {
    /// Thrown by check_interrupt() after SIGINT or SIGTERM.
    class Interrupted : public std::runtime_error
    {
    public:
      explicit Interrupted(int signal);
      int signal;
      /// 128 + the signal, as a shell reports a process ended by it.
      int
      exit_status() const
      {
        return 128 + signal;
      }
    };

    /// Record SIGINT and SIGTERM from now on (run_application does it).
    void
    install_signal_handlers();

    /// The signal received and not yet acted on, 0 if none (always 0 once
    /// collective_interrupts() is set: check_interrupt() decides then).
    int
    pending_signal();

    /// Throw Interrupted if a signal was received: call between steps.
    void
    check_interrupt();

    /**
     * From now on check_interrupt() decides together with every rank of
     * `comm`: it throws on all of them if any received a signal. For runs in
     * which the ranks take every step together (a distributed mesh): a
     * signal reaches the ranks at different moments, and a rank that
     * stopped alone would leave the others waiting in a collective call.
     */
    void
    collective_interrupts(MPI_Comm comm);

    /// collective_interrupts() was set: the ranks take every step together.
    bool
    interrupts_are_collective();

    /**
     * Take `directory` (created already) for this process: lock it, move the
     * files of the run that wrote there before into previous/, and start
     * the manifest. Throws InputError (exit 1) if another process holds it.
     * Idempotent for a directory this process holds already. `created`:
     * the run created it (a rollback may then remove it). `resume`: the run
     * continues the one there (--resume): its files and manifest are kept.
     */
    void
    claim_run_directory(const std::string &directory, bool created, bool resume = false);

    /// Add `path`, just written, to the manifest of the claimed directory it lies in (if any).
    void
    record_output_file(const std::string &path);

    /**
     * After bad input: every claimed directory where this run wrote nothing
     * but parameters.prm and logs is restored (its files removed, the earlier
     * run's files moved back from previous/).
     */
    void
    roll_back_unused_run_directories();
  } // namespace io
} // namespace cosmo

#endif
