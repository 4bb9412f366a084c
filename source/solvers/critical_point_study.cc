#include <deal.II/base/utilities.h>

#include <cosmo/config.h>
#include <cosmo/io/output.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/critical_curve.h>
#include <cosmo/io/checkpoint.h>
#include <cosmo/io/point_loop.h>
#include <cosmo/io/parameter_copy.h>
#include <cosmo/solvers/critical_point_study.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace solvers
  {
    EventRecord
    locate_continued_critical_point(ArclengthContinuation &driver,
                                    BifurcationProblem &   problem,
                                    const CriticalGuess &  g,
                                    const NewtonSettings & newton)
    {
      if (g.U.size() != problem.n_unknowns())
        throw io::RunFailure("the critical point to start from has " + std::to_string(g.U.size()) +
                             " unknowns, this problem " + std::to_string(problem.n_unknowns()));
      Vector<double> U = g.U;
      if (g.equilibrate)
        try
          {
            problem.set_load_parameter(g.t);
            newton_solve(problem, U, newton);
          }
        catch (NewtonFailure &e)
          {
            throw io::RunFailure(std::string("the guess does not converge at its load: ") +
                                 e.what());
          }
      const auto record = driver.locate_from(problem, U, g.t, g.fold, g.mode, 1e-10, 0.1);
      if (!record.event.located_by_newton)
        throw io::RunFailure(record.event.message);
      // Another negative eigenvalue than the critical one: a mode that
      // became critical below this one.
      if (other_negative_modes(record.event) > 0)
        {
          std::ostringstream m;
          m << "another mode is critical below the continued critical point ("
            << record.event.n_negative_after
            << " negative eigenvalues there, the critical one's eigenvalue " << std::setprecision(3)
            << record.event.eigenvalue << "): the critical mode changed";
          throw io::RunFailure(m.str());
        }
      return record;
    }

    void
    locate_and_report_continued_critical_point(BifurcationProblem &                               problem,
                                               const CriticalGuess &                              guess,
                                               const ArclengthSettings &                          arclength,
                                               const NewtonSettings &                             newton,
                                               const std::function<void(const std::string &)> &   progress,
                                               const std::function<void(const Vector<double> &)> &take_state)
    {
      ArclengthContinuation driver(arclength, newton);
      driver.progress   = progress;
      const auto record = locate_continued_critical_point(driver, problem, guess, newton);
      take_state(Vector<double>(record.state.begin(), record.state.end()));
      StepReport report;
      report.t          = record.event.lambda;
      report.n_negative = record.event.n_negative_after;
      report.final      = true; // the path's only state: written whatever 'Steps between outputs'
      problem.set_load_parameter(report.t);
      report_converged_step(problem, Vector<double>(record.state.begin(), record.state.end()), report);
    }

    namespace
    {
      /// The study's critical point of a run: its first event on branch 0.
      const EventRecord *
      first_critical_point(const std::vector<EventRecord> &events)
      {
        for (const auto &e : events)
          if (e.event.branch == 0)
            return &e;
        return nullptr;
      }

      Vector<double>
      as_vector(const std::vector<double> &v)
      {
        return Vector<double>(v.begin(), v.end());
      }

      /**
       * The parameters of value k: a copy of the study's (io/parameter_copy.h)
       * with the swept entry set, the output into `directory` (its
       * parameters.prm reproduces the point alone) and, on the library's path
       * sections, each path stopped at its first critical point. The study's
       * own handler is never written to.
       */
      std::unique_ptr<ParameterHandler>
      point_parameters(const ParameterHandler &  prm,
                       const io::ParameterSweep &sweep,
                       const CriticalPointStudy &study,
                       const unsigned int        k,
                       const std::string &       directory)
      {
        auto point = io::copy_parameters(prm, study.declare_parameters);
        if (study.arclength_sections)
          io::ParameterSweep::set_entry(*point, "Arclength continuation/Stop at first event",
                                        "true", "Arclength continuation", "Stop at first event");
        sweep.prepare_point(*point, k, directory);
        return point;
      }

      /// The critical load of the new mode continued back to an earlier value.
      struct ContinuedBack
      {
        double       t              = NAN;
        unsigned int factorizations = 0;
        std::string  message;
      };

      ContinuedBack
      continue_back(ParameterHandler &        prm,
                    const io::ParameterSweep &sweep,
                    const unsigned int        k,
                    const std::string &       directory,
                    const CriticalGuess &     g,
                    const io::RunOptions &    options,
                    const CriticalPointStudy &study)
      {
        const auto point = point_parameters(prm, sweep, study, k, directory);
        auto       run   = study.make_run(*point);
        run->start_from_critical_point(g);
        ContinuedBack back;
        // (a run of its own in its own directory, with postprocessors of its
        // own: the point's are the point's; the event files its summary.json
        // names are written by its 'fields')
        const io::RunOptions auxiliary = io::PointLoop::point_options(options, *point);
        try
          {
            run->run(auxiliary, *point);
          }
        catch (io::RunFailure &e)
          {
            back.message = e.what(); // (expected: the other mode is critical first there)
          }
        back.factorizations = run->factorizations();
        for (const auto &x : run->located_events())
          if (x.event.located_by_newton)
            back.t = x.event.lambda;
        return back;
      }
    } // namespace

    namespace
    {
      /// sweep.csv's (and critical_curve.csv's) columns.
      io::CSVTable
      study_columns(const CriticalPointStudy &study, const io::ParameterSweep &sweep)
      {
        io::CSVTable table;
        table.add_column("value", sweep.axis_label());
        for (const auto &c : {"converged", "t_critical", "t_resolution"})
          table.add_column(c);
        for (const auto &c : study.further_columns)
          table.add_column(c);
        for (const auto &c : study.mode_columns)
          table.add_column(c);
        for (const auto &c : {"dofs", "seconds", "factorizations", "continued", "mode_change",
                              "codim2_value", "codim2_t"})
          table.add_column(c);
        return table;
      }

      /// Classifications equal value by value (a NaN column, one the mesh
      /// cannot classify, equal to a NaN).
      bool
      same_class(const std::vector<double> &a, const std::vector<double> &b)
      {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](double x, double y) {
          return x == y || (std::isnan(x) && std::isnan(y));
        });
      }

      bool
      any_finite(const std::vector<double> &c)
      {
        return std::any_of(c.begin(), c.end(), [](double x) { return std::isfinite(x); });
      }

      /**
       * One value's run of a study and what the study carries from value to
       * value: the critical points continued so far (a critical curve) and
       * the last value with a located critical point (changes of the mode).
       */
      class StudyPoints
      {
      public:
        StudyPoints(ParameterHandler &              prm,
                    const io::RunOptions &          options,
                    const io::ParameterSweep &      sweep,
                    const CriticalPointStudy &      study,
                    const std::function<void(const std::string &)> &log)
          : prm(prm)
          , sweep(sweep)
          , study(study)
          , log(log)
          , options(options)
          , quiet(options)
          , curve(sweep.critical_curve())
          , n_mode(study.mode_columns.size())
          , n_more(study.further_columns.size())
        {
          quiet.quiet = true;             // each point's log.txt has the details
          quiet.resume_directory.clear(); // a point is run whole again
        }

        /// Value k, run in `directory`.
        io::PointLoop::Point
        run(unsigned int k, const std::string &directory);

        /// A value an earlier run did, taken as it is.
        io::PointLoop::Point
        take(unsigned int k, const std::vector<double> &row);

        void
        save(io::CheckpointWriter &w) const
        {
          predictor.save(w);
          w.put(previous.k);
          w.put(previous.value);
          w.put(previous.t);
          w.put_vector(previous.mode_class);
          w.put(std::uint64_t(previous.n_unknowns));
        }
        void
        load(io::CheckpointReader &r)
        {
          predictor.load(r);
          previous.k          = r.get_unsigned();
          previous.value      = r.get_double();
          previous.t          = r.get_double();
          previous.mode_class = r.get_vector();
          previous.n_unknowns = r.get_size();
        }

        /**
         * Rank 0, every rank's rows: a block's first value (and one after
         * values taken from a resumed run's checkpoints) was run without
         * the previous one; a change of the critical mode there is found
         * here, without a codimension-2 estimate.
         */
        void
        mark_mode_changes(std::vector<std::vector<double>> &rows) const;

      private:
        ParameterHandler &                              prm;
        /// The running value's own parameters (point_parameters).
        std::unique_ptr<ParameterHandler>               point_prm;
        const io::ParameterSweep &                      sweep;
        const CriticalPointStudy &                      study;
        std::function<void(const std::string &)>        log;
        const io::RunOptions &                          options;
        /// The running point's options (PointLoop::point_options).
        io::RunOptions                                  quiet;
        const bool                                      curve;
        const std::size_t                               n_mode, n_more;
        CriticalCurvePredictor                          predictor;
        struct Previous
        {
          unsigned int        k     = 0;
          double              value = NAN, t = NAN;
          std::vector<double> mode_class;
          std::size_t         n_unknowns = 0;
        } previous;

        /// What one value's run found.
        struct Found
        {
          double      converged = 0, t = NAN, resolution = NAN, dofs = NAN, factorizations = 0,
                 continued = 0, mode_change = 0, codim2_value = NAN, codim2_t = NAN;
          std::vector<double> mode_class, further;
          /// The previous mode's critical point continued to this value where
          /// another mode has become critical first (t there).
          double      previous_mode_t = NAN;
          std::string failure;
        };
        /// The run of value k: continued from the curve's prediction, else independent.
        std::unique_ptr<CriticalPointRun>
        solve(unsigned int k, Found &f);
        /// A new critical mode: the previous curve ends, with a codimension-2
        /// point between the two values where the two curves' secants cross.
        void
        mode_changed(unsigned int k, const EventRecord &e, const std::string &directory, Found &f);
      };

      std::unique_ptr<CriticalPointRun>
      StudyPoints::solve(const unsigned int k, Found &f)
      {
        auto          run = study.make_run(*point_prm);
        CriticalGuess g;
        unsigned int  order = 0;
        if (curve && predictor.predict(sweep.value(k), g.U, g.t, g.mode, &order))
          {
            g.equilibrate = order == 1;
            run->start_from_critical_point(g);
            try
              {
                run->run(quiet, *point_prm);
                f.converged = 1;
                f.continued = 1;
              }
            catch (io::RunFailure &e)
              {
                log("  point " + std::to_string(k) + ": continuing the critical point failed (" +
                    e.what() + "); an independent run instead");
                for (const auto &x : run->located_events())
                  if (x.event.located_by_newton && other_negative_modes(x.event) > 0)
                    f.previous_mode_t = x.event.lambda;
                f.factorizations += run->factorizations();
                run = study.make_run(*point_prm);
                // The independent run writes the point's files afresh: new
                // postprocessors, not the attempt's (its events would number
                // the run's, and summary.json names event-01).
                quiet = io::PointLoop::point_options(options, *point_prm);
              }
          }
        if (f.continued == 0)
          try
            {
              run->run(quiet, *point_prm);
              f.converged = 1;
            }
          catch (io::RunFailure &e)
            {
              f.failure = e.what();
            }
        f.dofs = run->n_dofs();
        f.factorizations += run->factorizations();
        return run;
      }

      void
      StudyPoints::mode_changed(const unsigned int k,
                                const EventRecord &e,
                                const std::string &directory,
                                Found &            f)
      {
        std::ostringstream m;
        m << std::setprecision(6) << "  the critical mode changes from "
          << study.describe_mode(previous.mode_class) << " to " << study.describe_mode(f.mode_class)
          << " between " << sweep.label() << " = " << previous.value << " and " << sweep.value(k);
        std::string why = "the old mode was not continued to this value";
        if (curve && std::isfinite(f.previous_mode_t) && previous.n_unknowns == e.state.size())
          {
            // Where the two critical curves cross: the new mode continued
            // back to the previous value (a few factorizations), the
            // secants intersected.
            CriticalGuess back_guess;
            back_guess.U    = as_vector(e.state);
            back_guess.mode = as_vector(e.mode);
            back_guess.t    = f.t;
            back_guess.fold = e.event.kind == BifurcationProblem::Event::Kind::fold;
            const auto back =
              continue_back(prm, sweep, previous.k, directory + "/back", back_guess, quiet, study);
            f.factorizations += back.factorizations;
            why = std::isfinite(back.t) ? "the secants do not cross between the values" :
                                          "continuing the new mode back failed: " + back.message;
            if (std::isfinite(back.t) &&
                codimension_two_estimate(previous.value, previous.t, back.t, sweep.value(k),
                                         f.previous_mode_t, f.t, f.codim2_value, f.codim2_t))
              why.clear();
          }
        if (why.empty())
          m << ": codimension-2 point near " << sweep.label() << " = " << f.codim2_value
            << ", t = " << f.codim2_t << " (the two critical curves' secants crossed)";
        else
          m << "; no codimension-2 estimate (" << why << ")";
        log(m.str());
      }

      io::PointLoop::Point
      StudyPoints::run(const unsigned int k, const std::string &directory)
      {
        const auto         start = std::chrono::steady_clock::now();
        Found              f;
        f.mode_class.assign(n_mode, NAN);
        f.further.assign(n_more, NAN);
        io::PointLoop::Point p;
        try
          {
            point_prm      = point_parameters(prm, sweep, study, k, directory);
            quiet          = io::PointLoop::point_options(options, *point_prm);
            const auto run = solve(k, f);
            io::PointLoop::finish_point(quiet, directory);
            if (const EventRecord *e = first_critical_point(run->located_events()))
              {
                f.t          = e->event.lambda;
                f.resolution = event_resolution(e->event);
                f.further    = run->further_columns(*e);
                if (!e->mode.empty())
                  f.mode_class = run->classify_mode(as_vector(e->mode));
                AssertThrow(f.further.size() == n_more && f.mode_class.size() == n_mode,
                            ExcMessage("the run's study columns differ from the study's"));
                const bool classified = n_mode > 0 && any_finite(f.mode_class) &&
                                        !previous.mode_class.empty() &&
                                        any_finite(previous.mode_class);
                if (classified && !same_class(f.mode_class, previous.mode_class))
                  {
                    f.mode_change = 1;
                    predictor.clear();
                  }
                if (curve && f.converged == 1 && e->event.located_by_newton)
                  predictor.add(sweep.value(k), f.t, as_vector(e->state), as_vector(e->mode));
                if (f.mode_change == 1)
                  mode_changed(k, *e, directory, f);
                previous = {k, sweep.value(k), f.t, f.mode_class, e->state.size()};
              }
            else if (f.converged == 1)
              f.failure = "no critical point on the first branch";
          }
        catch (io::InputError &e)
          {
            p.outcome   = io::PointLoop::Point::Outcome::rejected;
            p.rejection = "'" + sweep.text(k) + "' (" + e.what() + ")";
            f.failure   = std::string("refused: ") + e.what();
          }
        if (!std::isfinite(f.t) && p.outcome != io::PointLoop::Point::Outcome::rejected)
          p.outcome = io::PointLoop::Point::Outcome::failed; // no located critical point
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        p.row = {sweep.value(k), f.converged, f.t, f.resolution};
        p.row.insert(p.row.end(), f.further.begin(), f.further.end());
        p.row.insert(p.row.end(), f.mode_class.begin(), f.mode_class.end());
        p.row.insert(p.row.end(), {f.dofs, seconds, f.factorizations, f.continued, f.mode_change,
                                   f.codim2_value, f.codim2_t});
        std::ostringstream line;
        line << std::setprecision(10) << "  " << sweep.label() << " = " << sweep.value(k)
             << ": critical t = " << f.t << std::setprecision(3);
        if (std::isfinite(f.t))
          line << " (resolution " << f.resolution << "), mode "
               << (n_mode > 0 ? study.describe_mode(f.mode_class) : std::string("-"));
        line << ", " << f.factorizations << " factorizations"
             << (f.continued == 1 ? " (continued)" : "") << ", " << seconds << " s";
        if (!f.failure.empty())
          line << "; " << f.failure;
        p.line = line.str();
        return p;
      }

      io::PointLoop::Point
      StudyPoints::take(const unsigned int k, const std::vector<double> &row)
      {
        io::PointLoop::Point p;
        if (!std::isfinite(row[2]))
          p.outcome = io::PointLoop::Point::Outcome::failed; // (no located critical point)
        std::ostringstream line;
        line << std::setprecision(10) << "  " << sweep.label() << " = " << sweep.value(k)
             << ": critical t = " << row[2] << " (done before the resume)";
        p.line = line.str();
        predictor.clear(); // the curve goes on from points solved here
        if (std::isfinite(row[2]))
          previous = {k, sweep.value(k), row[2],
                      std::vector<double>(row.begin() + 4 + n_more, row.begin() + 4 + n_more + n_mode),
                      0}; // (no codimension-2 estimate from it: no state)
        return p;
      }

      void
      StudyPoints::mark_mode_changes(std::vector<std::vector<double>> &rows) const
      {
        // ..., mode columns, dofs, seconds, factorizations, continued, mode_change
        const std::size_t   mode0 = 4 + n_more, change = mode0 + n_mode + 4;
        std::vector<double> last_class;
        for (unsigned int r = 0; r < rows.size(); ++r)
          {
            auto &                    row = rows[r];
            const std::vector<double> c(row.begin() + mode0, row.begin() + mode0 + n_mode);
            if (n_mode == 0 || !any_finite(c))
              continue;
            if (row[change] == 0 && !last_class.empty() && !same_class(c, last_class))
              {
                row[change] = 1;
                std::ostringstream m;
                m << std::setprecision(6) << "  the critical mode changes from "
                  << study.describe_mode(last_class) << " to " << study.describe_mode(c)
                  << " between " << sweep.label() << " = " << sweep.value(r - 1) << " and "
                  << sweep.value(r)
                  << "; no codimension-2 estimate (the values were run apart: on different "
                     "ranks, or before and after a resume)";
                log(m.str());
              }
            last_class = c;
          }
      }
    } // namespace

    void
    run_critical_point_study(ParameterHandler &        prm,
                             const io::RunOptions &    options,
                             const io::ParameterSweep &sweep,
                             const CriticalPointStudy &study)
    {
      if (study.arclength_sections)
        {
          // Each run ends at the first critical point of its path.
          prm.enter_subsection("Path following");
          const std::string method = prm.get("Method");
          prm.leave_subsection();
          if (method != "arclength")
            throw io::InputError("Path following", "Method", method,
                                 "arclength in a study of critical points (section Parameter "
                                 "sweep): each value's path is followed to its first critical "
                                 "point");
          // (each value's copy of the parameters stops at the first event: point_parameters)
        }
      // Each value runs on a copy of the parameters (point_parameters): one
      // now, before the directory is opened, so that a copy that cannot be
      // made ends the study here, not at its first point.
      (void)io::copy_parameters(prm, study.declare_parameters);
      const bool              curve = sweep.critical_curve();
      io::PointLoop::Description d;
      d.application     = study.application;
      d.checkpoint_kind = study.application + " study";
      // A checkpoint of other parameters is refused before anything is touched.
      d.parameters = io::checkpoint_parameters(prm);
      prm.enter_subsection("Output");
      d.directory = prm.get("Output directory");
      prm.leave_subsection();
      if (curve)
        d.also_written = {"critical_curve.csv"};
      d.kind             = "study";
      d.converged_column = 1;
      d.rejected_entry   = "Values";
      d.failed_words     = "values have no located critical point";
      d.entry            = sweep.entry();
      for (unsigned int k = 0; k < sweep.size(); ++k)
        d.values.push_back(sweep.text(k));

      const bool                    resume = !options.resume_directory.empty();
      std::unique_ptr<StudyPoints>  points;
      io::PointLoop::Hooks          hooks;
      hooks.take_done     = [&](unsigned int k, const std::vector<double> &row) {
        return std::optional<io::PointLoop::Point>(points->take(k, row));
      };
      hooks.save_held     = [&](io::CheckpointWriter &w) { points->save(w); };
      hooks.load_held     = [&](io::CheckpointReader &r) { points->load(r); };
      hooks.complete_rows = [&](std::vector<std::vector<double>> &rows) {
        points->mark_mode_changes(rows);
      };
      io::PointLoop loop(d, study_columns(study, sweep), resume, hooks);
      const auto    log_file = io::open_run_directory(d.directory, prm, options.quiet, d.log_file, resume);
      auto &        log      = *log_file;
      points = std::make_unique<StudyPoints>(prm, options, sweep, study,
                                             [&log](const std::string &s) { log(s); });
      log(study.application + " " + std::string(COSMO_VERSION) + ": " + options.parameter_file +
          ", " + (curve ? "critical curve" : "study") + " of '" + sweep.entry() + "' over " +
          std::to_string(sweep.size()) + " values");
      loop.run(log, [&](const unsigned int k) {
        return points->run(k, io::ParameterSweep::point_directory(loop.shared_directory(), k));
      });
    }
  } // namespace solvers
} // namespace cosmo
