#include <cosmo/config.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/io/run_record.h>
#include <cosmo/solvers/sparse_direct.h>

#include <iomanip>
#include <sstream>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace cosmo
{
  namespace io
  {
    RunRecord::RunRecord(const std::string &application)
      : application(application)
    {}

    std::string
    RunRecord::progress(const double fraction, const unsigned int step) const
    {
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - opened_at).count();
      auto format = [](const double s) {
        std::ostringstream o;
        if (s < 60)
          o << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
        else if (s < 3600)
          o << int(s / 60) << " min " << int(s) % 60 << " s";
        else
          o << int(s / 3600) << " h " << int(s / 60) % 60 << " min";
        return o.str();
      };
      std::string out = "  [" + format(seconds);
      if (fraction > 0.01 && fraction < 1)
        {
          if (step > 0)
            out += ", step " + std::to_string(step) + " of ~" +
                   std::to_string(static_cast<unsigned long>(std::ceil(step / fraction - 1e-9)));
          out += ", ETA " + format(seconds * (1 - fraction) / fraction);
        }
      return out + "]";
    }

    void
    RunRecord::open(const std::string &directory, const ParameterHandler &prm,
                    const RunOptions &run_options)
    {
      options          = run_options;
      output_directory = directory;
      opened_at        = std::chrono::steady_clock::now();
      parameters       = checkpoint_parameters(prm);
      resumed          = !options.resume_directory.empty();
      // A checkpoint of other parameters is refused before anything is touched.
      // Rank k > 0 of a run resumed on more ranks than it was begun with
      // has no checkpoint of its own: its driver takes its points from the
      // others' (io/ranks.h).
      has_resume_data = resumed && !(ranks::rank() > 0 &&
                                     !std::filesystem::exists(directory + "/" + checkpoint_name));
      if (has_resume_data)
        resume_data = read_checkpoint(directory, application, parameters);
      log = open_run_directory(directory, prm, options.quiet, "log.txt", resumed);
      // Whoever looks now sees a run in progress, not the last run's result.
      JSON running  = summary();
      running["status"] = "running";
      running["pid"]    = static_cast<double>(::getpid());
      write_file_atomically(output_directory + "/summary.json",
                            [&](std::ostream &o) { o << running.str() << "\n"; });
      say(application + " " + std::string(COSMO_VERSION) + ": " + options.parameter_file);
      if (resumed)
        say("  resumed from the checkpoint in " + directory + "/");
    }

    CheckpointReader
    RunRecord::read_checkpoint_in(const std::string &directory) const
    {
      return read_checkpoint(directory, application, parameters);
    }

    void
    RunRecord::write_checkpoint(const CheckpointWriter &payload) const
    {
      io::write_checkpoint(output_directory, application, parameters, payload);
    }

    void
    RunRecord::say(const std::string &line) const
    {
      if (log)
        (*log)(line);
      else if (!options.quiet)
        std::cout << line << std::endl;
    }

    std::function<void(const std::string &)>
    RunRecord::reporter() const
    {
      return [this](const std::string &line) { say(line); };
    }

    namespace
    {
      /// How long a failing rank waits for the others to report the same
      /// failure: ranks in lockstep meet it within a step of each other.
      double
      agreement_seconds()
      {
        const char *s = std::getenv("COSMO_FAILURE_AGREEMENT_SECONDS");
        return s ? std::atof(s) : 30.;
      }
    } // namespace

    void
    RunRecord::attempt(const std::function<void()> &work)
    {
      try
        {
          work();
        }
      catch (InputError &)
        {
          throw;
        }
      catch (Interrupted &e)
        {
          // The last converged state is what was written; the summary says
          // where the run stopped.
          status      = "interrupted";
          message     = e.what();
          signal      = e.signal;
        }
      catch (std::exception &e)
        {
          // Not bad input: the run could not reach its target. Still leave a
          // summary of what was done.
          fail(e.what());
          if (lockstep_failure && !lockstep_failure(e) && !ranks::all_ranks_failed_within(agreement_seconds()))
            {
              // This rank's alone: the others cannot take part in finish().
              message += " (on MPI rank " + std::to_string(ranks::rank()) +
                         " alone: every rank ended)";
              write_file_atomically(ranks::shared_directory() + "/summary.json",
                                    [&](std::ostream &o) { o << summary().str() << "\n"; });
              throw RunFailure(message);
            }
        }
    }

    void
    RunRecord::set_lockstep(const std::function<bool(const std::exception &)> &raised_on_all_ranks)
    {
      lockstep_failure = raised_on_all_ranks;
      ranks::prepare_failure_agreement();
    }

    void
    RunRecord::fail(const std::string &what)
    {
      status  = "failed";
      message = what;
    }

    JSON
    RunRecord::summary() const
    {
      JSON j              = JSON::object();
      j["application"]    = application;
      j["version"]        = COSMO_VERSION;
      j["parameter_file"] = options.parameter_file;
      j["status"]         = status;
      j["message"]        = message;
      // Under mpirun: how many ranks shared the run (doc/parallel-runs.md).
      if (ranks::size() > 1)
        j["mpi_ranks"] = ranks::size();
      // A one-path run's MUMPS phases on all ranks (sparse_direct.h).
      if (solvers::factorization_ranks::active())
        j["mumps_phases_on_all_ranks"] = solvers::factorization_ranks::shared_phases();
      return j;
    }

    void
    RunRecord::finish(JSON summary, const PhaseTimer &timer, const unsigned int converged_states) const
    {
      summary["timings"] = timer.to_json();
      // The memory of the largest factorization: what a run of this size
      // needs (doc/parallel-runs.md, the cost model).
      const auto &f = solvers::largest_factorization();
      if (f.ranks > 0)
        {
          JSON m                 = JSON::object();
          m["unknowns"]          = f.unknowns;
          m["factor_entries"]    = f.factor_entries;
          m["mb_per_rank"]       = f.mb_per_rank;
          m["mb_all_ranks"]      = f.mb_all_ranks;
          m["ranks"]             = f.ranks;
          summary["factorization_memory"] = m;
        }
      // The work per converged state: what a faster solver has to reduce
      // (factorizations and Jacobian assemblies come in pairs; event
      // location and stability add to them). Of this process: a resumed
      // run counts from its resume, like its timings.
      if (converged_states > 0)
        {
          JSON w                  = JSON::object();
          w["converged_states"]   = static_cast<double>(converged_states);
          w["factorizations"]     = timer.calls("factorization") / double(converged_states);
          w["jacobian_assemblies"] = timer.calls("assembly (Jacobian)") / double(converged_states);
          w["residual_assemblies"] = timer.calls("assembly (residual)") / double(converged_states);
          w["wall_seconds"] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - opened_at).count() /
            converged_states;
          summary["work_per_state"] = w;
        }
      std::error_code ec;
      if (status == "interrupted" && std::filesystem::exists(output_directory + "/" + checkpoint_name, ec))
        {
          // Where to go on from: the checkpoint holds the last converged state.
          JSON r          = JSON::object();
          r["checkpoint"] = checkpoint_name;
          r["command"]    = application + " --resume " + output_directory;
          summary["resume"] = r;
        }
      write_file_atomically(output_directory + "/summary.json",
                            [&](std::ostream &o) { o << summary.str() << "\n"; });
      if (status == "interrupted")
        {
          if (std::filesystem::exists(output_directory + "/" + checkpoint_name, ec))
            say("interrupted; continue with: " + application + " --resume " + output_directory);
          throw Interrupted(signal);
        }
      // Nothing to resume from a run that ended.
      remove_checkpoint(output_directory);
      if (failed())
        throw RunFailure(message);
      say("output in " + output_directory + "/");
    }
  } // namespace io
} // namespace cosmo
