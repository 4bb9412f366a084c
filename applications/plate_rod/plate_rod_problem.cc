// The plate bounded by a rod (part 3): the problem's driver interface and
// its run; the assembly is in assembly.cc, the discretization in
// discretization.cc and mesh.cc, the reports in postprocess.cc.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/solvers/run_start.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/assumed_shear.h>
#include <cosmo/assembly/local_variables.h>
#include <cosmo/config.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/resources.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/materials/energy_derivatives.h>

#include <cosmo/materials/growth_admissibility.h>

#include "plate_rod_problem.h"

#include <chrono>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
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

    materials::RodNaturalState
    PlateRodParameters::rim_natural_state(const Point<2> &X, const kinematics::RimFrame &frame,
                                       const double t) const
    {
      materials::RodNaturalState n;
      n.reference_strains = kinematics::rim_reference_strains(X, frame);
      n.growth            = rod_growth_at(t);
      // The model's factor f on the shear stiffnesses GA1, GA2 (the Kirchhoff
      // penalty) as the weight sqrt(f) on the shear strains: K -> D K D, the
      // couplings by sqrt(f), which keeps K positive definite.
      for (const unsigned int k : {0u, 1u})
        n.weights[k] = std::sqrt(model->shear_scale());
      return n;
    }

    kinematics::PlateGrowthAtPoint
    PlateRodParameters::growth_at(const Point<2> &X, const double t) const
    {
      auto g              = kinematics::PlateGrowthAtPoint::of(plate_growth.value(X, t));
      g.natural_curvature = plate_growth.natural_curvature(X, t);
      return g;
    }

    double
    PlateRodParameters::thickness_at(const Point<2> &X) const
    {
      return thickness_profile ? thickness * thickness_profile->value(Point<3>(X[0], X[1], X.norm())) :
                                 thickness;
    }

    void
    PlateRodProblem::setup_system()
    {
      energy_assembly.clear();
      // A stiffness with its constraints eliminated: every diagonal entry is nonzero.
      system.set_nonzero_diagonal(true);
      discretization.reinit();
      discretization.reinit_system(system);
      solution.reinit(discretization.n_dofs());
    }

    double
    PlateRodProblem::energy(const Vector<double> &U)
    {
      Vector<double> R;
      AssertThrow(residual(U, R) == 0, ExcMessage("the energy cannot be evaluated at this state"));
      return energy_assembly.energy();
    }

    int
    PlateRodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
      if (energy_assembly.recall(U, load_parameter, R))
        return std::isfinite(energy_assembly.energy()) ? 0 : 1;
      io::PhaseTimer::Scope scope(timer, "assembly (residual)");
      return energy_assembly.assemble(U, load_parameter, &R, false);
    }

    int
    PlateRodProblem::setup_jacobian(const Vector<double> &U)
    {
      {
        io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
        if (energy_assembly.assemble(U, load_parameter, nullptr, true) != 0)
          return 1;
      }
      io::PhaseTimer::Scope scope(timer, "factorization");
      try
        {
          system.factorize();
        }
      catch (std::exception &e)
        {
          // (on a distributed mesh only MUMPS's own failure is every rank's:
          // anything else ends this rank, and so all)
          if (distributed_mesh && dynamic_cast<const solvers::FactorizationFailure *>(&e) == nullptr)
            throw;
          factorized_at.reinit(0);
          record.say(std::string("  factorization failed: ") + e.what());
          return 1;
        }
      factorized_at   = U;
      factorized_load = load_parameter;
      return 0;
    }

    int
    PlateRodProblem::solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst)
    {
      io::PhaseTimer::Scope scope(timer, "solve");
      system.solve(rhs, dst, {});
      discretization.distribute(dst);
      return 0;
    }

    double
    PlateRodProblem::jacobian_abs_form(const Vector<double> &v) const
    {
      return system.absolute_quadratic_form(v);
    }

    void
    PlateRodProblem::residual_weights(Vector<double> &w) const
    {
      // Nodal forces against E h R, nodal moments against E h R^2.
      const double F = plate_law->young() * thickness * radius;
      w.reinit(n_unknowns());
      for (unsigned int i = 0; i < w.size(); ++i)
        w[i] = discretization.dof_component[i] < 3 ? 1 / F : 1 / (F * radius);
    }

    double
    PlateRodParameters::mismatch(const double t) const
    {
      // Uniform isotropic plate growth only: g_r = g_t independent of r.
      const auto g0 = plate_growth.factors(0, t);
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const auto g = plate_growth.factors(radius * i / 10., t);
          if (std::abs(g[0] - g0[0]) > 1e-14 || std::abs(g[1] - g0[0]) > 1e-14)
            return std::numeric_limits<double>::quiet_NaN();
        }
      return analysis::growth_mismatch(g0[0], rod_growth_at(t));
    }

    void
    PlateRodProblem::solve_flat_state(const double t)
    {
      set_load_parameter(t);
      solvers::newton_solve(*this, solution, newton_settings);
    }

    std::vector<solvers::EventRecord>
    PlateRodProblem::follow_branches()
    {
      solvers::ArclengthContinuation driver(arclength_settings, newton_settings);
      driver.progress = [this](const std::string &s) { record.say(s); };
      if (write_output)
        {
          if (record.has_checkpoint())
            {
              driver.load(record.checkpoint());
              load_progress(record.checkpoint());
            }
          // After every converged step: the driver's state and what is written so far.
          driver.checkpoint = [this, &driver]() {
            io::PhaseTimer::Scope scope(timer, "checkpoint");
            io::CheckpointWriter  w;
            driver.save(w);
            save_progress(w);
            record.write_checkpoint(w);
          };
        }
      return driver.run(*this, solution, load_parameter);
    }

    void
    PlateRodProblem::locate_from_guess()
    {
      solvers::ArclengthContinuation driver(arclength_settings, newton_settings);
      driver.progress = [this](const std::string &s) { record.say(s); };
      const auto record = solvers::locate_continued_critical_point(driver, *this, *critical_guess,
                                                                  newton_settings);
      solution = Vector<double>(record.state.begin(), record.state.end());
      // The report below takes the inertia and smallest eigenvalue from the
      // last factorization, of the last Newton iterate: it differs from the
      // located state by the last update (critical_point.h), on which neither
      // depends beyond the located precision; not factorizing again is what
      // the continued point saves.
      report_with_last_factorization = true;
      solvers::StepReport report;
      report.t          = record.event.lambda;
      report.n_negative = record.event.n_negative_after;
      set_load_parameter(report.t);
      solvers::report_converged_step(*this, solution, report);
    }

    void
    PlateRodProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      write_output = true;
      solvers::start_run(record, *this, options, prm, output_directory, distributed_mesh);
      setup_system();
      record.say(discretization.describe());
      if (!stiffness_file.empty())
        record.say(rim_stiffness_text(*this));

      // The closed forms (Kirchhoff, small strain, uniform isotropic growth).
      double             first_closed = NAN;
      std::string        closed_text;
      const io::JSON     closed = closed_forms(first_closed, closed_text);
      if (!closed_text.empty())
        record.say(closed_text);

      steps_columns = plate_rod::steps_columns(discretization);

      record.attempt([&]() {
        if (critical_guess)
          return locate_from_guess();
        if (record.has_checkpoint())
          {
            follow_branches();
            return;
          }
        set_load_parameter(path_start);
        try
          {
            solve_flat_state(path_start);
          }
        catch (solvers::NewtonFailure &e)
          {
            throw io::RunFailure(std::string("the flat state at the start did not converge: ") +
                                 e.what());
          }
        if (setup_jacobian(solution) == 0 && n_negative_eigenvalues() > 0)
          throw io::InputError(
            "Growth path", "Start", std::to_string(path_start),
            "the flat state there is already unstable (" +
              std::to_string(n_negative_eigenvalues()) +
              " negative eigenvalues) and no initial guess of a buckled state can be given: "
              "start the path below the first critical growth (t = 0 always is)");
        follow_branches();
      });
      finish_run(closed);
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
            return std::make_unique<solvers::CriticalPointRunOf<PlateRodProblem>>(p);
          };
          study.declare_parameters = &PlateRodProblem::declare_parameters;
          return solvers::run_critical_point_study(prm, options, sweep, study);
        }
      PlateRodProblem problem;
      problem.parse_parameters(prm);
      // A distributed mesh: every rank runs the path on its part of the mesh.
      if (io::ranks::idle(problem.distributed_mesh))
        return;
      if (problem.distributed_mesh && io::ranks::size() > 1)
        io::collective_interrupts(MPI_COMM_WORLD);
      problem.run(options, prm);
    }
  } // namespace plate_rod
} // namespace cosmo
