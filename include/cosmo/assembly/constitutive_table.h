#ifndef cosmo_assembly_constitutive_table_h
#define cosmo_assembly_constitutive_table_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/run_record.h>
#include <cosmo/assembly/reduced_rod_problem.h>

#include <functional>
#include <string>

/**
 * A constitutive table of a reduced rod: energy, resultants and 6x6
 * stiffness on a grid of two strains (the others as prescribed or free in
 * "Rod strains"), so that a rod simulator can use the nonlinear law of the
 * section (doc/specification/strip.md, issue 4). Written as table.csv (one row per grid point)
 * and table.h5 (datasets strain_1, strain_2, energy [n1 x n2], resultants
 * [n1 x n2 x 6], stiffness [n1 x n2 x 6 x 6], converged [n1 x n2]).
 *
 * The grid is swept row by row in serpentine order, each point solved by
 * Newton from its neighbour; a point that does not converge is approached
 * in substeps, and recorded as not converged if that fails too.
 */
namespace cosmo
{
  namespace assembly
  {
    /**
     * Checkpoints of a table (io/checkpoint.h): after a finished point (at
     * most once a second, and at a signal) the points so far, with the
     * point header of io/ranks.h, and the state the next point starts
     * from; a resumed run goes on after the last point it holds and writes
     * the table an uninterrupted run writes.
     */
    struct TableCheckpointing
    {
      /// Write the run's checkpoint with this payload.
      std::function<void(const io::CheckpointWriter &)> write;
      /// The state `save` keeps (the next point's start), into a checkpoint as a vector.
      std::function<void(io::CheckpointWriter &)> save_start;
      /**
       * The run is resumed (--resume), with or without a checkpoint of this
       * rank's (io::ranks::resume_points, reading with read_in: the run's
       * checkpoint in a directory). On as many MPI ranks, each rank goes on
       * from its own; begun on another number, each rank takes the points
       * of its block any earlier rank did, and where an earlier rank
       * stopped, its state (set_start) is the next point's start.
       */
      bool resuming = false;
      std::function<io::CheckpointReader(const std::string &)> read_in;
      std::function<void(const std::vector<double> &)>         set_start;
    };

    /// What a table's file records about its run (table.h5 attributes).
    struct TableDescription
    {
      std::string application, version;
      /// io::checkpoint_parameters() of the run: every entry, one line each.
      std::string parameters;
      /// Units of the energy per length, forces n and moments m, and of length.
      std::string energy_unit = "E L^2", force_unit = "E L^2", moment_unit = "E L^3", length_unit = "L";
      std::array<bool, 6>   free_strains{};
      std::array<double, 6> held_resultants{};
    };

    class ConstitutiveTable
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      bool
      enabled() const
      {
        return is_enabled;
      }
      /// Is a table asked for in these (parsed) parameters?
      static bool
      enabled_in(ParameterHandler &prm);

      /// io::InputError naming the axis if an axis strain is free (its value would be ignored).
      void
      check_axes(const std::array<bool, 6> &free_strains) const;

      /// resolve(e): the converged state at prescribed strains e from the last one.
      using Resolver = std::function<ReducedRodState(const std::array<double, 6> &)>;

      /// Sweep the grid around `base` (the other strains) and write the files.
      /**
       * `start`: the strains of the problem's current state. `save` and
       * `restore` keep and bring back that state, so that a failed attempt
       * at a point is retried (and the next point started) from the last
       * converged point, not from a half-way substep.
       */
      void
      run(const std::array<double, 6> &base,
          const std::array<double, 6> &start,
          const Resolver &             resolve,
          const std::function<void()> &save,
          const std::function<void()> &restore,
          const std::string &          directory,
          const std::function<void(const std::string &)> &progress,
          const TableDescription &     description,
          const TableCheckpointing &   checkpointing = {}) const;

      /**
       * run() as an application calls it: around `base` from the state in
       * `solution` (which the points overwrite), with the run's checkpoints
       * and --resume (the start of the next point kept in the checkpoint),
       * progress to the run's log, and the files in `directory`.
       */
      void
      run_in(io::RunRecord &              record,
             Vector<double> &             solution,
             const std::array<double, 6> &base,
             const std::array<double, 6> &start,
             const Resolver &             resolve,
             const std::string &          directory,
             const TableDescription &     description) const;

      unsigned int first = 3, second = 5; ///< strain indices
      double       from1 = 0, to1 = 1, from2 = 0, to2 = 1;
      unsigned int n1 = 5, n2 = 5;
      /// Per point: energy, 6 resultants, 36 stiffnesses and the flag in memory,
      /// a CSV row of 30 numbers with its vector, the HDF5 and checkpoint copies.
      static constexpr double bytes_per_point = 44 * 8 + (30 * 8 + 24) + 2 * 44 * 8;

    private:
      bool is_enabled = false;
    };
  } // namespace assembly
} // namespace cosmo

#endif
