#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <cosmo/io/parameters.h>
#include <cosmo/io/ranks.h>
#include <cosmo/solvers/blas_threads.h>
#include <cosmo/solvers/sparse_direct.h>

#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include <cstdlib>

namespace cosmo
{
  namespace io
  {
    namespace ranks
    {
      using namespace dealii;

      namespace
      {
        std::string the_shared_directory;

        bool
        mpi_running()
        {
          int initialized = 0, finalized = 0;
          MPI_Initialized(&initialized);
          MPI_Finalized(&finalized);
          return initialized != 0 && finalized == 0;
        }
      } // namespace

      void
      prepare_single_process_mpi()
      {
        // The variables a launcher sets (Open MPI's mpirun, PMIx, PMI-1/2 of
        // MPICH and SLURM's srun).
        for (const char *launched :
             {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "SLURM_STEP_ID"})
          if (std::getenv(launched) != nullptr)
            return;
        ::setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
        ::setenv("OMPI_MCA_pml", "ob1", 0);
        ::setenv("OMPI_MCA_btl", "self,vader", 0);
      }

      unsigned int
      rank()
      {
        return mpi_running() ? Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) : 0;
      }

      unsigned int
      size()
      {
        return mpi_running() ? Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
      }

      std::pair<unsigned int, unsigned int>
      block(const unsigned int n, const unsigned int r, const unsigned int p)
      {
        const unsigned int q = n / p, extra = n % p;
        const unsigned int first = r * q + std::min(r, extra);
        return {first, first + q + (r < extra ? 1 : 0)};
      }

      std::string
      private_directory(const std::string &directory, const unsigned int k)
      {
        return directory + "/rank-" + std::to_string(k);
      }

      std::string
      enter_run(const std::string &directory)
      {
        the_shared_directory = directory;
        return rank() == 0 ? directory : private_directory(directory, rank());
      }

      const std::string &
      shared_directory()
      {
        return the_shared_directory;
      }

      /// The ranks' lists one after the other, at rank 0 (`to_all`: at every rank).
      template <typename T>
      std::vector<T>
      concatenated(const std::vector<T> &mine, const bool to_all)
      {
        if (size() == 1)
          return mine;
        std::vector<T> all;
        for (auto &part : to_all ? Utilities::MPI::all_gather(MPI_COMM_WORLD, mine) :
                                   Utilities::MPI::gather(MPI_COMM_WORLD, mine, 0))
          all.insert(all.end(), part.begin(), part.end());
        return all;
      }

      std::vector<std::vector<double>>
      gather_rows(const std::vector<std::vector<double>> &mine)
      {
        return concatenated(mine, false);
      }

      std::vector<std::string>
      gather_lines(const std::vector<std::string> &mine)
      {
        return concatenated(mine, false);
      }

      std::vector<std::string>
      all_gather_lines(const std::vector<std::string> &mine)
      {
        return concatenated(mine, true);
      }

      unsigned int
      sum(const unsigned int mine)
      {
        return size() == 1 ? mine : Utilities::MPI::sum(mine, MPI_COMM_WORLD);
      }

      void
      barrier()
      {
        if (size() > 1)
          {
            const int ierr = MPI_Barrier(MPI_COMM_WORLD);
            AssertThrowMPI(ierr);
          }
      }

      void
      wait_for_all()
      {
        if (size() == 1)
          return;
        MPI_Request request;
        int         ierr = MPI_Ibarrier(MPI_COMM_WORLD, &request);
        AssertThrowMPI(ierr);
        for (int done = 0; !done;)
          {
            ierr = MPI_Test(&request, &done, MPI_STATUS_IGNORE);
            AssertThrowMPI(ierr);
            if (!done)
              std::this_thread::sleep_for(std::chrono::milliseconds(20));
          }
      }

      namespace
      {
        MPI_Comm failure_comm = MPI_COMM_NULL;
      }

      void
      prepare_failure_agreement()
      {
        if (size() > 1 && failure_comm == MPI_COMM_NULL)
          AssertThrowMPI(MPI_Comm_dup(MPI_COMM_WORLD, &failure_comm));
      }

      bool
      all_ranks_failed_within(const double seconds)
      {
        if (size() == 1)
          return true;
        if (failure_comm == MPI_COMM_NULL)
          return false;
        MPI_Request request;
        AssertThrowMPI(MPI_Ibarrier(failure_comm, &request));
        const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        for (int done = 0;;)
          {
            AssertThrowMPI(MPI_Test(&request, &done, MPI_STATUS_IGNORE));
            if (done)
              return true;
            if (std::chrono::steady_clock::now() > until)
              return false; // (the request is left: this rank ends the run now)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
          }
      }

      namespace
      {
        /**
         * mpirun binds each rank to a core of its own (Open MPI's default
         * for two ranks or fewer): rank 0 of a one-path run, whose threads
         * are to use the cores of the sleeping ranks, takes the node's
         * CPUs back, for every thread it has (the kernel keeps the
         * process within its cgroup's CPUs). Measured: the Jacobian of the
         * plate dome took twice as long on one core (benchmarks/README.md).
         */
        void
        use_all_cores()
        {
#ifdef __linux__
          const long n = ::sysconf(_SC_NPROCESSORS_CONF);
          cpu_set_t  all;
          CPU_ZERO(&all);
          for (long c = 0; c < n && c < CPU_SETSIZE; ++c)
            CPU_SET(c, &all);
          std::error_code ec;
          for (const auto &task : std::filesystem::directory_iterator("/proc/self/task", ec))
            {
              const pid_t tid = static_cast<pid_t>(std::atol(task.path().filename().c_str()));
              ::sched_setaffinity(tid, sizeof(all), &all);
            }
#endif
        }
      } // namespace

      bool
      idle(const bool distributed)
      {
        if (size() == 1 || distributed)
          return false;
        if (rank() == 0)
          std::cout << "(mpirun: this run is one path, which rank 0 follows; the other "
                    << size() - 1 << (size() == 2 ? " rank takes" : " ranks take")
                    << " part in its factorizations of "
                    << solvers::factorization_ranks::min_unknowns()
                    << " unknowns or more: doc/parallel-runs.md)" << std::endl;
        if (rank() > 0)
          {
            solvers::factorization_ranks::serve();
            return true;
          }
        // Rank 0 assembles on the node's cores while the others sleep.
        use_all_cores();
        MultithreadInfo::set_thread_limit();
        solvers::factorization_ranks::enable();
        return false;
      }

      void
      put_mesh_ranks(CheckpointWriter &w, const bool distributed_mesh)
      {
        w.put(distributed_mesh ? size() : 0u);
      }

      void
      check_checkpoints_agree(const std::uint64_t value, const std::string &what)
      {
        unsigned long long v[2] = {value, ~static_cast<unsigned long long>(value)};
        MPI_Allreduce(MPI_IN_PLACE, v, 2, MPI_UNSIGNED_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
        if (v[0] != ~v[1])
          throw InputError("Output", "Output directory", shared_directory(),
                           "the ranks' checkpoints differ in " + what +
                             " (a run killed while its ranks wrote them, or resumed on more "
                             "ranks than it began on): resume with as many ranks, or start the "
                             "run again without --resume");
      }

      void
      check_mesh_ranks(CheckpointReader &r, const bool distributed_mesh, const std::string &section,
                       const std::string &entry)
      {
        const unsigned int then = r.at_end() ? 0u : r.get_unsigned();
        const unsigned int now  = distributed_mesh ? size() : 0u;
        if (then == now)
          return;
        auto mesh = [](const unsigned int n) {
          return n == 0 ? std::string("a serial mesh") :
                          "a mesh distributed over " + std::to_string(n) + (n == 1 ? " rank" : " ranks");
        };
        throw InputError(section, entry, distributed_mesh ? "true" : "false",
                         "the checkpoint was written on " + mesh(then) + ", whose DoF numbering " +
                           mesh(now) + " does not share: resume it " +
                           (then == 0 ? "with " + entry + " = false" :
                                        "with mpirun -np " + std::to_string(then)));
      }

      void
      put_point_header(CheckpointWriter &w, const unsigned int first, const unsigned int next,
                       const CSVTable &rows)
      {
        w.put(size());
        w.put(rank());
        w.put(first);
        w.put(next);
        rows.save(w);
      }

      PointHeader
      get_point_header(CheckpointReader &r, const CSVTable &columns)
      {
        PointHeader h;
        h.n_ranks = r.get_unsigned();
        h.rank    = r.get_unsigned();
        h.first   = r.get_unsigned();
        h.next    = r.get_unsigned();
        CSVTable t = columns;
        t.load(r);
        h.rows = t.row_values();
        if (h.next < h.first || h.rows.size() != h.next - h.first)
          throw std::runtime_error("the checkpoint's rows do not match its points");
        return h;
      }

      Resumed
      resume_points(const std::string &directory, const CSVTable &columns,
                    const std::function<CheckpointReader(const std::string &)> &read)
      {
        Resumed    out;
        const bool own = rank() == 0 || std::filesystem::exists(directory + "/" + checkpoint_name);
        if (own)
          {
            out.reader     = read(directory);
            out.own        = get_point_header(out.reader, columns);
            out.ranks_then = out.own.n_ranks;
            out.same_ranks = out.own.n_ranks == size();
            if (out.same_ranks)
              return out;
          }
        // Begun on another number of ranks: every earlier rank's points.
        const std::string shared = shared_directory().empty() ? directory : shared_directory();
        auto take = [&](CheckpointReader r) {
          const auto h = get_point_header(r, columns);
          out.ranks_then = h.n_ranks;
          for (unsigned int k = h.first; k < h.next; ++k)
            out.done[k] = h.rows[k - h.first];
          if (h.next > h.first)
            out.after[h.next] = std::move(r);
        };
        take(read(shared));
        for (unsigned int k = 1; k < out.ranks_then; ++k)
          if (std::filesystem::exists(private_directory(shared, k) + "/" + checkpoint_name))
            take(read(private_directory(shared, k)));
        return out;
      }

      void
      share_cores()
      {
        if (size() == 1)
          return;
        // (OpenBLAS read its environment when it was loaded; its own setter,
        // if the BLAS in use is OpenBLAS, is found at run time)
        solvers::pin_blas_threads(1);
      }
    } // namespace ranks
  }   // namespace io
} // namespace cosmo
