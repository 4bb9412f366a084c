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
#include <cosmo/solvers/factorization_mark.h>

#include <array>

#include "assembly.h"
#include "diagnostics.h"
#include "discretization.h"
#include "parameters.h"
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/factorization_mark.h>
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
 * on a mesh whose rim is curved (MappingQ(p), discretization.h). The rod is welded to the edge
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

    class PlateRodRun;

    /**
     * The problem on the parameters it was parsed from (parameters.h): the
     * run's configuration is a PlateRodParameters, parsed once; the problem
     * adds the state, its system and what the drivers report of the path
     * (the converged states, the located events, the log). The mesh, the
     * DoFs and their constraints are its PlateRodDiscretization, the energy
     * and its derivatives its PlateRodAssembly (assembly.h); what a state
     * shows (diagnostics, VTU files) is in diagnostics.h, on the
     * discretization alone. The run around it (the flat start, the path
     * with its checkpoint, the summary) is a PlateRodRun (run.h).
     */
    class PlateRodProblem : public solvers::BifurcationProblem, public PlateRodParameters
    {
    public:
      /// PlateRodParameters::parse_parameters, the residual cache cleared.
      void
      parse_parameters(ParameterHandler &prm);
      /// The discretization of the parameters, the Hessian's sparsity on it, a zero state.
      void
      setup_system();

      void
      set_quiet(const bool q)
      {
        record.set_quiet(q);
      }

      // NonlinearSystem / BifurcationProblem
      unsigned int
      n_unknowns() const override
      {
        return discretization.n_dofs();
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
      /**
       * 0 on the DoFs the constraints determine (mirror edges, alpha off the
       * rim): a constrained DoF's value follows from its masters, it carries
       * no independent part of a mode. Above all the border of the
       * critical-point system must vanish there: the solve returns J^-1 on
       * the constrained space only for right-hand sides with no slave
       * entries, and a border with them made the bordered test function g
       * unsymmetric, its derivative -v.dJ v wrong by ~3 % and Newton linear
       * (rate 0.026, measured on the sector) instead of quadratic.
       */
      void
      mode_mask(Vector<double> &mask) const override
      {
        discretization.free_dof_mask(mask);
      }
      /// The mirror edges' and in-plane constraints distributed onto a mode
      /// (all homogeneous: the slaves set from their masters, nothing added).
      void
      complete_mode(Vector<double> &v) const override
      {
        discretization.distribute(v);
      }
      /// Jacobians beside the factorized one, for the estimate's products (serial mesh).
      bool
      store_jacobian(const Vector<double> &U, unsigned int slot) override;
      void
      stored_jacobian_vmult(unsigned int slot, const Vector<double> &x, Vector<double> &y) const override
      {
        system.vmult(y, x, {}, stored_jacobians[slot]);
      }
      void
      release_stored_jacobians() override
      {
        for (auto &copy : stored_jacobians)
          copy.clear();
      }
      /// Full disc: (v + S v)/2 with S the reflection y -> -y (sector: false).
      bool
      project_to_fixed_point_space(Vector<double> &v) const override
      {
        return discretization.project_to_fixed_point_space(v);
      }
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
      std::vector<std::pair<std::string, std::string>>
      write_fields(const std::string &tag) const override;
      /// event-NN (the plate at a located event) and event-NN-mode (the mode added).
      std::vector<std::pair<std::string, std::string>>
      write_event_fields(const std::string &   tag,
                         const Vector<double> &U,
                         const Vector<double> *mode) const override;
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

      /// The total energy, plate and rim, at U and the current load parameter (at most one
      /// residual assembly; the residual is its gradient, test plate_rod.tangent_fd).
      double
      energy(const Vector<double> &U);

      /// Read-only views of the state, the path and its discretization (the
      /// tests, the benchmarks and the run; the diagnostics of a state are
      /// functions of the discretization, diagnostics.h).
      const PlateRodDiscretization &
      get_discretization() const
      {
        return discretization;
      }
      const Vector<double> &
      current_solution() const
      {
        return solution;
      }
      /// The Hessian of the last setup_jacobian() (serial mesh).
      const SparseMatrix<double> &
      system_matrix() const
      {
        return system.matrix;
      }
      /// The located events with state and mode (a study's critical points).
      const std::vector<solvers::EventRecord> &
      event_records() const
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

    private:
      /// The run reads and restores the state and the records (its
      /// checkpoint, its summary) and sets what the drivers' reports write.
      friend class PlateRodRun;

      bool   write_output   = false;
      double load_parameter = 0;

      /// The mesh, DoFs and constraints of these parameters (this problem's base).
      PlateRodDiscretization discretization{*this};
      /// The Hessian and its factorization, serial or distributed (no border;
      /// with 'Mesh / Distributed' each rank assembles its own cells into
      /// system.distributed_matrix, factorized by MUMPS with distributed input).
      assembly::BorderedSystem     system;
      Vector<double>               solution;
      /// The state of the last factorization; with_last: converged_step
      /// reports with it (a continued critical point).
      solvers::FactorizationMark   factorization;
      /// store_jacobian()'s copies
      std::array<assembly::BorderedSystem::AssembledBlocks, 3> stored_jacobians;
      /// The energy's assembly into `system`, with what its last assemblies
      /// found (cleared by parse_parameters and setup_system, which change
      /// what R depends on).
      PlateRodAssembly             energy_assembly{*this, discretization, system};

      // Run records
      std::vector<PlateRodState>        states;
      std::vector<solvers::EventRecord> located_events;
      /// steps.csv's columns (name, unit); the row is ContinuationProblem::steps_row.
      std::vector<std::pair<std::string, std::string>> steps_columns;
      io::RunRecord                     record{"plate_rod"};
      /// (mutable: the const output writers time themselves)
      mutable io::PhaseTimer            timer;
    };
  } // namespace plate_rod
} // namespace cosmo

#endif
