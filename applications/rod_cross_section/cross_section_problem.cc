// CrossSectionProblem: the run, the path, the coarse-mesh start, the modes' symmetries, the
// field's assembly (the section's energy: assembly.cc).
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools_interpolate.h>

#include <cosmo/solvers/run_start.h>
#include <cosmo/assembly/reduced_rod_table.h>
#include <cosmo/io/checkpoint.h>
#include <cosmo/config.h>
#include <cosmo/io/resources.h>

#include "cross_section_problem.h"
#include "section_assembly.h"
#include "section_output.h"

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      constexpr unsigned int n_strains = assembly::ReducedRodProblem::n_strains;
      constexpr unsigned int n_gauge   = assembly::ReducedRodProblem::n_gauge;
    } // namespace

    std::vector<double>
    CrossSectionProblem::classify_critical_mode(const Vector<double> &mode) const
    {
      std::vector<double> c;
      for (unsigned int axis = 0; axis < 2; ++axis)
        {
          const double p = discretization.mode_parity(mode, axis);
          c.push_back(p > 0.5 ? 1. : p < -0.5 ? -1. : std::isfinite(p) ? 0. : NAN);
        }
      return c;
    }

    CrossSectionState
    CrossSectionProblem::current_state()
    {
      return condensed_state(solution);
    }

    bool
    CrossSectionProblem::first_step_guess(const double t, Vector<double> &U)
    {
      // (not on a distributed mesh: the interpolation between two meshes needs their cells on
      // the same ranks, which p4est's partitions of two refinements do not give)
      if (coarse_start_levels == 0 || geometry.refinements == 0 || parameters_text.empty() ||
          distributed_mesh)
        return false;
      io::PhaseTimer::Scope scope(timer, "coarse-mesh start");
      // A copy of this problem on the section refined once less, from the run's own parameters.
      ParameterHandler prm;
      declare_parameters(prm);
      // (skipping the library's own entries, Postprocess and Additional shared libraries)
      prm.parse_input_from_string(parameters_text, "", /*skip_undefined=*/true);
      CrossSectionProblem coarse;
      coarse.parse_parameters(prm);
      coarse.quiet                = true;
      coarse.parameters_text      = parameters_text;
      coarse.geometry.refinements = geometry.refinements - 1;
      coarse.coarse_start_levels  = coarse_start_levels - 1;
      try
        {
          coarse.setup_system();
        }
      catch (const io::InputError &e)
        {
          // E.g. a shape that needs a refinement more than the coarser mesh has.
          say("  coarse-mesh start: no coarser mesh of this section (" + std::string(e.what()) +
              "); the first step starts from the reference state");
          return false;
        }
      // The interpolation follows the cells' hierarchy: the coarse cells must be the same
      // (interpolate_to_different_mesh asserts it, to the last bit). A section meshed anew per
      // refinement is not nested; nor is one shifted to its centroid, whose discrete centroid
      // moves with the refinement.
      const bool nested = GridTools::have_same_coarse_mesh(coarse.discretization.get_mesh().get(),
                                                           discretization.get_mesh().get());
      if (!nested)
        {
          say("  coarse-mesh start: the section refined once less has other coarse cells (a "
              "shape meshed anew per refinement, or shifted to its centroid); the first step "
              "starts from the reference state");
          return false;
        }
      Vector<double> Uc = coarse.solution;
      coarse.first_step_guess(t, Uc);
      coarse.set_load_parameter(t);
      solvers::NewtonResult r;
      try
        {
          // (the first step's Newton, as the driver solves it)
          solvers::NewtonSettings newton = newton_settings;
          newton.reuse_factorization     = continuation_settings.reuse_factorization;
          r = solvers::newton_solve(coarse, Uc, newton);
        }
      catch (const solvers::NewtonFailure &e)
        {
          say("  coarse-mesh start: Newton failed on " + std::to_string(coarse.n_unknowns()) +
              " unknowns (" + e.what() + "); starting from the reference state, also after a "
              "cut-back");
          coarse_start_levels = 0; // a cut-back would only repeat the failing coarse solves
          return false;
        }
      const unsigned int n_u = discretization.n_u(), coarse_n_u = coarse.discretization.n_u();
      Vector<double>     field_coarse(coarse_n_u), field(n_u);
      for (unsigned int i = 0; i < coarse_n_u; ++i)
        field_coarse[i] = Uc[i];
      VectorTools::interpolate_to_different_mesh(coarse.discretization.get_dof_handler(), field_coarse,
                                                 discretization.get_dof_handler(), field);
      for (unsigned int i = 0; i < n_u; ++i)
        U[i] = field[i];
      for (unsigned int k = 0; k < n_gauge + n_strains; ++k)
        U[n_u + k] = Uc[coarse_n_u + k];
      coarse_start_report = coarse.coarse_start_report + (coarse.coarse_start_report.empty() ? "" : ", ") +
                            std::to_string(r.iterations) + " on " +
                            std::to_string(coarse.n_unknowns());
      say("  first step started on coarser meshes (Newton iterations on unknowns: " +
          coarse_start_report + ")");
      return true;
    }

    CrossSectionState
    CrossSectionProblem::solve()
    {
      if (arclength_settings.enabled)
        {
          follow_path(arclength_settings, newton_settings, solution,
                      [this](const std::string &s) { say(s); });
          return last_state;
        }
      solvers::NaturalParameterContinuation driver(continuation_settings, newton_settings);
      driver.progress = [this](const std::string &s) { say(s); };
      checkpoints.connect(driver, *this, timer);
      driver.run(*this, solution);
      return last_state;
    }


    std::vector<std::pair<std::string, std::string>>
    CrossSectionProblem::quantity_columns() const
    {
      std::vector<std::pair<std::string, std::string>> c;
      for (const auto &n : {"step", "branch", "t", "newton_iterations", "residual", "cutbacks"})
        c.emplace_back(n, "");
      c.emplace_back("energy", "E L^2");
      for (const auto &s : kinematics::strain_names)
        c.emplace_back(s, s[0] == 'n' ? "1" : "1/L");
      for (unsigned int k = 0; k < 6; ++k)
        c.emplace_back(kinematics::resultant_names[k], k < 3 ? "E L^2" : "E L^3");
      for (unsigned int k = 1; k <= 6; ++k)
        c.emplace_back("multiplier" + std::to_string(k), "");
      for (const auto &s : kinematics::strain_names)
        c.emplace_back("K_" + s + "_" + s, "");
      c.emplace_back("n_negative_eigenvalues", "");
      c.emplace_back("min_elastic_J", "");
      return c;
    }

    void
    CrossSectionProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      solvers::start_run(record, *this, options, prm, output_directory, distributed_mesh);
      {
        io::PhaseTimer::Scope scope(timer, "setup");
        setup_system();
      }
      std::ostringstream info;
      info << "  section: " << geometry.shape << ", "
           << discretization.get_mesh().get().n_global_active_cells() << " cells, Q" << degree << ", "
           << discretization.n_u() << " field DoFs + 6 multipliers + 6 strains; area "
           << discretization.properties().area << "; estimated peak memory "
           << io::format_bytes(io::estimated_memory(n_unknowns(), degree));
      if (distributed_mesh)
        info << "; the mesh distributed over " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
             << (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ? " rank" : " ranks");
      say(info.str());
      if (!geometry.meshing_summary.empty())
        say("  " + geometry.meshing_summary);
      if (geometry.applied_shift.norm() > 0)
        say("  mesh shifted by (" + io::format_significant(geometry.applied_shift[0]) + ", " +
            io::format_significant(geometry.applied_shift[1]) + ") to put its centroid at the origin");
      for (const auto &m : materials.descriptions())
        say("  " + m);
      if (distributed_mesh)
        say("  linear section properties (reference): not computed on a distributed mesh "
            "(their warping problem is solved on one process: run the section with "
            "Distributed = false, on a coarser mesh if need be)");
      else
        {
          {
            io::PhaseTimer::Scope scope(timer, "section properties");
            reference_properties = discretization.linear_section_properties();
          }
          say_reference_properties(reference_properties, [this](const std::string &s) { say(s); });
        }
      for (unsigned int l = 0; l < surface_layers.layers().size(); ++l)
        say("  " + surface_layers.layers()[l].description() + " (arc length " +
            io::format_significant(discretization.get_surface_length()[l]) + ")");

      if (table.enabled())
        {
          // The path to t = 1 (the base state, redone on --resume: it is
          // short), then the table, whose checkpoints hold its points.
          record.attempt([&]() {
            solve();
            run_table(prm);
          });
          write_summary();
          return;
        }
      // Checkpoints after every converged step; --resume goes on from the last.
      checkpoints.connect_to(record);
      record.attempt([&]() { solve(); });
      if (!record.failed())
        say_result(last_state, timer, [this](const std::string &s) { say(s); });
      write_summary();
    }

    void
    CrossSectionProblem::run_table(const ParameterHandler &prm)
    {
      io::PhaseTimer::Scope scope(timer, "constitutive table");
      say("constitutive table around the state at t = 1:");
      set_load_parameter(1.);
      assembly::TableDescription d;
      d.application     = "rod_cross_section";
      d.version         = COSMO_VERSION;
      d.parameters      = io::checkpoint_parameters(prm);
      assembly::run_constitutive_table(table, *this, solution, newton_settings, last_state, record,
                                       output_directory, d);
    }

    int
    CrossSectionProblem::assemble_field(const Vector<double> &       U,
                                        const std::array<double, 6> &e,
                                        Vector<double> *             R,
                                        const bool                   jacobian,
                                        FullMatrix<double> &         E,
                                        FieldIntegrals &             results)
    {
      // The section's energy (section_assembly.h) at this load: its growth first.
      if (!discretization.update_growth_cache(load_parameter))
        return 1; // growth inadmissible at this trial load
      const assembly::AssemblyTarget target = field_target(R, jacobian, E);
      const assembly::AssemblyTotals totals = assemble_bulk(discretization, *this, U, e, target);
      if (!totals.admissible)
        return 1; // recoverable: Newton's line search or the driver cuts back
      results.energy        = totals.scalars[0];
      results.min_elastic_J = totals.minimum;
      for (unsigned int k = 0; k < n_strains; ++k)
        results.resultants[k] = totals.scalars[1 + k];
      if (!discretization.get_surface_faces().empty())
        assemble_surface_layers(discretization, *this, load_parameter, U, e, target, results.energy,
                                results.resultants);
      return 0;
    }

    void
    CrossSectionProblem::residual_scales(double &force, double &length) const
    {
      length = discretization.properties().diameter;
      force  = materials.max_young() * length * length;
    }
  } // namespace rod
} // namespace cosmo
