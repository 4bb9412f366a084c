#include <deal.II/base/utilities.h>

#include <cosmo/config.h>
#include <cosmo/io/output.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/critical_curve.h>
#include <cosmo/io/checkpoint.h>
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

      /// A point's run writes into `directory`; its parameters.prm reproduces it alone.
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
        sweep.prepare_point(prm, k, directory);
        auto run = study.make_run(prm);
        run->start_from_critical_point(g);
        ContinuedBack back;
        try
          {
            run->run(options, prm);
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
          io::ParameterSweep::set_entry(prm, "Arclength continuation/Stop at first event", "true",
                                        "Arclength continuation", "Stop at first event");
        }
      prm.enter_subsection("Output");
      const std::string directory = prm.get("Output directory");
      prm.leave_subsection();
      // A study resumed (--resume) goes on after its last finished point;
      // a checkpoint of other parameters is refused before anything is touched.
      const std::string  checkpoint_application = study.application + " study";
      const std::string  parameters             = io::checkpoint_parameters(prm);
      const bool         resume                 = !options.resume_directory.empty();
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
      io::ranks::Resumed resumed;
      if (resume)
        resumed = io::ranks::resume_points(directory, table, [&](const std::string &d) {
          return io::read_checkpoint(d, checkpoint_application, parameters);
        });
      const auto log_file =
        io::open_run_directory(directory, prm, options.quiet, "sweep-log.txt", resume);
      auto &     log      = *log_file;
      const bool curve    = sweep.critical_curve();
      // Under mpirun each rank takes a contiguous block of the values
      // (io/ranks.h), their point directories in the run's directory, which
      // rank 0 has taken (the previous run's files moved) before any starts.
      const unsigned int n_ranks = io::ranks::size();
      const auto [block_begin, block_end] = io::ranks::my_block(sweep.size());
      const std::string shared = n_ranks > 1 ? io::ranks::shared_directory() : directory;
      io::ranks::barrier();
      log(study.application + " " + std::string(COSMO_VERSION) + ": " + options.parameter_file +
          ", " + (curve ? "critical curve" : "study") + " of '" + sweep.entry() + "' over " +
          std::to_string(sweep.size()) + " values");
      const std::size_t n_mode = study.mode_columns.size();
      const std::size_t n_more = study.further_columns.size();

      // The critical points continued so far (critical curve), and the last
      // value's with a located critical point (mode changes).
      CriticalCurvePredictor predictor;
      struct Previous
      {
        unsigned int        k     = 0;
        double              value = NAN, t = NAN;
        std::vector<double> mode_class;
        std::size_t         n_unknowns = 0;
      } previous;
      io::RunOptions quiet = options;
      quiet.quiet          = true; // each point's log.txt has the details
      quiet.resume_directory.clear(); // a point is run whole again
      std::string  refused;
      unsigned int n_without = 0; // points without a located critical point
      unsigned int k0        = block_begin;
      // What the driver holds after a point (a checkpoint's payload after its header).
      auto load_held = [&](io::CheckpointReader &r) {
        predictor.load(r);
        previous.k          = r.get_unsigned();
        previous.value      = r.get_double();
        previous.t          = r.get_double();
        previous.mode_class = r.get_vector();
        previous.n_unknowns = r.get_size();
      };
      if (resume && resumed.same_ranks)
        {
          io::CheckpointReader &r = resumed.reader;
          k0                      = resumed.own.next;
          for (const auto &row : resumed.own.rows)
            table.add_row(row);
          load_held(r);
          refused             = r.get_string();
          n_without           = r.get_unsigned();
          table.write(directory + "/sweep.csv");
          if (curve)
            table.write(directory + "/critical_curve.csv");
          log("  resumed from the checkpoint: " + std::to_string(k0 - block_begin) + " of " +
              std::to_string(block_end - block_begin) + " values done");
        }
      else if (resume)
        log("  resumed on " + std::to_string(n_ranks) + " ranks a study begun on " +
            std::to_string(resumed.ranks_then) + ": the values done before are taken as they are");
      if (n_ranks > 1)
        log("  values " + std::to_string(block_begin + 1) + " to " + std::to_string(block_end) +
            " of " + std::to_string(sweep.size()) + " on rank " +
            std::to_string(io::ranks::rank()) + " of " + std::to_string(n_ranks));
      std::vector<std::string> point_lines; // this rank's, for rank 0's log
      try
        {
        for (unsigned int k = k0; k < block_end; ++k)
          {
            // Between points: sweep.csv holds every point done so far.
            io::check_interrupt();
            if (const auto done = resumed.done.find(k); done != resumed.done.end())
              {
                // Done by a rank of the run begun on another number of ranks.
                const auto &row = done->second;
                table.add_row(row);
                n_without += std::isfinite(row[2]) ? 0 : 1;
                std::ostringstream line;
                line << std::setprecision(10) << "  " << sweep.label() << " = " << sweep.value(k)
                     << ": critical t = " << row[2] << " (done before the resume)";
                log(line.str());
                point_lines.push_back(line.str());
                predictor.clear(); // the curve goes on from points solved here
                if (std::isfinite(row[2]))
                  previous = {k, sweep.value(k), row[2],
                              std::vector<double>(row.begin() + 4 + n_more,
                                                  row.begin() + 4 + n_more + n_mode),
                              0}; // (no codimension-2 estimate from it: no state)
                // The last point of an earlier rank's block: go on from what that
                // rank held there (the curve's predictor), as it would have, so
                // that the next point is continued as in the uninterrupted run.
                if (const auto a = resumed.after.find(k + 1);
                    a != resumed.after.end() && !resumed.done.count(k + 1))
                  load_held(a->second);
                continue;
              }
            const auto        start = std::chrono::steady_clock::now();
            const std::string point = io::ParameterSweep::point_directory(shared, k);
            double converged = 0, t = NAN, resolution = NAN, dofs = NAN, factorizations = 0,
                   continued = 0, mode_change = 0, codim2_value = NAN, codim2_t = NAN;
            std::vector<double> mode_class(n_mode, NAN), further(n_more, NAN);
            // The previous mode's critical point continued to this value where
            // another mode has become critical first (t there).
            double      previous_mode_t = NAN;
            std::string failure;
            try
              {
                sweep.prepare_point(prm, k, point);
                auto         run = study.make_run(prm);
                CriticalGuess g;
                unsigned int  order = 0;
                if (curve && predictor.predict(sweep.value(k), g.U, g.t, g.mode, &order))
                  {
                    g.equilibrate = order == 1;
                    run->start_from_critical_point(g);
                    try
                      {
                        run->run(quiet, prm);
                        converged = 1;
                        continued = 1;
                      }
                    catch (io::RunFailure &e)
                      {
                        log("  point " + std::to_string(k) +
                            ": continuing the critical point failed (" + e.what() +
                            "); an independent run instead");
                        for (const auto &x : run->located_events())
                          if (x.event.located_by_newton && other_negative_modes(x.event) > 0)
                            previous_mode_t = x.event.lambda;
                        factorizations += run->factorizations();
                        run = study.make_run(prm);
                      }
                  }
                if (continued == 0)
                  try
                    {
                      run->run(quiet, prm);
                      converged = 1;
                    }
                  catch (io::RunFailure &e)
                    {
                      failure = e.what();
                    }
                dofs = run->n_dofs();
                factorizations += run->factorizations();
                const auto &events = run->located_events();
                if (const EventRecord *e = first_critical_point(events))
                  {
                    t          = e->event.lambda;
                    resolution = event_resolution(e->event);
                    further    = run->further_columns(*e);
                    if (!e->mode.empty())
                      mode_class = run->classify_mode(as_vector(e->mode));
                    AssertThrow(further.size() == n_more && mode_class.size() == n_mode,
                                ExcMessage("the run's study columns differ from the study's"));
                    // A new critical mode: the previous curve ends (a
                    // codimension-2 point lies between the two values).
                    // (A NaN column is one the mesh cannot classify, e.g. a
                    // symmetry it lacks: equal to a NaN.)
                    auto finite = [](const std::vector<double> &c) {
                      return std::any_of(c.begin(), c.end(), [](double x) { return std::isfinite(x); });
                    };
                    auto same = [](const std::vector<double> &a, const std::vector<double> &b) {
                      return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](double x, double y) {
                        return x == y || (std::isnan(x) && std::isnan(y));
                      });
                    };
                    const bool classified = n_mode > 0 && finite(mode_class) &&
                                            !previous.mode_class.empty() &&
                                            finite(previous.mode_class);
                    if (classified && !same(mode_class, previous.mode_class))
                      {
                        mode_change = 1;
                        predictor.clear();
                      }
                    if (curve && converged == 1 && e->event.located_by_newton)
                      predictor.add(sweep.value(k), t, as_vector(e->state), as_vector(e->mode));
                    if (mode_change == 1)
                      {
                        std::ostringstream m;
                        m << std::setprecision(6) << "  the critical mode changes from "
                          << study.describe_mode(previous.mode_class) << " to "
                          << study.describe_mode(mode_class) << " between " << sweep.label()
                          << " = " << previous.value << " and " << sweep.value(k);
                        std::string why = "the old mode was not continued to this value";
                        if (curve && std::isfinite(previous_mode_t) &&
                            previous.n_unknowns == e->state.size())
                          {
                            // Where the two critical curves cross: the new mode
                            // continued back to the previous value (a few
                            // factorizations), the secants intersected.
                            CriticalGuess back_guess;
                            back_guess.U    = as_vector(e->state);
                            back_guess.mode = as_vector(e->mode);
                            back_guess.t    = t;
                            back_guess.fold = e->event.kind == BifurcationProblem::Event::Kind::fold;
                            const auto back = continue_back(prm, sweep, previous.k, point + "/back",
                                                            back_guess, quiet, study);
                            factorizations += back.factorizations;
                            why = std::isfinite(back.t) ?
                                    "the secants do not cross between the values" :
                                    "continuing the new mode back failed: " + back.message;
                            if (std::isfinite(back.t) &&
                                codimension_two_estimate(previous.value, previous.t, back.t,
                                                         sweep.value(k), previous_mode_t, t,
                                                         codim2_value, codim2_t))
                              why.clear();
                          }
                        if (why.empty())
                          m << ": codimension-2 point near " << sweep.label() << " = "
                            << codim2_value << ", t = " << codim2_t
                            << " (the two critical curves' secants crossed)";
                        else
                          m << "; no codimension-2 estimate (" << why << ")";
                        log(m.str());
                      }
                    previous = {k, sweep.value(k), t, mode_class, e->state.size()};
                  }
                else if (converged == 1)
                  failure = "no critical point on the first branch";
              }
            catch (io::InputError &e)
              {
                refused += std::string(refused.empty() ? "" : "; ") + e.what();
                failure = std::string("refused: ") + e.what();
              }
            if (!std::isfinite(t))
              ++n_without;
            const double seconds =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::vector<double> row = {sweep.value(k), converged, t, resolution};
            row.insert(row.end(), further.begin(), further.end());
            row.insert(row.end(), mode_class.begin(), mode_class.end());
            row.insert(row.end(), {dofs, seconds, factorizations, continued, mode_change,
                                   codim2_value, codim2_t});
            table.add_row(row);
            // Rewritten after every point: a killed study leaves a complete table.
            table.write(directory + "/sweep.csv");
            if (curve)
              table.write(directory + "/critical_curve.csv");
            std::ostringstream line;
            line << std::setprecision(10) << "  " << sweep.label() << " = " << sweep.value(k)
                 << ": critical t = " << t << std::setprecision(3);
            if (std::isfinite(t))
              line << " (resolution " << resolution << "), mode "
                   << (n_mode > 0 ? study.describe_mode(mode_class) : std::string("-"));
            line << ", " << factorizations << " factorizations"
                 << (continued == 1 ? " (continued)" : "") << ", " << seconds << " s";
            if (!failure.empty())
              line << "; " << failure;
            log(line.str());
            point_lines.push_back(line.str());
            // Everything the next points depend on: a killed study goes on from here (--resume).
            io::CheckpointWriter w;
            io::ranks::put_point_header(w, block_begin, k + 1, table);
            predictor.save(w);
            w.put(previous.k);
            w.put(previous.value);
            w.put(previous.t);
            w.put_vector(previous.mode_class);
            w.put(std::uint64_t(previous.n_unknowns));
            w.put(refused);
            w.put(n_without);
            io::write_checkpoint(directory, checkpoint_application, parameters, w);
          }
        }
      catch (io::Interrupted &)
        {
          log("interrupted; continue with: " + study.application + " --resume " + directory);
          throw;
        }
      if (n_ranks > 1 || !resumed.done.empty())
        {
          // Rank 0: every rank's rows (in rank order: the values' order) and
          // lines. A block's first value (and one after values taken from
          // a resumed run's checkpoints) was run without the previous one:
          // a change of the critical mode there is found here, without a
          // codimension-2 estimate.
          const auto rows  = io::ranks::gather_rows(table.row_values());
          const auto lines = io::ranks::gather_lines(point_lines);
          n_without        = io::ranks::sum(n_without);
          const auto all_refused = io::ranks::all_gather_lines({refused});
          refused.clear();
          for (const auto &r : all_refused)
            if (!r.empty())
              refused += std::string(refused.empty() ? "" : "; ") + r;
          if (io::ranks::rank() == 0)
            {
              if (n_ranks > 1)
                {
                  log("the " + std::to_string(n_ranks) + " ranks' values:");
                  for (const auto &l : lines)
                    log(l);
                }
              io::CSVTable whole = table;
              whole.clear_rows();
              // ..., mode columns, dofs, seconds, factorizations, continued, mode_change
              const std::size_t mode0 = 4 + n_more, change = mode0 + n_mode + 4;
              std::vector<double> last_class;
              for (unsigned int r = 0; r < rows.size(); ++r)
                {
                  auto row = rows[r];
                  const std::vector<double> c(row.begin() + mode0, row.begin() + mode0 + n_mode);
                  const bool classified =
                    n_mode > 0 && std::any_of(c.begin(), c.end(), [](double x) { return std::isfinite(x); });
                  if (classified)
                    {
                      if (row[change] == 0 && !last_class.empty() &&
                          !std::equal(c.begin(), c.end(), last_class.begin(), last_class.end(),
                                      [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); }))
                        {
                          row[change] = 1;
                          std::ostringstream m;
                          m << std::setprecision(6) << "  the critical mode changes from "
                            << study.describe_mode(last_class) << " to " << study.describe_mode(c)
                            << " between " << sweep.label() << " = " << sweep.value(r - 1)
                            << " and " << sweep.value(r)
                            << "; no codimension-2 estimate (the values were run apart: on "
                               "different ranks, or before and after a resume)";
                          log(m.str());
                        }
                      last_class = c;
                    }
                  whole.add_row(row);
                }
              whole.write(shared + "/sweep.csv");
              if (curve)
                whole.write(shared + "/critical_curve.csv");
            }
          else
            {
              log("the values of this rank are in " + shared + "/sweep.csv");
            }
        }
      // Not before: a rank stopped while the others still run resumes from it.
      io::remove_checkpoint(directory);
      log("output in " + shared + "/");
      if (!refused.empty())
        throw io::InputError("Parameter sweep", "Values", sweep.entry(), refused);
      if (n_without > 0)
        throw io::RunFailure(std::to_string(n_without) + " of " + std::to_string(sweep.size()) +
                             " values have no located critical point (see " + shared +
                             "/sweep-log.txt)");
    }
  } // namespace solvers
} // namespace cosmo
