#ifndef cosmo_assembly_reduced_rod_problem_h
#define cosmo_assembly_reduced_rod_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>
#include <cosmo/io/output.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_point_study.h>

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
 * and implements assemble_field(); this class does the gauge and strain rows,
 * the Newton interface, the condensed state and the stability count.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    /// The rod-level quantities of a converged state.
    struct ReducedRodState
    {
      double                t      = 0;
      double                energy = 0;        ///< Psi, energy per unit reference length
      std::array<double, 6> strains{};         ///< nu1..3, kappa1..3
      std::array<double, 6> resultants{};      ///< n1..3, m1..3 = dPsi/d(strains)
      std::array<double, 6> multipliers{};     ///< of the six gauge constraints
      FullMatrix<double>    stiffness;         ///< 6x6 d(n,m)/d(nu,kappa)
      int                   n_negative = -1;   ///< negative Hessian eigenvalues (constrained space)
      double                min_elastic_J = 0; ///< smallest det Fe (bulk problems)
    };

    class ReducedRodProblem : public solvers::BifurcationProblem
    {
    public:
      static constexpr unsigned int n_gauge   = 6;
      static constexpr unsigned int n_strains = 6;

      /// Section "Rod strains": Mode, Strains, Free strains.
      static void
      declare_strain_parameters(ParameterHandler &prm);
      void
      parse_strain_parameters(ParameterHandler &prm);

      /// Override the target strains (prescribed ones reach them at t = 1).
      void
      set_target_strains(const std::array<double, 6> &strains)
      {
        target_strains = strains;
        waypoints.clear();
      }
      /// Target resultants of the free strains (reached at t = 1).
      void
      set_target_resultants(const std::array<double, 6> &n)
      {
        target_resultants = n;
      }
      /// The resultants the free strains are held at, t times the targets (0 for prescribed strains).
      std::array<double, 6>
      resultants_at(double t) const;
      void
      set_free_strains(const std::array<bool, 6> &free)
      {
        strain_is_free = free;
      }
      const std::array<bool, 6> &
      free_strains() const
      {
        return strain_is_free;
      }
      /// The last assembled and factorized bordered Jacobian (tests).
      const BorderedSystem &
      bordered_system() const
      {
        return *system;
      }
      const io::PhaseTimer &
      timings() const
      {
        return timer;
      }
      unsigned int
      n_field_dofs() const
      {
        return n_field;
      }

      std::array<double, 6>
      strains_of(const Vector<double> &U) const;
      std::array<double, 6>
      prescribed_strains_at(double t) const;

      /// Energy, resultants, multipliers, (fresh) stiffness and stability at U.
      ReducedRodState
      condensed_state(const Vector<double> &U);

      /// Every converged state of a run, in order (record_state()).
      struct PathPoint
      {
        double                t;
        unsigned int          branch;
        double                energy;
        int                   n_negative;
        std::array<double, 6> strains;
        std::array<double, 6> resultants;
      };
      const std::vector<PathPoint> &
      path() const
      {
        return visited;
      }
      /// Events located by arclength continuation, with the strains there.
      const std::vector<Event> &
      events() const
      {
        return located_events;
      }
      /// The events with the state and mode at each (a study's critical points).
      const std::vector<solvers::EventRecord> &
      event_records() const
      {
        return records;
      }
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
      void
      mode_mask(Vector<double> &mask) const override;

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

      /// Where assemble_field() adds its cells: R, the system's matrix and
      /// border columns, and the border block E (assembly::EnergyAssembler).
      AssemblyTarget
      field_target(Vector<double> *R, const bool jacobian, FullMatrix<double> &E) const
      {
        AssemblyTarget target;
        target.residual     = R;
        target.jacobian     = jacobian;
        target.system       = system.get();
        target.border_block = &E;
        return target;
      }

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

      /// d(prescribed strains)/dt at t (the path's slope; 0 beyond its end).
      std::array<double, 6>
      prescribed_strain_rate(double t) const;

      /**
       * Set up the bordered system once the field exists: the sparsity of
       * E_UU (n_field x n_field entries; the gauge rows are added here) and
       * the six constraint rows C (integrals of the shape functions).
       */
      void
      setup_bordered_system(DynamicSparsityPattern &            field_pattern,
                            const std::array<Vector<double>, 6> &rows,
                            const std::string &                  linear_solver);

      /**
       * The same on a mesh distributed over the ranks of `comm`: this rank
       * owns the field DoFs `owned_field` (contiguous, in rank order) and
       * writes rows of `relevant_field`; `add_field_entries` adds E_UU's
       * entries of the rank's cells. The last rank owns the six gauge rows.
       * The constraint rows are whole on every rank. Afterwards
       * assemble_field() adds into system->distributed_matrix and sums
       * nothing itself: assemble() sums the ranks' parts (field_layout).
       */
      void
      setup_distributed_bordered_system(
        const IndexSet &                                             owned_field,
        const IndexSet &                                             relevant_field,
        const std::function<void(TrilinosWrappers::SparsityPattern &)> &add_field_entries,
        const std::array<Vector<double>, 6> &                        rows,
        MPI_Comm                                                     comm);

      /// The field DoFs' owners on a distributed mesh (identity otherwise).
      solvers::ReplicatedVectorLayout field_layout;

      /**
       * The rod-level keys of summary.json, shared by the applications:
       * energy, strains, resultants, multipliers, stiffness (and its order),
       * stability, events (kind, lambda, branch, counts, eigenvalue, strains;
       * `event_extra(k, entry)` may add keys to event k).
       */
      void
      add_state_to_summary(io::JSON &                                        j,
                           const ReducedRodState &                           s,
                           const std::function<void(unsigned int, io::JSON &)> &event_extra = {}) const;

      /**
       * Checkpoints (io/checkpoint.h), set by the application's run(): how
       * to write one, and the one to resume from (nullptr: start afresh).
       * follow_path() and the application's natural-parameter path call
       * connect_checkpoints() on their driver.
       */
      std::function<void(const io::CheckpointWriter &)> write_checkpoint;
      io::CheckpointReader *                            resume_from = nullptr;

      /// The path so far (visited states, events); an application adds what it writes.
      virtual void
      save_progress(io::CheckpointWriter &w) const;
      virtual void
      load_progress(io::CheckpointReader &r);

      /**
       * A driver (arclength or natural parameter) resumes from resume_from
       * if set, and writes a checkpoint of its state and save_progress()
       * after every converged step if write_checkpoint is set.
       */
      template <typename Driver>
      void
      connect_checkpoints(Driver &driver)
      {
        if (resume_from)
          {
            driver.load(*resume_from);
            load_progress(*resume_from);
            if (!resume_from->at_end())
              throw std::runtime_error("the checkpoint holds more than this run reads");
            resume_from = nullptr;
          }
        if (write_checkpoint)
          driver.checkpoint = [this, &driver]() {
            io::PhaseTimer::Scope scope(timer, "checkpoint");
            io::CheckpointWriter  w;
            driver.save(w);
            save_progress(w);
            write_checkpoint(w);
          };
      }

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
      /// Append a converged state to path().
      void
      record_state(const solvers::StepReport &report, const ReducedRodState &s)
      {
        visited.push_back({report.t, report.branch, s.energy, s.n_negative, s.strains, s.resultants});
      }

      /// Full assembly: field, gauge rows, strain rows. Returns > 0 if inadmissible.
      int
      assemble(const Vector<double> &U,
               Vector<double> *      R,
               bool                  jacobian,
               FieldIntegrals *      results = nullptr);

      unsigned int                    n_field = 0;
      std::array<Vector<double>, 6>   constraint_rows;
      std::unique_ptr<BorderedSystem> system;
      double                          load_parameter = 0;
      std::array<double, 6>           target_strains{{0, 0, 1, 0, 0, 0}};
      std::array<bool, 6>             strain_is_free{};
      std::array<double, 6>           target_resultants{};
      std::string                     mode = "natural shape";
      std::vector<std::array<double, 6>> waypoints; ///< 'Path' (empty: straight ramp)
      mutable io::PhaseTimer          timer; ///< (mutable: the const output writers time themselves)
      unsigned int                    total_newton_iterations = 0;
      /// condensed_state() calls: the converged states (path steps, table points) of a run.
      unsigned int                    n_condensed_states = 0;
      std::vector<PathPoint>             visited;
      std::vector<Event>                 located_events;
      std::vector<std::array<double, 6>> strains_at_events;
      std::vector<solvers::EventRecord>  records;
      std::unique_ptr<solvers::CriticalGuess> critical_guess;
      /// The state at which the system was last assembled and factorized
      /// (condensed_state() reuses that factorization when asked at it).
      Vector<double> factorized_at;
      double         factorized_load = 0;
      /// Whether the factorization in place is that of U at the current load.
      bool
      factorized_here(const Vector<double> &U) const;
      /// The next condensed_state() takes the last factorization as that of
      /// its state: a continued critical point, whose last Newton iterate
      /// differs from the located point by an update below the located
      /// precision (solvers/critical_point.h), set by follow_path().
      bool report_with_last_factorization = false;
      /// Where to report a failed factorization (may be empty).
      std::function<void(const std::string &)> report;
    };
  } // namespace assembly
} // namespace cosmo

#endif
