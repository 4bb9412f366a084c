#ifndef cosmo_applications_rod_cross_section_section_output_h
#define cosmo_applications_rod_cross_section_section_output_h

#include <deal.II/lac/vector.h>

#include <cosmo/analysis/section_properties.h>
#include <cosmo/assembly/reduced_rod_problem.h>
#include <cosmo/io/output.h>

#include "discretization.h"
#include "parameters.h"

#include <array>
#include <functional>
#include <string>

/**
 * What part 1 writes of a state, from read-only views of it: the VTU files
 * (vtu_output.cc; CrossSectionProblem::write_fields, the 'fields'
 * postprocessor's, names them) and the state in words (postprocess.cc).
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    /**
     * The VTU files of one state on the section's discretization: the
     * solution (the displacement its first DoFs) with its rod strains at
     * the load t, the materials and surface layers, and 'Output' of the
     * parameters (directory, rod piece). Each file is the rank's piece on a
     * distributed mesh (a .pvtu collects them).
     */
    class SectionVTUWriter
    {
    public:
      SectionVTUWriter(const SectionDiscretization &  discretization,
                       const CrossSectionParameters & parameters,
                       const Vector<double> &         solution,
                       const std::array<double, 6> &  strains,
                       double                         t);

      /// solution-`tag`.vtu: the deformed section with its stress and growth fields
      /// (as write_rod_piece).
      std::string
      write_section(const std::string &tag) const;
      /// The rod piece `name`.vtu (or `name`.pvtu of a distributed mesh's pieces); returns
      /// the file name written.
      std::string
      write_rod_piece(const std::string &name) const;
      /// surface-NNNN.vtu: the surface layers with their growth and stress (as write_rod_piece).
      std::string
      write_surface_layers(const std::string &name) const;
      /**
       * outline.csv: the section's boundary at this state, as closed loops of
       * points (X1, X2) with the section placement w and the von Mises stress
       * there (what the rod application sweeps along a whole rod). Given the
       * field's derivatives du/de_k in the six strains (the factorization's,
       * at this state), also the Cauchy stress there and its derivatives in
       * the strains: the rod then colours its section by the stress at its
       * own strains, linearized about this state.
       */
      void
      write_outline(const std::vector<Vector<double>> &field_sensitivities = {}) const;

    private:
      /// Per face (or loop), per point, outline.csv's values.
      using OutlineRows = std::vector<std::vector<std::vector<double>>>;
      void
      add_stress_derivatives(
        const std::vector<Vector<double>> &                                                 field_sensitivities,
        const std::function<OutlineRows(const Vector<double> &, const std::array<double, 6> &)> &at,
        OutlineRows &                                                                       segments) const;
      void
      write_outline_csv(const OutlineRows &loops, bool linearized) const;

      const SectionDiscretization & discretization;
      const CrossSectionParameters &parameters;
      const Vector<double> &        solution;
      const std::array<double, 6>   strains;
      const double                  t;
    };

    /// The final state in words: energy, strains, resultants, stiffness,
    /// centreline, and the run's timings; each block a line of `say`.
    void
    say_result(const assembly::ReducedRodState &                s,
               const io::PhaseTimer &                           timer,
               const std::function<void(const std::string &)> &say);
    /// The linear section properties, as the section tools print them.
    void
    say_reference_properties(const analysis::LinearSectionProperties &        p,
                             const std::function<void(const std::string &)> &say);
  } // namespace rod
} // namespace cosmo

#endif
