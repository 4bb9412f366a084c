// The run of part 3: the flat start, the path with its checkpoint or a
// continued critical point, the summary; the study's entry (run_plate_rod).
#include <deal.II/base/utilities.h>

#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/solvers/newton.h>
#include <cosmo/solvers/path_checkpoints.h>
#include <cosmo/solvers/run_start.h>

#include "run.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {
    namespace
    {
      /// The rim's stiffness file in the log: the full 6x6's diagonal and largest coupling.
      std::string
      rim_stiffness_text(const PlateRodParameters &p)
      {
        std::ostringstream m;
        m << "  rim stiffness from " << p.stiffness_file << ", the full 6x6: diagonal";
        for (const double k : p.rod_stiffness)
          m << " " << k;
        m << ", largest coupling K_ab / sqrt(K_aa K_bb) = " << p.stiffness_coupling;
        if (p.stiffness_coupling > 0)
          m << " (the closed forms below use the diagonal only)";
        return m.str();
      }
    } // namespace

    void
    PlateRodRun::solve_flat_state(const double t)
    {
      problem.set_load_parameter(t);
      solvers::newton_solve(problem, problem.solution, problem.newton_settings);
    }

    std::vector<solvers::EventRecord>
    PlateRodRun::follow_branches()
    {
      solvers::ArclengthContinuation driver(problem.arclength_settings, problem.newton_settings);
      driver.progress = [this](const std::string &s) { problem.record.say(s); };
      // After every converged step: the driver's state and what is written so
      // far (a run's, not a programmatic path's); --resume goes on from it.
      solvers::PathCheckpoints checkpoints;
      if (problem.write_output)
        {
          checkpoints.connect_to(problem.record);
          checkpoints.connect(driver, *this, problem.timer);
        }
      return driver.run(problem, problem.solution, problem.load_parameter);
    }

    void
    PlateRodRun::locate_from_guess()
    {
      solvers::locate_and_report_continued_critical_point(
        problem, *critical_guess, problem.arclength_settings, problem.newton_settings,
        [this](const std::string &s) { problem.record.say(s); },
        [this](const Vector<double> &U) {
          problem.solution = U;
          // The report takes the inertia and smallest eigenvalue from the
          // last factorization, of the last Newton iterate: it differs from
          // the located state by the last update (critical_point.h), on
          // which neither depends beyond the located precision; not
          // factorizing again is what the continued point saves.
          problem.factorization.with_last = true;
        });
    }

    void
    PlateRodRun::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      auto &record          = problem.record;
      problem.write_output  = true;
      solvers::start_run(record, problem, options, prm, problem.output_directory,
                         problem.distributed_mesh);
      problem.setup_system();
      record.say(problem.discretization.describe());
      if (!problem.stiffness_file.empty())
        record.say(rim_stiffness_text(problem));

      // The closed forms (Kirchhoff, small strain, uniform isotropic growth).
      double             first_closed = NAN;
      std::string        closed_text;
      const io::JSON     closed = problem.closed_forms(first_closed, closed_text);
      if (!closed_text.empty())
        record.say(closed_text);

      problem.steps_columns = plate_rod::steps_columns(problem.discretization);

      record.attempt([&]() {
        if (critical_guess)
          return locate_from_guess();
        if (record.has_checkpoint())
          {
            follow_branches();
            return;
          }
        const double path_start = problem.path_start;
        problem.set_load_parameter(path_start);
        try
          {
            solve_flat_state(path_start);
          }
        catch (solvers::NewtonFailure &e)
          {
            throw io::RunFailure(std::string("the flat state at the start did not converge: ") +
                                 e.what());
          }
        if (problem.setup_jacobian(problem.solution) == 0 && problem.n_negative_eigenvalues() > 0)
          throw io::InputError(
            "Growth path", "Start", std::to_string(path_start),
            "the flat state there is already unstable (" +
              std::to_string(problem.n_negative_eigenvalues()) +
              " negative eigenvalues) and no initial guess of a buckled state can be given: "
              "start the path below the first critical growth (t = 0 always is)");
        follow_branches();
      });
      finish_run(closed);
    }

    void
    PlateRodRun::save_progress(io::CheckpointWriter &w) const
    {
      w.put_vector(problem.solution);
      w.put(problem.load_parameter);
      w.put(std::uint64_t(problem.states.size()));
      for (const auto &s : problem.states)
        {
          for (const double x : {s.t, s.plate_energy, s.rod_energy, s.w_centre, s.max_abs_w,
                                 s.max_abs_inplane, s.rim_radial_strain, s.smallest_eigenvalue})
            w.put(x);
          w.put_vector(s.rim_w_amplitude);
          w.put_vector(s.rim_ur_amplitude);
          w.put(s.n_negative);
          w.put(s.branch);
        }
      w.put(std::uint64_t(problem.located_events.size()));
      for (const auto &e : problem.located_events)
        e.save(w);
      w.put_vector(problem.steps_row);
      problem.save_postprocessors(w);
      io::ranks::put_mesh_ranks(w, problem.distributed_mesh);
    }

    void
    PlateRodRun::load_progress(io::CheckpointReader &r)
    {
      auto &states         = problem.states;
      auto &located_events = problem.located_events;
      r.get_vector(problem.solution);
      problem.load_parameter = r.get_double();
      states.resize(r.get_size());
      for (auto &s : states)
        {
          for (double *x : {&s.t, &s.plate_energy, &s.rod_energy, &s.w_centre, &s.max_abs_w,
                            &s.max_abs_inplane, &s.rim_radial_strain, &s.smallest_eigenvalue})
            *x = r.get_double();
          s.rim_w_amplitude  = r.get_vector();
          s.rim_ur_amplitude = r.get_vector();
          s.n_negative       = r.get_int();
          s.branch           = r.get_unsigned();
        }
      located_events.resize(r.get_size());
      for (auto &e : located_events)
        e.load(r);
      problem.steps_row = r.get_vector();
      problem.load_postprocessors(r);
      io::ranks::check_mesh_ranks(r, problem.distributed_mesh, "Mesh", "Distributed");
      if (problem.distributed_mesh)
        io::ranks::check_checkpoints_agree(states.size(), "their last step");

      if (!r.at_end())
        throw std::runtime_error("the checkpoint holds more than this run reads");
      if (problem.solution.size() != problem.discretization.n_dofs())
        throw std::runtime_error("the checkpoint's state has another number of unknowns");
      std::ostringstream m;
      m << "  going on after step " << states.size() - 1 << " at t = " << std::setprecision(10)
        << problem.load_parameter << " (" << located_events.size() << " events located before)";
      problem.record.say(m.str());
    }

    std::vector<double>
    PlateRodRun::classify_critical_mode(const Vector<double> &mode) const
    {
      const auto c = classify_mode(problem.discretization, mode);
      return {double(c.first), double(c.second)};
    }

    std::vector<double>
    PlateRodRun::critical_point_columns(const solvers::EventRecord &e) const
    {
      double      closed = NAN;
      std::string text;
      problem.closed_forms(closed, text);
      return {problem.mismatch(e.event.lambda), closed};
    }

    void
    PlateRodRun::finish_run(const io::JSON &closed)
    {
      const auto &states         = problem.states;
      const auto &located_events = problem.located_events;
      const auto &discretization = problem.discretization;
      if (!states.empty())
        {
          std::vector<solvers::PathRow>                 rows;
          std::vector<solvers::BifurcationProblem::Event> ev;
          for (const auto &st : states)
            rows.push_back({st.branch, st.t, st.n_negative});
          for (const auto &e : located_events)
            ev.push_back(e.event);
          problem.record.say(solvers::path_summary(rows, ev, [&](const unsigned int k) {
            std::string words = ", mismatch Delta = " + io::format_significant(problem.mismatch(located_events[k].event.lambda), 6);
            if (!located_events[k].mode.empty())
              {
                const Vector<double> mode(located_events[k].mode.begin(), located_events[k].mode.end());
                const auto           c = classify_mode(discretization, mode);
                words += ", mode n = " + std::to_string(c.first) + (c.second ? " out of plane" : " planar");
              }
            return words;
          }));
        }

      io::JSON j       = problem.record.summary();
      j["model"]       = problem.model->name();
      j["domain"]      = problem.domain == "sector" ? "sector" : "full disc";
      if (problem.domain == "sector")
        j["sector_n"] = problem.sector_n;
      j["radius"]    = problem.radius;
      j["thickness"] = problem.thickness;
      j["dofs"]      = discretization.n_dofs();
      j["cells"]     = discretization.triangulation.get().n_global_active_cells();
      if (problem.distributed_mesh)
        j["distributed_mesh_ranks"] = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      j["closed_form"] = closed;
      if (!states.empty())
        {
          // The last converged state (of an interrupted run: where it stopped).
          const auto &s     = states.back();
          io::JSON    last  = io::JSON::object();
          last["step"]      = static_cast<unsigned int>(states.size() - 1);
          last["branch"]    = s.branch;
          last["t"]         = s.t;
          last["dome_height"] = s.w_centre;
          last["n_negative_eigenvalues"] = s.n_negative;
          j["last_state"] = last;
        }
      io::JSON ev      = io::JSON::array();
      for (unsigned int k = 0; k < located_events.size(); ++k)
        {
          const auto &e = located_events[k].event;
          io::JSON    x = io::JSON::object();
          x["kind"]              = e.name();
          x["t"]                 = e.lambda;
          x["mismatch"]          = problem.mismatch(e.lambda);
          x["branch"]            = e.branch;
          x["n_negative_before"] = e.n_negative_before;
          x["n_negative_after"]  = e.n_negative_after;
          const std::string tag  = Utilities::int_to_string(k + 1, 2);
          const std::string vtu  = problem.distributed_mesh ? ".pvtu" : ".vtu";
          x["state_vtu"]         = "event-" + tag + vtu;
          if (!located_events[k].mode.empty())
            {
              Vector<double> mode(located_events[k].mode.begin(), located_events[k].mode.end());
              ModeMargins    margins;
              const auto     c = classify_mode(discretization, mode, &margins);
              x["mode_number"]  = c.first;
              x["mode_type"]    = c.second ? "out of plane" : "planar";
              x["mode_type_out_of_plane"] = c.second ? 1 : 0;
              x["mode_type_margin"]   = margins.type;
              x["mode_number_margin"] = margins.number;
              x["mode_vtu"]     = "event-" + tag + "-mode" + vtu;
              x["eigenvalue"]   = e.eigenvalue;
            }
          solvers::add_location_to_json(e, x);
          ev.push_back(x);
        }
      j["events"] = ev;
      problem.record.finish(j, problem.timer, states.size());
    }

    void
    run_plate_rod(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      sweep.refuse_distributed_mesh(prm, "Mesh");
      if (sweep.enabled())
        {
          solvers::CriticalPointStudy study;
          study.application        = "plate_rod";
          study.arclength_sections = false; // its own 'Growth path / Stop at first event'
          study.mode_columns    = {"mode_number", "mode_out_of_plane"};
          study.further_columns = {"mismatch_critical", "closed_form_mismatch"};
          study.describe_mode   = [](const std::vector<double> &c) {
            std::ostringstream m;
            m << "n = " << c[0] << (c[1] == 1 ? " out of plane" : c[1] == 0 ? " planar" : "");
            return m.str();
          };
          study.make_run = [](ParameterHandler &p) {
            return std::make_unique<solvers::CriticalPointRunOf<PlateRodRun>>(p);
          };
          study.declare_parameters = &PlateRodProblem::declare_parameters;
          return solvers::run_critical_point_study(prm, options, sweep, study);
        }
      PlateRodRun run;
      run.parse_parameters(prm);
      const PlateRodProblem &problem = run.get_problem();
      // A distributed mesh: every rank runs the path on its part of the mesh.
      if (io::ranks::idle(problem.distributed_mesh))
        return;
      if (problem.distributed_mesh && io::ranks::size() > 1)
        io::collective_interrupts(MPI_COMM_WORLD);
      run.run(options, prm);
    }
  } // namespace plate_rod
} // namespace cosmo
