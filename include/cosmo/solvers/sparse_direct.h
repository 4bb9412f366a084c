#ifndef cosmo_solvers_sparse_direct_h
#define cosmo_solvers_sparse_direct_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

/**
 * A direct solver for the symmetric (possibly indefinite) Hessians of the
 * suite: the sparsity is analysed once, each Newton step refactorizes, and
 * the factorization is reused for any number of right-hand sides (Newton
 * step, stiffness condensation, predictor).
 *
 * MUMPS (LDL^T, symmetric indefinite) is the default: it is ~3x faster than
 * UMFPACK's LU on these matrices and reports the number of negative pivots,
 * i.e. the inertia of the matrix, which the stability indicator needs.
 * UMFPACK is kept as a reference (no inertia).
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /**
     * sum_ij |A_ij| |v_i| |v_j| over the first A.m() entries of v: the bound
     * of |v.dA v| for a componentwise perturbation |dA| <= |A| (round-off of
     * a backward-stable factorization is eps times this, up to growth).
     */
    double
    absolute_quadratic_form(const SparseMatrix<double> &A, const Vector<double> &v);

    /**
     * The rows of a bordered matrix that are dense: longer than 8 times the
     * median row (the gauge and strain rows couple to a whole field; a
     * field row to its element neighbours only).
     */
    std::vector<bool>
    dense_rows(const SparsityPattern &sp);

    /**
     * A fill-reducing order for the LDL^T of a bordered matrix: METIS's
     * nested dissection of the graph without the dense rows, those rows
     * last, as MUMPS's PERM_IN (1-based position of each unknown). Empty if
     * there is no border or no METIS. The null pivots of a singular block
     * (rigid motions fixed by the gauge rows) are delayed by MUMPS into the
     * last front, with the border: the LDL^T and its inertia are those of
     * the whole matrix.
     */
    std::vector<int>
    border_last_ordering(const SparsityPattern &sp);

    /**
     * The ranks of a one-path run under mpirun factorize together
     * (doc/parallel-runs.md): rank 0 assembles and drives the path as one
     * process would, and every MUMPS instance of more than min_unknowns()
     * unknowns that it creates afterwards runs on all ranks (MUMPS's host
     * with the matrix and the right-hand sides centralized on rank 0,
     * PAR = 1, ICNTL(13) = 1 so that INFOG(12) is the exact inertia in
     * parallel), while ranks > 0 serve in serve(): they wait for rank 0's
     * next MUMPS phase, asleep between phases, and take part in it.
     * Smaller matrices stay on rank 0 alone (MPI_COMM_SELF): their fronts
     * are too small for two processes to gain.
     */
    namespace factorization_ranks
    {
      /// Rank 0 of a run on several ranks: share the factorizations from now on.
      void
      enable();
      /// Rank 0: sharing factorizations with other ranks.
      bool
      active();
      /// The smallest matrix (unknowns) factorized on all ranks: 20000, or
      /// the environment's COSMO_PARALLEL_FACTORIZATION_MIN.
      unsigned int
      min_unknowns();
      /// Ranks > 0: take part in rank 0's MUMPS phases until release().
      void
      serve();
      /// Rank 0: end every shared MUMPS instance and the ranks' serve() (no-op unless active).
      void
      release();
      /// Rank 0: MUMPS phases run on all ranks so far (factorizations, solves).
      unsigned int
      shared_phases();
    } // namespace factorization_ranks

    /**
     * The largest MUMPS factorization of this process so far, as MUMPS
     * reports it (INFOG(21), INFOG(22): megabytes used in the
     * factorization on the rank that used most, and on all ranks; with
     * INFOG(29) the entries in the factors): what a run of this size
     * needs per rank (summary.json "factorization_memory", the cost model
     * of doc/parallel-runs.md).
     */
    struct FactorizationMemory
    {
      unsigned int unknowns       = 0;
      double       factor_entries = 0;
      double       mb_per_rank    = 0; ///< the rank that used most
      double       mb_all_ranks   = 0;
      unsigned int ranks          = 0; ///< 0: no MUMPS factorization yet
    };
    const FactorizationMemory &
    largest_factorization();
    /// Keep `f` as the largest if it used more memory on all ranks (every MUMPS factorization).
    void
    note_factorization(const FactorizationMemory &f);

    class SparseDirectSolver
    {
    public:
      enum class Kind
      {
        mumps,
        umfpack
      };

      explicit SparseDirectSolver(Kind kind = default_kind());
      ~SparseDirectSolver();

      static Kind
      default_kind();
      static Kind
      kind_from_string(const std::string &name);
      static std::string
      kind_names();

      /// Factorize (analysing the pattern the first time or when it changed).
      void
      factorize(const SparseMatrix<double> &A);

      /**
       * MUMPS: whether the matrices to come have no zero on their diagonal,
       * i.e. are a stiffness without Lagrange multipliers or bordered rows
       * (the plate's, whose constraints are eliminated). Then the analysis
       * skips the maximum weighted matching (ICNTL(6) = 0), whose purpose for
       * a symmetric matrix is to pair zero-diagonal rows into 2 x 2 pivots;
       * MUMPS then scales each factorization by its iterative row and column
       * scaling (INFOG(33) = 7) instead of the matching's (-2). On the plate:
       * 14 % fewer factor entries, 10 % less factorization time, located
       * thresholds within their resolution of the matching's, also at
       * h/R = 1e-3 and 3e-4 (benchmarks/README.md). The inertia is exact
       * either way. Takes effect at the next analysis (it forgets the last
       * one); default false.
       */
      void
      set_nonzero_diagonal(const bool nonzero)
      {
        nonzero_diagonal = nonzero;
        analysed_pattern = nullptr;
      }

      /**
       * The next factorization analyses its matrix's pattern again: for a
       * pattern rebuilt in place (the rod's self-contact pairs), whose
       * address and perhaps its number of entries are the old one's.
       */
      void
      forget_analysis()
      {
        analysed_pattern = nullptr;
      }

      /// Solve in place, A x = b.
      void
      solve(Vector<double> &rhs_and_solution) const;
      /// Solve for several right-hand sides at once (in place).
      void
      solve(std::vector<Vector<double>> &rhs_and_solutions) const;

      /// Number of negative eigenvalues of the last factorized matrix (-1 if unknown).
      int
      n_negative_eigenvalues() const
      {
        return n_negative;
      }

      Kind
      kind() const
      {
        return solver_kind;
      }

      /// MUMPS: floating-point operations of the last factorization
      /// (RINFOG(3)), NaN otherwise; with its time, the flop rate against
      /// the machine's peak (benchmarks/).
      double
      factorization_flops() const;
      /// MUMPS: entries in the factors (INFOG(29)), 0 otherwise.
      double
      factor_entries() const;

    private:
      Kind solver_kind;
      int  n_negative = -1;
      bool nonzero_diagonal = false;

      // UMFPACK
      std::unique_ptr<SparseDirectUMFPACK> umfpack;

      // MUMPS (opaque to keep dmumps_c.h out of the headers)
      struct MumpsData;
      std::unique_ptr<MumpsData> mumps;
      const SparsityPattern *    analysed_pattern = nullptr;
      std::size_t                analysed_nnz     = 0;
    };
  } // namespace solvers
} // namespace cosmo

#endif
