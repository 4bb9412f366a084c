#ifndef cosmo_solvers_continuation_h
#define cosmo_solvers_continuation_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/postprocessors.h>
#include <cosmo/solvers/newton.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

/**
 * Natural-parameter continuation (doc/specification/continuation.md): the load parameter t
 * (growth and prescribed strains are ramped by it) goes from its start to a
 * target in adaptive steps. Each step: a secant predictor, a checked Newton
 * corrector; an easy step (few iterations) lets the next one grow, a failed
 * one is cut back to half from the last converged state, and a step below
 * the minimum ends the run with a clear message (io::RunFailure) after
 * everything converged so far has been written.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    struct StepReport
    {
      unsigned int step              = 0;
      double       t                 = 0;
      double       step_length       = 0;
      unsigned int newton_iterations = 0;
      double       residual_norm     = 0;
      unsigned int cutbacks          = 0; ///< failed attempts before this step converged
      bool         final             = false;
      unsigned int branch            = 0;  ///< arclength continuation: 0 the first branch
      int          n_negative        = -1; ///< arclength continuation: stability count, -1 unknown
      /// The problem's factorization in place is not of this state but of
      /// the predictor one Newton step (below sqrt(eps) of the unknowns'
      /// scale) away, from which the count comes (arclength continuation,
      /// doc/theory-continuation.md 1).
      bool factorized_at_predictor = false;
      /// The driver stops at its first event ('Stop at first event'): this
      /// state is on the way to it (io::PostprocessedState).
      bool toward_first_event = false;
    };

    /**
     * A nonlinear system with a load parameter and an output hook; what it
     * shows of its states (io::StateSource) is what the run's postprocessors
     * write.
     */
    class ContinuationProblem : public NonlinearSystem, public io::StateSource
    {
    public:
      /// Set t; prescribed quantities (growth, prescribed strains) follow it.
      virtual void
      set_load_parameter(double t) = 0;
      /// Called after every converged step with the state at t.
      virtual void
      converged_step(const Vector<double> &U, const StepReport &report) = 0;
      /**
       * A start for the first step (from the starting state at t, before a
       * secant predictor exists) better than the starting state itself, e.g.
       * the step solved on a coarser mesh and interpolated (nested
       * iteration: the full mesh then needs only Newton's last, quadratic
       * iterations). Returns false, U untouched, where there is none. Where
       * the equilibrium at that load is unique, the converged state does not
       * depend on it beyond Newton's tolerance.
       */
      virtual bool
      first_step_guess(double /*t*/, Vector<double> & /*U*/)
      {
        return false;
      }

      /**
       * The postprocessors the drivers call after converged_step() and
       * located events (io/postprocessors.h), with the run's output
       * directory; null: none. The problem keeps neither.
       */
      void
      attach_postprocessors(io::Postprocessors *p, const std::string &output_directory)
      {
        postprocessors           = p;
        postprocessor_directory = output_directory;
      }
      /// Calls the attached postprocessors, if any, with `state` completed.
      void
      postprocess(io::PostprocessedState state) const;
      /// The attached postprocessors' state, for the application's
      /// checkpoint (nothing attached: an empty list) ...
      void
      save_postprocessors(io::CheckpointWriter &w) const;
      /// ... and back (their files rewritten as they were then).
      void
      load_postprocessors(io::CheckpointReader &r);
      /// steps.csv's row of the last converged state (io::StateSource).
      std::vector<double>
      quantity_values() const override
      {
        return steps_row;
      }

    protected:
      /// The last converged state's values of quantity_columns(), in order:
      /// set by the application's converged_step(), kept in its checkpoint.
      std::vector<double> steps_row;

    private:
      io::Postprocessors *postprocessors = nullptr;
      std::string         postprocessor_directory;
    };

    /// problem.converged_step(), then its postprocessors: how every driver
    /// reports a converged state.
    void
    report_converged_step(ContinuationProblem &problem, const Vector<double> &U, const StepReport &report);
    /// The postprocessors told that the path (or a branch) ends before its
    /// target at its last converged state U, reported before as `last`.
    void
    report_path_end(const ContinuationProblem &problem, const Vector<double> &U, const StepReport &last);


    struct ContinuationSettings
    {
      double       start            = 0;
      double       target           = 1;
      double       initial_step     = 0.25;
      double       minimum_step     = 1e-4;
      double       maximum_step     = 0.5;
      unsigned int maximum_steps    = 200;
      unsigned int easy_iterations  = 4;
      double       growth_factor    = 1.5;
      /// Newton keeps its factorization while it converges fast (chord
      /// steps, NewtonSettings::reuse_factorization).
      bool reuse_factorization = true;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    class NaturalParameterContinuation
    {
    public:
      NaturalParameterContinuation(const ContinuationSettings &settings,
                                   const NewtonSettings &      newton);

      /// Optional progress printer (one line per step or cut-back).
      std::function<void(const std::string &)> progress;

      /**
       * Follow the branch from (U, start) to the target. U must solve the
       * problem at `start` (for growth problems, the ungrown reference state);
       * it is reported as step 0. On return U is the state at the target.
       */
      unsigned int
      run(ContinuationProblem &problem, Vector<double> &U);

      /**
       * Called after every converged step (after problem.converged_step()),
       * where the driver can go on from what save() writes: the application
       * writes its checkpoint then (io/checkpoint.h).
       */
      std::function<void()> checkpoint;
      /// The driver's state at the last checkpoint() call.
      void
      save(io::CheckpointWriter &w) const;
      /// Restore it: the next run() goes on from there (U is set to its state).
      void
      load(io::CheckpointReader &r);

    private:
      ContinuationSettings settings;
      NewtonSettings       newton;
      /// Where the path is: the last two converged states, the step lengths, the steps taken.
      struct Progress
      {
        double         t = 0;
        Vector<double> U, U_previous;
        double         dt_previous = 0, dt = 0;
        unsigned int   step        = 0;
      } at;
      bool resume = false;
    };
  } // namespace solvers
} // namespace cosmo

#endif
