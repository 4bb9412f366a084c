#ifndef cosmo_applications_rod_cross_section_problem_h
#define cosmo_applications_rod_cross_section_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/analysis/section_properties.h>
#include <cosmo/assembly/constitutive_table.h>
#include <cosmo/assembly/reduced_rod_problem.h>
#include <cosmo/geometry/cross_section.h>
#include <cosmo/geometry/mesh_of_ranks.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/run_record.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/materials/material.h>
#include <cosmo/materials/surface_layer.h>
#include <cosmo/solvers/continuation.h>

#include "parameters.h"

#include <array>
#include <limits>
#include <memory>
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
     * the rod strains of its reduced-rod base; it adds the discretization,
     * the state and the run's records.
     */
    class CrossSectionProblem : public assembly::ReducedRodProblem, public CrossSectionParameters
    {
    public:
      CrossSectionProblem();
      ~CrossSectionProblem() override;

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

      /// Newton from the current solution to the state with these prescribed strains (t = 1).
      CrossSectionState
      resolve(const std::array<double, 6> &strains);

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

      /// 'Finite element / Distributed': the mesh divided over the MPI ranks.
      bool
      mesh_is_distributed() const
      {
        return distributed_mesh;
      }

      const geometry::SectionProperties &
      section() const
      {
        return section_properties;
      }
      /// The linear Saint-Venant properties of the reference section
      /// (analysis/section_properties.h): centres, principal axes, GJ, shear factors.
      analysis::LinearSectionProperties
      linear_section_properties() const;
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
      std::vector<double>
      quantity_values() const override
      {
        return steps_row;
      }
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

      /**
       * The parity of a mode's field under the half-turn of the rod about the
       * section's axis X_axis (axis 0 or 1; geometry::reflection_parity):
       * +1 symmetric, -1 antisymmetric, NaN where the mesh is not its own
       * mirror image about that axis.
       */
      double
      mode_parity(const Vector<double> &mode, unsigned int axis) const;
      /// A study's mode columns: mode_symmetry_X1, mode_symmetry_X2 (+1, -1,
      /// 0 mixed, NaN: no such symmetry of the mesh).
      std::vector<double>
      classify_critical_mode(const Vector<double> &mode) const override;

    private:
      /// The run writes its files (run()); programmatic use does not.
      bool                           write_output = false;
      bool                           quiet = false;   // a coarser copy says nothing
      std::string                    coarse_start_report; // Newton iterations per coarser mesh
      assembly::ConstitutiveTable    table;

      // Discretization (with 'Finite element / Distributed' the mesh is divided
      // over the ranks: each assembles its own cells, the bordered system's A
      // is distributed by rows, the drivers' vectors are whole on every rank;
      // doc/parallel-runs.md)
      geometry::MeshOfRanks<2>                triangulation;
      std::unique_ptr<FESystem<2>>            fe;
      std::unique_ptr<MappingQ<2>>            mapping;
      DoFHandler<2>                           dof_handler;
      geometry::SectionProperties             section_properties;
      analysis::LinearSectionProperties       reference_properties;
      Vector<double>                          solution;
      std::vector<Tensor<2, 3>>               growth_at_qp; // per cell and quadrature point
      double                                  growth_cached_for = std::numeric_limits<double>::quiet_NaN();

      /// A boundary face carrying a surface layer.
      struct SurfaceFace
      {
        typename DoFHandler<2>::active_cell_iterator cell;
        unsigned int                                 face;
        unsigned int                                 layer;
      };
      std::vector<SurfaceFace>           surface_faces;
      std::vector<std::array<double, 2>> surface_growth_at_qp; // (gT, g3) per face and point
      std::vector<double>                surface_length;       // per layer, reference arc length

      // Output and bookkeeping
      io::RunRecord                    record{"rod_cross_section"};
      /// steps.csv's row of the last converged state.
      std::vector<double>              steps_row;
      std::vector<io::JSON>            step_records;
      CrossSectionState                last_state;

      unsigned int
      n_u() const
      {
        return dof_handler.n_dofs();
      }
      /// Growth at the quadrature points at the current load; false where det Fg
      /// or a surface factor is not positive.
      bool
      update_growth_cache();
      /// io::InputError unless every bulk and surface law is admissible on every
      /// level of the mesh along the ramp (materials/growth_admissibility.h).
      void
      check_growth() const;
      /// The faces of every surface layer (after the mesh and DoFs exist).
      void
      setup_surface_faces();

      int
      assemble_field(const Vector<double> &       U,
                     const std::array<double, 6> &e,
                     Vector<double> *             R,
                     bool                         jacobian,
                     FullMatrix<double> &         border_block,
                     FieldIntegrals &             out) override;
      void
      residual_scales(double &force, double &length) const override;
      /// The section's bulk: false if growth or the state is inadmissible somewhere.
      bool
      assemble_bulk(const Vector<double> &       U,
                    const std::array<double, 6> &e,
                    Vector<double> *             R,
                    bool                         jacobian,
                    FullMatrix<double> &         border_block,
                    FieldIntegrals &             out);
      /// The surface layers on their boundary faces, added to the bulk's.
      void
      assemble_surface_layers(const Vector<double> &       U,
                              const std::array<double, 6> &e,
                              Vector<double> *             R,
                              bool                         jacobian,
                              FullMatrix<double> &         border_block,
                              FieldIntegrals &             out);

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
      write_surface_layers(const std::string &name, double t) const;
      void
      write_summary() const;
      /// After the path to t = 1: the constitutive table around that state.
      void
      run_table(const ParameterHandler &prm);
      /// The final state in words: energy, strains, resultants, stiffness, centreline.
      void
      say_result() const;
      /// The linear section properties, as the section tools print them.
      void
      say_reference_properties() const;
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
