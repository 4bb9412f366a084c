#ifndef cosmo_applications_strip_problem_h
#define cosmo_applications_strip_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/constitutive_table.h>
#include <cosmo/assembly/reduced_rod_problem.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/run_record.h>
#include <cosmo/materials/plate_law.h>
#include <cosmo/solvers/continuation.h>

#include "parameters.h"

#include <memory>
#include <string>

/**
 * Part 2: a strip (a Cosserat/Naghdi plate of width w and thickness h)
 * reduced to a special Cosserat rod by the helical Cauchy-Born rule
 * (doc/specification/strip.md):
 *
 *   phi(eta, s) = r(s) + R(s) y(eta),   d(eta, s) = R(s) q(eta),
 *
 * y = eta E1 + u the deformed cross-section curve, q = exp([theta]x) E2 the
 * thickness-line director, theta = (theta1, 0, theta3). The field is
 * (u, theta1, theta3) on the width line, FE_Q(p)^5; the six gauge
 * constraints are int u = 0, int eta u3 = 0 (rotation about the plate
 * normal), int eta u2 = 0 (rotation about the axis) and int theta1 = 0
 * (rotation about the width line: the linear counterpart of int q.E3 = 0,
 * doc/specification/strip.md). Free edges: natural boundary conditions.
 *
 * The plate energy at each quadrature point is differentiated by Sacado with
 * respect to its 16 local variables (u, u', theta1, theta3 and their
 * derivatives, and the six strains), on which the field DoFs act linearly.
 */
namespace cosmo
{
  namespace strip
  {
    using namespace dealii;

    /**
     * The problem on the parameters it was parsed from (parameters.h), with
     * the rod strains of its reduced-rod base; it adds the discretization,
     * the state and the run's records.
     */
    class StripProblem : public assembly::ReducedRodProblem, public StripParameters
    {
    public:
      StripProblem();
      ~StripProblem() override;

      /// StripParameters::parse_parameters, then the rod strains and the table.
      void
      parse_parameters(ParameterHandler &prm);

      /// Mesh, DoFs, constraints, the reference state.
      void
      setup_system();
      /// Continuation from the reference state to t = 1.
      assembly::ReducedRodState
      solve();

      /// The application: solve and write every output.
      void
      run(const io::RunOptions &options, const ParameterHandler &prm);

      /// No progress lines on the terminal (tests, benchmarks).
      void
      set_quiet(const bool q)
      {
        record.set_quiet(q);
      }

      const Vector<double> &
      current_solution() const
      {
        return solution;
      }

      void
      converged_step(const Vector<double> &U, const solvers::StepReport &report) override;
      /// What the run's postprocessors show of a state (io/postprocessors.h):
      /// steps.csv's columns and row, the section's and the strip's VTU files.
      std::vector<std::pair<std::string, std::string>>
      quantity_columns() const override;
      std::vector<std::pair<std::string, std::string>>
      write_fields(const std::string &tag) const override;
      /// event-NN.vtu (the section at the event) and event-NN-mode.vtu.
      std::vector<std::pair<std::string, std::string>>
      write_event_fields(const std::string &   tag,
                         const Vector<double> &U,
                         const Vector<double> *mode) const override;
      void
      located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode) override;
      /// The path so far and the postprocessors' state, for a checkpoint.
      void
      save_progress(io::CheckpointWriter &w) const override;
      void
      load_progress(io::CheckpointReader &r) override;

      /// Follow the path by arclength continuation, with event location and branch switching.
      std::vector<solvers::EventRecord>
      follow_branches();

      /**
       * The width-wise parity of a mode: sum u2(eta) u2(-eta) / sum u2(eta)^2
       * over the out-of-plane displacement u2 (the plate normal is E2), +1
       * for a mode symmetric about the centre line, -1 antisymmetric. The
       * mesh is symmetric about eta = 0 (NaN if not, or for a mode without u2).
       */
      double
      mode_parity(const Vector<double> &mode) const;
      /// The study's mode column mode_symmetry: +1 symmetric, -1 antisymmetric, 0 mixed.
      std::vector<double>
      classify_critical_mode(const Vector<double> &mode) const override;
      /// "symmetric" (parity > 1/2), "antisymmetric" (< -1/2) or "mixed".
      static std::string
      symmetry_name(double parity);

    protected:
      int
      assemble_field(const Vector<double> &       U,
                     const std::array<double, 6> &e,
                     Vector<double> *             R,
                     bool                         jacobian,
                     FullMatrix<double> &         border_block,
                     FieldIntegrals &             out) override;
      void
      residual_scales(double &force, double &length) const override;
      /// The strip's gauge rows are integrals over the width line: w^2, w^3, w.
      void
      gauge_weights(std::array<double, 6> &w) const override;
      /// Exact where only the prescribed strain rows depend on t; with a
      /// natural curvature of t, the residual's central difference.
      int
      load_derivative(const Vector<double> &U, double lambda, Vector<double> &dR) override;

    private:
      assembly::ConstitutiveTable   table;

      // Discretization
      Triangulation<1>             triangulation;
      std::unique_ptr<FESystem<1>> fe;
      DoFHandler<1>                dof_handler;
      Vector<double>               solution;

      assembly::ReducedRodState    last_state;
      /// mode_parity() of each located branch point's mode (NaN for folds).
      std::vector<double>          event_parities;
      io::RunRecord                record{"strip"};

      void
      say(const std::string &line) const
      {
        record.say(line);
      }
      void
      write_section(const std::string &file, const Vector<double> &U) const;
      /// outline.csv: the section's boundary (the width line thickened by h)
      /// at U, for the rod's body swept as a strip's section.
      void
      write_outline(const Vector<double> &U) const;
      /// strip-NNNN.vtu: a piece of the strip swept along the helix.
      void
      write_piece(const std::string &file) const;
    };

    /// The application: one run of the strip problem.
    void
    run_strip(ParameterHandler &prm, const io::RunOptions &options);
  } // namespace strip
} // namespace cosmo

#endif
