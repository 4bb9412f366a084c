#ifndef cosmo_applications_rod_cross_section_problem_h
#define cosmo_applications_rod_cross_section_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>
#include <cosmo/geometry/cross_section.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/materials/material.h>
#include <cosmo/materials/surface_layer.h>
#include <cosmo/solvers/continuation.h>

#include <array>
#include <memory>
#include <string>

/**
 * Part 1: the morphoelastic rod's cross-section problem
 * (rod-cross-section.md).
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

    /// The rod-level quantities of a converged state.
    struct CrossSectionState
    {
      double                t      = 0;
      double                energy = 0;         ///< Psi, energy per unit reference length
      std::array<double, 6> strains{};          ///< nu1..3, kappa1..3
      std::array<double, 6> resultants{};       ///< n1..3, m1..3 = dPsi/d(strains)
      std::array<double, 6> multipliers{};      ///< of the six gauge constraints
      FullMatrix<double>    stiffness;          ///< 6x6 d(n,m)/d(nu,kappa)
      int                   n_negative = -1;    ///< negative Hessian eigenvalues (constrained space)
      double                min_elastic_J = 0;  ///< smallest det Fe at quadrature points
    };

    class CrossSectionProblem : public solvers::ContinuationProblem
    {
    public:
      CrossSectionProblem();
      ~CrossSectionProblem() override;

      static void
      declare_parameters(ParameterHandler &prm);
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

      /// The last assembled and factorized bordered Jacobian (tests).
      const assembly::BorderedSystem &
      bordered_system() const
      {
        return *system;
      }
      const Vector<double> &
      current_solution() const
      {
        return solution;
      }
      /// Which strains are free (their rows are resultants) or prescribed.
      const std::array<bool, 6> &
      free_strains() const
      {
        return strain_is_free;
      }

      /// Override the target strains of the .prm (prescribed ones reach them at t = 1).
      void
      set_target_strains(const std::array<double, 6> &strains);
      void
      set_free_strains(const std::array<bool, 6> &free);

      const geometry::SectionProperties &
      section() const
      {
        return section_properties;
      }
      unsigned int
      n_field_dofs() const
      {
        return dof_handler.n_dofs();
      }
      const io::PhaseTimer &
      timings() const
      {
        return timer;
      }
      unsigned int
      newton_iterations() const
      {
        return total_newton_iterations;
      }

      // ContinuationProblem
      unsigned int
      n_unknowns() const override;
      int
      residual(const Vector<double> &U, Vector<double> &R) override;
      int
      setup_jacobian(const Vector<double> &U) override;
      int
      solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) override;
      void
      residual_weights(Vector<double> &w) const override;
      void
      set_load_parameter(double t) override;
      void
      converged_step(const Vector<double> &U, const solvers::StepReport &report) override;

    private:
      // Parameters
      geometry::CrossSectionGeometry geometry;
      materials::MaterialLibrary     materials;
      materials::SurfaceLayerLibrary surface_layers;
      unsigned int                   degree = 2;
      std::string                    mode;
      std::array<double, 6>          target_strains{};
      std::array<bool, 6>            strain_is_free{};
      solvers::NewtonSettings        newton_settings;
      solvers::ContinuationSettings  continuation_settings;
      std::string                    linear_solver_name;
      std::string                    output_directory;
      bool                           write_output = false;
      std::string                    vtu_frequency;
      double                         rod_piece_length = 0; // 0: automatic
      unsigned int                   rod_piece_slices = 24;
      bool                           stiffness_every_step = true;
      std::string                    parameter_file;

      // Discretization
      Triangulation<2>                        triangulation;
      std::unique_ptr<FESystem<2>>            fe;
      std::unique_ptr<MappingQ<2>>            mapping;
      DoFHandler<2>                           dof_handler;
      geometry::SectionProperties             section_properties;
      std::array<Vector<double>, 6>           constraint_rows; // C, integrals of shape functions
      std::unique_ptr<assembly::BorderedSystem> system;
      Vector<double>                          solution;
      double                                  load_parameter = 0;
      std::vector<Tensor<2, 3>>               growth_at_qp; // per cell and quadrature point
      double                                  growth_cached_for = -1;

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
      io::PhaseTimer                   timer;
      std::unique_ptr<io::RunLog>      log;
      std::unique_ptr<io::PVDSeries>   pvd, pvd_rod, pvd_surface;
      io::CSVTable                     steps_table;
      std::vector<io::JSON>            step_records;
      CrossSectionState                last_state;
      unsigned int                     total_newton_iterations = 0;
      bool                             quiet                    = false;

      unsigned int
      n_u() const
      {
        return dof_handler.n_dofs();
      }
      std::array<double, 6>
      strains_of(const Vector<double> &U) const;
      std::array<double, 6>
      prescribed_strains_at(double t) const;
      void
      update_growth_cache();
      /// The faces of every surface layer (after the mesh and DoFs exist).
      void
      setup_surface_faces();

      /// Integrals that come with every assembly.
      struct AssemblyResults
      {
        double                energy        = 0; ///< Psi
        double                min_elastic_J = 0; ///< smallest det Fe
        std::array<double, 6> resultants{};      ///< dPsi/de at fixed field
      };

      /**
       * Energy assembly at U: the residual (if `residual`), the bordered
       * Jacobian (if `jacobian`), and the integrals in `results` (if given).
       * Returns 1 if U is inadmissible (det Fe <= 0 somewhere).
       */
      int
      assemble(const Vector<double> &U, Vector<double> *residual, bool jacobian,
               AssemblyResults *results = nullptr);

      void
      write_vtu(unsigned int step, double t);
      void
      write_rod_piece(const std::string &file) const;
      /// surface-NNNN.vtu: the surface layers with their growth and stress.
      void
      write_surface_layers(const std::string &file, double t) const;
      void
      write_summary(const std::string &status, const std::string &message) const;
      void
      say(const std::string &line);
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
