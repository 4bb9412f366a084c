#include <cosmo/assembly/energy_assembler.h>

#include <algorithm>

namespace cosmo
{
  namespace assembly
  {
    void
    add_cell_contribution(const CellContribution &c, const AssemblyTarget &target)
    {
      const auto &idx = c.dof_indices;
      // A cell without constrained DoFs adds as it is: what
      // distribute_local_to_global() would do, without its sorting and
      // row resolution (most of a rod's or a plate's cells).
      const bool constrained =
        target.constraints != nullptr &&
        std::any_of(idx.begin(), idx.end(), [&](const types::global_dof_index i) {
          return target.constraints->is_constrained(i);
        });
      if (constrained)
        {
          // Condensed constraints: the rows of constrained DoFs are the
          // constraints' own (a residual is needed for the inhomogeneities).
          Assert(target.residual != nullptr, ExcMessage("condensed assembly without a residual"));
          if (target.jacobian && target.system->distributed())
            target.constraints->distribute_local_to_global(c.hessian, c.residual, idx,
                                                           target.system->distributed_matrix,
                                                           *target.residual);
          else if (target.jacobian)
            target.constraints->distribute_local_to_global(c.hessian, c.residual, idx,
                                                           target.system->matrix, *target.residual);
          else
            target.constraints->distribute_local_to_global(c.residual, idx, *target.residual);
          return;
        }
      if (target.residual != nullptr)
        for (unsigned int i = 0; i < idx.size(); ++i)
          (*target.residual)[idx[i]] += c.residual[i];
      if (!target.jacobian)
        return;
      if (target.system->distributed())
        target.system->distributed_matrix.add(idx, c.hessian, false);
      else
        target.system->matrix.add(idx, c.hessian);
      for (unsigned int i = 0; i < idx.size(); ++i)
        for (unsigned int k = 0; k < c.border.n(); ++k)
          target.system->border_columns[k][idx[i]] += c.border(i, k);
      if (target.border_block != nullptr && c.border_block.m() > 0)
        target.border_block->add(1., c.border_block);
    }
  } // namespace assembly
} // namespace cosmo
