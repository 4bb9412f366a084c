#ifndef cosmo_solvers_path_checkpoints_h
#define cosmo_solvers_path_checkpoints_h

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/io/run_record.h>

#include <functional>
#include <stdexcept>

namespace cosmo
{
  namespace solvers
  {
    /**
     * The checkpoints of a path followed by a continuation driver (arclength
     * or natural parameter): how to write one, and the one to resume from.
     * A checkpoint holds the driver's state, then the problem's progress
     * (its records, its state and its postprocessors'); connect() makes the
     * driver resume from one and write one after every converged step.
     */
    class PathCheckpoints
    {
    public:
      /// Write into the run's directory; resume from its checkpoint if the
      /// run was started with --resume and has one.
      void
      connect_to(io::RunRecord &record)
      {
        write = [&record](const io::CheckpointWriter &w) { record.write_checkpoint(w); };
        if (record.has_checkpoint())
          resume_from = &record.checkpoint();
      }

      /**
       * The driver resumes from resume_from if set (the driver's state, then
       * problem.load_progress(), which must read the rest), and writes a
       * checkpoint of its state and problem.save_progress() after every
       * converged step if write is set (timed as "checkpoint").
       */
      template <typename Driver, typename Problem>
      void
      connect(Driver &driver, Problem &problem, io::PhaseTimer &timer)
      {
        if (resume_from)
          {
            driver.load(*resume_from);
            problem.load_progress(*resume_from);
            if (!resume_from->at_end())
              throw std::runtime_error("the checkpoint holds more than this run reads");
            resume_from = nullptr;
          }
        if (write)
          driver.checkpoint = [this, &driver, &problem, &timer]() {
            io::PhaseTimer::Scope scope(timer, "checkpoint");
            io::CheckpointWriter  w;
            driver.save(w);
            problem.save_progress(w);
            write(w);
          };
      }

      std::function<void(const io::CheckpointWriter &)> write;
      io::CheckpointReader *                            resume_from = nullptr;
    };
  } // namespace solvers
} // namespace cosmo

#endif
