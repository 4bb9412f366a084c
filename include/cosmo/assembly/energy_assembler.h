#ifndef cosmo_assembly_energy_assembler_h
#define cosmo_assembly_energy_assembler_h

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>

#include <algorithm>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <vector>

/**
 * The cell loop of every energy of the suite (step-44's and step-72's
 * assembly, once): the application gives the derivatives of one cell's
 * energy -- with its faces, its local variables and their Sacado or
 * chain-rule derivatives (assembly/local_variables.h,
 * materials/energy_derivatives.h) -- and the assembler runs it on every
 * locally owned cell on all cores (WorkStream) and adds the cells in cell
 * order, so that every sum is reproducible to the bit:
 *
 * - the residual dE/dU into R, the Hessian d2E/dU2 into the system's sparse
 *   matrix (serial, or this rank's rows of a distributed one), through the
 *   constraints where the application condenses them (AffineConstraints) or
 *   as they are where its constraints are rows of the matrix (multipliers);
 * - the couplings with the bordered (global) unknowns e (the rod strains),
 *   d2E/dU de into the system's border columns and d2E/de2 into a block;
 * - the application's integrals (energies, resultants) summed, and a
 *   smallest value (e.g. det F) over the cells;
 * - a cell outside the energy's domain (admissible = false) ends the
 *   additions: the assembly reports it and the driver cuts its step.
 *
 * dim and spacedim are free (a section <2,2>, a strip <1,1>, a plate <2,2>,
 * a rod <1,3>). The unknowns' update (U += dU, or a rotation's
 * multiplicative update) is the driver's and the application's: the
 * assembler sees a state U and differentiates at it.
 *
 * The ranks' parts of R and of the integrals are summed by the caller
 * (solvers::ReplicatedVectorLayout), which knows which vectors are whole.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    /// What one cell (with its faces) adds.
    struct CellContribution
    {
      CellContribution(const unsigned int dofs_per_cell,
                       const unsigned int n_border  = 0,
                       const unsigned int n_scalars = 0)
        : dof_indices(dofs_per_cell)
        , residual(dofs_per_cell)
        , hessian(dofs_per_cell, dofs_per_cell)
        , border(dofs_per_cell, n_border)
        , border_block(n_border, n_border)
        , scalars(n_scalars, 0.)
      {}

      /// Zero everything for the next cell (the matrices only with the Jacobian).
      void
      reset(const bool jacobian)
      {
        residual = 0;
        std::fill(scalars.begin(), scalars.end(), 0.);
        minimum    = std::numeric_limits<double>::max();
        admissible = true;
        if (jacobian)
          {
            hessian      = 0;
            border       = 0;
            border_block = 0;
          }
      }

      std::vector<types::global_dof_index> dof_indices;
      Vector<double>                       residual;     ///< dE/dU_i
      FullMatrix<double>                   hessian;      ///< d2E/dU_i dU_j
      FullMatrix<double>                   border;       ///< d2E/dU_i de_k
      FullMatrix<double>                   border_block; ///< d2E/de_k de_l
      std::vector<double>                  scalars;      ///< summed over the cells
      double minimum    = std::numeric_limits<double>::max(); ///< the least over the cells
      bool   admissible = true; ///< false: the state is outside the energy's domain
    };

    /// Where the cells' contributions go.
    struct AssemblyTarget
    {
      /// The residual (zeroed by the caller; may be null).
      Vector<double> *residual = nullptr;
      bool            jacobian = false;
      /// Its matrix (serial or distributed) and border columns (zeroed by the caller).
      BorderedSystem *system = nullptr;
      /// d2E/de2 (with the Jacobian, if the system has a border).
      FullMatrix<double> *border_block = nullptr;
      /// Condensed constraints (distribute_local_to_global); null: added as they are.
      const AffineConstraints<double> *constraints = nullptr;
    };

    /// The cells' integrals, in cell order.
    struct AssemblyTotals
    {
      std::vector<double> scalars;
      double              minimum    = std::numeric_limits<double>::max();
      bool                admissible = true;
    };

    /// Adds one cell's contribution to the target (the copier of the loop).
    void
    add_cell_contribution(const CellContribution &c, const AssemblyTarget &target);

    template <int dim, int spacedim = dim>
    class EnergyAssembler
    {
    public:
      using CellIterator = typename DoFHandler<dim, spacedim>::active_cell_iterator;

      /**
       * Runs `worker(cell, scratch, c)`, the application's cell (it fills
       * `c`, reset and with its DoF indices set, at the state it holds), on
       * this rank's cells (all on one process) on all cores, and adds the
       * contributions to `target` in cell order. Returns the summed
       * scalars, the least minimum and whether every cell was admissible.
       */
      template <class Scratch, class Worker>
      static AssemblyTotals
      assemble(const DoFHandler<dim, spacedim> &dof_handler,
               const Worker &                   worker,
               const Scratch &                  sample_scratch,
               const CellContribution &         sample,
               const AssemblyTarget &           target)
      {
        AssemblyTotals totals;
        totals.scalars.assign(sample.scalars.size(), 0.);
        // An exception in a worker thread would end the process
        // (std::terminate): the first one is kept, the cell refused, and it
        // is thrown again here, in the calling thread, after the loop.
        std::exception_ptr first_error;
        std::mutex         error_mutex;
        auto cell_worker = [&](const CellIterator &cell, Scratch &scratch, CellContribution &c) {
          c.reset(target.jacobian);
          cell->get_dof_indices(c.dof_indices);
          try
            {
              worker(cell, scratch, c);
            }
          catch (...)
            {
              c.admissible = false;
              std::lock_guard<std::mutex> lock(error_mutex);
              if (!first_error)
                first_error = std::current_exception();
            }
        };
        auto copier = [&](const CellContribution &c) {
          if (!c.admissible)
            totals.admissible = false;
          if (!totals.admissible)
            return;
          for (unsigned int k = 0; k < c.scalars.size(); ++k)
            totals.scalars[k] += c.scalars[k];
          totals.minimum = std::min(totals.minimum, c.minimum);
          add_cell_contribution(c, target);
        };
        // Chunks of cells per task: WorkStream's default of 8 spends more
        // on its queue than on a rod's cells (microseconds each); 64 still
        // leaves hundreds of chunks per thread on the meshes of any size
        // where threads pay (benchmarks/README.md, the rod's path).
        const auto cells = filter_iterators(dof_handler.active_cell_iterators(), IteratorFilters::LocallyOwnedCell());
        WorkStream::run(cells.begin(), cells.end(), cell_worker, copier, sample_scratch, sample,
                        2 * MultithreadInfo::n_threads(), 64);
        if (first_error)
          std::rethrow_exception(first_error);
        return totals;
      }
    };
  } // namespace assembly
} // namespace cosmo

#endif
