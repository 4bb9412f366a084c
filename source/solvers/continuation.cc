#include <cosmo/io/parameters.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/continuation.h>
#include <cosmo/solvers/step_control.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace solvers
  {
    void
    ContinuationProblem::postprocess(io::PostprocessedState state) const
    {
      if (postprocessors == nullptr || postprocessors->empty())
        return;
      state.output_directory = postprocessor_directory;
      state.source           = this;
      if (state.kind == io::PostprocessedState::Kind::converged_state)
        {
          const auto columns = quantity_columns();
          const auto values  = quantity_values();
          for (unsigned int k = 0; k < columns.size() && k < values.size(); ++k)
            state.quantities.emplace_back(columns[k].first, values[k]);
        }
      postprocessors->execute(state);
    }

    void
    ContinuationProblem::save_postprocessors(io::CheckpointWriter &w) const
    {
      if (postprocessors == nullptr)
        w.put(std::uint64_t(0));
      else
        postprocessors->save(w);
    }

    void
    ContinuationProblem::load_postprocessors(io::CheckpointReader &r)
    {
      if (postprocessors == nullptr)
        {
          if (r.get_size() != 0)
            throw std::runtime_error("the checkpoint's postprocessors differ from this run's");
        }
      else
        postprocessors->load(r, postprocessor_directory);
    }

    namespace
    {
      /// What the postprocessors see of a state the driver reported.
      io::PostprocessedState
      postprocessed(const io::PostprocessedState::Kind kind, const Vector<double> &U, const StepReport &report)
      {
        io::PostprocessedState s;
        s.kind       = kind;
        s.step       = report.step;
        s.branch     = report.branch;
        s.t          = report.t;
        s.n_negative = report.n_negative;
        s.final      = report.final;
        s.unknowns   = &U;
        s.toward_first_event = report.toward_first_event;
        return s;
      }
    } // namespace

    void
    report_converged_step(ContinuationProblem &problem, const Vector<double> &U, const StepReport &report)
    {
      problem.converged_step(U, report);
      problem.postprocess(postprocessed(io::PostprocessedState::Kind::converged_state, U, report));
    }

    void
    report_path_end(const ContinuationProblem &problem, const Vector<double> &U, const StepReport &last)
    {
      problem.postprocess(postprocessed(io::PostprocessedState::Kind::path_end, U, last));
    }

    void
    ContinuationSettings::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Continuation");
      prm.declare_entry("Initial step", "0.25", Patterns::Double(1e-12, 1),
                        "First step of the load parameter t (t ramps growth and "
                        "prescribed strains from the reference state, t = 0, to the "
                        "values of the .prm, t = 1).");
      prm.declare_entry("Minimum step", "1e-4", Patterns::Double(1e-14, 1),
                        "Below this step the run stops with an error (exit status 2).");
      prm.declare_entry("Maximum step", "0.5", Patterns::Double(1e-12, 1),
                        "Largest step of t.");
      prm.declare_entry("Maximum number of steps", "200", Patterns::Integer(1),
                        "Stop with an error if the target is not reached in this many steps.");
      prm.declare_entry("Easy step iterations", "4", Patterns::Integer(1),
                        "A step that converges in at most this many Newton iterations "
                        "(those with a new factorization: chord steps, see 'Reuse "
                        "factorization', are not counted) lets the next step grow by "
                        "'Step growth factor'.");
      prm.declare_entry("Step growth factor", "1.5", Patterns::Double(1, 10),
                        "Factor by which an easy step lets the next one grow.");
      prm.declare_entry("Reuse factorization", "true", Patterns::Bool(),
                        "Newton keeps the factorization of the Jacobian for its next "
                        "steps while each contracts the residual at least tenfold (chord "
                        "steps: one residual and one solve instead of a Jacobian and a "
                        "factorization), and makes a new one where a step contracts less. "
                        "Where the tolerance is reached by such a step, up to two more "
                        "follow (chord steps while they contract tenfold, else a fresh one "
                        "where the residual is above 1/100 of the tolerance), so that the "
                        "state is as exact as after Newton's quadratic last step. The Newton "
                        "iterations "
                        "reported count them; 'Easy step iterations' counts the "
                        "factorized ones. false: a new factorization at every iteration.");
      prm.leave_subsection();
    }

    void
    ContinuationSettings::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Continuation");
      parse_step_control(prm, *this);
      reuse_factorization = prm.get_bool("Reuse factorization");
      if (minimum_step > initial_step)
        throw io::InputError("Continuation", "Minimum step", prm.get("Minimum step"),
                             "must not exceed 'Initial step' = " + prm.get("Initial step"));
      if (maximum_step < initial_step)
        throw io::InputError("Continuation", "Maximum step", prm.get("Maximum step"),
                             "must not be below 'Initial step' = " + prm.get("Initial step"));
      prm.leave_subsection();
    }

    NaturalParameterContinuation::NaturalParameterContinuation(
      const ContinuationSettings &settings,
      const NewtonSettings &      newton)
      : settings(settings)
      , newton(newton)
    {
      this->newton.reuse_factorization = settings.reuse_factorization;
    }

    void
    NaturalParameterContinuation::save(io::CheckpointWriter &w) const
    {
      w.put(at.t);
      w.put_vector(at.U);
      w.put_vector(at.U_previous);
      w.put(at.dt_previous);
      w.put(at.dt);
      w.put(at.step);
    }

    void
    NaturalParameterContinuation::load(io::CheckpointReader &r)
    {
      at.t = r.get_double();
      r.get_vector(at.U);
      r.get_vector(at.U_previous);
      at.dt_previous = r.get_double();
      at.dt          = r.get_double();
      at.step        = r.get_unsigned();
      resume         = true;
    }

    namespace
    {
      /// Step 0: the starting state must be converged too (it usually is exact).
      void
      converge_starting_state(ContinuationProblem &       problem,
                              Vector<double> &            U,
                              const NewtonSettings &      newton,
                              const ContinuationSettings &settings,
                              const double                t,
                              StepReport &                report)
      {
        const NewtonResult r     = newton_solve(problem, U, newton);
        report.step              = 0;
        report.t                 = t;
        report.newton_iterations = r.iterations;
        report.residual_norm     = r.residual_norm;
        report.final             = (t >= settings.target);
        report_converged_step(problem, U, report);
      }

      /// A run that needs more than the allowed number of steps ends.
      void
      check_step_limit(const unsigned int step, const ContinuationSettings &settings, const double t)
      {
        if (step >= settings.maximum_steps)
          throw io::RunFailure("the target t = " + std::to_string(settings.target) +
                               " was not reached in " +
                               std::to_string(settings.maximum_steps) +
                               " steps (last converged t = " + std::to_string(t) + ")");
      }

      /// Secant predictor from the last two converged states (U at t,
      /// U_previous a step dt_previous before); on the first step the
      /// problem's own guess.
      Vector<double>
      secant_predictor(ContinuationProblem & problem,
                       const Vector<double> &U,
                       const Vector<double> &U_previous,
                       const double          t,
                       const double          t_new,
                       const double          dt_previous,
                       const unsigned int    step)
      {
        Vector<double> U_trial = U;
        if (dt_previous > 0)
          U_trial.add((t_new - t) / dt_previous, U, -(t_new - t) / dt_previous, U_previous);
        else if (step == 0)
          problem.first_step_guess(t_new, U_trial);
        return U_trial;
      }

      /// After the step from t to t_new failed (`what`): halve dt, saying so
      /// through `progress`; below the minimum step the run ends.
      void
      cut_back(double &                                        dt,
               const double                                    t,
               const double                                    t_new,
               const char *                                    what,
               const ContinuationSettings &                    settings,
               const std::function<void(const std::string &)> &progress)
      {
        std::ostringstream s;
        s << "  step to t = " << t_new << " failed (" << what << "); cutting back to "
          << dt / 2;
        if (progress)
          progress(s.str());
        dt /= 2;
        if (dt < settings.minimum_step)
          throw io::RunFailure("continuation stalled at t = " + std::to_string(t) +
                               ": the step fell below the minimum " +
                               std::to_string(settings.minimum_step) +
                               " (last failure: " + what + ")");
      }
    } // namespace

    unsigned int
    NaturalParameterContinuation::run(ContinuationProblem &problem, Vector<double> &U)
    {
      double         t = settings.start;
      StepReport     report;
      Vector<double> U_previous = U;
      double         dt_previous = 0;
      double         dt          = settings.initial_step;
      unsigned int   step        = 0;
      unsigned int   cutbacks    = 0;
      auto           save_point  = [&]() {
        if (!checkpoint)
          return;
        at.t           = t;
        at.U           = U;
        at.U_previous  = U_previous;
        at.dt_previous = dt_previous;
        at.dt          = dt;
        at.step        = step;
        checkpoint();
      };
      if (resume)
        {
          // Go on from the checkpoint's state (its steps are written already).
          resume      = false;
          t           = at.t;
          U           = at.U;
          U_previous  = at.U_previous;
          dt_previous = at.dt_previous;
          dt          = at.dt;
          step        = at.step;
          report.step = step; // (the path's end, should it end before its target)
          report.t    = t;
        }
      else
        {
          problem.set_load_parameter(t);
          converge_starting_state(problem, U, newton, settings, t, report);
          U_previous = U;
          save_point();
        }

      try
        {
          while (t < settings.target - 1e-14)
            {
              io::check_interrupt(); // between steps: the last converged state is written
              check_step_limit(step, settings, t);
              dt                 = std::min(dt, settings.target - t);
              const double t_new = (settings.target - (t + dt) < 1e-12) ? settings.target : t + dt;

              Vector<double> U_trial =
                secant_predictor(problem, U, U_previous, t, t_new, dt_previous, step);

              problem.set_load_parameter(t_new);
              try
                {
                  const NewtonResult r = newton_solve(problem, U_trial, newton);
                  U_previous           = U;
                  U                    = U_trial;
                  dt_previous          = t_new - t;
                  t                    = t_new;
                  ++step;
                  report.step              = step;
                  report.t                 = t;
                  report.step_length       = dt_previous;
                  report.newton_iterations = r.iterations;
                  report.residual_norm     = r.residual_norm;
                  report.cutbacks          = cutbacks;
                  report.final             = (t >= settings.target - 1e-14);
                  report_converged_step(problem, U, report);
                  cutbacks = 0;
                  // (a chord step costs a residual and a solve: the
                  // factorized iterations measure the step's cost)
                  if (r.iterations - r.chord_steps <= settings.easy_iterations)
                    dt = std::min(settings.maximum_step, dt * settings.growth_factor);
                  save_point();
                }
              catch (NewtonFailure &e)
                {
                  ++cutbacks;
                  problem.set_load_parameter(t);
                  cut_back(dt, t, t_new, e.what(), settings, progress);
                }
            }
        }
      catch (io::RunFailure &)
        {
          // The target is not reached: the last converged state is the path's end.
          report_path_end(problem, U, report);
          throw;
        }
      return step;
    }
  } // namespace solvers
} // namespace cosmo
