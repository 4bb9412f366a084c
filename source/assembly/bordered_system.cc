#include <deal.II/lac/lapack_full_matrix.h>

#include <cosmo/assembly/bordered_system.h>

#include <cmath>

namespace cosmo
{
  namespace assembly
  {
    BorderedSystem::BorderedSystem(const solvers::SparseDirectSolver::Kind kind)
      : direct_solver(kind)
    {}

    void
    BorderedSystem::reinit(const DynamicSparsityPattern &dsp, const unsigned int n_b)
    {
      matrix.clear();
      distributed_solver.reset(); // (serial now, whatever it was before)
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      // (a pattern copied into the same object may keep its address and its
      // number of entries: its analysis must not be taken for the old one's)
      direct_solver.forget_analysis();
      border_columns.assign(n_b, Vector<double>(pattern.n_rows()));
      sensitivities.assign(n_b, Vector<double>(pattern.n_rows()));
      border_block.reinit(n_b, n_b);
      schur.reinit(n_b, n_b);
    }

    void
    BorderedSystem::reinit(const TrilinosWrappers::SparsityPattern &sp,
                           const unsigned int                       n_b,
                           const solvers::ReplicatedVectorLayout &  layout)
    {
      matrix.clear();
      pattern.reinit(0, 0, 0);
      distributed_matrix.reinit(sp);
      inner_layout = layout;
      if (!distributed_solver)
        distributed_solver =
          std::make_unique<solvers::DistributedDirectSolver>(sp.get_mpi_communicator());
      const unsigned int n = sp.n_rows();
      border_columns.assign(n_b, Vector<double>(n));
      sensitivities.assign(n_b, Vector<double>(n));
      border_block.reinit(n_b, n_b);
      schur.reinit(n_b, n_b);
    }

    void
    BorderedSystem::solve_with_A(Vector<double> &x) const
    {
      if (distributed())
        distributed_solver->solve(x);
      else
        direct_solver.solve(x);
    }

    double
    BorderedSystem::absolute_quadratic_form(const Vector<double> &v) const
    {
      if (distributed())
        return solvers::absolute_quadratic_form(distributed_matrix, v, inner_layout);
      return solvers::absolute_quadratic_form(matrix, v);
    }

    void
    BorderedSystem::clear()
    {
      if (distributed())
        distributed_matrix = 0;
      else
        matrix = 0;
      for (auto &b : border_columns)
        b = 0;
      border_block = 0;
    }

    void
    BorderedSystem::factorize()
    {
      sensitivities = border_columns;
      if (distributed())
        {
          distributed_solver->factorize(distributed_matrix);
          distributed_solver->solve(sensitivities);
        }
      else
        {
          direct_solver.factorize(matrix);
          direct_solver.solve(sensitivities);
        }
      const unsigned int nb = n_border();
      // Not symmetrized: S is symmetric in exact arithmetic, and its
      // measured asymmetry is a check of the assembly and the solver.
      for (unsigned int i = 0; i < nb; ++i)
        for (unsigned int j = 0; j < nb; ++j)
          schur(i, j) = border_block(i, j) - border_columns[i] * sensitivities[j];
    }

    namespace
    {
      /// dst = [[A, B], [B^T, E]] src, rows of prescribed border unknowns the identity.
      void
      bordered_vmult(const SparseMatrix<double> &       A,
                     const std::vector<Vector<double>> &B,
                     const FullMatrix<double> &         E,
                     Vector<double> &                   dst,
                     const Vector<double> &             src,
                     const std::vector<bool> &          free)
      {
        const unsigned int ni = A.m(), nb = B.size();
        AssertDimension(src.size(), ni + nb);
        Vector<double> src_in(ni), dst_in(ni);
        for (unsigned int i = 0; i < ni; ++i)
          src_in[i] = src[i];
        A.vmult(dst_in, src_in);
        dst.reinit(ni + nb);
        for (unsigned int k = 0; k < nb; ++k)
          for (unsigned int i = 0; i < ni; ++i)
            dst_in[i] += B[k][i] * src[ni + k];
        for (unsigned int i = 0; i < ni; ++i)
          dst[i] = dst_in[i];
        for (unsigned int k = 0; k < nb; ++k)
          {
            if (!free[k])
              {
                dst[ni + k] = src[ni + k];
                continue;
              }
            double r = B[k] * src_in;
            for (unsigned int l = 0; l < nb; ++l)
              r += E(k, l) * src[ni + l];
            dst[ni + k] = r;
          }
      }
    } // namespace

    void
    BorderedSystem::vmult(Vector<double> &         dst,
                          const Vector<double> &   src,
                          const std::vector<bool> &free) const
    {
      AssertThrow(!distributed(), ExcMessage("BorderedSystem::vmult of a distributed A"));
      bordered_vmult(matrix, border_columns, border_block, dst, src, free);
    }

    void
    BorderedSystem::vmult(Vector<double> &         dst,
                          const Vector<double> &   src,
                          const std::vector<bool> &free,
                          const AssembledBlocks &  copy) const
    {
      bordered_vmult(copy.A, copy.B, copy.E, dst, src, free);
    }

    bool
    BorderedSystem::assemble_copy(const std::function<bool()> &assemble, AssembledBlocks &copy)
    {
      if (distributed())
        return false;
      auto save = [this](AssembledBlocks &c) {
        c.A.reinit(pattern);
        c.A.copy_from(matrix);
        c.B = border_columns;
        c.E = border_block;
      };
      AssembledBlocks in_place;
      save(in_place);
      const bool assembled = assemble();
      if (assembled)
        save(copy);
      matrix.copy_from(in_place.A);
      border_columns = in_place.B;
      border_block   = in_place.E;
      return assembled;
    }

    void
    BorderedSystem::solve(const Vector<double> &   rhs,
                          Vector<double> &         dst,
                          const std::vector<bool> &free) const
    {
      const unsigned int ni = n_inner(), nb = n_border();
      AssertDimension(rhs.size(), ni + nb);
      AssertDimension(free.size(), nb);

      Vector<double> x0(ni);
      for (unsigned int i = 0; i < ni; ++i)
        x0[i] = rhs[i];
      solve_with_A(x0); // A^-1 r_in

      // Prescribed border unknowns move by their right-hand side.
      std::vector<double> d(nb, 0.);
      for (unsigned int k = 0; k < nb; ++k)
        if (!free[k])
          {
            d[k] = rhs[ni + k];
            if (d[k] != 0.)
              x0.add(-d[k], sensitivities[k]);
          }

      // Free ones: S_FF d_F = r_F - B_F^T x0 - E_FP d_P.
      std::vector<unsigned int> F;
      for (unsigned int k = 0; k < nb; ++k)
        if (free[k])
          F.push_back(k);
      if (!F.empty())
        {
          LAPACKFullMatrix<double> S(F.size(), F.size());
          Vector<double>           h(F.size());
          for (unsigned int a = 0; a < F.size(); ++a)
            {
              const unsigned int j = F[a];
              h[a]                 = rhs[ni + j] - border_columns[j] * x0;
              for (unsigned int k = 0; k < nb; ++k)
                if (!free[k])
                  h[a] -= border_block(j, k) * d[k];
              for (unsigned int b = 0; b < F.size(); ++b)
                S(a, b) = schur(j, F[b]);
            }
          S.compute_lu_factorization();
          S.solve(h);
          for (unsigned int a = 0; a < F.size(); ++a)
            {
              d[F[a]] = h[a];
              x0.add(-h[a], sensitivities[F[a]]);
            }
        }

      dst.reinit(ni + nb);
      for (unsigned int i = 0; i < ni; ++i)
        dst[i] = x0[i];
      for (unsigned int k = 0; k < nb; ++k)
        dst[ni + k] = d[k];
    }

    int
    BorderedSystem::n_negative_eigenvalues(const std::vector<bool> &free,
                                           const unsigned int       n_constraints) const
    {
      const int neg_A = distributed() ? distributed_solver->n_negative_eigenvalues() :
                                        direct_solver.n_negative_eigenvalues();
      if (neg_A < 0)
        return -1;
      std::vector<unsigned int> F;
      for (unsigned int k = 0; k < free.size(); ++k)
        if (free[k])
          F.push_back(k);
      int neg_S = 0;
      if (!F.empty())
        {
          LAPACKFullMatrix<double> S(F.size(), F.size());
          for (unsigned int a = 0; a < F.size(); ++a)
            for (unsigned int b = 0; b < F.size(); ++b)
              {
                S(a, b) = schur(F[a], F[b]);
                // LAPACK's dgeev does not return on a matrix that is not
                // finite (moduli of 1e300): unknown, not an endless balance.
                if (!std::isfinite(S(a, b)))
                  return -1;
              }
          S.compute_eigenvalues();
          for (unsigned int a = 0; a < F.size(); ++a)
            if (S.eigenvalue(a).real() < 0)
              ++neg_S;
        }
      return neg_A - static_cast<int>(n_constraints) + neg_S;
    }
  } // namespace assembly
} // namespace cosmo
