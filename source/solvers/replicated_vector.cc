#include <cosmo/solvers/replicated_vector.h>

#include <stdexcept>
#include <string>

namespace cosmo
{
  namespace solvers
  {
    ReplicatedVectorLayout::ReplicatedVectorLayout(MPI_Comm c, const IndexSet &locally_owned)
      : comm(c)
    {
      const unsigned int p = Utilities::MPI::n_mpi_processes(comm);
      rank                 = Utilities::MPI::this_mpi_process(comm);
      if (p == 1)
        return;
      // Each rank's range [first, first + count): contiguous and in rank order, so that an
      // all-gather of the ranges is the whole vector.
      int first = 0, count = locally_owned.n_elements();
      int contiguous = locally_owned.is_contiguous() ? 1 : 0;
      if (count > 0)
        first = *locally_owned.begin();
      counts.resize(p);
      displacements.resize(p);
      std::vector<int> contiguous_all(p);
      MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
      MPI_Allgather(&first, 1, MPI_INT, displacements.data(), 1, MPI_INT, comm);
      MPI_Allgather(&contiguous, 1, MPI_INT, contiguous_all.data(), 1, MPI_INT, comm);
      long next = 0;
      for (unsigned int r = 0; r < p; ++r)
        {
          if (!contiguous_all[r] || (counts[r] > 0 && displacements[r] != next))
            throw std::logic_error("ReplicatedVectorLayout: the unknowns of rank " +
                                   std::to_string(r) +
                                   " are not the contiguous range after those of the ranks before");
          displacements[r] = next;
          next += counts[r];
        }
      if (next != static_cast<long>(locally_owned.size()))
        throw std::logic_error("ReplicatedVectorLayout: the ranks own " + std::to_string(next) +
                               " of " + std::to_string(locally_owned.size()) + " unknowns");
    }

    void
    ReplicatedVectorLayout::sum_parts(Vector<double> &v) const
    {
      if (!distributed())
        return;
      // Each owner sums its range (MPI_Reduce_scatter), then everyone takes it.
      std::vector<double> mine(counts[rank]);
      MPI_Reduce_scatter(v.data(), mine.data(), counts.data(), MPI_DOUBLE, MPI_SUM, comm);
      MPI_Allgatherv(mine.data(), counts[rank], MPI_DOUBLE, v.data(), counts.data(),
                     displacements.data(), MPI_DOUBLE, comm);
    }

    void
    ReplicatedVectorLayout::take_from_owners(Vector<double> &v) const
    {
      if (!distributed())
        return;
      MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DOUBLE, v.data(), counts.data(), displacements.data(),
                     MPI_DOUBLE, comm);
    }

    void
    ReplicatedVectorLayout::take_from_owners(std::vector<unsigned char> &v) const
    {
      if (!distributed())
        return;
      MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_UNSIGNED_CHAR, v.data(), counts.data(),
                     displacements.data(), MPI_UNSIGNED_CHAR, comm);
    }

    void
    sum_on_all_ranks(std::vector<double> &x, MPI_Comm comm)
    {
      if (Utilities::MPI::n_mpi_processes(comm) == 1 || x.empty())
        return;
      // Summed on rank 0 and sent from there: the same bits everywhere (an
      // all-reduce need not give every rank the same rounding).
      const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
      MPI_Reduce(root ? MPI_IN_PLACE : x.data(), x.data(), x.size(), MPI_DOUBLE, MPI_SUM, 0, comm);
      MPI_Bcast(x.data(), x.size(), MPI_DOUBLE, 0, comm);
    }

    void
    ReplicatedVectorLayout::sum(std::vector<double> &x) const
    {
      if (distributed())
        sum_on_all_ranks(x, comm);
    }

    void
    ReplicatedVectorLayout::max(std::vector<double> &x) const
    {
      if (!distributed() || x.empty())
        return;
      MPI_Allreduce(MPI_IN_PLACE, x.data(), x.size(), MPI_DOUBLE, MPI_MAX, comm);
    }
  } // namespace solvers
} // namespace cosmo
