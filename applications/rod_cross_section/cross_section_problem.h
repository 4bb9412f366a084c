#ifndef cosmo_applications_rod_cross_section_problem_h
#define cosmo_applications_rod_cross_section_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/analysis/section_properties.h>
#include <cosmo/assembly/constitutive_table.h>
#include <cosmo/assembly/reduced_rod_problem.h>
#include <cosmo/geometry/cross_section.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/run_record.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/materials/material.h>
#include <cosmo/materials/surface_layer.h>
#include <cosmo/solvers/continuation.h>

#include "discretization.h"
#include "parameters.h"

#include <array>
#include <string>

/**
 * Part 1: the morphoelastic rod's cross-section problem
 * (doc/specification/rod-cross-section.md).
 *
 * Unknowns, in this order: the displacement u = w - X of the cross-section
 * (three components on the 2D section, FE_Q(p)^3), the six multipliers of the
 * gauge constraints, and the six rod strains (nu, kappa). Each strain is
 * either prescribed (ramped by the load parameter t from the reference state)
 * or free (its resultant vanishes); all free gives the natural shape.
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    using CrossSectionState = assembly::ReducedRodState;

    /**
     * The problem on the parameters it was parsed from (parameters.h), with
     * the rod strains of its reduced-rod base and the section's
     * discretization (discretization.h); it adds the state and the run's
     * records. The VTU files and the words of a state are written from
     * read-only views of it (section_output.h).
     */
    class CrossSectionProblem : public assembly::ReducedRodProblem, public CrossSectionParameters
    {
    public:
      /// CrossSectionParameters::parse_parameters, then the rod strains and the table.
      void
      parse_parameters(ParameterHandler &prm);

      /// The application: solve along the load path and write every output.
      void
      run(const io::RunOptions &options, const ParameterHandler &prm);

      /// Programmatic use (tests, benchmarks): mesh, DoFs, constraints.
      void
      setup_system();
      /// Continuation from the reference state to t = 1; no files unless output is on.
      CrossSectionState
      solve();
      /// Energy, resultants, multipliers and (fresh) stiffness at the current solution.
      CrossSectionState
      current_state();

      /// The state of the last converged step.
      const CrossSectionState &
      final_state() const
      {
        return last_state;
      }

      const Vector<double> &
      current_solution() const
      {
        return solution;
      }

      /// The mesh, element and DoFs, the section's properties, mode parities and
      /// linear section properties (after setup_system()).
      const SectionDiscretization &
      get_discretization() const
      {
        return discretization;
      }
      unsigned int
      newton_iterations() const
      {
        return total_newton_iterations;
      }

      // ContinuationProblem
      void
      converged_step(const Vector<double> &U, const solvers::StepReport &report) override;
      /// What the run's postprocessors show of a state (io/postprocessors.h):
      /// steps.csv's columns and row, the section's, the rod piece's and the
      /// surface layers' VTU files.
      std::vector<std::pair<std::string, std::string>>
      quantity_columns() const override;
      std::vector<std::pair<std::string, std::string>>
      write_fields(const std::string &tag) const override;
      /// Nested iteration: the first step solved on the section refined 'Coarse-mesh start'
      /// times less (recursively), interpolated to this mesh.
      bool
      first_step_guess(double t, Vector<double> &U) override;
      /// The path so far and the postprocessors' state, for a checkpoint.
      void
      save_progress(io::CheckpointWriter &w) const override;
      void
      load_progress(io::CheckpointReader &r) override;

      /// A study's mode columns: mode_symmetry_X1, mode_symmetry_X2 (+1, -1,
      /// 0 mixed, NaN: no such symmetry of the mesh; SectionDiscretization::mode_parity).
      std::vector<double>
      classify_critical_mode(const Vector<double> &mode) const override;

    private:
      /// du/de_k of the field in the six strains at the current state, if
      /// the factorization in place is its own (else empty).
      std::vector<Vector<double>>
      field_sensitivities() const;

      bool                           quiet = false;   // a coarser copy says nothing
      std::string                    coarse_start_report; // Newton iterations per coarser mesh
      assembly::ConstitutiveTable    table;

      /// On this problem's parameters (its CrossSectionParameters base, made first).
      SectionDiscretization             discretization{*this};
      analysis::LinearSectionProperties reference_properties;
      Vector<double>                    solution;

      // Output and bookkeeping
      io::RunRecord                    record{"rod_cross_section"};
      CrossSectionState                last_state;

      /// The section's bulk, then its surface layers (assembly.cc).
      int
      assemble_field(const Vector<double> &       U,
                     const std::array<double, 6> &e,
                     Vector<double> *             R,
                     bool                         jacobian,
                     FullMatrix<double> &         border_block,
                     FieldIntegrals &             out) override;
      void
      residual_scales(double &force, double &length) const override;

      void
      write_summary() const;
      /// After the path to t = 1: the constitutive table around that state.
      void
      run_table(const ParameterHandler &prm);
      void
      say(const std::string &line) const
      {
        if (!quiet)
          record.say(line);
      }
    };

    /**
     * The application: one run, or, with a 'Parameter sweep' in the .prm, one
     * run per value (output in point-NN/ subdirectories) and sweep.csv, a
     * table of the final strains, resultants and stiffness against the value.
     */
    void
    run_study(ParameterHandler &prm, const io::RunOptions &options);
  } // namespace rod
} // namespace cosmo

#endif
