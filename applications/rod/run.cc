// The rod's run: the start, the path with its events and checkpoints, the summary.
#include <deal.II/base/utilities.h>

#include <cosmo/io/parameter_sweep.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/solvers/newton.h>
#include <cosmo/solvers/path_checkpoints.h>
#include <cosmo/solvers/run_start.h>

#include "run.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      io::JSON
      vector_json(const double *x, const unsigned int n)
      {
        io::JSON a = io::JSON::array();
        for (unsigned int i = 0; i < n; ++i)
          a.push_back(x[i]);
        return a;
      }

      /// A ring's link, twist and writhe, and the self-contact's gap, pairs and force, where there are.
      void
      add_topology(io::JSON &x, const RodState &s)
      {
        if (!std::isnan(s.link))
          {
            x["link"]   = s.link;
            x["twist"]  = s.twist;
            x["writhe"] = s.writhe;
          }
        if (!std::isnan(s.contact_gap))
          {
            // (+infinity where no pair is within 4a: JSON has no infinity)
            x["contact_gap"]   = std::isfinite(s.contact_gap) ? io::JSON(s.contact_gap) : io::JSON();
            x["contact_pairs"] = s.contact_pairs;
            x["contact_force"] = s.contact_force;
          }
      }

      std::string
      support_name(const RodEnd &e)
      {
        return e.support == RodEnd::Support::clamped ? "clamped" :
               e.support == RodEnd::Support::pinned  ? "pinned" :
               e.support == RodEnd::Support::free    ? "free" :
                                                       "rotation only";
      }
    } // namespace

    void
    RodRun::solve_start()
    {
      // The reference is the stress-free state only where the natural
      // strains at the start are its own; Newton finds the start otherwise.
      problem.set_load_parameter(problem.start);
      try
        {
          solvers::newton_solve(problem, problem.solution, problem.newton_settings);
        }
      catch (solvers::NewtonFailure &e)
        {
          throw io::RunFailure(std::string("the state at the path's start did not converge: ") + e.what());
        }
    }

    void
    RodRun::check_start() const
    {
      // The element's logarithm needs its relative rotation below pi: a
      // start past the limit is a mesh too coarse for the shape asked. The
      // rotations asked are those of the natural strains (a natural shape)
      // or of the circle and the seam's twist (a ring): measured on the
      // nodes, a turn past pi would read as a shorter turn the other way.
      const double h       = problem.element_length();
      double       largest = 0;
      if (problem.ring)
        {
          const double bend = 2 * M_PI / problem.n_elements,
                       seam = 2 * M_PI * RodParameters::evaluate(problem.seam_twist, 0, problem.start)[0];
          largest           = std::sqrt(bend * bend + seam * seam);
        }
      else if (problem.shape == "natural")
        for (unsigned int e = 0; e < problem.n_elements; ++e)
          {
            const auto k = problem.natural_state((e + 0.5) * h, problem.start).reference_strains;
            largest      = std::max(largest, h * std::sqrt(k[3] * k[3] + k[4] * k[4] + k[5] * k[5]));
          }
      if (largest > problem.rotation_limit)
        throw io::InputError("Rod", "Number of elements", std::to_string(problem.n_elements),
                             "enough elements that none turns by more than 'Largest element rotation' = " +
                               io::format_number(problem.rotation_limit * 180 / M_PI) +
                               " degrees: the start's elements turn by up to " +
                               io::format_number(largest * 180 / M_PI) + " degrees; use at least " +
                               std::to_string(static_cast<unsigned int>(
                                 std::ceil(problem.n_elements * largest / problem.rotation_limit))) +
                               " elements");
    }

    void
    RodRun::follow_path()
    {
      if (!problem.arclength_settings.enabled)
        {
          solvers::NaturalParameterContinuation driver(problem.continuation_settings, problem.newton_settings);
          driver.progress = [this](const std::string &s) { problem.record.say(s); };
          solvers::PathCheckpoints checkpoints;
          checkpoints.connect_to(problem.record);
          checkpoints.connect(driver, *this, problem.timer);
          driver.run(problem, problem.solution);
          return;
        }
      solvers::ArclengthContinuation driver(problem.arclength_settings, problem.newton_settings);
      driver.progress = [this](const std::string &s) { problem.record.say(s); };
      solvers::PathCheckpoints checkpoints;
      checkpoints.connect_to(problem.record);
      checkpoints.connect(driver, *this, problem.timer);
      driver.run(problem, problem.solution, problem.load_parameter);
    }

    void
    RodRun::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      auto &record = problem.record;
      solvers::start_run(record, problem, options, prm, problem.output_directory, false);
      problem.setup_system();
      std::ostringstream m;
      m << "  rod of length " << problem.length << ", " << problem.n_elements << " helicoidal elements, "
        << problem.n_unknowns() << " unknowns; "
        << (problem.ring ? std::string("a closed ring") :
                           "end A " + support_name(problem.ends[0]) + ", end B " + support_name(problem.ends[1]))
        << "\n  law: " << problem.law->description();
      record.say(m.str());
      check_start();
      record.attempt([&]() {
        try
          {
            if (critical_guess)
              return locate_from_guess();
            if (!record.has_checkpoint())
              solve_start();
            follow_path();
          }
        catch (io::RunFailure &e)
          {
            // A path stopped by the law's range says so.
            throw io::RunFailure(problem.refusals.explain(e.what()));
          }
      });
      finish_run();
    }

    void
    RodRun::locate_from_guess()
    {
      solvers::locate_and_report_continued_critical_point(
        problem, *critical_guess, problem.arclength_settings, problem.newton_settings,
        [this](const std::string &s) { problem.record.say(s); },
        [this](const Vector<double> &U) { problem.solution = U; });
    }

    std::vector<double>
    RodRun::classify_critical_mode(const Vector<double> &mode) const
    {
      std::array<double, 3> weight{};
      for (unsigned int k = 0; k < problem.n_nodes(); ++k)
        {
          const Tensor<1, 3> u = problem.displacement(mode, k);
          for (unsigned int i = 0; i < 3; ++i)
            weight[i] += u[i] * u[i];
        }
      return {double(1 + std::max_element(weight.begin(), weight.end()) - weight.begin())};
    }

    std::vector<double>
    RodRun::critical_point_columns(const solvers::EventRecord &e) const
    {
      for (unsigned int k = 0; k < problem.located_events.size(); ++k)
        if (problem.located_events[k].event.lambda == e.event.lambda)
          return {problem.event_states[k].end_loads[1][2]};
      return {NAN};
    }

    void
    RodRun::save_progress(io::CheckpointWriter &w) const
    {
      w.put_vector(problem.solution);
      w.put(problem.load_parameter);
      w.put(std::uint64_t(problem.states.size()));
      for (const auto &s : problem.states)
        {
          w.put(s.t);
          w.put(s.energy);
          for (unsigned int i = 0; i < 3; ++i)
            w.put(s.end_position[i]);
          for (unsigned int k = 0; k < 2; ++k)
            for (const double x : s.end_loads[k])
              w.put(x);
          w.put(s.max_rotation);
          for (const double x : {s.link, s.twist, s.writhe})
            w.put(x);
          if (problem.contact_radius > 0)
            for (const double x : {s.contact_gap, double(s.contact_pairs), s.contact_force})
              w.put(x);
          w.put(s.n_negative);
          w.put(s.branch);
        }
      w.put(std::uint64_t(problem.located_events.size()));
      for (const auto &e : problem.located_events)
        e.save(w);
      w.put_vector(problem.steps_row);
      problem.save_postprocessors(w);
    }

    void
    RodRun::load_progress(io::CheckpointReader &r)
    {
      r.get_vector(problem.solution);
      problem.load_parameter = r.get_double();
      problem.states.resize(r.get_size());
      for (auto &s : problem.states)
        {
          s.t      = r.get_double();
          s.energy = r.get_double();
          for (unsigned int i = 0; i < 3; ++i)
            s.end_position[i] = r.get_double();
          for (unsigned int k = 0; k < 2; ++k)
            for (double &x : s.end_loads[k])
              x = r.get_double();
          s.max_rotation = r.get_double();
          for (double *x : {&s.link, &s.twist, &s.writhe})
            *x = r.get_double();
          if (problem.contact_radius > 0)
            {
              s.contact_gap   = r.get_double();
              s.contact_pairs = static_cast<unsigned int>(r.get_double());
              s.contact_force = r.get_double();
            }
          s.n_negative   = r.get_int();
          s.branch       = r.get_unsigned();
        }
      problem.located_events.resize(r.get_size());
      for (auto &e : problem.located_events)
        e.load(r);
      problem.event_states.clear();
      for (const auto &e : problem.located_events)
        problem.event_states.push_back(
          problem.describe(Vector<double>(e.state.begin(), e.state.end()), e.event.lambda));
      problem.steps_row = r.get_vector();
      problem.load_postprocessors(r);
      if (problem.solution.size() != problem.n_unknowns())
        throw std::runtime_error("the checkpoint's state has another number of unknowns");
      std::ostringstream m;
      m << "  going on after step " << problem.states.size() - 1 << " at t = " << std::setprecision(10)
        << problem.load_parameter << " (" << problem.located_events.size() << " events located before)";
      problem.record.say(m.str());
    }

    io::JSON
    RodRun::event_json(const unsigned int k)
    {
      const auto &record     = problem.located_events[k];
      const auto &e          = record.event;
      io::JSON    x          = io::JSON::object();
      x["kind"]              = e.name();
      x["t"]                 = e.lambda;
      x["branch"]            = e.branch;
      x["n_negative_before"] = e.n_negative_before;
      x["n_negative_after"]  = e.n_negative_after;
      const std::string tag  = Utilities::int_to_string(k + 1, 2);
      x["state_vtu"]         = "event-" + tag + ".vtu";
      if (!record.mode.empty())
        {
          x["mode_vtu"]   = "event-" + tag + "-mode.vtu";
          x["eigenvalue"] = e.eigenvalue;
        }
      // The loads of the supports, the end and the ring's topology at the event.
      const RodState &s = problem.event_states[k];
      x["loads_A"]           = vector_json(s.end_loads[0].data(), 6);
      x["loads_B"]           = vector_json(s.end_loads[1].data(), 6);
      x["end_position"]      = vector_json(&s.end_position[0], 3);
      add_topology(x, s);
      solvers::add_location_to_json(e, x);
      return x;
    }

    void
    RodRun::finish_run()
    {
      const auto &states = problem.states;
      const auto &events = problem.located_events;
      if (!states.empty())
        {
          std::vector<solvers::PathRow>                   rows;
          std::vector<solvers::BifurcationProblem::Event> ev;
          for (const auto &s : states)
            rows.push_back({s.branch, s.t, s.n_negative});
          for (const auto &e : events)
            ev.push_back(e.event);
          problem.record.say(solvers::path_summary(rows, ev, [](unsigned int) { return std::string(); }));
        }
      io::JSON j             = problem.record.summary();
      j["length"]            = problem.length;
      j["elements"]          = problem.n_elements;
      j["unknowns"]          = problem.n_unknowns();
      j["ring"]              = problem.ring;
      j["law"]               = problem.law->description();
      if (!states.empty())
        {
          const auto &s              = states.back();
          io::JSON    last           = io::JSON::object();
          last["step"]               = static_cast<unsigned int>(states.size() - 1);
          last["branch"]             = s.branch;
          last["t"]                  = s.t;
          last["energy"]             = s.energy;
          last["end_position"]       = vector_json(&s.end_position[0], 3);
          last["loads_A"]            = vector_json(s.end_loads[0].data(), 6);
          last["loads_B"]            = vector_json(s.end_loads[1].data(), 6);
          last["max_element_rotation"] = s.max_rotation;
          last["n_negative_eigenvalues"] = s.n_negative;
          add_topology(last, s);
          j["last_state"]            = last;
        }
      io::JSON ev = io::JSON::array();
      for (unsigned int k = 0; k < events.size(); ++k)
        ev.push_back(event_json(k));
      j["events"] = ev;
      problem.record.finish(j, problem.timer, states.size());
    }

    void
    run_rod(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      if (sweep.enabled())
        {
          // A study of the rod is one of its first critical point.
          solvers::CriticalPointStudy study;
          study.application     = "rod";
          study.mode_columns    = {"mode_direction"};
          study.further_columns = {"force_B_z"};
          study.describe_mode   = [](const std::vector<double> &c) {
            return "along e" + std::to_string(static_cast<int>(c[0]));
          };
          study.make_run = [](ParameterHandler &p) {
            return std::make_unique<solvers::CriticalPointRunOf<RodRun>>(p);
          };
          study.declare_parameters = &RodParameters::declare_parameters;
          return solvers::run_critical_point_study(prm, options, sweep, study);
        }
      RodRun run;
      run.parse_parameters(prm);
      run.run(options, prm);
    }
  } // namespace rod
} // namespace cosmo
