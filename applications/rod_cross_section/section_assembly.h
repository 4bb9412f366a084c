#ifndef cosmo_applications_rod_cross_section_section_assembly_h
#define cosmo_applications_rod_cross_section_section_assembly_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/reduced_rod_problem.h>

#include "discretization.h"
#include "parameters.h"

#include <array>

/**
 * The energy of part 1's section and its derivatives (assembly.cc), at the
 * field U (the displacement its first DoFs) and the rod strains e, on the
 * section's discretization with its growth at the points of the current load
 * (SectionDiscretization::update_growth_cache()). CrossSectionProblem's
 * assemble_field() adds the bulk, then the surface layers, into its bordered
 * system.
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    /// The bulk into `target`, its cells on all cores and added in cell order:
    /// the cells' scalars are the energy, then the six resultants dE/de; the
    /// minimum is the least det Fe; not admissible where the law refuses the state.
    assembly::AssemblyTotals
    assemble_bulk(const SectionDiscretization &   section,
                  const CrossSectionParameters &  parameters,
                  const Vector<double> &          U,
                  const std::array<double, 6> &   e,
                  const assembly::AssemblyTarget &target);

    /// The surface layers on their boundary faces at load t, added to the bulk's
    /// in `target` (its border block point by point), their energy and
    /// resultants added to `energy`, `resultants`.
    void
    assemble_surface_layers(const SectionDiscretization &   section,
                            const CrossSectionParameters &  parameters,
                            double                          t,
                            const Vector<double> &          U,
                            const std::array<double, 6> &   e,
                            const assembly::AssemblyTarget &target,
                            double &                        energy,
                            std::array<double, 6> &         resultants);
  } // namespace rod
} // namespace cosmo

#endif
