#ifndef cosmo_applications_plate_rod_problem_h
#define cosmo_applications_plate_rod_problem_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/analysis/plate_rod_thresholds.h>
#include <cosmo/assembly/bordered_system.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/geometry/mesh_of_ranks.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/run_record.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/kinematics/plate_model.h>
#include <cosmo/materials/growth.h>
#include <cosmo/materials/plate_growth.h>
#include <cosmo/materials/plate_law.h>
#include <cosmo/materials/rod_growth.h>
#include <cosmo/materials/rod_law.h>

#include "parameters.h"
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/solvers/replicated_vector.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

/**
 * Part 3: a growing circular Cosserat plate bounded by a Cosserat rod
 * (doc/specification/plate-rod.md). The disc |X| <= R (or the sector 0 <= theta <= pi/n with
 * mirror conditions) carries the plate's displacement u (3), its rotation
 * vector (theta1, theta2) and the rim's rotation alpha about the plate
 * normal (a field whose DoFs off the rim are constrained to zero): FE_Q(p)^6
 * on a mesh whose rim is curved (MappingQ(p)). The rod is welded to the edge
 * by construction (kinematics/plate_rod.h). Growth of the plate and of the
 * rod is ramped by the load parameter t; the arclength driver follows the
 * flat branch, counts the negative eigenvalues of the Hessian (MUMPS
 * inertia), locates where the count changes and follows the bifurcated
 * branches.
 */
namespace cosmo
{
  namespace plate_rod
  {
    using namespace dealii;

    /// Rim boundary id; the mirror edges of a sector are 1 (theta = 0) and 2 (theta = pi/n).
    constexpr types::boundary_id rim_id = 0, mirror_first = 1, mirror_second = 2;

    /// What one state looks like, for steps.csv and summary.json.
    struct PlateRodState
    {
      double              t = 0;
      double              plate_energy = 0, rod_energy = 0;
      double              w_centre = 0, max_abs_w = 0, max_abs_inplane = 0;
      double              rim_radial_strain = 0; ///< mean u_r / R on the rim
      std::vector<double> rim_w_amplitude;  ///< |Fourier coefficient| of w on the rim, m = k step
      std::vector<double> rim_ur_amplitude; ///< same for the radial displacement
      int                 n_negative = -1;
      double              smallest_eigenvalue = 0;
      unsigned int        branch = 0; ///< of the continuation (0 the first)
      double              constraint_violation = 0; ///< PlateRodProblem::constraint_violation
    };

    /**
     * The problem on the parameters it was parsed from (parameters.h): the
     * run's configuration is a PlateRodParameters, parsed once; the problem
     * adds the discretization, the state and the run's records.
     */
    class PlateRodProblem : public solvers::BifurcationProblem, public PlateRodParameters
    {
    public:
      PlateRodProblem();
      ~PlateRodProblem() override;

      /// PlateRodParameters::parse_parameters, the residual cache cleared.
      void
      parse_parameters(ParameterHandler &prm);

      void
      setup_system();
      /// The application: the flat state at the start of the path, then the branches.
      void
      run(const io::RunOptions &options, const ParameterHandler &prm);

      void
      set_quiet(const bool q)
      {
        record.set_quiet(q);
      }

      // NonlinearSystem / BifurcationProblem
      unsigned int
      n_unknowns() const override
      {
        return dof_handler.n_dofs();
      }
      int
      residual(const Vector<double> &U, Vector<double> &R) override;
      int
      setup_jacobian(const Vector<double> &U) override;
      int
      solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) override;
      /// A direct solve on the constrained space; the residual vanishes on
      /// constrained rows, where the solve's distribute() sets the slaves.
      bool
      solves_exactly() const override
      {
        return true;
      }
      void
      residual_weights(Vector<double> &w) const override;
      /// 0 on the DoFs the constraints determine (mirror edges, alpha off the rim).
      void
      mode_mask(Vector<double> &mask) const override;
      /// The mirror edges' and in-plane constraints distributed onto a mode.
      void
      complete_mode(Vector<double> &v) const override;
      /// max |u_s - sum_m w_m u_m| over the constraints (0 to round-off on every state).
      double
      constraint_violation(const Vector<double> &U) const;
      void
      set_load_parameter(double t) override
      {
        load_parameter = t;
      }
      void
      converged_step(const Vector<double> &U, const solvers::StepReport &report) override;
      /// What the run's postprocessors show of a state (io/postprocessors.h):
      /// steps.csv's columns and row, the plate's and the rim's VTU files.
      std::vector<std::pair<std::string, std::string>>
      quantity_columns() const override
      {
        return steps_columns;
      }
      std::vector<double>
      quantity_values() const override
      {
        return steps_row;
      }
      std::vector<std::pair<std::string, std::string>>
      write_fields(const std::string &tag) const override;
      int
      n_negative_eigenvalues() override
      {
        return system.n_negative_eigenvalues({}, 0);
      }
      /// |v|.|J||v| with the assembled Hessian (resolution of a located event).
      double
      jacobian_abs_form(const Vector<double> &v) const override;
      /// Displacements are nonlinear on the scale of the radius, rotations on 1: the smaller.
      double
      unknowns_scale(const Vector<double> &) const override
      {
        return std::min(radius, 1.);
      }
      void
      located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode) override;

      /// Solve the flat state at the load parameter t from the current solution.
      void
      solve_flat_state(double t);
      /// Follow the growth path by arclength continuation from the current solution.
      std::vector<solvers::EventRecord>
      follow_branches();
      /// What the run has written and found so far, for its checkpoint (io/checkpoint.h).
      void
      save_progress(io::CheckpointWriter &w) const;
      /// Restore it (its postprocessors rewrite steps.csv and the PVD files as they were then).
      void
      load_progress(io::CheckpointReader &r);
      /// The total energy, plate and rim, at U and the current load parameter (at most one
      /// residual assembly; the residual is its gradient, test plate_rod.tangent_fd).
      double
      energy(const Vector<double> &U);
      /// Diagnostics of a state (energies, deflections, rim Fourier amplitudes).
      PlateRodState
      analyse(const Vector<double> &U, unsigned int n_modes = PlateRodProblem::n_modes) const;

      const Vector<double> &
      current_solution() const
      {
        return solution;
      }
      Vector<double> &
      current_solution()
      {
        return solution;
      }
      const std::vector<solvers::EventRecord> &
      events() const
      {
        return located_events;
      }
      const std::vector<PlateRodState> &
      path() const
      {
        return states;
      }
      const io::PhaseTimer &
      timings() const
      {
        return timer;
      }
      unsigned int
      n_dofs() const
      {
        return dof_handler.n_dofs();
      }
      /// 'Mesh / Distributed': the mesh divided over the MPI ranks.
      bool
      mesh_is_distributed() const
      {
        return distributed_mesh;
      }
      const SparseMatrix<double> &
      system_matrix() const
      {
        return system.matrix;
      }
      const AffineConstraints<double> &
      dof_constraints() const
      {
        return constraints;
      }
      /// 1 on the full disc, n on a sector pi/n: the admitted mode numbers are its multiples.
      unsigned int
      sector_step() const
      {
        return domain == "sector" ? sector_n : 1;
      }
      /// Number of rim Fourier modes reported (m = k sector_step(), k = 0 .. n_modes - 1).
      static constexpr unsigned int n_modes = 9;

      /// How clear a classification is: the smaller over the larger of the
      /// two type measures (half the range of w, the largest in-plane
      /// displacement) and of the two largest rim Fourier amplitudes; near 1
      /// the mode is a mix (e.g. of a near-double eigenvalue) and its type or
      /// number can flip under round-off.
      struct ModeMargins
      {
        double type   = 0;
        double number = 0;
      };
      /// Mode type and number of a perturbation: dominant rim Fourier number and whether the
      /// out-of-plane part dominates (and, if asked, how clearly).
      std::pair<unsigned int, bool>
      classify_mode(const Vector<double> &mode, ModeMargins *margins = nullptr) const;
      /// The study's mode columns (critical_point_study.h): mode_number, mode_out_of_plane.
      std::vector<double>
      classify_critical_mode(const Vector<double> &mode) const;
      /// The study's further columns: mismatch_critical, closed_form_mismatch.
      std::vector<double>
      critical_point_columns(const solvers::EventRecord &e) const;
      /// The located events with state and mode (a study's critical points).
      const std::vector<solvers::EventRecord> &
      event_records() const
      {
        return located_events;
      }

    private:

    public:
      /**
       * A critical point to start from instead of a path from t: run() then
       * locates the critical point by Newton on the augmented system from
       * this guess (the next point of a critical curve) and reports it as
       * the first event. The guess must have this problem's DoFs.
       */
      void
      start_from_critical_point(const solvers::CriticalGuess &g)
      {
        critical_guess = std::make_unique<solvers::CriticalGuess>(g);
      }

      /// Full disc: (v + S v)/2 with S the reflection y -> -y (sector: false).
      bool
      project_to_fixed_point_space(Vector<double> &v) const override;

    private:
      std::unique_ptr<solvers::CriticalGuess> critical_guess;
      /// Full disc: the DoF each DoF maps to under y -> -y, and the sign.
      std::vector<std::pair<types::global_dof_index, double>> reflection;
      void
      make_reflection();
      void
      locate_from_guess();
      bool                           write_output = false;
      double                         load_parameter = 0;

      // Discretization (with 'Mesh / Distributed' the mesh is divided over the
      // ranks: each assembles its own cells into system.distributed_matrix,
      // factorized by MUMPS with distributed input, and the drivers' vectors are whole on
      // every rank, kept equal by `layout`)
      geometry::MeshOfRanks<2>     triangulation;
      std::unique_ptr<MappingQ<2>> mapping;
      std::unique_ptr<FESystem<2>> fe;
      DoFHandler<2>                dof_handler;
      AffineConstraints<double>    constraints;
      /// The Hessian and its factorization, serial or distributed (no border).
      assembly::BorderedSystem        system;
      solvers::ReplicatedVectorLayout layout;
      Vector<double>               solution;
      std::vector<unsigned char>   dof_component; ///< field component of each DoF
      std::vector<unsigned char>   dof_constrained; ///< 1 where the constraints set the DoF
      Vector<double>               factorized_at;  ///< the state of the last factorization
      double                       factorized_load = 0;
      /// converged_step reports with the last factorization (a continued critical point)
      bool                         report_with_last_factorization = false;
      Vector<double>               assembled_at;   ///< the state of the last assembly
      double                       assembled_load = 0;
      std::array<double, 2>        assembled_energy{}; ///< its plate and rim energies
      /// The last two assemblies' residuals, with their energies (cleared by
      /// parse_parameters and setup_system, which change what R depends on).
      solvers::ResidualCache       residuals;

      // Run records
      std::vector<PlateRodState>        states;
      std::vector<solvers::EventRecord> located_events;
      /// steps.csv's columns (name, unit) and the last converged state's row.
      std::vector<std::pair<std::string, std::string>> steps_columns;
      std::vector<double>               steps_row;
      io::RunRecord                     record{"plate_rod"};
      /// (mutable: the const output writers time themselves)
      mutable io::PhaseTimer            timer;

      /// The run's discretization, and the rim's stiffness file, in the log.
      void
      say_discretization() const;
      /// steps.csv's columns.
      void
      add_steps_columns();
      /// The path's summary in the log, summary.json (with the closed forms), the run's end.
      void
      finish_run(const io::JSON &closed);
      void
      make_mesh();
      void
      make_constraints();
      int
      assemble(const Vector<double> &U, Vector<double> *R, bool jacobian, double *energy = nullptr);
      /// The cell loop's work space and what its cells share (plate_rod_problem.cc).
      struct Scratch;
      struct CellLoopData;
      /// The plate's membrane, bending and transverse shear on one cell.
      void
      plate_of_cell(const CellLoopData &                         d,
                    const DoFHandler<2>::active_cell_iterator &cell,
                    Scratch &                                    sc,
                    assembly::CellContribution &                 c) const;
      /// The transverse shear of one cell by assumed covariant strains; returns its energy.
      double
      assumed_shear_of_cell(const CellLoopData &d, Scratch &sc, assembly::CellContribution &c) const;
      /// The rim rod on the cell's rim faces.
      void
      rim_of_cell(const CellLoopData &                         d,
                  const DoFHandler<2>::active_cell_iterator &cell,
                  Scratch &                                    sc,
                  assembly::CellContribution &                 c) const;
      /// io::InputError unless the thickness profile and the natural curvature are finite at
      /// every quadrature point of the mesh and the thickness positive there.
      void
      check_plate_fields() const;
      void
      say(const std::string &line) const
      {
        record.say(line);
      }
      void
      write_event(const Event &e, const Vector<double> &U, const Vector<double> *mode);
      /// plate VTU `name`.vtu in the output directory, or `name`.pvtu of a distributed mesh's
      /// pieces; returns the file name written (for the .pvd series).
      std::string
      write_plate(const std::string &name, const Vector<double> &U) const;
      /// The same for the rim rod.
      std::string
      write_rim(const std::string &name, const Vector<double> &U) const;
    };

    void
    run_plate_rod(ParameterHandler &prm, const io::RunOptions &options);
  } // namespace plate_rod
} // namespace cosmo

#endif
