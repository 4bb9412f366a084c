#ifndef cosmo_io_ranks_h
#define cosmo_io_ranks_h

#include <deal.II/base/mpi.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

/**
 * The MPI ranks of a run (`mpirun -np N app file.prm`, doc/parallel-runs.md).
 *
 * What is spread over the ranks are the points of what consists of many
 * independent or loosely coupled solves: a constitutive table (contiguous
 * blocks of its serpentine, each rank continuing from its own converged
 * neighbour) and a parameter study (contiguous blocks of its values). Every
 * rank runs the application from the start (the mesh, the base state) and
 * takes its block; rank 0 gathers the results and writes the one result
 * set of the run in the output directory.
 *
 * So that no two ranks write the same file, rank k > 0 runs in its own
 * directory, `<output directory>/rank-k` (its log.txt, its checkpoint, the
 * base state's files it repeats); a run that ends well removes it, a
 * failed or stopped one keeps it. What the ranks write together (a study's
 * point directories, the collective table.h5) is named from
 * shared_directory(). A run with nothing to spread (one path) is rank 0's
 * alone (idle()).
 *
 * With one process (no mpirun) everything here is the identity: rank 0 of
 * 1, the run as before.
 */
namespace cosmo
{
  namespace io
  {
    namespace ranks
    {
      /**
       * Before MPI_Init: when no launcher (mpirun, srun) started this process,
       * let Open MPI start as an isolated singleton with its shared-memory and
       * self transports only. Its default singleton start probes for a
       * runtime server and the network (UCX): 0.3 s of every run measured
       * against 0.02 s (benchmarks/README.md). Settings the user has made in
       * the environment are kept; other MPI libraries ignore these names.
       */
      void
      prepare_single_process_mpi();

      /**
       * What every main() of the suite constructs first: deal.II's
       * MPI_InitFinalize after prepare_single_process_mpi() (C++17 returns
       * the non-movable object in place).
       */
      inline Utilities::MPI::MPI_InitFinalize
      init_mpi(int &argc, char **&argv, const unsigned int max_threads = numbers::invalid_unsigned_int)
      {
        prepare_single_process_mpi();
        return Utilities::MPI::MPI_InitFinalize(argc, argv, max_threads);
      }

      /// This process' rank in MPI_COMM_WORLD, and their number (0 and 1 without MPI).
      unsigned int
      rank();
      unsigned int
      size();

      /**
       * The contiguous block [first, second) of `n` items that rank `r` of
       * `p` takes: the first n % p ranks one more than the others, in order.
       */
      std::pair<unsigned int, unsigned int>
      block(unsigned int n, unsigned int r, unsigned int p);

      /// block() for this rank.
      inline std::pair<unsigned int, unsigned int>
      my_block(const unsigned int n)
      {
        return block(n, rank(), size());
      }

      /// Where rank k > 0 of a run into `directory` writes: `directory`/rank-k.
      std::string
      private_directory(const std::string &directory, unsigned int k);

      /**
       * Called by run_application before the run: remember `directory` (the
       * output directory of the parameter file) as the shared one and return
       * the directory this rank runs in (`directory` on rank 0).
       */
      std::string
      enter_run(const std::string &directory);

      /// The run's output directory as the parameter file names it (rank 0's).
      const std::string &
      shared_directory();

      /// Rank 0 holds every rank's rows, in rank order (others: an empty list).
      std::vector<std::vector<double>>
      gather_rows(const std::vector<std::vector<double>> &mine);

      /// Rank 0 holds every rank's lines, in rank order (others: an empty list).
      std::vector<std::string>
      gather_lines(const std::vector<std::string> &mine);

      /// Every rank holds every rank's lines, in rank order.
      std::vector<std::string>
      all_gather_lines(const std::vector<std::string> &mine);

      /// The sum over the ranks, on every rank.
      unsigned int
      sum(unsigned int mine);

      /// Wait for every rank.
      void
      barrier();

      /// Wait for every rank, asleep rather than spinning (a rank done early).
      void
      wait_for_all();

      /**
       * For a run whose ranks take every step together (a distributed mesh):
       * make the communicator on which failing ranks ask whether the others
       * failed too (all ranks, at the same point, before the run).
       */
      void
      prepare_failure_agreement();

      /**
       * Called by a rank that met a failure: true if every rank calls it
       * within `seconds` (the same failure met at the same point of a
       * lockstep run), false if not (this rank's alone: the others wait in a
       * collective call of the run and never come). On a communicator of its
       * own, so that it cannot be matched with the run's collective calls.
       */
      bool
      all_ranks_failed_within(double seconds);

      /**
       * A run with nothing to spread over the ranks (`distributed` false:
       * a single path) is rank 0's alone, on all its threads: true on the
       * ranks k > 0, which then do nothing; rank 0 says so on the terminal.
       */
      bool
      idle(bool distributed);

      /**
       * The checkpoints of a driver of independent points (a study): their
       * payload begins with the header put_point_header() writes, the
       * number of ranks, the rank, its block and its rows so far, so that
       * a run resumed on another number of ranks takes every point done
       * from whichever rank did it.
       */
      void
      put_point_header(CheckpointWriter &w, unsigned int first, unsigned int next,
                       const CSVTable &rows);

      /// What a header says: [first, next) done, their rows in order.
      struct PointHeader
      {
        unsigned int                     n_ranks = 1, rank = 0, first = 0, next = 0;
        std::vector<std::vector<double>> rows;
      };
      /// Read put_point_header()'s header (`columns`: the table's columns, no rows).
      PointHeader
      get_point_header(CheckpointReader &r, const CSVTable &columns);

      /**
       * A resumed run of a driver of independent points on this rank: its
       * own checkpoint if it has one and was begun on as many ranks
       * (`same_ranks`, the reader after its header), else the rows of
       * every point any rank of the earlier run did (by index), read with
       * `read` from the run's directory (rank 0's) and rank-k/.
       */
      struct Resumed
      {
        bool                                        same_ranks = false;
        PointHeader                                 own;
        CheckpointReader                            reader;
        std::map<unsigned int, std::vector<double>> done;
        unsigned int                                ranks_then = 1;
        /// An earlier rank's checkpoint after its header, by the first point it
        /// had not done: what the driver holds after that rank's last point
        /// (a critical curve's predictor), to go on from there as it would have.
        std::map<unsigned int, CheckpointReader> after;
      };
      Resumed
      resume_points(const std::string &directory, const CSVTable &columns,
                    const std::function<CheckpointReader(const std::string &)> &read);

      /**
       * The end of a checkpoint of a run on a distributed mesh: the number
       * of ranks its mesh was divided over (0: a serial mesh). The DoFs of a
       * distributed mesh are numbered by the ranks' parts, so its state means
       * something only on as many ranks.
       */
      void
      put_mesh_ranks(CheckpointWriter &w, bool distributed_mesh);

      /**
       * On a distributed mesh every rank resumes from its own checkpoint,
       * which must be of the same step as every other's (a run killed while
       * the ranks wrote them may leave some a step behind, or without one):
       * throw io::InputError on all ranks unless `value` (whether there is a
       * checkpoint, the number of converged steps) is the same on all.
       */
      void
      check_checkpoints_agree(std::uint64_t value, const std::string &what);

      /**
       * Read put_mesh_ranks()'s number (a checkpoint written before it ends
       * without: a serial mesh) and throw io::InputError, naming the entry
       * `section / entry` that makes the mesh distributed, unless this run's
       * mesh is the same.
       */
      void
      check_mesh_ranks(CheckpointReader &r, bool distributed_mesh, const std::string &section,
                       const std::string &entry);

      /**
       * One BLAS thread per rank when the ranks share the node's cores
       * (OPENBLAS_NUM_THREADS, if set, is kept): the assembly's threads
       * are divided among the ranks by deal.II already.
       */
      void
      share_cores();
    } // namespace ranks
  }   // namespace io
} // namespace cosmo

#endif
