// CrossSectionProblem's set-up: the discretization (discretization.cc), the gauge rows, the
// bordered system and the reference state.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "cross_section_problem.h"

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      constexpr unsigned int n_strains = assembly::ReducedRodProblem::n_strains;
      constexpr unsigned int n_gauge   = assembly::ReducedRodProblem::n_gauge;

      /// The six gauge constraints C U = 0, as integrals of the shape functions
      /// (not sums of nodal values, which would weight nodes by the mesh), over
      /// this rank's cells.
      std::array<Vector<double>, 6>
      gauge_constraint_rows(const Mapping<2> &       mapping,
                            const FiniteElement<2> & fe,
                            const DoFHandler<2> &    dof_handler,
                            const unsigned int       degree)
      {
        std::array<Vector<double>, 6> rows;
        for (auto &c : rows)
          c.reinit(dof_handler.n_dofs());
        const QGauss<2> quadrature(degree + 1);
        FEValues<2>     fev(mapping, fe, quadrature,
                            update_values | update_quadrature_points | update_JxW_values);
        std::vector<types::global_dof_index> idx(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fev.reinit(cell);
              cell->get_dof_indices(idx);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const Point<2> X  = fev.quadrature_point(q);
                  const double   dA = fev.JxW(q);
                  for (unsigned int i = 0; i < idx.size(); ++i)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      const double       N = fev.shape_value(i, q) * dA;
                      rows[c][idx[i]] += N; // int u = 0
                      if (c == 1)
                        rows[3][idx[i]] += X[0] * N; // int X1 u2 - X2 u1 = 0
                      if (c == 0)
                        rows[3][idx[i]] -= X[1] * N;
                      if (c == 2)
                        {
                          rows[4][idx[i]] += X[0] * N; // int X1 u3 = 0
                          rows[5][idx[i]] += X[1] * N; // int X2 u3 = 0
                        }
                    }
                }
            }
        return rows;
      }

      /// The field's couplings on a distributed mesh: every pair of DoFs of one
      /// of this rank's cells.
      void
      add_owned_cell_couplings(const DoFHandler<2> &dof_handler, TrilinosWrappers::SparsityPattern &sp)
      {
        std::vector<types::global_dof_index> idx(dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(idx);
              for (const auto i : idx)
                sp.add_entries(i, idx.begin(), idx.end());
            }
      }

      /// The field's couplings on a whole mesh: every pair of DoFs of a cell.
      /// (Filled in place: a DynamicSparsityPattern copies only when empty.)
      void
      add_cell_couplings(const DoFHandler<2> &dof_handler, DynamicSparsityPattern &dsp)
      {
        std::vector<types::global_dof_index> idx(dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(idx);
            for (const auto i : idx)
              dsp.add_entries(i, idx.begin(), idx.end());
          }
      }
    } // namespace

    void
    CrossSectionProblem::setup_system()
    {
      discretization.create_mesh();
      materials.resolve_regions(geometry.region_ids());
      materials.check_regions(discretization.material_ids());
      discretization.distribute_dofs();
      const DoFHandler<2> &dof_handler = discretization.get_dof_handler();

      // The six gauge constraints C U = 0.
      std::array<Vector<double>, 6> rows = gauge_constraint_rows(
        discretization.get_mapping(), discretization.get_fe(), dof_handler, degree);

      if (distributed_mesh)
        {
          // Each rank integrated its own cells: the rows summed by their owners.
          const solvers::ReplicatedVectorLayout owners(MPI_COMM_WORLD, dof_handler.locally_owned_dofs());
          for (auto &c : rows)
            owners.sum_parts(c);
          IndexSet relevant;
          DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
          setup_distributed_bordered_system(
            dof_handler.locally_owned_dofs(), relevant,
            [this](TrilinosWrappers::SparsityPattern &sp) {
              add_owned_cell_couplings(discretization.get_dof_handler(), sp);
            },
            rows, MPI_COMM_WORLD);
        }
      else
        {
          DynamicSparsityPattern dsp(discretization.n_u());
          add_cell_couplings(dof_handler, dsp);
          setup_bordered_system(dsp, rows, linear_solver_name);
        }
      report = [this](const std::string &line) { say(line); };

      // Bad input, refused now rather than met as a nonlinear failure on the
      // path, or missed (materials/growth_admissibility.h).
      discretization.check_growth();

      solution.reinit(n_unknowns());
      const auto ref = kinematics::RodStrains::reference().as_array();
      for (unsigned int k = 0; k < n_strains; ++k)
        solution[discretization.n_u() + n_gauge + k] = ref[k];
    }
  } // namespace rod
} // namespace cosmo
