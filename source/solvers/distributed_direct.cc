#include <cosmo/config.h>
#include <cosmo/solvers/distributed_direct.h>

#ifdef COSMO_WITH_MUMPS
#  include <dmumps_c.h>
#endif

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cosmo
{
  namespace solvers
  {
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
          throw std::runtime_error("MUMPS (distributed input) failed in phase " + std::to_string(job) +
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
      id.icntl[0] = -1;
      id.icntl[1] = -1;
      id.icntl[2] = -1;
      id.icntl[3] = 0;
      id.icntl[17] = 3; // distributed assembled input, analysis and factorization
      id.icntl[12] = 1; // no ScaLAPACK on the root front: INFOG(12) is the exact inertia
      id.icntl[13] = 60; // extra workspace (delayed pivots of indefinite matrices)
#else
      (void)comm;
      throw std::runtime_error("DistributedDirectSolver needs MUMPS");
#endif
    }

    DistributedDirectSolver::~DistributedDirectSolver()
    {
#ifdef COSMO_WITH_MUMPS
      if (data && data->comm != MPI_COMM_NULL)
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
      // A new analysis where the positions changed on any rank.
      int changed = !d.analysed || n != d.n || irn != d.irn || jcn != d.jcn;
      MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, d.comm);
      d.a = values;
      auto &id = d.id;
      if (changed)
        {
          d.irn    = std::move(irn);
          d.jcn    = std::move(jcn);
          d.n      = n;
          id.n     = n;
          id.nnz_loc = d.irn.size();
          id.irn_loc = d.irn.data();
          id.jcn_loc = d.jcn.data();
          id.a_loc   = d.a.data();
          d.analysed = false; // (until this analysis succeeds)
          d.call(1);
          d.analysed = true;
        }
      id.a_loc = d.a.data();
      for (unsigned int attempt = 0;; ++attempt)
        {
          id.job = 2;
          dmumps_c(&id);
          if ((id.infog[0] == -8 || id.infog[0] == -9) && attempt < 6)
            {
              id.icntl[13] = 2 * id.icntl[13] + 100;
              continue;
            }
          d.check(2);
          break;
        }
      n_negative = id.infog[11];
#else
      (void)n, (void)rows, (void)columns, (void)values;
#endif
    }

    void
    DistributedDirectSolver::factorize(const TrilinosWrappers::SparseMatrix &A)
    {
      std::vector<unsigned int> rows, columns;
      std::vector<double>       values;
      for (const auto row : A.locally_owned_range_indices())
        {
          const auto end = A.end(row);
          for (auto it = A.begin(row); it != end; ++it)
            if (it->column() >= row) // the upper triangle
              {
                rows.push_back(row);
                columns.push_back(it->column());
                values.push_back(it->value());
              }
        }
      factorize(A.m(), rows, columns, values);
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

    double
    absolute_quadratic_form(const TrilinosWrappers::SparseMatrix &A,
                            const Vector<double> &                v,
                            const ReplicatedVectorLayout &        layout)
    {
      std::vector<double> s(1, 0.);
      for (const auto row : A.locally_owned_range_indices())
        {
          const auto end = A.end(row);
          for (auto it = A.begin(row); it != end; ++it)
            s[0] += std::abs(it->value() * v[row] * v[it->column()]);
        }
      layout.sum(s);
      return s[0];
    }
  } // namespace solvers
} // namespace cosmo
