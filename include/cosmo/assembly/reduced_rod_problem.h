#ifndef cosmo_assembly_reduced_rod_problem_h
#define cosmo_assembly_reduced_rod_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/gauged_system.h>
#include <cosmo/assembly/reduced_rod_records.h>
#include <cosmo/assembly/rod_strain_control.h>
#include <cosmo/io/output.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/solvers/factorization_mark.h>
#include <cosmo/solvers/path_checkpoints.h>

#include <array>
#include <functional>
#include <memory>

/**
 * The common structure of parts 1 and 2: a field on a cross-section (a 2D
 * section, or the width line of a strip) reduced to a rod by the helical
 * Cauchy-Born rule. Unknowns, in this order: the field DoFs, the six
 * multipliers of the linear gauge constraints C U = 0, and the six rod
 * strains e = (nu, kappa). Each strain is prescribed (ramped by the load
 * parameter t from the reference (0,0,1,0,0,0)) or free (its resultant
 * dPsi/de vanishes, or reaches t times a target: resultant control, the
 * equilibrium of Psi - t nbar.e under dead loads nbar). The Jacobian is a BorderedSystem: the sparse block
 * [[E_UU, C^T],[C, 0]] is factorized, the strains are eliminated through its
 * Schur complement, which is the 6x6 stiffness.
 *
 * A derived class builds the field (mesh, DoFs, constraint rows, sparsity)
 * and implements assemble_field(). This class puts together what the
 * strains ask (RodStrainControl: prescribed, free, held resultants), the
 * bordered linear system with the gauge rows (GaugedSystem) and what the
 * run has seen (ReducedRodRecords); it assembles the whole residual and
 * Jacobian and is the Newton and continuation interface, with the
 * condensed state and the stability count.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    class ReducedRodProblem : public solvers::BifurcationProblem,
                              public RodStrainControl,
                              public GaugedSystem,
                              public ReducedRodRecords
    {
    public:
      using Event = solvers::BifurcationProblem::Event;

      const io::PhaseTimer &
      timings() const
      {
        return timer;
      }
      std::array<double, 6>
      strains_of(const Vector<double> &U) const;

      /// Energy, resultants, multipliers, (fresh) stiffness and stability at U.
      ReducedRodState
      condensed_state(const Vector<double> &U);

      /**
       * A critical point to start from: follow_path() then locates it by
       * Newton on the augmented system from this guess (the next point of a
       * critical curve) instead of following the path from t = 0.
       */
      void
      start_from_critical_point(const solvers::CriticalGuess &g)
      {
        critical_guess = std::make_unique<solvers::CriticalGuess>(g);
      }
      /**
       * A study's classification of a critical mode (the values of its mode
       * columns, critical_point_study.h); none by default.
       */
      virtual std::vector<double>
      classify_critical_mode(const Vector<double> &) const
      {
        return {};
      }
      /// A study's further columns at a critical point: the six strains there.
      std::vector<double>
      critical_point_columns(const solvers::EventRecord &e) const;
      /// Their names: nu1_critical, ..., kappa3_critical.
      static std::vector<std::string>
      critical_point_column_names();
      /// Records the event (derived classes may add output and call this).
      void
      located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode) override;

      // ContinuationProblem / BifurcationProblem
      unsigned int
      n_unknowns() const override
      {
        return n_field + n_gauge + n_strains;
      }
      int
      residual(const Vector<double> &U, Vector<double> &R) override;
      int
      setup_jacobian(const Vector<double> &U) override;
      int
      solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) override;
      /// The bordered direct solve of the whole Jacobian (prescribed strains:
      /// identity rows), no constraints besides: J dst = rhs.
      bool
      solves_exactly() const override
      {
        return true;
      }
      void
      residual_weights(Vector<double> &w) const override;
      void
      set_load_parameter(double t) override
      {
        load_parameter = t;
      }
      int
      n_negative_eigenvalues() override;
      /// |v|.|J||v| with the assembled Hessian (block A) (resolution of a located event).
      double
      jacobian_abs_form(const Vector<double> &v) const override;
      /// Jacobians beside the factorized one, for the estimate's products (serial).
      bool
      store_jacobian(const Vector<double> &U, unsigned int slot) override;
      void
      stored_jacobian_vmult(unsigned int slot, const Vector<double> &x, Vector<double> &y) const override;
      void
      release_stored_jacobians() override
      {
        for (auto &copy : stored_jacobians)
          copy.clear();
      }
      /// Chord steps on the path: the weighted residual sees every equation.
      bool
      chord_steps_on_path() const override
      {
        return true;
      }
      void
      mode_mask(Vector<double> &mask) const override;
      /// The field and the free strains: the energy is minimized over both.
      void
      stability_mask(Vector<double> &mask) const override;

      /// The path so far (load, Newton count, the records) into a checkpoint
      /// (solvers::PathCheckpoints) and back; an application adds what it writes.
      virtual void
      save_progress(io::CheckpointWriter &w) const;
      virtual void
      load_progress(io::CheckpointReader &r);

    protected:
      /// Integrals that come with every assembly.
      struct FieldIntegrals
      {
        double                energy        = 0; ///< Psi
        double                min_elastic_J = 0; ///< smallest det Fe (0 if not applicable)
        std::array<double, 6> resultants{};      ///< dPsi/de at fixed field
      };

      /**
       * Add the field's energy derivatives at U with strains e: the field
       * residual into R[0..n_field) (R is zeroed, may be null), and with
       * `jacobian` E_UU into system->matrix, E_Ue into
       * system->border_columns and E_ee into `border_block` (all zeroed):
       * the cell loop of assembly::EnergyAssembler into an AssemblyTarget of
       * `system`. Returns > 0 if U is inadmissible.
       */
      virtual int
      assemble_field(const Vector<double> &       U,
                     const std::array<double, 6> &e,
                     Vector<double> *             R,
                     bool                         jacobian,
                     FullMatrix<double> &         border_block,
                     FieldIntegrals &             out) = 0;

      /**
       * Scales that make the residual rows dimensionless: a modulus times
       * area (force per unit length of rod, e.g. E D^2 or E w h) and a
       * length (the section size D or the strip width w).
       */
      virtual void
      residual_scales(double &force, double &length) const = 0;

      /**
       * Weights of the six gauge rows C U (their natural sizes): by default
       * those of integrals over a 2D section of size D, 1/D^3 for the
       * translations and 1/D^4 for the rotations; a problem whose rows are
       * other integrals overrides this.
       */
      virtual void
      gauge_weights(std::array<double, 6> &w) const;

      /**
       * Arclength continuation from U at t = 0 (every converged state and
       * event reported through converged_step() and located_event()), or,
       * after start_from_critical_point(), the critical point located from
       * the guess and reported as the path's only state and event
       * (io::RunFailure if that fails). U ends at the last state.
       */
      void
      follow_path(const solvers::ArclengthSettings &arclength,
                  const solvers::NewtonSettings &   newton,
                  Vector<double> &                  U,
                  const std::function<void(const std::string &)> &progress);

      /// Full assembly: field, gauge rows, strain rows. Returns > 0 if inadmissible.
      int
      assemble(const Vector<double> &U,
               Vector<double> *      R,
               bool                  jacobian,
               FieldIntegrals *      results = nullptr);

      double                          load_parameter = 0;
      mutable io::PhaseTimer          timer; ///< (mutable: the const output writers time themselves)
      unsigned int                    total_newton_iterations = 0;
      /// condensed_state() calls: the converged states (path steps, table points) of a run.
      unsigned int                    n_condensed_states = 0;
      std::unique_ptr<solvers::CriticalGuess> critical_guess;
      /// The state at which the system was last factorized (condensed_state()
      /// and Newton's first Jacobian reuse that factorization when asked at it).
      solvers::FactorizationMark factorization;
      /// store_jacobian()'s copies
      std::array<BorderedSystem::AssembledBlocks, 3> stored_jacobians;
      /**
       * Checkpoints (io/checkpoint.h), set by the application's run(): how
       * to write one, and the one to resume from (nullptr: start afresh).
       * follow_path() and the application's natural-parameter path connect
       * their driver to them.
       */
      solvers::PathCheckpoints checkpoints;
      /// Where to report a failed factorization (may be empty).
      std::function<void(const std::string &)> report;
    };
  } // namespace assembly
} // namespace cosmo

#endif
