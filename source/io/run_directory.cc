#include <cosmo/io/parameters.h>
#include <cosmo/io/run_directory.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace cosmo
{
  namespace io
  {
    namespace fs = std::filesystem;

    namespace
    {
      volatile std::sig_atomic_t received = 0;

      extern "C" void
      on_signal(int s)
      {
        if (received != 0)
          {
            // The second signal: the user insists; end now.
            std::signal(s, SIG_DFL);
            std::raise(s);
            return;
          }
        received = s;
      }

      const char *const manifest_name = ".cosmo-files";
      const char *const lock_name     = ".cosmo-lock";

      struct Claimed
      {
        int                      lock_fd = -1;
        std::vector<std::string> written; // relative to the directory
        bool                     had_previous = false;
        bool                     created      = false; ///< by this run
        std::string              stash; ///< the older previous/, until this run writes a result
        std::string              old_lock; ///< the lock file's text before (a rollback restores it)
        bool                     had_lock = false;
        bool                     resumed  = false; ///< continues the run there (--resume)
      };

      /// The directories this process holds, by their canonical path.
      std::map<std::string, Claimed> &
      claimed()
      {
        static std::map<std::string, Claimed> c;
        return c;
      }

      std::string
      canonical(const std::string &path)
      {
        std::error_code ec;
        const fs::path  p = fs::weakly_canonical(fs::absolute(path), ec);
        return ec ? path : p.string();
      }

      /// Files of a run made before manifests existed: its fixed names and outputs.
      bool
      is_legacy_output(const fs::directory_entry &e)
      {
        const std::string name = e.path().filename().string();
        if (!e.is_regular_file())
          return false;
        static const std::set<std::string> names = {
          "summary.json", "log.txt", "sweep-log.txt", "steps.csv", "sweep.csv",
          "critical_curve.csv", "table.csv", "table.h5"};
        const std::string ext = e.path().extension().string();
        return names.count(name) || ext == ".vtu" || ext == ".pvtu" || ext == ".pvd" ||
               name.find(".tmp") != std::string::npos;
      }

      /// What a run writes before its work: no result yet.
      bool
      is_setup_file(const std::string &f)
      {
        return f == "parameters.prm" || f == "log.txt" || f == "sweep-log.txt" ||
               f == "summary.json";
      }

      void
      move_into(const fs::path &dir, const std::string &relative, const fs::path &target_dir)
      {
        std::error_code ec;
        const fs::path  from = dir / relative;
        if (!fs::exists(from, ec))
          return;
        const fs::path to = target_dir / relative;
        fs::create_directories(to.parent_path(), ec);
        fs::rename(from, to, ec);
      }
    } // namespace

    Interrupted::Interrupted(const int signal)
      : std::runtime_error(std::string("interrupted by ") +
                           (signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" :
                                                                              "signal " +
                                                                                std::to_string(signal)))
      , signal(signal)
    {}

    void
    install_signal_handlers()
    {
      struct sigaction a;
      std::memset(&a, 0, sizeof(a));
      a.sa_handler = on_signal;
      sigemptyset(&a.sa_mask);
      a.sa_flags = SA_RESTART; // writes in progress go on
      sigaction(SIGINT, &a, nullptr);
      sigaction(SIGTERM, &a, nullptr);
    }

    namespace
    {
      MPI_Comm interrupt_comm = MPI_COMM_NULL;
    }

    int
    pending_signal()
    {
      // (with collective interrupts only check_interrupt() acts on a signal,
      // on all ranks together: a rank that stopped a solve alone would leave
      // the others in its residual's collective calls)
      return interrupt_comm != MPI_COMM_NULL ? 0 : received;
    }

    void
    collective_interrupts(MPI_Comm comm)
    {
      if (interrupt_comm == MPI_COMM_NULL)
        MPI_Comm_dup(comm, &interrupt_comm);
    }

    bool
    interrupts_are_collective()
    {
      return interrupt_comm != MPI_COMM_NULL;
    }

    void
    check_interrupt()
    {
      int signal = received;
      if (interrupt_comm != MPI_COMM_NULL)
        MPI_Allreduce(MPI_IN_PLACE, &signal, 1, MPI_INT, MPI_MAX, interrupt_comm);
      if (signal != 0)
        throw Interrupted(signal);
    }

    namespace
    {
      /**
       * Lock `dir` against other runs (the lock file holds this run's pid,
       * for the message of a second run): a claim with the lock's file
       * descriptor and what a rollback restores. `directory` is the name
       * the user gave, for the messages.
       */
      Claimed
      lock_run_directory(const fs::path &dir, const std::string &directory)
      {
        std::error_code lock_ec;
        const bool      had_lock = fs::exists(dir / lock_name, lock_ec);
        const int      fd = ::open((dir / lock_name).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0)
          throw InputError("Output", "Output directory", directory,
                           "a directory where this run can write (cannot create its lock file: " +
                             std::string(std::strerror(errno)) + ")");
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
          {
            char    buffer[64] = {0};
            ssize_t n          = ::pread(fd, buffer, sizeof(buffer) - 1, 0);
            ::close(fd);
            std::string pid = n > 0 ? std::string(buffer, n) : std::string("?");
            pid.erase(std::remove(pid.begin(), pid.end(), '\n'), pid.end());
            throw InputError("Output", "Output directory", directory,
                             "a directory no other run is writing to: the run with pid " + pid +
                               " is writing there now (wait for it, or choose another directory)");
          }
        std::string old_lock;
        {
          char    buffer[64] = {0};
          ssize_t n          = ::pread(fd, buffer, sizeof(buffer) - 1, 0);
          if (n > 0)
            old_lock.assign(buffer, n);
        }
        const std::string pid = std::to_string(::getpid()) + "\n";
        if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0)
          { /* the pid is only for the message of a second run */
          }
        Claimed c;
        c.lock_fd  = fd;
        c.had_lock = had_lock;
        c.old_lock = old_lock;
        return c;
      }

      /// Append the lines of a manifest not yet in `lines` (each file once, in order).
      void
      append_manifest_lines(std::istream &manifest, std::vector<std::string> &lines)
      {
        std::string line;
        while (std::getline(manifest, line))
          if (!line.empty() && std::find(lines.begin(), lines.end(), line) == lines.end())
            lines.push_back(line);
      }

      /// A resumed run: its files stay, and the manifest's list goes on into c.written.
      void
      resume_claim(const fs::path &dir, Claimed &c)
      {
        // A killed run may have left the file it was writing half done.
        std::error_code ec;
        for (const auto &e : fs::directory_iterator(dir, ec))
          if (e.is_regular_file() && e.path().filename().string().find(".tmp.") != std::string::npos)
            fs::remove(e.path(), ec);
        std::ifstream manifest(dir / manifest_name);
        append_manifest_lines(manifest, c.written);
      }

      /// The earlier run's files in `dir`: its manifest's, or (a run from
      /// before manifests) its outputs by name; unfinished files removed.
      std::vector<std::string>
      earlier_outputs(const fs::path &dir)
      {
        std::error_code          ec;
        std::vector<std::string> earlier;
        std::ifstream            manifest(dir / manifest_name);
        if (manifest)
          append_manifest_lines(manifest, earlier);
        else
          for (const auto &e : fs::directory_iterator(dir, ec))
            if (is_legacy_output(e))
              earlier.push_back(e.path().filename().string());
        // A temporary file is a write a killed run never completed (each file
        // is written under a temporary name and renamed): removed, not kept
        // in previous/ as if it were a result.
        std::vector<fs::path> unfinished;
        for (const auto &e : fs::directory_iterator(dir, ec))
          if (e.is_regular_file() && e.path().filename().string().find(".tmp") != std::string::npos)
            unfinished.push_back(e.path());
        for (const auto &f : unfinished)
          {
            fs::remove(f, ec);
            earlier.erase(std::remove(earlier.begin(), earlier.end(), f.filename().string()),
                          earlier.end());
          }
        return earlier;
      }

      /// Move the `earlier` files (and their manifest) into dir/previous/,
      /// the older previous/ aside into c.stash.
      void
      move_into_previous(const fs::path &dir, const std::vector<std::string> &earlier, Claimed &c)
      {
        std::error_code ec;
        // Stashes of older previous/ directories left by runs that ended
        // without a result are obsolete.
        for (const auto &e : fs::directory_iterator(dir, ec))
          if (e.path().filename().string().rfind(".cosmo-previous-", 0) == 0)
            fs::remove_all(e.path(), ec);
        if (earlier.empty())
          return;
        const fs::path previous = dir / "previous";
        // The older previous/ is kept aside until this run writes a
        // result: a run rejected before that puts everything back.
        if (fs::exists(previous, ec))
          {
            c.stash = ".cosmo-previous-" + std::to_string(::getpid());
            fs::rename(previous, dir / c.stash, ec);
            if (ec)
              fs::remove_all(previous, ec);
          }
        for (const auto &f : earlier)
          move_into(dir, f, previous);
        move_into(dir, manifest_name, previous);
        c.had_previous = true;
      }
    } // namespace

    void
    claim_run_directory(const std::string &directory, const bool created, const bool resume)
    {
      const std::string key = canonical(directory);
      if (claimed().count(key))
        return;
      const fs::path dir(key);
      Claimed        c = lock_run_directory(dir, directory);
      c.created        = created;
      if (resume)
        {
          // The run goes on: its files stay, its manifest grows.
          c.resumed = true;
          resume_claim(dir, c);
          claimed()[key] = c;
          return;
        }

      // The earlier run's files into previous/ (replacing an older previous/).
      move_into_previous(dir, earlier_outputs(dir), c);
      // A fresh manifest; a directory inside another run's (a study's
      // point) is one of that run's outputs.
      std::ofstream(dir / manifest_name, std::ios::trunc);
      record_output_file(key);
      claimed()[key] = c;
    }

    void
    record_output_file(const std::string &path)
    {
      if (claimed().empty())
        return;
      const std::string full = canonical(path);
      for (auto &[dir, c] : claimed())
        if (full.size() > dir.size() && full.compare(0, dir.size(), dir) == 0 &&
            full[dir.size()] == '/')
          {
            // The innermost claimed directory holds it (a study's points are
            // runs of their own inside the study's directory).
            bool inner = false;
            for (const auto &[other, unused] : claimed())
              if (other.size() > dir.size() && full.compare(0, other.size(), other) == 0 &&
                  full[other.size()] == '/' && other.compare(0, dir.size(), dir) == 0)
                inner = true;
            if (inner)
              continue;
            const std::string relative = full.substr(dir.size() + 1);
            if (std::find(c.written.begin(), c.written.end(), relative) != c.written.end())
              return;
            c.written.push_back(relative);
            std::ofstream m(fs::path(dir) / manifest_name, std::ios::app);
            m << relative << "\n";
            if (!c.stash.empty() && !is_setup_file(relative))
              {
                std::error_code ec;
                fs::remove_all(fs::path(dir) / c.stash, ec);
                c.stash.clear();
              }
            return;
          }
    }

    void
    roll_back_unused_run_directories()
    {
      for (auto &[dir, c] : claimed())
        {
          if (c.resumed)
            continue; // checked before anything was written; nothing to undo
          const bool only_setup = std::all_of(c.written.begin(), c.written.end(), is_setup_file);
          if (!only_setup)
            continue;
          std::error_code ec;
          const fs::path  d(dir);
          for (const auto &f : c.written)
            fs::remove(d / f, ec);
          fs::remove(d / manifest_name, ec);
          if (c.had_previous)
            {
              const fs::path previous = d / "previous";
              for (const auto &e : fs::directory_iterator(previous, ec))
                fs::rename(e.path(), d / e.path().filename(), ec);
              fs::remove(previous, ec);
            }
          if (!c.stash.empty())
            fs::rename(d / c.stash, d / "previous", ec);
          if (c.had_lock)
            {
              if (::ftruncate(c.lock_fd, 0) != 0 ||
                  ::pwrite(c.lock_fd, c.old_lock.data(), c.old_lock.size(), 0) < 0)
                { /* informational only */
                }
            }
          else
            fs::remove(d / lock_name, ec);
          if (c.created && fs::is_empty(d, ec))
            fs::remove(d, ec);
        }
    }
  } // namespace io
} // namespace cosmo
