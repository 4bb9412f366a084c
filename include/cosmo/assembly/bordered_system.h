#ifndef cosmo_assembly_bordered_system_h
#define cosmo_assembly_bordered_system_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cosmo/solvers/sparse_direct.h>

#include <vector>

/**
 * The bordered Newton system of an energy with a few global unknowns:
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

      unsigned int
      n_inner() const
      {
        return matrix.m();
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
       * residual checks, predictors and tests of the assembly.
       */
      void
      vmult(Vector<double> &dst, const Vector<double> &src, const std::vector<bool> &free) const;

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

      const solvers::SparseDirectSolver &
      solver() const
      {
        return direct_solver;
      }

    private:
      SparsityPattern             pattern;
      solvers::SparseDirectSolver direct_solver;
      std::vector<Vector<double>> sensitivities;
      FullMatrix<double>          schur;
    };
  } // namespace assembly
} // namespace cosmo

#endif
