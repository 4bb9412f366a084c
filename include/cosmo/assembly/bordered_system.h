#ifndef cosmo_assembly_bordered_system_h
#define cosmo_assembly_bordered_system_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cosmo/solvers/distributed_direct.h>
#include <cosmo/solvers/replicated_vector.h>
#include <cosmo/solvers/sparse_direct.h>

#include <functional>
#include <memory>

#include <vector>

/**
 * The factorized system of every problem of the suite (assembled by
 * assembly::EnergyAssembler): the Hessian, serial or distributed over the
 * ranks, its MUMPS (or UMFPACK) factorization, the inertia, and the bordered
 * Newton system of an energy with a few global unknowns (none: the plain
 * Hessian, as the plate's):
 *
 *     [ A    B ] [d_in]   [r_in]        A = [[E_UU, C^T], [C, 0]]  (sparse:
 *     [ B^T  E ] [d_b ] = [r_b ]        field Hessian + linear constraints)
 *
 * with n_border global unknowns (the six rod strains) coupled densely to the
 * field through B = E_Ue. Only A goes to the sparse direct solver; the border
 * is eliminated with Y = A^-1 B (n_border extra solves with the same
 * factorization) and the small Schur complement S = E - B^T Y, which is the
 * condensed stiffness d(n, m)/d(nu, kappa) of the rod when the field is at
 * equilibrium (doc/specification/rod-cross-section.md).
 *
 * Each border unknown is either free (its row is the equation above) or
 * prescribed (its row is the identity: the driver changes it, Newton does
 * not), so one factorization serves prescribed strains, natural shapes and
 * mixed problems alike.
 *
 * On a mesh distributed over MPI ranks (reinit() with a Trilinos pattern),
 * A is `distributed_matrix`, each rank holding its rows, and is factorized
 * by MUMPS with distributed input; B, E, Y and S stay whole on every rank
 * (the vectors summed by `layout` after assembly), so the border and the
 * solves below run the same on every rank.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    class BorderedSystem
    {
    public:
      BorderedSystem(solvers::SparseDirectSolver::Kind kind =
                       solvers::SparseDirectSolver::default_kind());

      /// Set up A's pattern (size n_inner) and a border of n_border unknowns.
      void
      reinit(const DynamicSparsityPattern &dsp, unsigned int n_border);

      /**
       * The same for A distributed by rows over the ranks of `layout` (its
       * rows: `sp`'s, whose row partition `layout` describes); every rank
       * calls every function of this class.
       */
      void
      reinit(const TrilinosWrappers::SparsityPattern &sp,
             unsigned int                             n_border,
             const solvers::ReplicatedVectorLayout &  layout);

      /// A distributed over ranks (the second reinit()).
      bool
      distributed() const
      {
        return distributed_solver != nullptr;
      }

      unsigned int
      n_inner() const
      {
        return distributed() ? distributed_matrix.m() : matrix.m();
      }
      unsigned int
      n_border() const
      {
        return border_columns.size();
      }
      unsigned int
      size() const
      {
        return n_inner() + n_border();
      }

      /// Zero A, B and E for assembly.
      void
      clear();

      SparseMatrix<double>        matrix;         ///< A
      TrilinosWrappers::SparseMatrix distributed_matrix; ///< A, distributed by rows
      std::vector<Vector<double>> border_columns; ///< B, one vector per border unknown
      FullMatrix<double>          border_block;   ///< E

      /// Factorize A, compute Y = A^-1 B and S = E - B^T Y.
      void
      factorize();

      /// Solve J dst = rhs (vectors of size(); border unknowns not free get dst = rhs).
      void
      solve(const Vector<double> &rhs, Vector<double> &dst, const std::vector<bool> &free) const;

      /**
       * dst = J src with the assembled blocks (rows of prescribed border
       * unknowns are the identity): the Jacobian as an operator, for
       * residual checks, predictors and tests of the assembly. (Not of a
       * distributed A.)
       */
      void
      vmult(Vector<double> &dst, const Vector<double> &src, const std::vector<bool> &free) const;

      /// The assembled blocks A (serial), B and E: J at some state.
      struct AssembledBlocks
      {
        SparseMatrix<double>        A;
        std::vector<Vector<double>> B;
        FullMatrix<double>          E;
        void
        clear()
        {
          A.clear();
          B.clear();
          E.reinit(0, 0);
        }
      };

      /**
       * Call `assemble` (which fills A, B and E here) and move what it
       * assembled into `copy`, the blocks in place restored: the Jacobian at
       * another state beside the factorized one, for products (the
       * critical-point estimate's Hessians along the path). False on a
       * distributed A, or if `assemble` returns false (`copy` is then void).
       */
      bool
      assemble_copy(const std::function<bool()> &assemble, AssembledBlocks &copy);

      /// dst = J src with a copy's blocks (as vmult above).
      void
      vmult(Vector<double> &           dst,
            const Vector<double> &     src,
            const std::vector<bool> &  free,
            const AssembledBlocks &    copy) const;

      /// S = E - B^T A^-1 B, the Schur complement on the border (condensed stiffness).
      const FullMatrix<double> &
      schur_complement() const
      {
        return schur;
      }

      /**
       * Negative eigenvalues of the Hessian on the constrained space, the free
       * border unknowns condensed: inertia(J_FF) = inertia(A) + inertia(S_FF)
       * (Haynsworth), and the n_constraints multipliers of A contribute
       * exactly n_constraints negative eigenvalues, which are subtracted.
       * -1 if the solver does not report the inertia.
       */
      int
      n_negative_eigenvalues(const std::vector<bool> &free, unsigned int n_constraints) const;

      /// |v|.|A||v| for the resolution of a located event (v at least of size n_inner()).
      double
      absolute_quadratic_form(const Vector<double> &v) const;

      const solvers::SparseDirectSolver &
      solver() const
      {
        return direct_solver;
      }
      /// A's diagonal has no zero (its constraints condensed, no multipliers):
      /// the serial solver may order it for that (SparseDirectSolver).
      void
      set_nonzero_diagonal(const bool nonzero)
      {
        direct_solver.set_nonzero_diagonal(nonzero);
      }

    private:
      SparsityPattern             pattern;
      solvers::SparseDirectSolver direct_solver;
      std::unique_ptr<solvers::DistributedDirectSolver> distributed_solver;
      solvers::ReplicatedVectorLayout                  inner_layout;
      void
      solve_with_A(Vector<double> &x) const;
      std::vector<Vector<double>> sensitivities;
      FullMatrix<double>          schur;
    };
  } // namespace assembly
} // namespace cosmo

#endif
