#include <cosmo/assembly/gauged_system.h>

#include <deal.II/base/mpi.h>

#include <algorithm>

namespace cosmo
{
  namespace assembly
  {
    void
    GaugedSystem::setup_bordered_system(DynamicSparsityPattern &            field_pattern,
                                             const std::array<Vector<double>, 6> &rows,
                                             const std::string &                  linear_solver)
    {
      constraint_rows = rows;
      n_field         = rows[0].size();
      DynamicSparsityPattern dsp(n_field + n_gauge);
      for (unsigned int i = 0; i < n_field; ++i)
        for (auto it = field_pattern.begin(i); it != field_pattern.end(i); ++it)
          dsp.add(i, it->column());
      for (unsigned int k = 0; k < n_gauge; ++k)
        for (unsigned int i = 0; i < n_field; ++i)
          if (constraint_rows[k][i] != 0)
            {
              dsp.add(n_field + k, i);
              dsp.add(i, n_field + k);
            }
      system = std::make_unique<BorderedSystem>(
        solvers::SparseDirectSolver::kind_from_string(linear_solver));
      system->reinit(dsp, n_strains);
    }

    void
    GaugedSystem::setup_distributed_bordered_system(
      const IndexSet &                                                 owned_field,
      const IndexSet &                                                 relevant_field,
      const std::function<void(TrilinosWrappers::SparsityPattern &)> &add_field_entries,
      const std::array<Vector<double>, 6> &                            rows,
      MPI_Comm                                                         comm)
    {
      constraint_rows = rows;
      n_field         = rows[0].size();
      const bool last = Utilities::MPI::this_mpi_process(comm) + 1 == Utilities::MPI::n_mpi_processes(comm);
      IndexSet   owned(n_field + n_gauge), writable(n_field + n_gauge);
      owned.add_indices(owned_field);
      writable.add_indices(relevant_field);
      if (last)
        {
          owned.add_range(n_field, n_field + n_gauge);
          writable.add_range(n_field, n_field + n_gauge);
        }
      owned.compress();
      writable.compress();
      TrilinosWrappers::SparsityPattern sp;
      sp.reinit(owned, owned, writable, comm);
      add_field_entries(sp);
      // C: its columns on the rows of the DoFs' owners, its rows on the last rank.
      for (unsigned int k = 0; k < n_gauge; ++k)
        for (unsigned int i = 0; i < n_field; ++i)
          if (constraint_rows[k][i] != 0)
            {
              if (owned_field.is_element(i))
                sp.add(i, n_field + k);
              if (last)
                sp.add(n_field + k, i);
            }
      sp.compress();
      field_layout = solvers::ReplicatedVectorLayout(comm, owned_field);
      system       = std::make_unique<BorderedSystem>();
      system->reinit(sp, n_strains, solvers::ReplicatedVectorLayout(comm, owned));
      // (the strains' and gauge rows' residuals are computed from whole vectors on every rank)
    }

    void
    GaugedSystem::add_distributed_gauge_entries()
    {
      // The gauge block C (A is zeroed: adding sets), on the rows this rank
      // owns, a row per call (entry by entry took a second per assembly of
      // 250 000 unknowns); the last rank adds C's own rows.
      const unsigned int nf   = n_field;
      const bool         last = field_layout.is_last_rank();
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
      for (types::global_dof_index i = 0; i < nf; ++i)
        if (field_layout.owns(i))
          {
            columns.clear();
            values.clear();
            for (unsigned int k = 0; k < n_gauge; ++k)
              if (constraint_rows[k][i] != 0)
                {
                  columns.push_back(nf + k);
                  values.push_back(constraint_rows[k][i]);
                }
            if (!columns.empty())
              system->distributed_matrix.add(i, columns.size(), columns.data(), values.data());
          }
      if (last)
        for (unsigned int k = 0; k < n_gauge; ++k)
          {
            columns.clear();
            values.clear();
            for (types::global_dof_index i = 0; i < nf; ++i)
              if (constraint_rows[k][i] != 0)
                {
                  columns.push_back(i);
                  values.push_back(constraint_rows[k][i]);
                }
            system->distributed_matrix.add(nf + k, columns.size(), columns.data(), values.data());
          }
      system->distributed_matrix.compress(VectorOperation::add);
    }

    void
    GaugedSystem::sum_rank_parts(Vector<double> *       R,
                                 const bool             jacobian,
                                 FullMatrix<double> &   E,
                                 double &               energy,
                                 std::array<double, 6> &resultants,
                                 double &               min_elastic_J)
    {
      if (R)
        field_layout.sum_parts(*R);
      std::vector<double> sums = {energy};
      sums.insert(sums.end(), resultants.begin(), resultants.end());
      if (jacobian)
        {
          for (auto &b : system->border_columns)
            field_layout.sum_parts(b);
          sums.insert(sums.end(), E.begin(), E.end());
        }
      field_layout.sum(sums);
      energy = sums[0];
      for (unsigned int k = 0; k < 6; ++k)
        resultants[k] = sums[1 + k];
      if (jacobian)
        std::copy(sums.begin() + 7, sums.end(), E.begin());
      std::vector<double> smallest = {-min_elastic_J};
      field_layout.max(smallest);
      min_elastic_J = -smallest[0];
    }

    void
    GaugedSystem::add_gauge_residuals(Vector<double> &R, const Vector<double> &U) const
    {
      const unsigned int nf = n_field;
      for (unsigned int k = 0; k < n_gauge; ++k)
        {
          const double lambda_k = U[nf + k];
          double       cu       = 0;
          for (unsigned int i = 0; i < nf; ++i)
            {
              const double cki = constraint_rows[k][i];
              if (cki != 0)
                {
                  R[i] += lambda_k * cki;
                  cu += cki * U[i];
                }
            }
          R[nf + k] = cu;
        }
    }

    void
    GaugedSystem::set_gauge_entries()
    {
      const unsigned int nf = n_field;
      for (unsigned int k = 0; k < n_gauge; ++k)
        for (unsigned int i = 0; i < nf; ++i)
          if (constraint_rows[k][i] != 0)
            {
              system->matrix.set(nf + k, i, constraint_rows[k][i]);
              system->matrix.set(i, nf + k, constraint_rows[k][i]);
            }
    }
  } // namespace assembly
} // namespace cosmo
