#ifndef cosmo_solvers_distributed_direct_h
#define cosmo_solvers_distributed_direct_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/solvers/replicated_vector.h>

#include <memory>
#include <stdexcept>
#include <vector>

/**
 * MUMPS LDL^T with distributed assembled input, for runs whose matrix is
 * assembled on several ranks (a mesh distributed over them, issue: beyond one
 * machine). Every rank calls every function (SPMD), each giving the entries
 * of its own rows; the right-hand side and the solution are replicated
 * vectors (the drivers' vectors stay whole on every rank: 8 MB per million
 * unknowns, far below the factors). The inertia is INFOG(12) with
 * ICNTL(13) = 1, exact in parallel as in solvers::factorization_ranks.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /// A failure MUMPS reports in INFOG(1), the same on every rank (every rank throws it).
    class FactorizationFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    class DistributedDirectSolver
    {
    public:
      explicit DistributedDirectSolver(MPI_Comm comm);
      ~DistributedDirectSolver();

      /**
       * Factorize the symmetric matrix of order n whose upper-triangle entries
       * this rank holds: rows[k] <= columns[k] (0-based), values[k]; each
       * off-diagonal pair is given once, by one rank, and duplicates of a
       * position are summed. An entry below the diagonal on any rank is an
       * error on all of them (std::invalid_argument). The analysis runs the
       * first time and whenever the entries' positions change on any rank.
       */
      void
      factorize(unsigned int                     n,
                const std::vector<unsigned int> &rows,
                const std::vector<unsigned int> &columns,
                const std::vector<double> &      values);

      /**
       * Factorize a symmetric matrix distributed by rows over the ranks of
       * this solver's communicator (a matrix assembled on the locally owned
       * cells of a distributed mesh): each rank gives its locally owned rows.
       */
      void
      factorize(const TrilinosWrappers::SparseMatrix &A);

      /// Solve in place, the same replicated vector (of the matrix's order) on every rank.
      void
      solve(Vector<double> &rhs_and_solution) const;

      /// The same for several right-hand sides at once (one solve phase of MUMPS).
      void
      solve(std::vector<Vector<double>> &rhs_and_solutions) const;

      /// Negative eigenvalues of the last matrix factorized (the same on every rank).
      int
      n_negative_eigenvalues() const
      {
        return n_negative;
      }

    private:
      /// Analyse (if the positions changed on any rank) and factorize what Data holds.
      void
      run_factorization(unsigned int n, bool positions_changed);
      struct Data;
      std::unique_ptr<Data> data;
      int                   n_negative = -1;
    };

    /**
     * |v|.|A||v| of a matrix distributed by rows and a replicated v (the
     * resolution of a located event, as absolute_quadratic_form of a serial
     * matrix): each rank sums its rows, the same total on every rank.
     */
    double
    absolute_quadratic_form(const TrilinosWrappers::SparseMatrix &A,
                            const Vector<double> &                v,
                            const ReplicatedVectorLayout &        layout);
  } // namespace solvers
} // namespace cosmo

#endif
