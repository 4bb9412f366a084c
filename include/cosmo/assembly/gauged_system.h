#ifndef cosmo_assembly_gauged_system_h
#define cosmo_assembly_gauged_system_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/solvers/replicated_vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    /**
     * The linear system of a field on a cross-section bordered by the six rod
     * strains: the field DoFs, the six multipliers of the gauge constraints
     * C U = 0 that fix the section's rigid motion, and the strains. The
     * sparse block [[E_UU, C^T],[C, 0]] is factorized, serial or over the
     * ranks of a distributed mesh (one place for that branch); the strains
     * are its border (BorderedSystem). This class holds C, the system, and
     * the gauge rows' contributions to the residual and the matrix; the field
     * adds its cells through field_target().
     */
    class GaugedSystem
    {
    public:
      static constexpr unsigned int n_gauge   = 6;
      static constexpr unsigned int n_strains = 6;

      /// The last assembled and factorized bordered Jacobian (tests).
      const BorderedSystem &
      bordered_system() const
      {
        return *system;
      }
      unsigned int
      n_field_dofs() const
      {
        return n_field;
      }

    protected:
      /**
       * Set up the bordered system once the field exists: the sparsity of
       * E_UU (n_field x n_field entries; the gauge rows are added here) and
       * the six constraint rows C (integrals of the shape functions).
       */
      void
      setup_bordered_system(DynamicSparsityPattern &            field_pattern,
                            const std::array<Vector<double>, 6> &rows,
                            const std::string &                  linear_solver);

      /**
       * The same on a mesh distributed over the ranks of `comm`: this rank
       * owns the field DoFs `owned_field` (contiguous, in rank order) and
       * writes rows of `relevant_field`; `add_field_entries` adds E_UU's
       * entries of the rank's cells. The last rank owns the six gauge rows.
       * The constraint rows are whole on every rank. Afterwards the field's
       * assembly adds into system->distributed_matrix and sums nothing
       * itself: sum_rank_parts() sums the ranks' parts (field_layout).
       */
      void
      setup_distributed_bordered_system(
        const IndexSet &                                                 owned_field,
        const IndexSet &                                                 relevant_field,
        const std::function<void(TrilinosWrappers::SparsityPattern &)> &add_field_entries,
        const std::array<Vector<double>, 6> &                            rows,
        MPI_Comm                                                         comm);

      /// Where the field's assembly adds its cells: R, the system's matrix and
      /// border columns, and the border block E (assembly::EnergyAssembler).
      AssemblyTarget
      field_target(Vector<double> *R, const bool jacobian, FullMatrix<double> &E) const
      {
        AssemblyTarget target;
        target.residual     = R;
        target.jacobian     = jacobian;
        target.system       = system.get();
        target.border_block = &E;
        return target;
      }

      /// The gauge constraints with their multipliers U[n_field + k]: C^T
      /// lambda into the field rows of R, C U into its gauge rows.
      void
      add_gauge_residuals(Vector<double> &R, const Vector<double> &U) const;
      /// C and C^T into the serial matrix (after the field's entries).
      void
      set_gauge_entries();
      /// C and C^T into the distributed matrix; compresses it.
      void
      add_distributed_gauge_entries();
      /**
       * Sum the ranks' parts of a distributed assembly: the residual R (may
       * be null), the energy and resultants, and with the `jacobian` the
       * system's border columns and the block E; the smallest det Fe over
       * the ranks.
       */
      void
      sum_rank_parts(Vector<double> *       R,
                     bool                   jacobian,
                     FullMatrix<double> &   E,
                     double &               energy,
                     std::array<double, 6> &resultants,
                     double &               min_elastic_J);

      unsigned int                    n_field = 0;
      std::array<Vector<double>, 6>   constraint_rows;
      std::unique_ptr<BorderedSystem> system;
      /// The field DoFs' owners on a distributed mesh (identity otherwise).
      solvers::ReplicatedVectorLayout field_layout;
    };
  } // namespace assembly
} // namespace cosmo

#endif
