#include <deal.II/sundials/kinsol.h>

#include <cosmo/io/stderr_capture.h>

#include <cosmo/io/parameters.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/distributed_direct.h>
#include <cosmo/solvers/chord_newton.h>
#include <cosmo/solvers/newton.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace solvers
  {
    bool
    is_driver_failure(const std::exception &e)
    {
      return dynamic_cast<const NewtonFailure *>(&e) != nullptr ||
             dynamic_cast<const io::RunFailure *>(&e) != nullptr ||
             dynamic_cast<const FactorizationFailure *>(&e) != nullptr;
    }

    void
    NewtonSettings::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Relative tolerance",
                        "1e-10",
                        Patterns::Double(1e-15, 1e-2),
                        "Newton converges when the max-norm of the residual, each "
                        "equation made dimensionless by its natural scale, is below this "
                        "(rod_cross_section: nodal forces by E times the section diameter D, "
                        "resultants by E D^2 and E D^3, constraints by D^3, D^4; strip: "
                        "forces by E w h; plate_rod: nodal forces by E h R, moments by "
                        "E h R^2).");
      prm.declare_entry("Maximum iterations",
                        "25",
                        Patterns::Integer(1, 1000),
                        "Newton iterations per continuation step before the step is "
                        "declared failed and cut back.");
      prm.leave_subsection();
    }

    void
    NewtonSettings::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
      prm.leave_subsection();
    }

    bool
    dq_point_of(const Vector<double> &v,
                const Vector<double> &u,
                const Vector<double> &p,
                double &              sigma)
    {
      // KINSOL's own sigma (kinLsDQJtimes, after Brown and Saad, with the
      // unit solution scaling newton_solve leaves): sign(u.p) sqrt(uround)
      // max(|u.p|, ||p||_1) / ||p||_2^2. Only that point is answered: no
      // line-search point u + t p has t equal to it, and another KINSOL that
      // chose sigma otherwise gets its residuals assembled, as before.
      if (v.size() != u.size() || v.size() != p.size())
        return false;
      double up = 0, p1 = 0;
      for (unsigned int i = 0; i < u.size(); ++i)
        up += u[i] * p[i], p1 += std::abs(p[i]);
      const double pp = p.norm_sqr();
      if (!(pp > 0))
        return false;
      const double eps = std::numeric_limits<double>::epsilon();
      sigma = (up >= 0 ? 1. : -1.) * std::sqrt(eps) * std::max(std::abs(up), p1) / pp;
      // v = u + sigma p entry by entry, to the rounding of the sum (eps/2 of
      // |v_i|) and of our sigma against KINSOL's: the same formula, its sums
      // in another order (relative 1e-6 covers n eps for any n < 1e9).
      const double sigma_p = std::abs(sigma) * p.linfty_norm();
      for (unsigned int i = 0; i < v.size(); ++i)
        if (std::abs(v[i] - u[i] - sigma * p[i]) > 1e-6 * sigma_p + 2 * eps * (std::abs(u[i]) + std::abs(v[i])))
          return false;
      return true;
    }

    bool
    same_point(const Vector<double> &a, const Vector<double> &b)
    {
      return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
    }

    const ResidualCache::Entry *
    ResidualCache::find(const Vector<double> &U, const double load) const
    {
      for (unsigned int k = 0; k < entries.size(); ++k)
        if (valid[k] && entries[k].load == load && same_point(entries[k].U, U))
          return &entries[k];
      return nullptr;
    }

    void
    ResidualCache::store(const Vector<double> &U, const double load, const Vector<double> &R,
                         const std::vector<double> &scalars)
    {
      // The entry of this state if it is held already, else the older one.
      const Entry *      held = find(U, load);
      const unsigned int k    = held ? held - entries.data() : 1 - newest;
      entries[k].U       = U;
      entries[k].R       = R;
      entries[k].load    = load;
      entries[k].scalars = scalars;
      valid[k]           = true;
      newest             = k;
    }

    void
    ResidualCache::clear()
    {
      valid.fill(false);
    }

    double
    scaled_residual_norm(const NonlinearSystem &system, const Vector<double> &R)
    {
      Vector<double> w;
      system.residual_weights(w);
      double m = 0;
      for (unsigned int i = 0; i < R.size(); ++i)
        m = std::max(m, std::abs(w[i] * R[i]));
      return m;
    }

    namespace
    {
      /// Exact Newton: a new Jacobian at every iteration, and no cap on the
      /// step length (KINSOL's default cap truncates steps on large systems).
      SUNDIALS::KINSOL<Vector<double>>::AdditionalData
      exact_newton_data(const NewtonSettings &settings)
      {
        using AdditionalData = SUNDIALS::KINSOL<Vector<double>>::AdditionalData;
        AdditionalData data;
        data.strategy                      = AdditionalData::linesearch;
        data.maximum_non_linear_iterations = settings.max_iterations;
        data.function_tolerance            = settings.relative_tolerance;
        data.step_tolerance                = 1e-15;
        data.maximum_setup_calls           = 1;
        data.maximum_newton_step           = 1e12;
        return data;
      }

      /**
       * The residuals and Jacobian solves KINSOL asks of the system, with
       * what saves assemblies: the residual of the guess newton_solve has
       * already evaluated, the last one KINSOL evaluated (that of the final
       * iterate, which the check after the solve would otherwise assemble
       * again), and J p for the difference quotient after an exact solve.
       */
      struct KinsolEvaluations
      {
        KinsolEvaluations(NonlinearSystem &system, NewtonResult &result)
          : system(system)
          , result(result)
        {}

        /// Whether u is (bitwise) the point of the residual kept in last_r.
        bool
        is_last(const Vector<double> &u) const
        {
          return last_status >= 0 && same_point(u, last_u);
        }

        /// The guess U first: true (and result set) if it passes the
        /// stopping test; otherwise its residual is KINSOL's first.
        bool
        guess_converged(const Vector<double> &U, const double tolerance)
        {
          last_status = system.residual(U, last_r);
          io::check_interrupt();
          last_u = U;
          if (last_status == 0)
            {
              const double norm = scaled_residual_norm(system, last_r);
              if (std::isfinite(norm) && norm <= tolerance)
                {
                  result.iterations    = 0;
                  result.residual_norm = norm;
                  return true;
                }
            }
          first_call = true;
          return false;
        }

        /// R(u) for KINSOL, assembled only where it is not known already.
        int
        residual(const Vector<double> &u, Vector<double> &r)
        {
          // SIGINT/SIGTERM: end this solve now (an unrecoverable error for
          // KINSOL), then report the interruption after it, not a failure.
          if (io::pending_signal() != 0)
            return -1;
          if (first_call)
            {
              first_call = false;
              if (is_last(u))
                {
                  r = last_r;
                  return last_status;
                }
            }
          // Right after a solve, KINSOL approximates J p by the difference
          // quotient (R(u + sigma p) - R(u)) / sigma (kinLsDQJtimes: the
          // deal.II 9.4 wrapper offers no J p of its own). For an exact solve
          // J p = b: return R(u) + sigma b, the quotient is then J p itself,
          // without an assembly.
          if (jp_pending)
            {
              jp_pending = false;
              double sigma = 0;
              if (dq_point_of(u, last_u, solved_p, sigma))
                {
                  r = last_r;
                  r.add(sigma, solved_rhs);
                  ++result.exact_jacobian_products;
                  return last_status;
                }
            }
          last_status = system.residual(u, r);
          last_u      = u;
          last_r      = r;
          return last_status;
        }

        /// exact_jp: keep the solve for the residual KINSOL asks next.
        int
        solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst, const bool exact_jp)
        {
          const int status = system.solve_with_jacobian(rhs, dst);
          jp_pending       = status == 0 && exact_jp && last_status == 0 && system.solves_exactly();
          if (jp_pending)
            {
              solved_rhs = rhs;
              solved_p   = dst;
            }
          return status;
        }

        NonlinearSystem &system;
        NewtonResult &   result;
        // The last residual KINSOL evaluated, kept: it is that of the final
        // iterate, which the check after the solve would otherwise assemble
        // again.
        Vector<double> last_u, last_r;
        int            last_status = -1;
        // The last Newton solve J p = b, for the residual KINSOL asks next.
        Vector<double> solved_rhs, solved_p;
        bool           jp_pending = false;
        // The guess's residual is still to be handed to KINSOL.
        bool first_call = false;
      };

      /**
       * kinsol.solve(U). KINSOL's own messages (a failed line search, ...)
       * go with this solve's outcome into the log, not to the terminal's
       * stderr: returned as " (KINSOL said: ...)", or "" if none. Where
       * KINSOL stops with an error, U is reset to U0 and NewtonFailure
       * thrown (or the error passed on, see below).
       */
      std::string
      solve_capturing_messages(SUNDIALS::KINSOL<Vector<double>> &kinsol,
                               Vector<double> &                  U,
                               const Vector<double> &            U0,
                               NewtonResult &                    result)
      {
        io::StderrCapture kinsol_messages;
        auto              said = [&kinsol_messages]() {
          const std::string text = kinsol_messages.release();
          return text.empty() ? text : " (KINSOL said: " + text + ")";
        };
        try
          {
            result.iterations = kinsol.solve(U);
          }
        catch (std::exception &e)
          {
            const std::string messages = said();
            U = U0;
            // Ranks in lockstep (a distributed mesh): an error not every rank
            // raised (one rank's memory, say) ends this rank, and so all of them
            // (MPI_Abort), rather than wait in the check after the solve for
            // the others, which wait in the residual's collective calls.
            if (io::interrupts_are_collective() && !is_driver_failure(e) &&
                dynamic_cast<const SUNDIALS::KINSOL<Vector<double>>::ExcKINSOLError *>(&e) == nullptr)
              throw;
            io::check_interrupt();
            throw NewtonFailure(std::string("KINSOL stopped: ") + e.what() + messages);
          }
        return said();
      }
    } // namespace

    namespace
    {
      /**
       * Newton with the factorization kept while it pays (the chord method,
       * Kelley 2003, ch. 5; settings.reuse_factorization). A step with the
       * Jacobian of an earlier iterate u0 contracts the residual by about
       * |J(u0)^-1 (J(u) - J(u0))|, that is, by the distance from u0: once a
       * fresh Newton step has contracted it tenfold, the next steps keep
       * its factorization, and a new one is made only where a step
       * contracts less than tenfold. From a start near the solution (a
       * coarse-mesh start, a secant predictor) one factorization then does
       * the work of two or three, each further step costing one residual and
       * one solve. Where the tolerance is reached by such a step, further
       * steps follow (at most two: a chord step where the last contracted
       * tenfold, else a fresh one), so that the state is as exact as after
       * Newton's last, quadratic step, not just below the tolerance. No
       * line search: a fresh step that does not
       * decrease the residual, a failed setup or solve, or the iteration
       * limit ends the attempt with U at its last accepted iterate, and
       * newton_solve() goes on from there with KINSOL's line search.
       * in_place: the first step is a chord step with the factorization in
       * place (a nearby state's: newton_solve_from_factorization()), made
       * afresh where that step fails or contracts less than tenfold.
       * Returns whether U has converged.
       */
      bool
      chord_newton(NonlinearSystem &system, Vector<double> &U, const NewtonSettings &settings,
                   const bool take_guess, const bool in_place, NewtonResult &result)
      {
        constexpr double reuse_rate = 0.1, guess_fraction = 0.01;
        constexpr unsigned int max_polish = 2;
        const unsigned int n = system.n_unknowns();
        Vector<double>     R(n), rhs(n), dU(n), U_new(n), R_new(n);
        if (system.residual(U, R) != 0)
          return false;
        io::check_interrupt();
        double norm = scaled_residual_norm(system, R);
        if (!std::isfinite(norm))
          return false;
        // (the same rule for a guess as KINSOL's, or take_guess's)
        if (norm <= (take_guess ? 1. : guess_fraction) * settings.relative_tolerance)
          {
            result.residual_norm = norm;
            return true;
          }
        bool         fresh = false;    // the factorization in place is of U
        bool         keep   = in_place; // the next step keeps it
        unsigned int polish = 0;
        for (unsigned int it = 0; it < settings.max_iterations;)
          {
            // (a failure in the polish of a converged U keeps it)
            if (!keep)
              {
                if (system.setup_jacobian(U) != 0)
                  return polish > 0;
                fresh = true;
              }
            rhs = R;
            rhs *= -1.;
            if (system.solve_with_jacobian(rhs, dU) != 0)
              {
                // (a kept factorization that no longer solves is made afresh)
                if (fresh || polish > 0)
                  return polish > 0;
                keep = false;
                continue;
              }
            U_new = U;
            U_new += dU;
            const int status = system.residual(U_new, R_new);
            io::check_interrupt();
            const double norm_new = status == 0 ? scaled_residual_norm(system, R_new) : INFINITY;
            if (!(norm_new < norm))
              {
                // The polish of a converged U just stops; a stale
                // factorization that no longer contracts is made afresh; a
                // fresh step that does not decrease R is KINSOL's (line search).
                if (polish > 0)
                  return true;
                if (fresh)
                  return false;
                keep = false;
                continue;
              }
            const double rate  = norm_new / norm;
            const bool   chord = !fresh;
            U.swap(U_new);
            R.swap(R_new);
            norm                 = norm_new;
            result.residual_norm = norm;
            ++it;
            ++result.iterations;
            result.chord_steps += chord ? 1 : 0;
            if (norm <= settings.relative_tolerance)
              {
                // A quadratic step's result is final; a chord step's is
                // polished: by chord steps while they contract tenfold, else
                // by a fresh step where it stopped above 1/100 of the
                // tolerance (KINSOL's own bar for a guess: a chord step that
                // just passed the tolerance says little about the state's
                // error; one at the round-off floor needs nothing).
                if (!chord || polish == max_polish ||
                    (rate > reuse_rate && norm <= guess_fraction * settings.relative_tolerance))
                  return true;
                ++polish;
              }
            keep  = rate <= reuse_rate;
            fresh = false; // (the factorization is of the previous iterate now)
          }
        // (the iteration limit, possibly in the polish of a converged state)
        return norm <= settings.relative_tolerance;
      }
    } // namespace

    namespace
    {
      NewtonResult
      solve(NonlinearSystem &      system,
            Vector<double> &       U,
            const NewtonSettings & settings,
            const bool             take_guess,
            const bool             in_place)
      {
        NewtonResult   result;
        Vector<double> U_start = U;
        if (settings.reuse_factorization)
          {
            try
              {
                if (chord_newton(system, U, settings, take_guess, in_place, result))
                  return result;
              }
            catch (...)
              {
                U = U_start; // (an interruption: the caller's state as it was)
                throw;
              }
            // Not converged: KINSOL, with its line search, from the last
            // accepted iterate (no worse than the guess), with the iterations
            // left and its count after the chord steps'.
          }
        const NewtonResult chord = result;
        result                   = NewtonResult();
        NewtonSettings rest      = settings;
        rest.max_iterations      = std::max(1u, settings.max_iterations - std::min(settings.max_iterations, chord.iterations));
        auto with_chord          = [&chord](NewtonResult r) {
          r.iterations += chord.iterations;
          r.chord_steps = chord.chord_steps;
          return r;
        };
        Vector<double> weights;
        system.residual_weights(weights);

        SUNDIALS::KINSOL<Vector<double>> kinsol(exact_newton_data(rest));
        const unsigned int                n = system.n_unknowns();
        kinsol.reinit_vector = [n](Vector<double> &v) { v.reinit(n); };
        kinsol.get_function_scaling = [&]() -> Vector<double> & { return weights; };
        KinsolEvaluations evaluations(system, result);

        // take_guess: the guess first, taken if it passes the stopping test;
        // otherwise its residual is KINSOL's first.
        if (take_guess && evaluations.guess_converged(U, settings.relative_tolerance))
          return with_chord(result);
        kinsol.residual = [&](const Vector<double> &u, Vector<double> &r) {
          return evaluations.residual(u, r);
        };
        kinsol.setup_jacobian = [&](const Vector<double> &u, const Vector<double> &) {
          return system.setup_jacobian(u);
        };
        static const bool exact_jp = std::getenv("COSMO_DQ_JP") == nullptr; // to measure against
        kinsol.solve_with_jacobian = [&](const Vector<double> &rhs, Vector<double> &dst, double) {
          return evaluations.solve_with_jacobian(rhs, dst, exact_jp);
        };

        Vector<double>    U0       = U;
        std::string       messages;
        try
          {
            messages = solve_capturing_messages(kinsol, U, U0, result);
          }
        catch (const NewtonFailure &)
          {
            U = U_start; // (the guess, not the chord steps' last iterate)
            throw;
          }
        result = with_chord(result);

        // A signal ends the solve with an error KINSOL does not report in
        // Release: whatever U is now, it is an interruption, not a failure
        // (which a caller might work around, e.g. by bisecting an event).
        io::check_interrupt();
        // KINSOL reports failure only through (Debug-mode) assertions: check.
        Vector<double> R(n);
        const int      status = evaluations.is_last(U) ?
                                  (R = evaluations.last_r, evaluations.last_status) :
                                  system.residual(U, R);
        result.residual_norm = (status == 0) ? scaled_residual_norm(system, R) : INFINITY;
        if (status != 0 || !std::isfinite(result.residual_norm) ||
            result.residual_norm > settings.relative_tolerance)
          {
            std::ostringstream s;
            s << "Newton did not converge in " << settings.max_iterations
              << " iterations: scaled residual " << result.residual_norm << " > tolerance "
              << settings.relative_tolerance << messages;
            U = U_start;
            throw NewtonFailure(s.str());
          }
        return result;
      }
    } // namespace

    NewtonResult
    newton_solve(NonlinearSystem &      system,
                 Vector<double> &       U,
                 const NewtonSettings & settings,
                 const bool             take_guess)
    {
      return solve(system, U, settings, take_guess, false);
    }

    NewtonResult
    newton_solve_from_factorization(NonlinearSystem &system, Vector<double> &U, const NewtonSettings &settings)
    {
      NewtonSettings chord      = settings;
      chord.reuse_factorization = true;
      return solve(system, U, chord, false, true);
    }
  } // namespace solvers
} // namespace cosmo
