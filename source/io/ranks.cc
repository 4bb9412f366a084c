#include <deal.II/base/mpi.h>

#include <cosmo/io/ranks.h>

#include <dlfcn.h>

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

      std::vector<std::vector<double>>
      gather_rows(const std::vector<std::vector<double>> &mine)
      {
        if (size() == 1)
          return mine;
        std::vector<std::vector<double>> all;
        for (auto &part : Utilities::MPI::gather(MPI_COMM_WORLD, mine, 0))
          all.insert(all.end(), part.begin(), part.end());
        return all;
      }

      std::vector<std::string>
      gather_lines(const std::vector<std::string> &mine)
      {
        if (size() == 1)
          return mine;
        std::vector<std::string> all;
        for (auto &part : Utilities::MPI::gather(MPI_COMM_WORLD, mine, 0))
          all.insert(all.end(), part.begin(), part.end());
        return all;
      }

      std::vector<std::string>
      all_gather_lines(const std::vector<std::string> &mine)
      {
        if (size() == 1)
          return mine;
        std::vector<std::string> all;
        for (auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, mine))
          all.insert(all.end(), part.begin(), part.end());
        return all;
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
      share_cores()
      {
        if (size() == 1 || std::getenv("OPENBLAS_NUM_THREADS") != nullptr)
          return;
        // OpenBLAS read its environment when it was loaded; its own setter
        // (if the BLAS in use is OpenBLAS) is found at run time.
        using Setter = void (*)(int);
        if (auto set = reinterpret_cast<Setter>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
          set(1);
      }
    } // namespace ranks
  }   // namespace io
} // namespace cosmo
