#ifndef cosmo_solvers_replicated_vector_h
#define cosmo_solvers_replicated_vector_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <vector>

/**
 * The drivers' vectors of a run on a distributed mesh (doc/parallel-runs.md,
 * "Distributed meshes"). The continuation, critical-point and Newton drivers
 * work on dealii::Vector: on a distributed mesh every rank holds the whole
 * vector (a replicated vector, 8 MB per million unknowns) and runs the
 * drivers on it, while assembly and factorization are divided. The drivers
 * then take the same decisions on every rank only if every rank holds the
 * same vector to the last bit. This class keeps them so: each rank owns a
 * contiguous range of the unknowns (the DoFs of a
 * parallel::distributed::Triangulation are numbered so), every entry is
 * computed once, by its owner, and copied from there.
 *
 * Default-constructed (one process, a serial mesh) every function is the
 * identity.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /// Sums of numbers each rank of `comm` holds a part of, the same on every rank (summed
    /// on rank 0 and broadcast: an all-reduce need not round alike on every rank).
    void
    sum_on_all_ranks(std::vector<double> &x, MPI_Comm comm);

    class ReplicatedVectorLayout
    {
    public:
      ReplicatedVectorLayout() = default;
      /// Ranks of `comm` owning `locally_owned` each, contiguous, in rank order (checked).
      ReplicatedVectorLayout(MPI_Comm comm, const IndexSet &locally_owned);

      /// More than one rank shares the vectors.
      bool
      distributed() const
      {
        return counts.size() > 1;
      }

      /// This rank owns entry i (every entry, undivided).
      bool
      owns(const types::global_dof_index i) const
      {
        return !distributed() || (i >= static_cast<types::global_dof_index>(displacements[rank]) &&
                                  i < static_cast<types::global_dof_index>(displacements[rank] + counts[rank]));
      }

      /// This rank is the last (or the only) one.
      bool
      is_last_rank() const
      {
        return !distributed() || rank + 1 == counts.size();
      }

      /**
       * Each rank holds a part of a sum in v (its cells' contributions to a
       * residual): afterwards every rank holds the whole sum, bitwise the
       * same on every rank (each entry summed by its owner, then copied).
       */
      void
      sum_parts(Vector<double> &v) const;

      /// Every rank takes each entry from its owner (after a step only owners do right).
      void
      take_from_owners(Vector<double> &v) const;
      /// The same for flags per unknown (a field component, whether constrained).
      void
      take_from_owners(std::vector<unsigned char> &v) const;

      /// Sums of numbers each rank holds a part of, the same on every rank (summed on rank 0).
      void
      sum(std::vector<double> &x) const;
      /// Maxima over the ranks (exact, so the same on every rank).
      void
      max(std::vector<double> &x) const;

    private:
      MPI_Comm         comm = MPI_COMM_SELF;
      unsigned int     rank = 0;
      std::vector<int> counts, displacements; ///< of each rank's range
    };
  } // namespace solvers
} // namespace cosmo

#endif
