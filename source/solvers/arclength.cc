#include <cosmo/io/parameters.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/io/fault_injection.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/chord_newton.h>
#include <cosmo/solvers/critical_estimate.h>
#include <cosmo/solvers/critical_point.h>
#include <cosmo/solvers/step_control.h>

#include <algorithm>
#include <functional>
#include <map>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <iostream>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace solvers
  {
    void
    report_located_event(BifurcationProblem &              problem,
                         const BifurcationProblem::Event &e,
                         const Vector<double> &            U,
                         const Vector<double> *            mode)
    {
      problem.located_event(e, U, mode);
      io::PostprocessedState s;
      s.kind       = io::PostprocessedState::Kind::located_event;
      s.branch     = e.branch;
      s.t          = e.lambda;
      s.n_negative = e.n_negative_after;
      s.event      = e.name();
      s.unknowns   = &U;
      s.mode       = mode;
      problem.postprocess(s);
    }

    namespace
    {
      /// The report of a branch's last converged state s (step `step`).
      template <typename State>
      StepReport
      branch_end_report(const State &s, const unsigned int step, const unsigned int branch)
      {
        StepReport last;
        last.step       = step;
        last.t          = s.lambda;
        last.branch     = branch;
        last.n_negative = s.n_negative;
        return last;
      }
    } // namespace

    int
    BifurcationProblem::load_derivative(const Vector<double> &U,
                                        const double          lambda,
                                        Vector<double> &      dR_dlambda)
    {
      const double   h = 1e-6 * (1 + std::abs(lambda));
      Vector<double> Rp(U.size()), Rm(U.size());
      set_load_parameter(lambda + h);
      int status = residual(U, Rp);
      set_load_parameter(lambda - h);
      status += residual(U, Rm);
      set_load_parameter(lambda);
      dR_dlambda = Rp;
      dR_dlambda -= Rm;
      dR_dlambda /= 2 * h;
      return status;
    }

    std::string
    path_summary(const std::vector<PathRow> &                     rows,
                 const std::vector<BifurcationProblem::Event> &   events,
                 const std::function<std::string(unsigned int)> & extra)
    {
      std::map<unsigned int, std::vector<const PathRow *>> by_branch;
      for (const auto &r : rows)
        by_branch[r.branch].push_back(&r);
      std::ostringstream o;
      o << "Summary: " << by_branch.size() << " branch" << (by_branch.size() == 1 ? "" : "es") << ", "
        << rows.size() << " states, " << events.size() << " event" << (events.size() == 1 ? "" : "s")
        << "\n  branch  states  t from .. to                stable states (max. negative eigenvalues)\n";
      for (const auto &[b, list] : by_branch)
        {
          unsigned int stable = 0, known = 0;
          int          most   = 0;
          for (const PathRow *r : list)
            if (r->n_negative >= 0)
              {
                ++known;
                stable += r->n_negative == 0;
                most = std::max(most, r->n_negative);
              }
          std::ostringstream range;
          range << std::setprecision(6) << list.front()->t << " .. " << list.back()->t;
          o << "  " << std::setw(6) << b << "  " << std::setw(6) << list.size() << "  " << std::left
            << std::setw(26) << range.str() << std::right << "  ";
          if (known == 0)
            o << "(not computed)";
          else
            o << stable << " of " << known << " (" << most << ")";
          o << "\n";
        }
      for (unsigned int k = 0; k < events.size(); ++k)
        {
          const auto &e = events[k];
          o << "  event " << k + 1 << ": " << e.name() << " at t = " << std::setprecision(10) << e.lambda
            << " on branch " << e.branch << ", negative eigenvalues " << e.n_negative_before << " -> "
            << e.n_negative_after;
          if (extra)
            o << extra(k);
          o << "\n";
        }
      std::string text = o.str();
      if (!text.empty() && text.back() == '\n')
        text.pop_back();
      return text;
    }

    double
    path_fraction(const StepReport &report, const ArclengthSettings &arclength)
    {
      if (!arclength.enabled)
        return report.t;
      if (report.branch == 0 && arclength.lambda_max > 0 && arclength.lambda_max < 1e300)
        return report.t / arclength.lambda_max;
      return std::numeric_limits<double>::quiet_NaN();
    }

    double
    BifurcationProblem::unknowns_scale(const Vector<double> &U) const
    {
      Vector<double> mask;
      mode_mask(mask);
      return std::max(1., masked_max(U, mask));
    }

    void
    BifurcationProblem::mode_mask(Vector<double> &mask) const
    {
      mask.reinit(n_unknowns());
      mask = 1.;
    }

    void
    BifurcationProblem::stability_mask(Vector<double> &mask) const
    {
      mode_mask(mask);
    }

    double
    event_resolution(const BifurcationProblem::Event &e)
    {
      return std::max(e.precision, e.resolution);
    }

    int
    other_negative_modes(const BifurcationProblem::Event &e)
    {
      return e.n_negative_after - (e.eigenvalue < 0 ? 1 : 0);
    }

    namespace
    {
      /// Round-off leaves fewer than three digits of the located lambda.
      bool
      poorly_resolved(const BifurcationProblem::Event &e)
      {
        return e.resolution > 1e-3 * std::abs(e.lambda);
      }
      const char *const poorly_resolved_text =
        "the round-off resolution exceeds 1e-3 of lambda: fewer than three digits are "
        "significant (a badly conditioned Hessian, e.g. a very thin plate on a fine mesh: "
        "doc/theory-plate-rod.md section 9)";
    } // namespace

    void
    add_location_to_json(const BifurcationProblem::Event &e, io::JSON &event)
    {
      io::JSON x    = io::JSON::object();
      x["method"]   = e.located_by_newton ? "newton (minimally augmented system)" :
                                            "bisection of the stability count";
      x["factorizations"] = e.factorizations;
      x["last_update"]    = e.precision;
      x["resolution"]     = event_resolution(e);
      x["bracket"]        = io::JSON::array({e.lambda_lo, e.lambda_hi});
      x["multiplicity"]   = e.multiplicity;
      if (e.located_by_newton)
        {
          x["newton_iterations"] = e.newton_iterations;
          x["residual"]          = e.residual_norm;
          x["test_function"]     = e.test_function;
          x["unfolding"]         = e.unfolding;
        }
      else
        x["arclength_interval"] = e.arclength;
      if (!e.message.empty())
        x["message"] = e.message;
      if (e.located_by_newton && poorly_resolved(e))
        x["warning"] = poorly_resolved_text;
      event["location"] = x;
    }

    void
    ArclengthSettings::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Path following");
      prm.declare_entry("Method", "natural parameter",
                        Patterns::Selection("natural parameter|arclength"),
                        "natural parameter: the load parameter t goes from 0 to 1 "
                        "(section Continuation); arclength: pseudo-arclength continuation "
                        "in t with the stability count at every step, location of folds and "
                        "branch points, and branch switching (section Arclength "
                        "continuation; set its Parameter range, e.g. 0, 1).");
      prm.leave_subsection();
      prm.enter_subsection("Arclength continuation");
      prm.declare_entry("Initial step", "0.05", Patterns::Double(1e-14),
                        "First arclength step (ds^2 = theta |dU|^2 + dlambda^2).");
      prm.declare_entry("Minimum step", "1e-8", Patterns::Double(1e-16),
                        "A branch ends (with a message) when its step falls below this.");
      prm.declare_entry("Maximum step", "0.2", Patterns::Double(1e-14),
                        "Largest arclength step.");
      prm.declare_entry("Maximum number of steps", "200", Patterns::Integer(1),
                        "Steps per branch.");
      prm.declare_entry("Easy step iterations", "4", Patterns::Integer(1),
                        "A step converging in at most this many Newton iterations lets "
                        "the next one grow by 'Step growth factor'.");
      prm.declare_entry("Step growth factor", "1.5", Patterns::Double(1, 10),
                        "Growth of the step after an easy one.");
      prm.declare_entry("Parameter range", "-1e300, 1e300", Patterns::List(Patterns::Double(), 2, 2),
                        "A branch ends when its parameter lambda leaves [min, max].");
      prm.declare_entry("Initial direction", "increasing",
                        Patterns::Selection("increasing|decreasing"),
                        "Whether the first branch starts with lambda increasing or decreasing.");
      prm.declare_entry("Field weight", "0", Patterns::Double(0),
                        "theta in ds^2 = theta |dU|^2 + dlambda^2; 0: 1/(number of mode "
                        "unknowns), i.e. the mean square of the field.");
      prm.declare_entry("Event location", "newton", Patterns::Selection("newton|bisection"),
                        "A change of the stability count detects a fold or branch point. "
                        "newton: locate it by Newton on the minimally augmented system "
                        "(R = 0 and the bordered test function g = 0; branch points with an "
                        "unfolding parameter), to round-off, with ~3-5 factorizations; "
                        "bisection: bisect the count in the arclength to 'Event tolerance' "
                        "(~30 factorizations, resolution limited by the sign of the crossing "
                        "pivot). Newton falls back to bisection where it fails, and says so.");
      prm.declare_entry("Event tolerance", "1e-8", Patterns::Double(1e-15),
                        "Bisection (Event location = bisection, or the fallback) stops when "
                        "the arclength interval is below this.");
      prm.declare_entry("Switch branches", "true", Patterns::Bool(),
                        "At a simple branch point on the first branch, switch to the "
                        "bifurcated branch and follow it.");
      prm.declare_entry("Both directions", "true", Patterns::Bool(),
                        "Follow the bifurcated branch on both sides (+phi and -phi).");
      prm.declare_entry("Switch amplitude", "1e-2", Patterns::Double(1e-14),
                        "Distance a (in the arclength norm) of the first point of a new "
                        "branch from the branch point, along the mode.");
      prm.declare_entry("Maximum number of branches", "4", Patterns::Integer(1, 100),
                        "Branches followed in all, the first included.");
      prm.declare_entry("Maximum branch depth", "1", Patterns::Integer(0, 100),
                        "Switch at simple branch points on branches of depth below this: "
                        "0 no switching, 1 on the first branch only, 2 also on the branches "
                        "switched to from it (secondary bifurcations), and so on. The branches "
                        "switched to from a branch are followed right after it, up to "
                        "'Maximum number of branches' in all.");
      prm.declare_entry("Follow mirror images", "false", Patterns::Bool(),
                        "At a branch point where the branches along +phi and -phi start at the "
                        "same lambda (to 1e-6 of their distance from the branch point: the "
                        "two halves of a symmetric pitchfork, images of each other under the "
                        "problem's symmetry), follow only +phi and say so; true follows both.");
      prm.declare_entry("Stop at first event", "false", Patterns::Bool(),
                        "End the run at the first located fold or branch point (the "
                        "critical point of the first branch): what a study of critical "
                        "points (section Parameter sweep) needs of each run.");
      prm.declare_entry("First event by estimate", "true", Patterns::Bool(),
                        "With 'Stop at first event': from the stable start, estimate the first "
                        "critical load from one eigenproblem (the Hessian's rate along the "
                        "path, Lanczos with the start's factorization; where its loads "
                        "cluster or its check at its prediction fails, a second-order model "
                        "of the path and the Hessian: doc/theory-continuation.md 10) and "
                        "locate it by Newton on the augmented system from there, instead of "
                        "following the path to it; where that does not converge, from a "
                        "state on the path short of the estimate. The inertia guards it (no "
                        "other negative mode at the located point). Where the location "
                        "fails, the path is followed from the start. false: always follow "
                        "the path.");
      prm.declare_entry("Refine estimate", "false", Patterns::Bool(),
                        "With 'First event by estimate': refine a second-order estimate "
                        "before Newton on the augmented system, with the start's "
                        "factorization alone: Newton on the smallest eigenvalue of the "
                        "Hessian over the start's along the path, the states by GMRES and "
                        "the eigenvalue by Lanczos, both preconditioned with that "
                        "factorization (doc/theory-continuation.md 10). A twisted strip's "
                        "or section's threshold then takes 3 factorizations instead of "
                        "6-12, but 220-500 solves: on the suite's strips and sections "
                        "(381-16383 DoFs), where a factorization costs about 10 solves, "
                        "1.2-2.3 times the time (benchmarks/README.md). For problems whose "
                        "factorization costs over ~100 solves.");
      prm.declare_entry("Reuse factorization", "true", Patterns::Bool(),
                        "The corrector's Newton starts from the factorization of the last "
                        "converged state (made there for its stability count and tangent) "
                        "and keeps it while each step contracts the residual at least "
                        "tenfold (chord steps: one residual and one solve instead of a "
                        "Jacobian and a factorization); a new one is made where a step "
                        "contracts less. The Newton iterations reported count them; 'Easy "
                        "step iterations' counts the factorized ones. The states are those "
                        "of exact Newton to the tolerance. Sections and strips only, on the "
                        "way to the first critical point of the first branch (past it a "
                        "state's factorization may be nearly singular along a mode, and "
                        "chord steps with it can land on another branch); the plate-rod and "
                        "rod applications keep exact Newton. false: a new factorization at "
                        "every iteration, the first at the predictor.");
      prm.leave_subsection();
    }

    void
    ArclengthSettings::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Path following");
      enabled = prm.get("Method") == "arclength";
      prm.leave_subsection();
      prm.enter_subsection("Arclength continuation");
      parse_step_control(prm, *this);
      const auto range = io::get_double_list(prm, "Parameter range", 2, "Arclength continuation");
      lambda_min       = range[0];
      lambda_max       = range[1];
      direction        = prm.get("Initial direction") == "increasing" ? 1. : -1.;
      theta            = prm.get_double("Field weight");
      event_tolerance  = prm.get_double("Event tolerance");
      newton_location  = prm.get("Event location") == "newton";
      switch_branches  = prm.get_bool("Switch branches");
      both_directions  = prm.get_bool("Both directions");
      switch_amplitude = prm.get_double("Switch amplitude");
      maximum_branches = prm.get_integer("Maximum number of branches");
      maximum_depth    = prm.get_integer("Maximum branch depth");
      follow_mirror_images = prm.get_bool("Follow mirror images");
      stop_at_first_event  = prm.get_bool("Stop at first event");
      first_event_by_estimate = prm.get_bool("First event by estimate");
      refine_estimate         = prm.get_bool("Refine estimate");
      reuse_factorization     = prm.get_bool("Reuse factorization");
      if (!(lambda_min < lambda_max))
        throw io::InputError("Arclength continuation", "Parameter range",
                             prm.get("Parameter range"), "min < max");
      if (minimum_step > initial_step || initial_step > maximum_step)
        throw io::InputError("Arclength continuation", "Initial step", prm.get("Initial step"),
                             "between 'Minimum step' and 'Maximum step'");
      prm.leave_subsection();
    }

    namespace
    {
      /**
       * The augmented system [R(U, lambda); theta (m o dU).(U - Up) +
       * dl (lambda - lp)] in the unknowns [U; lambda], solved by bordering
       * with the problem's factorization of J = dR/dU.
       */
      class AugmentedSystem : public NonlinearSystem
      {
      public:
        AugmentedSystem(BifurcationProblem &  problem,
                        const double          theta,
                        const Vector<double> &mask,
                        const Vector<double> &dU,
                        const double          dl,
                        const Vector<double> &Up,
                        const double          lp,
                        unsigned int &        factorizations)
          : problem(problem)
          , factorizations(factorizations)
          , n(problem.n_unknowns())
          , theta(theta)
          , dl(dl)
          , lp(lp)
          , c(dU)
          , Up(Up)
          , b(n)
        {
          c.scale(mask);
          c *= theta;
        }

        unsigned int
        n_unknowns() const override
        {
          return n + 1;
        }

        int
        residual(const Vector<double> &X, Vector<double> &R) override
        {
          // (the predictor's, which newton_solve has just evaluated, is asked
          // for again by the corrector's own Newton step)
          if (last_status == 0 && same_point(X, last_X))
            {
              R = last_R;
              return 0;
            }
          last_status = -1;
          Vector<double> U(X.begin(), X.begin() + n), RU(n);
          problem.set_load_parameter(X[n]);
          const int status = problem.residual(U, RU);
          if (status != 0)
            return status;
          R.reinit(n + 1);
          std::copy(RU.begin(), RU.end(), R.begin());
          double s = 0;
          for (unsigned int i = 0; i < n; ++i)
            s += c[i] * (U[i] - Up[i]);
          R[n] = s + dl * (X[n] - lp);
          last_X      = X;
          last_R      = R;
          last_status = 0;
          return 0;
        }

        /// J^-1 dR/dlambda at the last setup_jacobian().
        const Vector<double> &
        J_inv_R_lambda() const
        {
          return b;
        }

        /// Solve with the problem's factorization in place (of a nearby
        /// state, with J^-1 dR/dlambda there) until the first setup.
        void
        take_factorization_in_place(const Vector<double> &J_inv_R_lambda)
        {
          b = J_inv_R_lambda;
        }

        /// How many factorizations this system made, and where the last was.
        unsigned int   setups = 0;
        Vector<double> setup_X;
        bool           setup_ok = false;

        int
        setup_jacobian(const Vector<double> &X) override
        {
          // Set up already at this point (the corrector's first, at the
          // predictor): the problem's factorization is still that one.
          if (setups > 0 && setup_ok && same_point(X, setup_X))
            return 0;
          ++setups;
          setup_X  = X;
          setup_ok = false;
          Vector<double> U(X.begin(), X.begin() + n), Rl(n);
          problem.set_load_parameter(X[n]);
          if (problem.load_derivative(U, X[n], Rl) != 0)
            return 1;
          ++factorizations;
          if (problem.setup_jacobian(U) != 0)
            return 1;
          // b = J^-1 dR/dlambda
          setup_ok = problem.solve_with_jacobian(Rl, b) == 0;
          return setup_ok ? 0 : 1;
        }

        int
        solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) override
        {
          Vector<double> r(rhs.begin(), rhs.begin() + n), a(n);
          if (problem.solve_with_jacobian(r, a) != 0)
            return 1;
          const double denominator = dl - (c * b);
          if (denominator == 0)
            return 1;
          const double x_lambda = (rhs[n] - (c * a)) / denominator;
          dst.reinit(n + 1);
          for (unsigned int i = 0; i < n; ++i)
            dst[i] = a[i] - b[i] * x_lambda;
          dst[n] = x_lambda;
          return 0;
        }

        /// The bordering solves its matrix exactly when the problem's solves
        /// are exact: J p is then the right-hand side for the linear model
        /// KINSOL's line search measures (dR/dlambda in it is a central
        /// difference, 1e-12 relative, the same in both).
        bool
        solves_exactly() const override
        {
          return problem.solves_exactly();
        }

        void
        residual_weights(Vector<double> &w) const override
        {
          Vector<double> wU;
          problem.residual_weights(wU);
          w.reinit(n + 1);
          std::copy(wU.begin(), wU.end(), w.begin());
          w[n] = 1;
        }

      private:
        BifurcationProblem &problem;
        unsigned int &      factorizations;
        const unsigned int  n;
        const double        theta, dl, lp;
        Vector<double>      c;  // theta (mask o dU)
        const Vector<double> Up;
        Vector<double>      b;
        Vector<double>      last_X, last_R;
        int                 last_status = -1;
      };
    } // namespace

    namespace
    {
      /**
       * Power iteration on P (J^-1 - shift I) on the mode unknowns, with the
       * problem's current factorization: P masks, projects onto the fixed-point
       * space (if project is given) and deflates the vectors orthogonal_to.
       * From a fixed, generic start (seed chooses one of two), until the
       * iterate moves by less than tolerance. mode: the unit iterate; returns
       * 1/rho with rho the last Rayleigh quotient of P J^-1 (0 if none), i.e.
       * with shift 0 the eigenvalue of J nearest zero (inverse iteration).
       */
      double
      power_iteration(BifurcationProblem &                          problem,
                      const Vector<double> &                        mask,
                      const double                                  shift,
                      const unsigned int                            max_iterations,
                      const double                                  tolerance,
                      const std::vector<Vector<double>> &           orthogonal_to,
                      Vector<double> &                              mode,
                      const unsigned int                            seed    = 0,
                      const std::function<void(Vector<double> &)> &project = {},
                      const Vector<double> *start_orthogonal_to           = nullptr)
      {
        const unsigned int n = problem.n_unknowns();
        auto dot = [&](const Vector<double> &a, const Vector<double> &b) { return masked_dot(a, b, mask); };
        auto restrict = [&](Vector<double> &y) {
          y.scale(mask);
          if (project)
            project(y);
          for (const auto &q : orthogonal_to)
            y.add(-dot(y, q) / dot(q, q), q);
        };
        Vector<double> x(n);
        for (unsigned int i = 0; i < n; ++i)
          x[i] = seed == 0 ? 1 + 0.1 * std::sin(1.3 * i + 0.7) : 1 + 0.3 * std::cos(0.7 * i + 0.2);
        restrict(x);
        if (start_orthogonal_to)
          x.add(-dot(x, *start_orthogonal_to) / dot(*start_orthogonal_to, *start_orthogonal_to),
                *start_orthogonal_to);
        x /= std::sqrt(dot(x, x));
        double rho = 0;
        for (unsigned int it = 0; it < max_iterations; ++it)
          {
            Vector<double> y(n);
            problem.solve_with_jacobian(x, y);
            restrict(y);
            rho = dot(x, y);
            y.add(-shift, x);
            y /= std::sqrt(dot(y, y));
            if (dot(y, x) < 0)
              y *= -1.;
            Vector<double> d = y;
            d -= x;
            x = y;
            if (std::sqrt(dot(d, d)) < tolerance)
              break;
          }
        mode = x;
        return rho != 0 ? 1. / rho : 0.;
      }
    } // namespace

    double
    smallest_eigenvalue(BifurcationProblem &               problem,
                        const Vector<double> &             mask,
                        Vector<double> &                   phi,
                        const unsigned int                 max_iterations,
                        const std::vector<Vector<double>> &orthogonal_to,
                        const double                       tolerance)
    {
      return power_iteration(problem, mask, 0., max_iterations, tolerance, orthogonal_to, phi);
    }

    namespace
    {
      /// An event located by Newton: its load, state and the iteration's figures.
      void
      take_location(const CriticalPoint &cp, EventRecord &record)
      {
        auto &e             = record.event;
        e.located_by_newton = true;
        e.lambda            = cp.lambda;
        e.newton_iterations = cp.iterations;
        e.residual_norm     = cp.residual_norm;
        e.test_function     = cp.test_function;
        e.unfolding         = cp.unfolding;
        e.eigenvalue        = cp.eigenvalue;
        e.precision         = cp.lambda_update;
        e.resolution        = cp.resolution;
        e.message.clear();
        record.state.assign(cp.U.begin(), cp.U.end());
      }

      /**
       * The mode of the eigenvalue of J nearest zero with the given sign:
       * inverse iteration; if that finds an eigenvalue mu0 of the other sign
       * (a cluster of soft modes nearer zero than the crossing one), power
       * iteration on J^-1 - (1/mu0) I, whose dominant eigenvalue is 1/mu - 1/mu0
       * of the wanted sign's eigenvalue nearest zero: every eigenvalue of the
       * other sign maps into (-|1/mu0|, 0] or [0, |1/mu0|), the wanted ones
       * beyond |1/mu0|. Returns the eigenvalue (0 if none of that sign found).
       */
      double
      crossing_mode(BifurcationProblem &                          problem,
                    const Vector<double> &                        mask,
                    const double                                  wanted_sign,
                    const std::vector<Vector<double>> &           orthogonal_to,
                    Vector<double> &                              phi,
                    const std::function<void(Vector<double> &)> &project = {})
      {
        const double mu0 =
          power_iteration(problem, mask, 0., 30, 1e-8, orthogonal_to, phi, 0, project);
        if (mu0 * wanted_sign >= 0 || mu0 == 0)
          return mu0;
        // (the start orthogonal to the mode found; the iterates are not:
        // that mode is the one the shift maps below the wanted ones)
        Vector<double> x1;
        const double   mu =
          power_iteration(problem, mask, 1. / mu0, 300, 1e-8, orthogonal_to, x1, 1, project,
                          &phi);
        phi = x1;
        return mu * wanted_sign > 0 ? mu : 0.;
      }
    } // namespace

    void
    EventRecord::save(io::CheckpointWriter &w) const
    {
      const auto &e = event;
      w.put(e.kind == BifurcationProblem::Event::Kind::fold);
      for (const double x : {e.lambda, e.arclength, e.eigenvalue, e.residual_norm, e.test_function,
                             e.unfolding, e.precision, e.resolution, e.lambda_lo, e.lambda_hi})
        w.put(x);
      for (const unsigned int x : {e.branch, e.newton_iterations, e.factorizations, e.multiplicity})
        w.put(x);
      w.put(e.n_negative_before);
      w.put(e.n_negative_after);
      w.put(e.located_by_newton);
      w.put(e.message);
      w.put_vector(state);
      w.put_vector(mode);
    }

    void
    EventRecord::load(io::CheckpointReader &r)
    {
      auto &e = event;
      e.kind  = r.get_bool() ? BifurcationProblem::Event::Kind::fold :
                               BifurcationProblem::Event::Kind::branch_point;
      for (double *x : {&e.lambda, &e.arclength, &e.eigenvalue, &e.residual_norm, &e.test_function,
                        &e.unfolding, &e.precision, &e.resolution, &e.lambda_lo, &e.lambda_hi})
        *x = r.get_double();
      for (unsigned int *x : {&e.branch, &e.newton_iterations, &e.factorizations, &e.multiplicity})
        *x = r.get_unsigned();
      e.n_negative_before = r.get_int();
      e.n_negative_after  = r.get_int();
      e.located_by_newton = r.get_bool();
      e.message           = r.get_string();
      state               = r.get_vector();
      mode                = r.get_vector();
    }

    namespace
    {
      template <typename State>
      void
      save_state(io::CheckpointWriter &w, const State &s)
      {
        w.put_vector(s.U);
        w.put(s.lambda);
        w.put_vector(s.tU);
        w.put(s.tlambda);
        w.put(s.n_negative);
        w.put(s.depth);
        w.put(s.branch);
        w.put(s.sign);
      }

      template <typename State>
      void
      load_state(io::CheckpointReader &r, State &s)
      {
        r.get_vector(s.U);
        s.lambda = r.get_double();
        r.get_vector(s.tU);
        s.tlambda    = r.get_double();
        s.n_negative = r.get_int();
        s.depth      = r.get_unsigned();
        s.branch     = r.get_unsigned();
        s.sign       = r.get_double();
      }
    } // namespace

    void
    ArclengthContinuation::save(io::CheckpointWriter &w) const
    {
      w.put(std::uint64_t(at.events.size()));
      for (const auto &e : at.events)
        e.save(w);
      w.put(std::uint64_t(at.switches.size()));
      for (const auto &s : at.switches)
        save_state(w, s);
      w.put(std::uint64_t(at.plus_lambda.size()));
      for (const auto &[key, l] : at.plus_lambda)
        {
          w.put(key.first);
          w.put(key.second);
          w.put(l);
        }
      w.put(at.step);
      w.put(at.branch);
      w.put(std::uint64_t(at.q));
      w.put(std::uint64_t(at.queued));
      w.put(at.may_switch);
      save_state(w, at.s);
      w.put(at.ds);
      w.put(at.k);
      w.put(at.chord_from_state);
      w.put(factorizations);
      w.put(incomplete);
    }

    void
    ArclengthContinuation::load(io::CheckpointReader &r)
    {
      at = Progress();
      at.events.resize(r.get_size());
      for (auto &e : at.events)
        e.load(r);
      at.switches.resize(r.get_size());
      for (auto &s : at.switches)
        load_state(r, s);
      const std::uint64_t n = r.get_size();
      for (std::uint64_t i = 0; i < n; ++i)
        {
          const unsigned int b = r.get_unsigned();
          const double       l = r.get_double();
          at.plus_lambda[std::make_pair(b, l)] = r.get_double();
        }
      at.step       = r.get_unsigned();
      at.branch     = r.get_unsigned();
      at.q          = static_cast<std::size_t>(r.get_size());
      at.queued     = static_cast<std::size_t>(r.get_size());
      at.may_switch = r.get_bool();
      load_state(r, at.s);
      at.ds          = r.get_double();
      at.k           = r.get_unsigned();
      at.chord_from_state = r.get_bool();
      factorizations = r.get_unsigned();
      incomplete     = r.get_strings();
      resume         = true;
    }

    ArclengthContinuation::ArclengthContinuation(const ArclengthSettings &settings,
                                                 const NewtonSettings &   newton)
      : settings(settings)
      , newton(newton)
    {}

    void
    ArclengthContinuation::say(const std::string &s) const
    {
      if (progress)
        progress(s);
    }

    double
    ArclengthContinuation::dot(const Vector<double> &a, const Vector<double> &b) const
    {
      return theta * masked_dot(a, b, mask);
    }

    double
    ArclengthContinuation::norm2(const Vector<double> &v) const
    {
      return dot(v, v);
    }

    NewtonResult
    ArclengthContinuation::correct(BifurcationProblem &  problem,
                                   State &               s,
                                   const Vector<double> &direction_U,
                                   const double          direction_lambda,
                                   const Vector<double> &predictor_U,
                                   const double          predictor_lambda,
                                   const bool            from_state_factorization)
    {
      const unsigned int n = problem.n_unknowns();
      AugmentedSystem    system(problem, theta, mask, direction_U, direction_lambda, predictor_U,
                             predictor_lambda, factorizations);
      Vector<double> X(n + 1);
      std::copy(predictor_U.begin(), predictor_U.end(), X.begin());
      X[n] = predictor_lambda;
      // A predictor that passes the stopping test (the plate's flat branch:
      // the tangent is exact there to ~1e-10 of the step) costs no Newton
      // factorization: the corrector makes one Newton step from it with the
      // factorization at the predictor, which the analysis of the state
      // needs anyway and keeps (its count and tangent). The step makes the
      // state as exact as Newton's last step makes any (the tolerance alone
      // did not: a thin plate's dome 0.4 % off). One factorization per such
      // step instead of two (doc/theory-continuation.md 1).
      static const bool take_guess = std::getenv("COSMO_NO_PREDICTOR_STEP") == nullptr;
      at_predictor.valid = false;
      const Vector<double> X_predictor = X;
      // The analysis keeps the predictor's factorization only when the
      // step was small against the scale of the unknowns (sqrt(eps): the
      // Jacobian then differs from the state's by ~1e-8 relative, like
      // the difference steps elsewhere; on the flat branch the step is
      // 6e-11 to 1.4e-9 of it). A residual below the tolerance does not
      // bound the step where J is nearly singular (a small-amplitude
      // branch start, say): there the state is analysed afresh.
      auto keep_predictor_factorization = [&](const Vector<double> &X1) {
        Vector<double> dU(n), U1(X1.begin(), X1.begin() + n);
        for (unsigned int i = 0; i < n; ++i)
          dU[i] = X1[i] - X_predictor[i];
        const double near = std::sqrt(std::numeric_limits<double>::epsilon());
        if (masked_max(dU, mask) <= near * problem.unknowns_scale(U1) &&
            std::abs(X1[n] - X_predictor[n]) <= near * (1 + std::abs(X1[n])))
          {
            at_predictor.U              = U1;
            at_predictor.lambda         = X1[n];
            at_predictor.J_inv_R_lambda = system.J_inv_R_lambda();
            at_predictor.valid          = true;
          }
      };
      // The Jacobian at the predictor first: every path below sets it up
      // (Newton's first iteration, or the step from an accepted guess), and
      // a problem that keeps the residual its Jacobian's assembly computed
      // (the rod, the plate) then answers the guess's test without a
      // residual assembly of its own: one assembly per step saved. A
      // failure here is left to Newton's own first setup, as before.
      // From the last state's factorization (from_state_factorization, at
      // s, which the predictor left by the step ds): chord steps on it
      // while each contracts tenfold, a new factorization where not. On
      // the strip's path to its threshold one or two per state (with
      // analyse's) instead of three (doc/theory-continuation.md 1).
      // (a predictor that passes the stopping test takes the step below:
      // as exact as Newton's last, with the factorization the analysis keeps)
      bool predictor_passes = false;
      if (from_state_factorization && take_guess)
        {
          Vector<double> R0(n + 1);
          predictor_passes =
            system.residual(X, R0) == 0 && scaled_residual_norm(system, R0) <= newton.relative_tolerance;
        }
      if (from_state_factorization && !predictor_passes)
        {
          system.take_factorization_in_place(at_state.J_inv_R_lambda);
          NewtonResult r = newton_solve_from_factorization(system, X, newton);
          if (r.iterations > 0 && system.setups == 1 && same_point(system.setup_X, X_predictor))
            keep_predictor_factorization(X);
          s.U.reinit(n);
          std::copy(X.begin(), X.begin() + n, s.U.begin());
          s.lambda = X[n];
          problem.set_load_parameter(s.lambda);
          return r;
        }
      if (take_guess)
        system.setup_jacobian(X);
      NewtonResult r = newton_solve(system, X, newton, take_guess);
      // Newton from the predictor converged on the factorization made there
      // (its only one: one iteration, where round-off kept the predictor
      // above the tolerance, e.g. the rod's stiff extension, EA/h = 1e7):
      // kept as the state's if the step was small.
      if (r.iterations > 0 && take_guess && system.setups == 1 && same_point(system.setup_X, X_predictor))
        keep_predictor_factorization(X);
      if (r.iterations == 0 && take_guess)
        {
          Vector<double> R(n + 1), d(n + 1);
          if (system.setup_jacobian(X) != 0 || system.residual(X, R) != 0 ||
              system.solve_with_jacobian(R, d) != 0)
            throw NewtonFailure("the Jacobian cannot be set up at the predictor");
          Vector<double> X1 = X;
          X1 -= d;
          bool converged = false;
          if (system.residual(X1, R) == 0)
            {
              const double norm = scaled_residual_norm(system, R);
              if (std::isfinite(norm) && norm <= newton.relative_tolerance)
                {
                  converged       = true;
                  X               = X1;
                  r.iterations    = 1;
                  r.residual_norm = norm;
                }
            }
          if (converged)
            keep_predictor_factorization(X1);
          if (!converged) // (not seen: Newton from the predictor as before)
            r = newton_solve(system, X, newton);
        }
      s.U.reinit(n);
      std::copy(X.begin(), X.begin() + n, s.U.begin());
      s.lambda = X[n];
      problem.set_load_parameter(s.lambda);
      return r;
    }

    void
    ArclengthContinuation::analyse(BifurcationProblem &  problem,
                                   State &               s,
                                   const Vector<double> *oU,
                                   const double          ol)
    {
      const unsigned int n = problem.n_unknowns();
      problem.set_load_parameter(s.lambda);
      Vector<double> z(n);
      s.factorized_at_predictor =
        at_predictor.valid && at_predictor.lambda == s.lambda && same_point(s.U, at_predictor.U);
      at_predictor.valid = false;
      at_state.valid = false;
      if (s.factorized_at_predictor)
        {
          // The count and J^-1 R_lambda of the predictor, one Newton step
          // (below sqrt(eps) of the unknowns' scale) away (correct()).
          s.n_negative = problem.n_negative_eigenvalues();
          z            = at_predictor.J_inv_R_lambda;
        }
      else
        {
          factorize_state(problem, s);
          s.n_negative = problem.n_negative_eigenvalues();
          z            = at_state.J_inv_R_lambda;
        }
      z *= -1.;
      const double tl = 1. / std::sqrt(1. + norm2(z));
      s.tU            = z;
      s.tU *= tl;
      s.tlambda = tl;
      const double orientation = oU ? dot(s.tU, *oU) + s.tlambda * ol : s.tlambda * ol;
      if (orientation < 0)
        {
          s.tU *= -1.;
          s.tlambda *= -1.;
        }
    }

    void
    ArclengthContinuation::factorize_state(BifurcationProblem &problem, const State &s)
    {
      const unsigned int n = problem.n_unknowns();
      Vector<double>     Rl(n), z(n);
      problem.set_load_parameter(s.lambda);
      ++factorizations;
      at_state.valid = false;
      if (problem.load_derivative(s.U, s.lambda, Rl) != 0 || problem.setup_jacobian(s.U) != 0)
        throw NewtonFailure("the Jacobian cannot be set up at a converged state");
      if (problem.solve_with_jacobian(Rl, z) != 0) // z = J^-1 R_lambda; tangent (-z, 1)
        throw NewtonFailure("the tangent solve failed at a converged state");
      at_state.U              = s.U;
      at_state.J_inv_R_lambda = z;
      at_state.factorizations = factorizations;
      at_state.valid          = true;
    }

    bool
    ArclengthContinuation::reuse_factorization(const BifurcationProblem &problem) const
    {
      return settings.reuse_factorization && problem.chord_steps_on_path();
    }

    bool
    ArclengthContinuation::StateFactorization::of(const State &s, const unsigned int count) const
    {
      return valid && factorizations == count && same_point(U, s.U);
    }

    bool
    ArclengthContinuation::point_on_step(BifurcationProblem &problem,
                                         const State &       s,
                                         const double        sigma_lo,
                                         const double        sigma_hi,
                                         State &             mid,
                                         double &            sigma)
    {
      // The midpoint, or next to it if the Jacobian is exactly singular
      // there (a dyadic midpoint can hit the event).
      for (const double fraction : {0.5, 0.49, 0.51})
        {
          sigma             = sigma_lo + fraction * (sigma_hi - sigma_lo);
          Vector<double> Um = s.U;
          Um.add(sigma, s.tU);
          try
            {
              correct(problem, mid, s.tU, s.tlambda, Um, s.lambda + sigma * s.tlambda);
              analyse(problem, mid, &s.tU, s.tlambda);
              return true;
            }
          catch (NewtonFailure &failure)
            {
              say(std::string("  event location: the corrector failed inside the step (") +
                  failure.what() + ")");
            }
        }
      return false;
    }

    namespace
    {
      /// Which end of the detection bracket the problem's factorization belongs to.
      enum class Factorized
      {
        lo,
        hi,
        none
      };

      /**
       * The crossings of the stability count on one step, from s to next (a
       * step of length ds along s's tangent), located one after the other
       * (ArclengthContinuation::locate_events): the bracket of the crossing
       * at hand and what the pieces of its location share. The driver's
       * private members come in as references, its private functions as
       * callables (say, its arclength dot product, point_on_step along s).
       */
      template <typename State>
      struct StepCrossings
      {
        using Kind = BifurcationProblem::Event::Kind;
        /// The driver's say(), dot() and point_on_step(problem, s, ...).
        using Say         = std::function<void(const std::string &)>;
        using Dot         = std::function<double(const Vector<double> &, const Vector<double> &)>;
        using PointOnStep = std::function<bool(double, double, State &, double &)>;

        StepCrossings(BifurcationProblem &     problem,
                      const State &            s,
                      const double             ds,
                      const State &            next,
                      const unsigned int       branch,
                      const ArclengthSettings &settings,
                      const double             newton_tolerance,
                      const Vector<double> &   mask,
                      unsigned int &           factorizations,
                      Say                      say,
                      Dot                      dot,
                      PointOnStep              point_on_step)
          : problem(problem)
          , s(s)
          , ds(ds)
          , next(next)
          , branch(branch)
          , settings(settings)
          , newton_tolerance(newton_tolerance)
          , mask(mask)
          , factorizations(factorizations)
          , say(std::move(say))
          , dot(std::move(dot))
          , point_on_step(std::move(point_on_step))
          , from(s)
        {}

        /// Whether the count changes between the last event located (or s) and next.
        bool
        count_changes() const
        {
          return s.n_negative >= 0 && next.n_negative >= 0 && next.n_negative != from.n_negative;
        }

        /// Halve the bracket by the count at a point inside it
        /// (bisection_failed where none converges).
        void
        bisect_once()
        {
          State  mid;
          double sigma = 0;
          if (!point_on_step(sigma_lo, sigma_hi, mid, sigma))
            {
              bisection_failed = true;
              return;
            }
          if (mid.n_negative == lo.n_negative)
            {
              sigma_lo   = sigma;
              lo         = mid;
              factorized = Factorized::lo;
            }
          else
            {
              sigma_hi   = sigma;
              hi         = mid;
              factorized = Factorized::hi;
            }
        }

        /// The bracket from the last event located (or s) to next, narrowed
        /// to the next crossing.
        void
        isolate_crossing()
        {
          sigma_lo = sigma_from;
          sigma_hi = ds;
          lo       = from;
          hi       = next;

          // Isolate one crossing: bisect the count until it changes by one
          // across the bracket (keeping the first crossing).
          bisection_failed = false;
          // A double crossing of a problem with a reflection may be a double
          // eigenvalue (D_n symmetry): it is located in the reflection's
          // fixed-point space, where it is simple, rather than bisected.
          Vector<double> probe(s.U.size());
          has_reflection = problem.project_to_fixed_point_space(probe);
          while (std::abs(hi.n_negative - lo.n_negative) > 1 &&
                 !(has_reflection && std::abs(hi.n_negative - lo.n_negative) == 2) &&
                 sigma_hi - sigma_lo > settings.event_tolerance && !bisection_failed)
            bisect_once();
        }

        /// The event the bracket holds, as detected: its kind, counts and
        /// bracket; and whether it is a double eigenvalue to be located in
        /// the reflection's fixed-point space (project).
        EventRecord
        detected_event()
        {
          EventRecord record;
          auto &      e       = record.event;
          e.kind              = (lo.tlambda * hi.tlambda < 0) ? Kind::fold : Kind::branch_point;
          e.branch            = branch;
          e.n_negative_before = from.n_negative;
          e.n_negative_after  = hi.n_negative;
          e.multiplicity      = std::abs(hi.n_negative - lo.n_negative);
          e.lambda_lo         = lo.lambda;
          e.lambda_hi         = hi.lambda;
          e.arclength         = sigma_hi - sigma_lo;

          symmetric_double = has_reflection && e.multiplicity == 2;
          project          = nullptr;
          if (symmetric_double)
            project = [&problem = problem](Vector<double> &v) {
              problem.project_to_fixed_point_space(v);
            };
          return record;
        }

        /// Locate a simple crossing by Newton on the augmented system, from
        /// the end of the bracket that is factorized. The crossing lies
        /// strictly inside the bracket; a Newton point outside it is another
        /// critical point nearby (two crossings close together): halve the
        /// bracket by the count and try again from its new end.
        void
        locate_by_newton(EventRecord &record, Vector<double> &phi)
        {
          const auto &e = record.event;
          if (settings.newton_location && (e.multiplicity == 1 || symmetric_double))
            for (unsigned int attempt = 0; attempt < 4 && !e.located_by_newton; ++attempt)
              {
                if (attempt > 0)
                  {
                    bisect_once();
                    if (bisection_failed)
                      break;
                  }
                if (!newton_from_factorized_end(record, phi, attempt))
                  break;
              }
        }

        /// One attempt of locate_by_newton(); false if the Jacobian cannot be
        /// set up at the end it starts from.
        bool
        newton_from_factorized_end(EventRecord &      record,
                                   Vector<double> &   phi,
                                   const unsigned int attempt)
        {
          auto &       e     = record.event;
          const State &start = (factorized == Factorized::lo) ? lo : hi;
          problem.set_load_parameter(start.lambda);
          if (factorized == Factorized::none)
            {
              ++factorizations;
              if (problem.setup_jacobian(start.U) != 0)
                {
                  e.message = "the Jacobian cannot be set up at the detection bracket";
                  return false;
                }
            }
          // The border: the mode of the crossing eigenvalue, i.e. the
          // one nearest zero with the sign the crossing gives it at
          // this end (negative past a loss of stability), orthogonal to
          // the modes located earlier in this step.
          const bool     count_rises = hi.n_negative > lo.n_negative;
          const bool     at_hi       = (&start == &hi);
          const double   wanted_sign = (count_rises == at_hi) ? -1. : 1.;
          Vector<double> border;
          // (a double eigenvalue: in the fixed-point space of the
          // reflection, where its symmetric representative is simple)
          crossing_mode(problem, mask, wanted_sign, modes_of_this_step, border, project);
          // Newton stops once the error left is below a tenth of the
          // point's round-off resolution, as a critical curve's points
          // do (doc/theory-continuation.md 7): iterating further only
          // moves t inside its scatter, and costs a factorization each.
          CriticalPointSettings location;
          location.resolution_fraction = 0.1;
          const CriticalPoint cp = locate_critical_point(
            problem, e.kind == Kind::fold, start.U, start.lambda, border, mask, s.tU, s.tlambda,
            true, std::abs(hi.lambda - lo.lambda), newton_tolerance, location, project);
          factorizations += cp.factorizations;
          factorized = Factorized::none;
          take_if_inside_bracket(cp, record, phi, attempt);
          return true;
        }

        /// The point Newton located, taken if it lies in the bracket;
        /// otherwise e.message says why not.
        void
        take_if_inside_bracket(const CriticalPoint &cp,
                               EventRecord &        record,
                               Vector<double> &     phi,
                               const unsigned int   attempt)
        {
          auto &e = record.event;
          // Its arclength along the step's tangent.
          Vector<double> dU = cp.U;
          dU -= s.U;
          const double sigma  = dot(s.tU, dU) + s.tlambda * (cp.lambda - s.lambda);
          const double margin = 1e-6 * (sigma_hi - sigma_lo);
          if (cp.converged && sigma >= sigma_lo - margin && sigma <= sigma_hi + margin)
            {
              take_location(cp, record);
              phi = cp.mode;
            }
          else
            {
              std::ostringstream m;
              if (cp.converged)
                m << std::setprecision(10) << "Newton found the critical point at t = "
                  << cp.lambda << ", outside the detection bracket [" << lo.lambda << ", "
                  << hi.lambda << "]";
              else
                m << "Newton on the augmented system failed: " << cp.message;
              e.message = m.str();
              say("  event location: " + e.message +
                  (attempt + 1 < 4 ? "; halving the bracket" : ""));
            }
        }

        /// Bisection of the count to the event tolerance: lambda in the
        /// middle of the bracket, the state at its lower end.
        void
        locate_by_bisection(EventRecord &record, Vector<double> &phi)
        {
          auto &e = record.event;
          while (sigma_hi - sigma_lo > settings.event_tolerance && !bisection_failed)
            bisect_once();
          e.lambda    = 0.5 * (lo.lambda + hi.lambda);
          e.precision = 0.5 * std::abs(hi.lambda - lo.lambda);
          e.arclength = sigma_hi - sigma_lo;
          record.state.assign(lo.U.begin(), lo.U.end());
          // The mode: inverse iteration with J at the event (nearly
          // singular there), on the mode unknowns only.
          if (e.kind == Kind::branch_point)
            {
              problem.set_load_parameter(lo.lambda);
              ++factorizations;
              AssertThrow(problem.setup_jacobian(lo.U) == 0,
                          ExcMessage("the Jacobian cannot be set up at a located event"));
              e.eigenvalue = smallest_eigenvalue(problem, mask, phi);
            }
        }

        /// The mode completed (and kept, for the crossings later in this
        /// step), a branch point's made unit; the event reported.
        void
        report(EventRecord &record, Vector<double> &phi, const Vector<double> &U_event)
        {
          const auto &e = record.event;
          if (phi.size())
            {
              problem.complete_mode(phi);
              modes_of_this_step.push_back(phi);
            }
          if (e.kind == Kind::branch_point && phi.size())
            {
              phi /= std::sqrt(dot(phi, phi)); // unit in the arclength norm
              record.mode.assign(phi.begin(), phi.end());
            }
          problem.set_load_parameter(e.lambda);
          report_located_event(problem, e, U_event, record.mode.size() ? &phi : nullptr);
        }

        /// At a simple branch point, where switching is allowed: the starts
        /// of the branches along +phi (and -phi), queued.
        void
        queue_switches(const EventRecord &   record,
                       const Vector<double> &phi,
                       const Vector<double> &U_event,
                       const bool            may_switch,
                       std::vector<State> &  switches) const
        {
          const auto &e = record.event;
          if (e.kind == Kind::branch_point && may_switch && phi.size() &&
              (e.multiplicity == 1 || (symmetric_double && e.located_by_newton)))
            for (const double sign : settings.both_directions ? std::vector<double>{1., -1.} :
                                                                std::vector<double>{1.})
              {
                State start;
                start.U      = U_event;
                start.lambda = e.lambda;
                start.tU     = phi;
                start.tU *= sign;
                start.tlambda = 0;
                start.depth   = s.depth + 1;
                start.branch  = branch;
                start.sign    = sign;
                switches.push_back(start);
              }
        }

        /// After an event: false if it was the last crossing of this step
        /// (or the bracket did not shrink); else the next bracket starts
        /// at its upper end.
        bool
        move_past_event()
        {
          if (sigma_hi >= ds || hi.n_negative == next.n_negative || bisection_failed)
            return false;
          sigma_from = sigma_hi;
          from       = hi;
          // (the last factorization is of wherever this event's location
          // ended, not of the next bracket's ends)
          factorized = Factorized::none;
          return true;
        }

        BifurcationProblem &     problem;
        const State &            s;
        const double             ds;
        const State &            next;
        const unsigned int       branch;
        const ArclengthSettings &settings;
        const double             newton_tolerance;
        const Vector<double> &   mask;
        unsigned int &           factorizations;
        const Say                say;
        const Dot                dot;
        const PointOnStep        point_on_step;

        // Which end of the bracket the problem's factorization belongs to:
        // analyse(next) was the last factorization.
        Factorized                  factorized = Factorized::hi;
        double                      sigma_from = 0;
        std::vector<Vector<double>> modes_of_this_step;
        State                       from;

        // The bracket of the crossing at hand.
        double sigma_lo = 0, sigma_hi = 0;
        State  lo, hi;
        bool   bisection_failed = false;
        bool   has_reflection   = false;
        bool   symmetric_double = false;
        std::function<void(Vector<double> &)> project;
      };

      /// The line the log gets about a located event.
      std::string
      event_summary(const BifurcationProblem::Event &e,
                    const unsigned int               branch,
                    const bool                       symmetric_double,
                    const double                     event_tolerance)
      {
        std::ostringstream m;
        m << std::setprecision(12) << "  " << e.name() << " on branch " << branch
          << " at t = " << e.lambda << " (negative eigenvalues " << e.n_negative_before
          << " -> " << e.n_negative_after << "; ";
        if (e.located_by_newton)
          {
            m << "Newton on the augmented system: " << e.newton_iterations
              << " iterations, |d lambda| " << std::setprecision(2) << e.precision;
            if (e.resolution >= 0)
              m << " (round-off resolution " << e.resolution << ")";
            m << ", residual " << e.residual_norm;
            if (poorly_resolved(e))
              m << "; WARNING: " << poorly_resolved_text;
          }
        else
          m << "bisection of the count to arclength " << std::setprecision(3) << e.arclength
            << (e.arclength > 2 * event_tolerance ?
                  ", NOT refined to the tolerance: the corrector failed inside the step" :
                  "");
        m << "; " << e.factorizations << " factorizations)";
        if (e.multiplicity > 1 && symmetric_double && e.located_by_newton)
          m << " -- a double eigenvalue: located and switched onto its symmetric "
               "representative, in the fixed-point space of the problem's reflection";
        else if (e.multiplicity > 1)
          m << " -- a multiple eigenvalue (" << e.multiplicity
            << " cross at once): not switched here; a symmetry-reduced domain makes it simple";
        return m.str();
      }
    } // namespace

    bool
    ArclengthContinuation::locate_events(BifurcationProblem &      problem,
                                         const State &             s,
                                         const double              ds,
                                         const State &             next,
                                         const unsigned int        branch,
                                         const bool                may_switch,
                                         std::vector<EventRecord> &events,
                                         std::vector<State> &      switches)
    {
      StepCrossings<State> crossings(
        problem, s, ds, next, branch, settings, newton.relative_tolerance, mask, factorizations,
        [this](const std::string &m) { say(m); },
        [this](const Vector<double> &a, const Vector<double> &b) { return dot(a, b); },
        [this, &problem, &s](const double sigma_lo, const double sigma_hi, State &mid,
                             double &sigma) {
          return point_on_step(problem, s, sigma_lo, sigma_hi, mid, sigma);
        });
      // Two crossings inside one step are two events: after the first,
      // look again between it and next.
      while (crossings.count_changes())
        {
          const unsigned int factorizations_at_detection = factorizations;
          crossings.isolate_crossing();
          EventRecord    record = crossings.detected_event();
          auto &         e      = record.event;
          Vector<double> phi;

          crossings.locate_by_newton(record, phi);
          if (settings.newton_location && !e.located_by_newton)
            say("  event location: falling back to bisection of the stability count");
          if (!e.located_by_newton)
            crossings.locate_by_bisection(record, phi);
          e.factorizations = factorizations - factorizations_at_detection;
          Vector<double> U_event(record.state.begin(), record.state.end());
          crossings.report(record, phi, U_event);
          say(event_summary(e, branch, crossings.symmetric_double, settings.event_tolerance));

          crossings.queue_switches(record, phi, U_event, may_switch, switches);
          events.push_back(record);
          if (settings.stop_at_first_event)
            return true;
          if (!crossings.move_past_event())
            break; // the last crossing of this step (or the bracket did not shrink)
        }
      return false;
    }

    void
    ArclengthContinuation::follow(BifurcationProblem &      problem,
                                  State                     s,
                                  const unsigned int        branch,
                                  const bool                may_switch,
                                  std::vector<EventRecord> &events,
                                  std::vector<State> &      switches,
                                  unsigned int &            step,
                                  double                    ds,
                                  const unsigned int        k0)
    {
      unsigned int cutbacks = 0;
      // Chord steps on the last state's factorization only on the way to the
      // first critical point of the first branch: near a branch point the
      // factorization of a state a step away is nearly singular along the
      // mode, and chord steps with it can land on the other branch's point
      // of the arclength hyperplane (the seed pod's switched branch fell back
      // onto the symmetric one; doc/theory-continuation.md 1).
      const auto chord_from = [&](const State &x) {
        return reuse_factorization(problem) && branch == 0 && events.empty() && at_state.of(x, factorizations);
      };
      // A point to go on from: the state, the next step length, the steps taken.
      auto save_point = [&](const unsigned int next_k) {
        if (!checkpoint)
          return;
        at.s    = s;
        at.ds   = ds;
        at.k    = next_k;
        at.step = step;
        at.chord_from_state = chord_from(s);
        checkpoint();
      };
      save_point(k0);
      for (unsigned int k = k0; k < settings.maximum_steps; ++k)
        {
          io::check_interrupt(); // between steps: the last converged state is written
          if (s.lambda < settings.lambda_min || s.lambda > settings.lambda_max)
            {
              say("  branch " + std::to_string(branch) + " left the parameter range at t = " +
                  std::to_string(s.lambda));
              return;
            }
          Vector<double> Up = s.U;
          Up.add(ds, s.tU);
          const double lp = s.lambda + ds * s.tlambda;
          State        next;
          next.depth = s.depth;
          NewtonResult r;
          unsigned int analysed_with = 0; // the factorization count after analyse(next)
          try
            {
              r = correct(problem, next, s.tU, s.tlambda, Up, lp, chord_from(s));
              analyse(problem, next, &s.tU, s.tlambda);
              analysed_with = factorizations;
            }
          catch (NewtonFailure &e)
            {
              ++cutbacks;
              ds /= 2;
              std::ostringstream m;
              m << "  branch " << branch << ": step failed (" << e.what() << "); cutting back to "
                << ds;
              say(m.str());
              if (ds < settings.minimum_step)
                {
                  std::ostringstream m;
                  m << "branch " << branch << " ends at t = " << std::setprecision(10)
                    << s.lambda << ", before its target: the step fell below the minimum ("
                    << settings.minimum_step << ") after " << cutbacks << " cut-backs ("
                    << e.what() << ")";
                  say("  " + m.str());
                  // The path did not reach its target: the run fails at the end
                  // (after the other branches), never "converged".
                  incomplete.push_back(m.str());
                  report_path_end(problem, s.U, branch_end_report(s, step, branch));
                  return;
                }
              --k;
              continue;
            }

          if (locate_events(problem, s, ds, next, branch, may_switch, events, switches))
            {
              stopped = true; // the first event, and the run is to stop there
              return;
            }

          s = next;
          ++step;
          StepReport report;
          report.step              = step;
          report.t                 = s.lambda;
          report.step_length       = ds;
          report.newton_iterations = r.iterations;
          report.residual_norm     = r.residual_norm;
          report.cutbacks          = cutbacks;
          report.branch            = branch;
          report.n_negative        = s.n_negative;
          // (an event located since has factorized elsewhere)
          report.factorized_at_predictor =
            s.factorized_at_predictor && factorizations == analysed_with;
          report.final = (k + 1 == settings.maximum_steps || s.lambda < settings.lambda_min ||
                          s.lambda > settings.lambda_max);
          report.toward_first_event = settings.stop_at_first_event;
          problem.set_load_parameter(s.lambda);
          report_converged_step(problem, s.U, report);
          io::inject_fault("step " + std::to_string(step)); // (robustness tests only)
          cutbacks = 0;
          // (the factorized iterations: chord steps cost a residual and a solve)
          if (r.iterations - r.chord_steps <= settings.easy_iterations)
            ds = std::min(settings.maximum_step, ds * settings.growth_factor);
          save_point(k + 1);
        }
    }

    void
    ArclengthContinuation::set_mask_and_weight(BifurcationProblem &problem)
    {
      problem.mode_mask(mask);
      // 'Field weight' 0: 1/(number of mode unknowns), the mean square of the field.
      theta = settings.theta > 0 ? settings.theta : 1. / std::max(1., mask.l1_norm());
    }

    EventRecord
    ArclengthContinuation::locate_from(BifurcationProblem &  problem,
                                       const Vector<double> &U,
                                       const double          lambda,
                                       const bool            fold,
                                       const Vector<double> &mode,
                                       const double          relative_tolerance,
                                       const double          resolution_fraction)
    {
      set_mask_and_weight(problem);
      EventRecord record;
      auto &      e = record.event;
      e.kind = fold ? BifurcationProblem::Event::Kind::fold : BifurcationProblem::Event::Kind::branch_point;
      const Vector<double>  no_tangent(U.size());
      CriticalPointSettings cps;
      cps.lambda_tolerance    = relative_tolerance;
      cps.resolution_fraction = resolution_fraction;
      const CriticalPoint   cp =
        locate_critical_point(problem, fold, U, lambda, mode, mask, no_tangent, 0., false,
                              1e-2 * std::abs(lambda) + 1e-12, newton.relative_tolerance, cps);
      e.factorizations    = cp.factorizations;
      e.n_negative_before = 0;
      e.n_negative_after  = problem.n_negative_eigenvalues();
      e.lambda_lo = e.lambda_hi = lambda;
      if (!cp.converged)
        {
          e.message = "Newton on the augmented system failed: " + cp.message;
          say("  critical point from the guess at t = " + std::to_string(lambda) + ": " +
              e.message);
          return record;
        }
      take_location(cp, record);
      Vector<double> phi = cp.mode;
      problem.complete_mode(phi);
      phi /= std::sqrt(norm2(phi));
      record.mode.assign(phi.begin(), phi.end());
      std::ostringstream m;
      m << std::setprecision(12) << "  " << e.name() << " at t = " << e.lambda
        << " from the guess at t = " << lambda << " (Newton on the augmented system: "
        << e.newton_iterations << " iterations, " << e.factorizations
        << " factorizations, resolution " << std::setprecision(2) << event_resolution(e)
        << ", negative eigenvalues there " << e.n_negative_after << ")";
      say(m.str());
      problem.set_load_parameter(e.lambda);
      report_located_event(problem, e, cp.U, e.kind == BifurcationProblem::Event::Kind::branch_point ? &phi : nullptr);
      return record;
    }

    namespace
    {
      /// A branch's first converged state (the starting point, or the first
      /// point of a switched branch) reported as a step.
      void
      report_first_state(BifurcationProblem &  problem,
                         const Vector<double> &U,
                         const double          t,
                         const NewtonResult &  r,
                         const int             n_negative,
                         const unsigned int    step,
                         const unsigned int    branch,
                         const bool            factorized_at_predictor,
                         const bool            toward_first_event)
      {
        StepReport report;
        report.step                    = step;
        report.t                       = t;
        report.newton_iterations       = r.iterations;
        report.residual_norm           = r.residual_norm;
        report.branch                  = branch;
        report.n_negative              = n_negative;
        report.factorized_at_predictor = factorized_at_predictor;
        report.toward_first_event      = toward_first_event;
        problem.set_load_parameter(t);
        report_converged_step(problem, U, report);
      }

      /**
       * Whether the branch from the switch start (first: its first point)
       * is the mirror image of the one along +phi from the same branch
       * point: then the line saying so, else "". plus_lambda: the first
       * point of the +phi branch of each branch point switched at (by the
       * branch it leaves and its lambda), recorded here, to recognize the
       * -phi branch as its mirror image.
       */
      template <typename State>
      std::string
      mirror_image_message(const State &                                       start,
                           const State &                                       first,
                           std::map<std::pair<unsigned int, double>, double> &plus_lambda,
                           const ArclengthSettings &                           settings)
      {
        const auto key = std::make_pair(start.branch, start.lambda);
        if (start.sign > 0)
          plus_lambda[key] = first.lambda;
        else if (start.sign < 0 && plus_lambda.count(key) && !settings.follow_mirror_images)
          {
            // The halves of a symmetric pitchfork start at the same lambda
            // (lambda - lambda* is even in the amplitude); a generic branch
            // point's differ at first order.
            const double d = std::abs(first.lambda - plus_lambda[key]);
            const double scale = std::max(std::abs(first.lambda - start.lambda),
                                          std::abs(plus_lambda[key] - start.lambda));
            if (d <= 1e-6 * scale + 1e-14 * (1 + std::abs(start.lambda)))
              {
                std::ostringstream m;
                m << std::setprecision(10) << "  the branch along -phi from t = "
                  << start.lambda << " (branch " << start.branch
                  << ") is the mirror image of the one along +phi (their first points agree in "
                     "lambda to "
                  << std::setprecision(2) << d
                  << "): followed once ('Follow mirror images = true' follows both)";
                return m.str();
              }
          }
        return "";
      }

      /**
       * The branches switched to from the branch of switches[q] (queued from
       * switches[queued] on) come next (depth first): a secondary
       * bifurcation is followed before the first branch's later branch
       * points.
       */
      template <typename State>
      void
      queue_depth_first(std::vector<State> &switches, const std::size_t q, const std::size_t queued)
      {
        std::rotate(switches.begin() + q + 1, switches.begin() + queued, switches.end());
      }

      /// Branches that ended before their target (incomplete): the run fails.
      void
      fail_if_incomplete(const std::vector<std::string> &incomplete)
      {
        if (!incomplete.empty())
          {
            // Every branch followed so far has been reported (its steps and
            // events are in the output); the run still did not do what it was
            // asked: it fails (exit 2, "status": "failed").
            std::string m = "the path did not reach its target: " + incomplete[0];
            if (incomplete.size() > 1)
              m += " (and " + std::to_string(incomplete.size() - 1) + " more, in the log)";
            throw io::RunFailure(m);
          }
      }
    } // namespace

    namespace
    {
      /**
       * The linear model's check on itself: v.J v at its prediction (U0 +
       * tau dU, lambda0 + tau) over v.J0 v, v its mode, by central
       * differences of the residual (4 residuals). Zero where the model is
       * exact (the Hessian linear in the load along the path); NaN where a
       * residual cannot be evaluated.
       */
      double
      linear_model_defect(BifurcationProblem &    problem,
                          const Vector<double> &  U0,
                          const double            lambda0,
                          const CriticalEstimate &estimate,
                          const Vector<double> &  mask)
      {
        Vector<double> v = estimate.mode;
        problem.complete_mode(v); // (the unknowns constraints determine: a mode of the constrained problem)
        const double vmax = masked_max(v, mask);
        if (!(vmax > 0))
          return NAN;
        const double eps = 1e-6 * problem.unknowns_scale(U0) / vmax;
        auto         form = [&](const Vector<double> &U, const double lambda) {
          Vector<double> Up = U, Um = U, Rp(U.size()), Rm(U.size());
          Up.add(eps, v);
          Um.add(-eps, v);
          problem.set_load_parameter(lambda);
          if (problem.residual(Up, Rp) != 0 || problem.residual(Um, Rm) != 0)
            return double(NAN);
          Rp -= Rm;
          return masked_dot(v, Rp, mask) / (2 * eps);
        };
        const double at_prediction = form(estimate.U, estimate.lambda), at_start = form(U0, lambda0);
        problem.set_load_parameter(lambda0);
        return at_prediction / at_start;
      }

      /**
       * A second-order estimate refined with the start's factorization
       * alone ('Refine estimate', refine_critical_estimate()), said: Newton
       * on the augmented system then takes two iterations from it, as from
       * the plates' linear estimates.
       */
      void
      refine_and_say(BifurcationProblem &                             problem,
                     const Vector<double> &                           U,
                     const double                                     lambda,
                     const Vector<double> &                           dU,
                     const Vector<double> &                           mask,
                     const std::function<void(const std::string &)> & say,
                     CriticalEstimate &                               estimate)
      {
        const EstimateRefinement r = refine_critical_estimate(problem, U, lambda, dU, mask, estimate);
        std::ostringstream       m;
        m << std::setprecision(10) << "  refined with the start's factorization: ";
        if (r.refined)
          m << "t = " << estimate.lambda;
        else
          m << "not (" << r.message << ")";
        m << " (" << r.evaluations << " states, " << r.newton << " Newton steps with " << r.krylov << " GMRES steps, "
          << r.lanczos << " Lanczos steps, " << r.solves << " solves, " << r.jacobians << " Jacobians)";
        say(m.str());
      }

      /**
       * The first critical point's estimate from (U, lambda) with the tangent
       * dU (critical_estimate.h, doc/theory-continuation.md 10), said:
       * the linear model's, or where that finds none or a cluster (the
       * next critical load estimated less than twice as far as the first:
       * the linear model does not single out the first mode) or fails its
       * check (linear_model_defect() above 5e-3) the second-order model's.
       * Returns whether the second-order model made it; `estimate.found`
       * false, with `why`, where there is none within `lambda_max`.
       */
      bool
      make_estimate(BifurcationProblem &                             problem,
                    const Vector<double> &                           U,
                    const double                                     lambda,
                    const Vector<double> &                           dU,
                    const Vector<double> &                           mask,
                    const double                                     lambda_max,
                    const bool                                       refine,
                    const std::function<void(const std::string &)> & say,
                    CriticalEstimate &                               estimate,
                    std::string &                                    why)
      {
        auto report = [&](const char *model, const char *method) {
          std::ostringstream m;
          m << std::setprecision(10) << "  first critical point estimated at t = " << estimate.lambda << " from t = "
            << lambda << " (" << model << ": " << estimate.steps << ' ' << method << " steps, " << estimate.solves
            << " solves, " << estimate.jacobians << " Jacobians, " << estimate.residuals
            << " residuals; the next at t = " << estimate.next_lambda
            << (estimate.converged ? "" : "; not converged: the guard is the inertia at the located point") << ")";
          say(m.str());
        };
        // (the Lanczos run stops where the separation test below is
        // certain to fail: the twisted strip's 15 steps become 7)
        CriticalEstimateSettings lanczos;
        lanczos.cluster_factor = 2;
        estimate = estimate_first_critical_point(problem, U, lambda, dU, mask, lanczos);
        if (estimate.found)
          report("linear", "Lanczos");
        // The cluster: a twisted strip's or section's modes, which the
        // path's nonlinearity reorders (linear estimates of 0.069 and 0.079
        // for a threshold at 0.608); the plate's flat states separate them
        // 3-7x. A double eigenvalue (a symmetric mode pair) is not one. The
        // strip's Hessian depends on the twist to second order: the
        // second-order model's estimate, 0.757, is 24 % high, close enough
        // for Newton on the augmented system (5 iterations).
        // COSMO_ESTIMATE_FIRST_ORDER: the linear model alone, to measure
        // against (benchmarks/).
        static const bool first_order_only = std::getenv("COSMO_ESTIMATE_FIRST_ORDER") != nullptr;
        const double first = estimate.lambda - lambda, second = estimate.next_lambda - lambda;
        const bool   cluster = estimate.found && !(std::abs(second - first) <= 1e-6 * first) && second < 2 * first;
        // Where the model's own check fails (the Hessian at its prediction
        // along its mode, section 10: zero where it is exact, 1e-4 on the
        // von Karman flat starts), the second-order model too: above 5e-3
        // Newton from the linear estimate took a third iteration (the
        // thickest Cosserat plates, 1.2e-2 and 2.7e-2; the dome with its
        // rim, 9.5e-2, its estimate 10 % low), below it two (up to 3.2e-3).
        const double defect = (estimate.found && !cluster && !first_order_only) ?
                                linear_model_defect(problem, U, lambda, estimate, mask) :
                                0.;
        // (a defect that cannot be evaluated: the model unchecked, as failed)
        const bool curved = !(std::abs(defect) <= 5e-3);
        if (curved)
          {
            std::ostringstream m;
            m << std::setprecision(2) << "  the linear model's defect at its prediction: " << defect
              << " (above 5e-3): the second-order model";
            say(m.str());
          }
        const bool second_order = (cluster || !estimate.found || curved) && !first_order_only;
        const CriticalEstimate linear     = estimate;
        bool                   fell_back = false;
        if (second_order)
          {
            const double range = lambda_max - lambda;
            CriticalEstimateSettings arnoldi;
            arnoldi.max_steps = 60;
            arnoldi.tolerance = 1e-8;
            estimate          = estimate_first_critical_point_second_order(
              problem, U, lambda, dU, mask,
              (cluster || curved) ? first : std::isfinite(range) ? range : 1 + std::abs(lambda), arnoldi);
            if (estimate.found)
              {
                report("second order", "Arnoldi");
                if (refine)
                  refine_and_say(problem, U, lambda, dU, mask, say, estimate);
              }
            else if (curved)
              {
                // (the linear estimate still stands)
                say("  the second-order model: " + estimate.message + "; the linear estimate");
                estimate  = linear;
                fell_back = true;
              }
          }
        else if (cluster)
          {
            std::ostringstream w;
            w << std::setprecision(6) << "the next critical point is estimated less than twice as far (t = "
              << estimate.next_lambda << "): the linear model does not single out the first mode";
            why            = w.str();
            estimate.found = false;
            return false;
          }
        if (!estimate.found || estimate.lambda > lambda_max)
          {
            why            = estimate.found ? "estimated beyond the parameter range" : estimate.message;
            estimate.found = false;
          }
        return second_order && !fell_back;
      }

      /**
       * Where Newton from a second-order estimate fails (the section's
       * later growths: estimates 0.1-7.4 % high, at the two largest with a
       * mode Arnoldi had not converged in its 60 steps), a state on the
       * path short of it to estimate again from: the series' state U + s
       * dU + s^2/2 d2U (d2U = (tangent - dU)/tau, the estimate's own) at s
       * = 0.7 tau, converged there by Newton. 0.7 stays below the critical
       * load for estimates up to 43 % high, and leaves the next estimate
       * 25-30 % of the distance (the section's), where the series'
       * third-order error is 40-60 times smaller. `on_path` stays empty
       * where Newton fails: the path is then followed.
       */
      void
      converge_short_of_estimate(BifurcationProblem &                             problem,
                                 const Vector<double> &                           U,
                                 const double                                     lambda,
                                 const Vector<double> &                           dU,
                                 const Vector<double> &                           mask,
                                 const NewtonSettings &                           newton,
                                 const std::function<void(const std::string &)> & say,
                                 const CriticalEstimate &                         estimate,
                                 Vector<double> &                                 on_path,
                                 double &                                         on_path_lambda,
                                 unsigned int &                                   spent)
      {
        const double tau = estimate.lambda - lambda, s = 0.7 * tau;
        unsigned int iterations = 0;
        if (!(tau > 0) || estimate.tangent.size() != U.size())
          return;
        Vector<double> guess = U, d2U = estimate.tangent;
        d2U -= dU;
        guess.add(s, dU, 0.5 * s * s / tau, d2U);
        const Vector<double> predicted = guess;
        // (a few iterations: where the guess is that far off, the path
        // followed from the start is the cheaper way; KINSOL's line search
        // crept on the seed pod's natural shape, 25 iterations without
        // converging)
        NewtonSettings capped = newton;
        capped.max_iterations = std::min(newton.max_iterations, 8u);
        try
          {
            problem.set_load_parameter(lambda + s);
            const NewtonResult r = newton_solve(problem, guess, capped);
            spent += r.iterations - r.chord_steps;
            iterations = r.iterations;
          }
        catch (NewtonFailure &f)
          {
            spent += capped.max_iterations; // (at most: KINSOL may stop earlier)
            say(std::string("  the state short of the estimate does not converge: ") + f.what());
            return;
          }
        // A state converged at fixed load from a guess need not lie on the
        // path from the start (another branch, a snapped state): Newton's
        // correction must stay below half the series' step from the start
        // (the section's: 0.16-0.20 of it).
        Vector<double> step = predicted, correction = guess;
        step -= U;
        correction -= predicted;
        const double ratio = masked_max(correction, mask) / masked_max(step, mask);
        std::ostringstream m;
        m << std::setprecision(10) << "  converged at t = " << lambda + s << ", short of the estimate, "
          << iterations << " Newton iterations, correction " << std::setprecision(2) << ratio
          << " of the series' step";
        if (!(ratio <= 0.5))
          {
            say(m.str() + ": not taken for the path's state");
            return;
          }
        on_path        = guess;
        on_path_lambda = lambda + s;
        say(m.str() + "; estimating again from there");
      }

      /// The critical point from one estimate at (U, lambda) with the tangent dU
      /// = dU/dlambda there (the factorization in place is J(U, lambda)):
      /// Newton on the augmented system from the prediction, or where that
      /// does not converge within a few iterations, from the guess converged
      /// onto the path at the estimated load. Returns false with `why` set if
      /// the estimate, its state or the location fails; `estimate` is kept.
      /// `spent` counts the factorizations besides the located Newton run's
      /// (a direct attempt that failed, states converged onto the path).
      bool
      locate_from_estimate(BifurcationProblem &                             problem,
                           const Vector<double> &                           U,
                           const double                                     lambda,
                           const Vector<double> &                           dU,
                           const Vector<double> &                           mask,
                           const Vector<double> &                           stability,
                           const ArclengthSettings &                        settings,
                           const NewtonSettings &                           newton,
                           const double                                     lambda0,
                           const std::function<void(const std::string &)> & say,
                           CriticalEstimate &                               estimate,
                           Vector<double> &                                 on_path,
                           double &                                         on_path_lambda,
                           bool &                                           fold,
                           CriticalPoint &                                  cp,
                           unsigned int &                                   spent,
                           std::string &                                    why)
      {
        // COSMO_ESTIMATE_VIA_PATH: always converge the guess onto the path
        // first, to measure against (benchmarks/).
        static const bool via_path = std::getenv("COSMO_ESTIMATE_VIA_PATH") != nullptr;
        cp       = CriticalPoint(); // (this attempt's: none until located)
        on_path.reinit(0);          // (set once the guess has converged onto the path)
        on_path_lambda = NAN;       // (its load, set with it)
        const bool second_order =
          make_estimate(problem, U, lambda, dU, stability, settings.lambda_max, settings.refine_estimate, say, estimate,
                        why);
        if (!estimate.found)
          return false;
        // (the location's border and null vector live on the mode unknowns)
        estimate.mode.scale(mask);
        Vector<double> dR(U.size());
        problem.set_load_parameter(lambda);
        problem.load_derivative(U, lambda, dR);
        const double dR_norm = std::sqrt(masked_dot(dR, dR, mask));
        const double v_norm  = std::sqrt(masked_dot(estimate.mode, estimate.mode, mask));
        fold = dR_norm > 0 && std::abs(masked_dot(estimate.mode, dR, mask)) > 1e-4 * dR_norm * v_norm;
        CriticalPointSettings location;
        location.resolution_fraction = 0.1;
        // Newton on the augmented system stays within four times the
        // estimate's distance and the parameter range: an iterate beyond
        // has run away (the seed pod's estimate without its free strains,
        // with another mode, sent it to t = 239) and costs one
        // factorization, not the iteration cap. (The seed pod's estimates
        // are 2.5x low, and its first iterate lands at the critical load.)
        location.lambda_lo = lambda - (estimate.lambda - lambda);
        location.lambda_hi = std::min(settings.lambda_max, lambda + 4 * (estimate.lambda - lambda));
        // Newton on the augmented system straight from the prediction: it
        // converges the state onto the path and the load together, which
        // saves the 1-2 factorizations of converging onto the path at the
        // estimated load first (on the plate's flat starts two or three
        // iterations locate it to its resolution). A few only: where they
        // do not converge (a path far from linear in the load), the guess
        // is converged onto the path and located from there, as below.
        // The second-order estimate's guess takes six (its first step
        // overshoots: the twisted strip's and section's test functions are
        // far from linear over the 24 % and 0.7 % they are off) and is not
        // converged onto the path where they fail: its model has nothing
        // better to offer (the seed pod's state did not converge there).
        if (!via_path)
          {
            location.max_iterations = second_order ? 6 : 4;
            cp = locate_critical_point(problem, fold, estimate.U, estimate.lambda, estimate.mode, mask, estimate.tangent, 1.,
                                       false, std::abs(estimate.lambda - lambda0), newton.relative_tolerance,
                                       location);
            if (cp.converged)
              {
                on_path = cp.U;
                return true;
              }
            spent += cp.factorizations;
            if (second_order)
              {
                why = "from the prediction: " + cp.message;
                say("  " + why);
                cp = CriticalPoint();
                converge_short_of_estimate(problem, U, lambda, dU, mask, newton, say, estimate, on_path, on_path_lambda,
                                           spent);
                return false;
              }
            say("  from the prediction: " + cp.message + "; converging the guess onto the path");
            cp = CriticalPoint();
          }
        // The guess converged onto the path first: Newton on the augmented
        // system fixes the load to its tolerance, but a branch point's state
        // along the mode only to about its square root; from a state on the
        // path (as the followed path's bracket gives it) it stays there.
        Vector<double> guess = estimate.U;
        try
          {
            problem.set_load_parameter(estimate.lambda);
            const NewtonResult r = newton_solve(problem, guess, newton);
            spent += r.iterations - r.chord_steps;
            on_path        = guess;
            on_path_lambda = estimate.lambda;
          }
        catch (NewtonFailure &f)
          {
            why = std::string("its state does not converge: ") + f.what();
            return false;
          }
        location.max_iterations = 6; // (a distant guess: re-estimate rather than wander)
        // (a branch point's system takes the tangent for the branch's direction)
        cp = locate_critical_point(problem, fold, on_path, estimate.lambda, estimate.mode, mask, estimate.tangent, 1., false,
                                   std::abs(estimate.lambda - lambda0), newton.relative_tolerance, location);
        if (!cp.converged)
          why = "Newton on the augmented system: " + cp.message;
        return cp.converged;
      }

      /**
       * The first event of a 'Stop at first event' path from one
       * eigenproblem (critical_estimate.h, doc/theory-continuation.md 10):
       * from the stable start (U, lambda) with its tangent (tU, tlambda) and
       * its factorization in place, the estimate's guess located by Newton
       * on the augmented system; where that does not converge (a path far
       * from linear in the load), the estimate is made again from the
       * guess's state on the path while it is stable, up to four times. The
       * inertia guards the result: no mode other than the critical one may
       * be negative at the located point (a crossing the estimate missed).
       * A mode orthogonal to dR/dlambda is taken for a branch point, else a
       * fold. Returns false, with nothing reported, where it does not hold:
       * the path is then followed from the start ('First event by
       * estimate').
       */
      bool
      estimated_first_event(BifurcationProblem &                             problem,
                            const Vector<double> &                           U0,
                            const double                                     lambda0,
                            const Vector<double> &                           tU,
                            const double                                     tlambda,
                            const Vector<double> &                           mask,
                            const ArclengthSettings &                        settings,
                            const NewtonSettings &                           newton,
                            const std::function<void(const std::string &)> & say,
                            EventRecord &                                    record)
      {
        if (!(tlambda > 0))
          return false;
        Vector<double> U = U0, dU = tU, on_path, dR(U0.size()), stability;
        dU /= tlambda;
        problem.stability_mask(stability);
        double           lambda = lambda0;
        CriticalEstimate estimate;
        CriticalPoint    cp;
        bool             fold = false;
        std::string      why;
        unsigned int     factorizations = 0;
        for (unsigned int attempt = 0;; ++attempt)
          {
            double     on_path_lambda = NAN;
            const bool located = locate_from_estimate(problem, U, lambda, dU, mask, stability, settings, newton, lambda0, say,
                                                      estimate, on_path, on_path_lambda, fold, cp, factorizations,
                                                      why);
            factorizations += cp.factorizations;
            if (located)
              break;
            // Again from the guess's state on the path, if it is stable there
            // (not if there was no estimate, or its state did not converge).
            auto stable_on_path = [&]() {
              if (attempt == 3 || !estimate.found || on_path.size() != U.size() ||
                  !(on_path_lambda <= settings.lambda_max))
                return false;
              problem.set_load_parameter(on_path_lambda);
              return problem.setup_jacobian(on_path) == 0 && problem.n_negative_eigenvalues() == 0;
            };
            if (!stable_on_path())
              {
                say("  the estimated critical point: " + why + "; following the path");
                problem.set_load_parameter(lambda0);
                // (whether Newton ran: the factorization in place is then
                // no longer the start's)
                record.event.factorizations =
                  (attempt > 0 || factorizations > 0 || cp.iterations > 0 || on_path.size() > 0) ? 1 : 0;
                return false;
              }
            ++factorizations;
            U      = on_path;
            lambda = on_path_lambda;
            problem.load_derivative(U, lambda, dR);
            problem.solve_with_jacobian(dR, dU);
            dU *= -1.;
          }
        auto &e             = record.event;
        e.kind              = fold ? BifurcationProblem::Event::Kind::fold : BifurcationProblem::Event::Kind::branch_point;
        e.factorizations    = factorizations;
        e.n_negative_before = 0;
        e.n_negative_after  = problem.n_negative_eigenvalues();
        e.lambda_lo         = lambda0;
        e.lambda_hi         = estimate.lambda;
        take_location(cp, record);
        e.lambda_hi = std::max(e.lambda_hi, e.lambda); // (an estimate below the point)
        if (e.n_negative_after < 0 || other_negative_modes(e) != 0)
          {
            say("  the estimated critical point has " + std::to_string(e.n_negative_after) +
                " negative eigenvalues: a crossing below it; following the path");
            problem.set_load_parameter(lambda0);
            return false;
          }
        e.n_negative_after = 1;
        Vector<double> phi = cp.mode;
        problem.complete_mode(phi);
        phi /= std::sqrt(masked_dot(phi, phi, mask));
        record.mode.assign(phi.begin(), phi.end());
        std::ostringstream l;
        l << std::setprecision(12) << "  " << e.name() << " at t = " << e.lambda
          << " from the estimate (Newton on the augmented system: " << e.newton_iterations << " iterations; "
          << e.factorizations << " factorizations since the start, resolution " << std::setprecision(2)
          << event_resolution(e) << ")";
        say(l.str());
        problem.set_load_parameter(e.lambda);
        report_located_event(problem, e, cp.U, fold ? nullptr : &phi);
        return true;
      }
    } // namespace

    std::vector<EventRecord>
    ArclengthContinuation::run(BifurcationProblem &problem, Vector<double> &U, const double lambda)
    {
      set_mask_and_weight(problem);
      stopped = false;
      std::vector<EventRecord> &events   = at.events;
      std::vector<State> &      switches = at.switches; // grows while branches are followed
      unsigned int              branch   = 1;
      std::size_t               q0       = 0;
      if (!resume)
        {
          // The starting point: converge it at fixed lambda, analyse, report.
          State s;
          problem.set_load_parameter(lambda);
          const NewtonResult r0 = newton_solve(problem, U, newton);
          s.U                   = U;
          s.lambda              = lambda;
          analyse(problem, s, nullptr, settings.direction);
          at = Progress();
          incomplete.clear();
          report_first_state(problem, s.U, lambda, r0, s.n_negative, 0, 0, false, settings.stop_at_first_event);
          if (settings.first_event_by_estimate && settings.stop_at_first_event && s.n_negative == 0)
            {
              EventRecord record;
              // (the factorization in place is the start's: analyse's)
              if (estimated_first_event(problem, s.U, lambda, s.tU, s.tlambda, mask, settings, newton,
                                        [this](const std::string &l) { say(l); },
                                        record))
                {
                  factorizations += record.event.factorizations;
                  events.push_back(record);
                  say("  stopped at the first event ('Stop at first event')");
                  return events;
                }
              if (record.event.factorizations > 0)
                at_state.valid = false;
            }
          at.may_switch = settings.switch_branches && settings.maximum_depth > 0;
          follow(problem, s, 0, at.may_switch, events, switches, at.step, settings.initial_step,
                 0);
        }
      else
        {
          // Go on inside the branch the checkpoint was written on, from the
          // factorization the uninterrupted run's next corrector started on.
          resume = false;
          if (at.chord_from_state && reuse_factorization(problem))
            {
              factorize_state(problem, at.s);
              // (made again, not one more: the counts stay the uninterrupted run's)
              at_state.factorizations = --factorizations;
            }
          follow(problem, at.s, at.branch, at.may_switch, events, switches, at.step, at.ds, at.k);
          if (at.q != Progress::no_switch)
            {
              queue_depth_first(switches, at.q, at.queued);
              branch = at.branch + 1;
              q0     = at.q + 1;
            }
        }
      unsigned int &step = at.step;
      if (stopped)
        {
          say("  stopped at the first event ('Stop at first event')");
          return events;
        }

      for (std::size_t q = q0; q < switches.size(); ++q)
        {
          io::check_interrupt();
          const State start = switches[q];
          if (branch >= settings.maximum_branches)
            {
              say("  maximum number of branches reached; further branch switches skipped");
              break;
            }
          // First point of the new branch: a distance a along the mode, on
          // the hyperplane orthogonal to it (so not back on the old branch).
          State          first;
          first.depth = start.depth;
          Vector<double> Up = start.U;
          Up.add(settings.switch_amplitude, start.tU);
          NewtonResult r;
          try
            {
              r = correct(problem, first, start.tU, 0., Up, start.lambda);
              analyse(problem, first, &start.tU, 0.);
            }
          catch (NewtonFailure &e)
            {
              const std::string m =
                "the switch to branch " + std::to_string(branch) + " failed: " + e.what();
              say("  " + m);
              incomplete.push_back(m);
              ++branch;
              continue;
            }
          const std::string mirror = mirror_image_message(start, first, at.plus_lambda, settings);
          if (!mirror.empty())
            {
              say(mirror);
              continue;
            }
          report_first_state(problem, first.U, first.lambda, r, first.n_negative, ++step, branch,
                             first.factorized_at_predictor, false);
          say("  following branch " + std::to_string(branch) + " (depth " +
              std::to_string(first.depth) + ", from branch " + std::to_string(start.branch) +
              ") from t = " + std::to_string(first.lambda));
          const std::size_t queued = switches.size();
          at.branch     = branch;
          at.q          = q;
          at.queued     = queued;
          at.may_switch = settings.switch_branches && first.depth < settings.maximum_depth;
          follow(problem, first, branch, at.may_switch, events, switches, step,
                 settings.initial_step, 0);
          queue_depth_first(switches, q, queued);
          ++branch;
        }
      fail_if_incomplete(incomplete);
      return events;
    }
  } // namespace solvers
} // namespace cosmo
