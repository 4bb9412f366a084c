#include <deal.II/lac/trilinos_index_access.h>

#include <cosmo/config.h>
#include <cosmo/solvers/distributed_direct.h>
#include <cosmo/solvers/sparse_direct.h>

#include "mumps_phases.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cosmo
{
  namespace solvers
  {
    namespace
    {
      /// f(row, column, value) for the entries of this rank's rows, through
      /// Epetra's views: deal.II's iterators over a Trilinos matrix cost about
      /// a microsecond per entry (5 s per pass over 75 000 unknowns of the
      /// plate, benchmarks/README.md "Distributed meshes").
      template <typename F>
      void
      for_each_owned_entry(const TrilinosWrappers::SparseMatrix &A, const F &f)
      {
        const Epetra_CrsMatrix &M = A.trilinos_matrix();
        for (int local = 0; local < M.NumMyRows(); ++local)
          {
            int     n = 0;
            double *v = nullptr;
            int *   c = nullptr;
            M.ExtractMyRowView(local, n, v, c);
            const unsigned int row = TrilinosWrappers::global_row_index(M, local);
            for (int k = 0; k < n; ++k)
              f(row, static_cast<unsigned int>(TrilinosWrappers::global_column_index(M, c[k])), v[k]);
          }
      }
    } // namespace

#ifdef COSMO_WITH_MUMPS
    struct DistributedDirectSolver::Data
    {
      DMUMPS_STRUC_C   id{};
      MPI_Comm         comm = MPI_COMM_NULL;
      bool             analysed = false;
      std::vector<int> irn, jcn;     // 1-based, this rank's entries
      std::vector<double> a;
      unsigned int     n = 0;

      void
      call(const int job)
      {
        id.job = job;
        dmumps_c(&id);
        check(job);
      }

      /// INFOG(1) is the same on every rank: all of them throw, or none.
      void
      check(const int job) const
      {
        if (id.infog[0] < 0)
          throw FactorizationFailure("MUMPS (distributed input) failed in phase " + std::to_string(job) +
                                   ": INFOG(1) = " + std::to_string(id.infog[0]) +
                                   ", INFOG(2) = " + std::to_string(id.infog[1]));
      }
    };
#else
    struct DistributedDirectSolver::Data
    {};
#endif

    DistributedDirectSolver::DistributedDirectSolver(MPI_Comm comm)
      : data(std::make_unique<Data>())
    {
#ifdef COSMO_WITH_MUMPS
      MPI_Comm_dup(comm, &data->comm);
      auto &id        = data->id;
      id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(data->comm);
      id.par          = 1;
      id.sym          = 2; // symmetric, possibly indefinite: LDL^T
      data->call(-1);
      mumps_phases::silence(id);
      id.icntl[17] = 3; // distributed assembled input, analysis and factorization
      id.icntl[12] = 1; // no ScaLAPACK on the root front: INFOG(12) is the exact inertia
      id.icntl[13] = 60; // extra workspace (delayed pivots of indefinite matrices)
      // Sequential ordering on the host, QAMD as SparseDirectSolver's: on
      // one rank the same factorization as one process's (the dome's located
      // threshold the same to the last bit, benchmarks/README.md
      // "Distributed meshes").
      id.icntl[27] = 1;
      id.icntl[6]  = 6;
      if (const char *o = std::getenv("COSMO_MUMPS_ORDERING"))
        if (std::atoi(o) >= 0 && std::atoi(o) <= 7) // (100, the border-last ordering: serial only)
          id.icntl[6] = std::atoi(o);
#else
      (void)comm;
      throw std::runtime_error("DistributedDirectSolver needs MUMPS");
#endif
    }

    DistributedDirectSolver::~DistributedDirectSolver()
    {
#ifdef COSMO_WITH_MUMPS
      // (not while an exception of this rank alone unwinds: MUMPS's end and
      // MPI_Comm_free are collective, and the others are elsewhere; the error
      // ends every rank through MPI_Abort)
      if (data && data->comm != MPI_COMM_NULL && std::uncaught_exceptions() == 0)
        {
          data->id.job = -2;
          dmumps_c(&data->id);
          MPI_Comm_free(&data->comm);
        }
#endif
    }

    void
    DistributedDirectSolver::factorize(const unsigned int               n,
                                       const std::vector<unsigned int> &rows,
                                       const std::vector<unsigned int> &columns,
                                       const std::vector<double> &      values)
    {
#ifdef COSMO_WITH_MUMPS
      auto &d = *data;
      std::vector<int> irn(rows.size()), jcn(rows.size());
      int              below = 0;
      for (std::size_t k = 0; k < rows.size(); ++k)
        {
          below |= rows[k] > columns[k];
          irn[k] = rows[k] + 1;
          jcn[k] = columns[k] + 1;
        }
      // (all ranks decide together: a throw on one rank alone would leave the
      // others waiting in the next collective call)
      MPI_Allreduce(MPI_IN_PLACE, &below, 1, MPI_INT, MPI_MAX, d.comm);
      if (below)
        throw std::invalid_argument("DistributedDirectSolver::factorize: an entry below the "
                                    "diagonal (give the upper triangle, each pair once)");
      const bool changed = !d.analysed || n != d.n || irn != d.irn || jcn != d.jcn;
      if (changed)
        {
          d.irn = std::move(irn);
          d.jcn = std::move(jcn);
        }
      d.a = values;
      run_factorization(n, changed);
#else
      (void)n, (void)rows, (void)columns, (void)values;
#endif
    }

    void
    DistributedDirectSolver::factorize(const TrilinosWrappers::SparseMatrix &A)
    {
#ifdef COSMO_WITH_MUMPS
      // The upper triangle of this rank's rows straight into MUMPS's arrays:
      // the positions are compared with the analysed ones in place and
      // copied only when they changed (no copy of the matrix beside them).
      auto &      d       = *data;
      std::size_t count   = 0;
      bool        same    = d.analysed && d.n == A.m();
      for_each_owned_entry(A, [&](const unsigned int row, const unsigned int column, const double) {
        if (column >= row)
          {
            same = same && count < d.irn.size() && d.irn[count] == int(row + 1) &&
                   d.jcn[count] == int(column + 1);
            ++count;
          }
      });
      same = same && count == d.irn.size();
      if (!same)
        {
          d.irn.clear();
          d.jcn.clear();
          d.irn.reserve(count);
          d.jcn.reserve(count);
        }
      d.a.clear();
      d.a.reserve(count);
      for_each_owned_entry(A, [&](const unsigned int row, const unsigned int column, const double v) {
        if (column >= row) // the upper triangle
          {
            if (!same)
              {
                d.irn.push_back(row + 1);
                d.jcn.push_back(column + 1);
              }
            d.a.push_back(v);
          }
      });
      run_factorization(A.m(), !same);
#else
      (void)A;
#endif
    }

    void
    DistributedDirectSolver::run_factorization(const unsigned int n, const bool positions_changed)
    {
#ifdef COSMO_WITH_MUMPS
      auto &d = *data;
      // A new analysis where the positions changed on any rank.
      int changed = positions_changed ? 1 : 0;
      MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, d.comm);
      auto &id = d.id;
      if (changed)
        {
          d.n        = n;
          id.n       = n;
          id.nnz_loc = d.irn.size();
          id.irn_loc = d.irn.data();
          id.jcn_loc = d.jcn.data();
          id.a_loc   = d.a.data();
          d.analysed = false; // (until this analysis succeeds)
          d.call(1);
          d.analysed = true;
        }
      id.a_loc = d.a.data();
      mumps_phases::factorize_enlarging_workspace(id, [&](const int job) {
        id.job = job;
        dmumps_c(&id);
      });
      d.check(2);
      n_negative = id.infog[11];
      FactorizationMemory f;
      f.unknowns       = n;
      f.factor_entries = id.infog[28] >= 0 ? double(id.infog[28]) : -1e6 * id.infog[28];
      f.mb_per_rank    = id.infog[20];
      f.mb_all_ranks   = id.infog[21];
      int ranks        = 1;
      MPI_Comm_size(d.comm, &ranks);
      f.ranks = ranks;
      note_factorization(f);
#else
      (void)n, (void)positions_changed;
#endif
    }

    void
    DistributedDirectSolver::solve(Vector<double> &x) const
    {
#ifdef COSMO_WITH_MUMPS
      auto &d  = *data;
      auto &id = d.id;
      int   rank = 0;
      MPI_Comm_rank(d.comm, &rank);
      if (x.size() != d.n)
        throw std::invalid_argument("DistributedDirectSolver::solve: a vector of size " +
                                    std::to_string(x.size()) + " for a matrix of order " +
                                    std::to_string(d.n));
      // Centralized right-hand side and solution on the host (rank 0), then
      // the solution to every rank.
      id.nrhs = 1;
      id.lrhs = x.size();
      id.rhs  = rank == 0 ? x.data() : nullptr;
      d.call(3);
      MPI_Bcast(x.data(), x.size(), MPI_DOUBLE, 0, d.comm);
#else
      (void)x;
#endif
    }

    void
    DistributedDirectSolver::solve(std::vector<Vector<double>> &xs) const
    {
#ifdef COSMO_WITH_MUMPS
      if (xs.empty())
        return;
      auto &d  = *data;
      auto &id = d.id;
      for (const auto &x : xs)
        if (x.size() != d.n)
          throw std::invalid_argument("DistributedDirectSolver::solve: a vector of size " +
                                      std::to_string(x.size()) + " for a matrix of order " +
                                      std::to_string(d.n));
      // The right-hand sides side by side (column-major), centralized on the
      // host, then every solution to every rank.
      std::vector<double> all(std::size_t(d.n) * xs.size());
      for (std::size_t k = 0; k < xs.size(); ++k)
        std::copy(xs[k].begin(), xs[k].end(), all.begin() + k * d.n);
      int rank = 0;
      MPI_Comm_rank(d.comm, &rank);
      id.nrhs = xs.size();
      id.lrhs = d.n;
      id.rhs  = rank == 0 ? all.data() : nullptr;
      d.call(3);
      MPI_Bcast(all.data(), all.size(), MPI_DOUBLE, 0, d.comm);
      for (std::size_t k = 0; k < xs.size(); ++k)
        std::copy(all.begin() + k * d.n, all.begin() + (k + 1) * d.n, xs[k].begin());
#else
      (void)xs;
#endif
    }

    double
    absolute_quadratic_form(const TrilinosWrappers::SparseMatrix &A,
                            const Vector<double> &                v,
                            const ReplicatedVectorLayout &        layout)
    {
      std::vector<double> s(1, 0.);
      for_each_owned_entry(A, [&](const unsigned int row, const unsigned int column, const double a) {
        s[0] += std::abs(a * v[row] * v[column]);
      });
      layout.sum(s);
      return s[0];
    }
  } // namespace solvers
} // namespace cosmo
