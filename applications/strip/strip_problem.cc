// The strip's energy is assembled here: its derivatives by the chain rule
// (kinematics::strip_energy_derivatives), or by nested Sacado in all 16 local
// variables (COSMO_NESTED_AD, the reference): the heavy translation unit of part 2.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/solvers/run_start.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/local_variables.h>
#include <cosmo/assembly/reduced_rod_table.h>
#include <cosmo/config.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/ranks.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/kinematics/rotation.h>
#include <cosmo/kinematics/strip.h>
#include <cosmo/materials/energy_derivatives.h>

#include "strip_problem.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace strip
  {
    namespace
    {
      constexpr int n_local = kinematics::strip_local_variables;

      /// The local variables a shape function of component c drives: its value (u, theta1,
      /// theta3 at 0-2, 6, 7) with weight N and its derivative (3-5, 8, 9) with weight N'.
      assembly::Drive
      strip_drive(const unsigned int c, const double N, const double dN)
      {
        if (c < 3)
          return {2, {c, 3 + c, 0}, {N, dN, 0}};
        return {2, {c == 3 ? 6u : 7u, c == 3 ? 8u : 9u, 0}, {N, dN, 0}};
      }

      /// What table.h5 records about a strip's run (its units, its parameters).
      assembly::TableDescription
      table_description(const ParameterHandler &prm)
      {
        assembly::TableDescription d;
        d.application     = "strip";
        d.version         = COSMO_VERSION;
        d.parameters      = io::checkpoint_parameters(prm);
        d.energy_unit     = "E w h";
        d.force_unit      = "E w h";
        d.moment_unit     = "E w h L";
        d.length_unit     = "L";
        return d;
      }
    } // namespace

    StripProblem::StripProblem() = default;
    StripProblem::~StripProblem()
    {
      dof_handler.clear();
    }

    void
    StripProblem::setup_system()
    {
      triangulation.clear();
      std::vector<std::vector<double>> steps(1);
      for (unsigned int i = 0; i < n_cells; ++i)
        {
          auto vertex = [&](const double k) {
            const double xi = -1 + 2 * k / n_cells;
            return mesh_kind == "graded" ? 0.5 * strip_width * std::sin(0.5 * M_PI * xi) :
                                           0.5 * strip_width * xi;
          };
          steps[0].push_back(vertex(i + 1) - vertex(i));
        }
      GridGenerator::subdivided_hyper_rectangle(triangulation, steps,
                                                Point<1>(-0.5 * strip_width),
                                                Point<1>(0.5 * strip_width));
      fe = std::make_unique<FESystem<1>>(FE_Q<1>(degree), 5);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(*fe);
      const unsigned int n = dof_handler.n_dofs();

      // Gauge rows: int u = 0 (0-2), int eta u3 = 0 (3), int eta u2 = 0 (4),
      // int theta1 = 0 (5), as integrals of the shape functions.
      std::array<Vector<double>, 6> rows;
      for (auto &r : rows)
        r.reinit(n);
      const QGauss<1>                      quadrature(degree + 1);
      FEValues<1>                          fev(*fe, quadrature,
                          update_values | update_quadrature_points | update_JxW_values);
      std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
      DynamicSparsityPattern               dsp(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          cell->get_dof_indices(idx);
          for (const auto i : idx)
            dsp.add_entries(i, idx.begin(), idx.end());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < idx.size(); ++i)
              {
                const unsigned int c   = fe->system_to_component_index(i).first;
                const double       N   = fev.shape_value(i, q) * fev.JxW(q);
                const double       eta = fev.quadrature_point(q)[0];
                if (c < 3)
                  rows[c][idx[i]] += N;
                if (c == 2)
                  rows[3][idx[i]] += eta * N;
                if (c == 1)
                  rows[4][idx[i]] += eta * N;
                if (c == 3)
                  rows[5][idx[i]] += N;
              }
        }
      setup_bordered_system(dsp, rows, linear_solver_name);
      report = [this](const std::string &line) { say(line); };

      solution.reinit(n_unknowns());
      const auto ref = kinematics::RodStrains::reference().as_array();
      for (unsigned int k = 0; k < n_strains; ++k)
        solution[n_field + n_gauge + k] = ref[k];
    }

    void
    StripProblem::residual_scales(double &force, double &length) const
    {
      length = strip_width;
      force  = plate_law->young() * strip_width * thickness;
    }

    void
    StripProblem::gauge_weights(std::array<double, 6> &w) const
    {
      const double W = strip_width;
      // int u (L^2), int eta u (L^3), int theta1 (L)
      w = {{1 / (W * W), 1 / (W * W), 1 / (W * W), 1 / (W * W * W), 1 / (W * W * W), 1 / W}};
    }

    int
    StripProblem::load_derivative(const Vector<double> &U, const double lambda, Vector<double> &dR)
    {
      // A natural curvature of t acts on the field rows too: the residual's
      // central difference in t (exact for a curvature linear in t and a
      // quadratic law, to round-off).
      if (natural_curvature)
        return BifurcationProblem::load_derivative(U, lambda, dR);
      dR.reinit(n_unknowns());
      // Prescribed strain rows e - eP(t), free rows dPsi/de - t nbar.
      const auto rate = prescribed_strain_rate(lambda);
      const auto nbar = resultants_at(1.);
      for (unsigned int k = 0; k < n_strains; ++k)
        dR[n_field + n_gauge + k] = strain_is_free[k] ? -nbar[k] : -rate[k];
      return 0;
    }

    namespace
    {
      /// Per-thread work space of the strip assembly (WorkStream scratch).
      struct StripScratch
      {
        StripScratch(const FiniteElement<1> &fe, const Quadrature<1> &full, const Quadrature<1> &reduced)
          : fev_full(fe, full, update_values | update_gradients | update_quadrature_points | update_JxW_values)
          , fev_reduced(fe, reduced,
                        update_values | update_gradients | update_quadrature_points | update_JxW_values)
          , U_local(fe.n_dofs_per_cell())
          , drives(fe.n_dofs_per_cell())
        {}
        StripScratch(const StripScratch &o)
          : StripScratch(o.fev_full.get_fe(), o.fev_full.get_quadrature(), o.fev_reduced.get_quadrature())
        {}
        FEValues<1>                               fev_full, fev_reduced;
        std::vector<double>                       U_local;
        std::vector<assembly::Drive>              drives;
        std::array<double, n_local>               z, g;
        std::array<double, n_local * n_local>     H;
      };

    } // namespace

    int
    StripProblem::assemble_field(const Vector<double> &       U,
                                 const std::array<double, 6> &e,
                                 Vector<double> *             R,
                                 const bool                   jacobian,
                                 FullMatrix<double> &         E,
                                 FieldIntegrals &             out)
    {
      const unsigned int        dpc = fe->n_dofs_per_cell();
      std::vector<unsigned int> comp(dpc);
      for (unsigned int i = 0; i < dpc; ++i)
        comp[i] = fe->system_to_component_index(i).first;
      const QGauss<1> full(degree + 1), reduced(reduced_shear ? degree : degree + 1);
      // COSMO_NESTED_AD: nested AD in all 16 local variables, the former
      // assembly and the reference of the chain rule, to measure against
      // (benchmarks/strip_table.sh).
      static const bool nested_ad = std::getenv("COSMO_NESTED_AD") != nullptr;
      const materials::PlateLawAt law(*plate_law, thickness);

      // Cells are independent: the worker runs on all cores, the copier adds
      // the contributions in cell order (so sums are reproducible).
      // The cell's scalars: its energy, then the six resultants dE/de.
      auto worker = [&](const typename DoFHandler<1>::active_cell_iterator &cell,
                        StripScratch &                                      sc,
                        assembly::CellContribution &                        c) {
        for (unsigned int i = 0; i < dpc; ++i)
          sc.U_local[i] = U[c.dof_indices[i]];
        auto &z = sc.z;
        auto &g = sc.g;
        auto &H = sc.H;
        for (const bool membrane_bending : {true, false})
          {
            FEValues<1> &fev = membrane_bending ? sc.fev_full : sc.fev_reduced;
            fev.reinit(cell);
            for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
              {
                z.fill(0.);
                for (unsigned int i = 0; i < dpc; ++i)
                  sc.drives[i] = strip_drive(comp[i], fev.shape_value(i, q), fev.shape_grad(i, q)[0]);
                assembly::gather_local_variables<n_local>(sc.drives, sc.U_local, z);
                for (unsigned int k = 0; k < n_strains; ++k)
                  z[10 + k] = e[k];
                const double eta  = fev.quadrature_point(q)[0];
                const double dA   = fev.JxW(q);
                const auto   kbar = natural_curvature_at(eta, load_parameter);
                double       W    = 0;
                if (nested_ad)
                  materials::internal::differentiate<n_local>(
                    z,
                    [&](const auto &x) { return kinematics::strip_energy(x, eta, law, membrane_bending, kbar); },
                    jacobian,
                    W,
                    g,
                    H);
                else
                  kinematics::strip_energy_derivatives(z, eta, law, membrane_bending, jacobian, W, g, H, kbar);
                c.scalars[0] += W * dA;
                for (unsigned int k = 0; k < n_strains; ++k)
                  c.scalars[1 + k] += g[10 + k] * dA;
                assembly::add_point<n_local>(sc.drives, g, H, dA, jacobian, c.residual, c.hessian);
                if (jacobian)
                  assembly::add_strain_blocks<n_local>(sc.drives, H, dA, 10, n_strains, c.border,
                                                       c.border_block);
              }
          }
      };

      const auto totals = assembly::EnergyAssembler<1>::assemble(
        dof_handler, worker, StripScratch(*fe, full, reduced),
        assembly::CellContribution(dpc, n_strains, 1 + n_strains), field_target(R, jacobian, E));
      out.energy = totals.scalars[0];
      for (unsigned int k = 0; k < n_strains; ++k)
        out.resultants[k] = totals.scalars[1 + k];
      out.min_elastic_J = 0;
      return 0;
    }

    assembly::ReducedRodState
    StripProblem::solve()
    {
      solvers::NaturalParameterContinuation driver(continuation_settings, newton_settings);
      driver.progress = [this](const std::string &s) { say(s); };
      checkpoints.connect(driver, *this, timer);
      driver.run(*this, solution);
      return last_state;
    }

    std::vector<solvers::EventRecord>
    StripProblem::follow_branches()
    {
      follow_path(arclength_settings, newton_settings, solution,
                  [this](const std::string &s) { say(s); });
      return event_records();
    }

    std::vector<std::pair<std::string, std::string>>
    StripProblem::quantity_columns() const
    {
      std::vector<std::pair<std::string, std::string>> c;
      for (const auto &n : {"step", "branch", "t", "newton_iterations", "residual"})
        c.emplace_back(n, "");
      c.emplace_back("energy", "E w h");
      for (const auto &s : kinematics::strain_names)
        c.emplace_back(s, s[0] == 'n' ? "1" : "1/L");
      for (unsigned int k = 0; k < 6; ++k)
        c.emplace_back(kinematics::resultant_names[k], k < 3 ? "E w h" : "E w h L");
      for (const auto &s : kinematics::strain_names)
        c.emplace_back("K_" + s + "_" + s, "");
      c.emplace_back("n_negative_eigenvalues", "");
      c.emplace_back("smallest_eigenvalue", "");
      // The section's out-of-plane deflection at both edges and the centre:
      // mirror-image branches (+phi, -phi of a pitchfork) have the same strains
      // and energy, these tell them apart.
      for (const auto &n : {"u2_left_edge", "u2_centre", "u2_right_edge"})
        c.emplace_back(n, "L");
      return c;
    }

    void
    StripProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      solvers::start_run(record, *this, options, prm, output_directory, false);
      setup_system();
      std::ostringstream info;
      info << "  strip w = " << strip_width << ", h = " << thickness << " (w/h = "
           << strip_width / thickness << "), " << n_cells << " " << mesh_kind << " cells, Q"
           << degree << ", " << n_field << " field DoFs; E = " << plate_law->young()
           << ", Poisson " << plate_law->poisson() << ", shear " << (reduced_shear ? "reduced" : "full");
      say(info.str());
      record.attempt([&]() {
        if (table.enabled())
          {
            io::PhaseTimer::Scope scope(timer, "constitutive table");
            set_load_parameter(1.);
            assembly::run_constitutive_table(table, *this, solution, newton_settings, last_state,
                                             record, output_directory, table_description(prm));
          }
        else if (arclength_settings.enabled)
          {
            checkpoints.connect_to(record);
            follow_branches();
          }
        else
          {
            checkpoints.connect_to(record);
            solve();
          }
      });
      if (!table.enabled() && path().size() > 1)
        {
          std::vector<solvers::PathRow> rows;
          for (const auto &p : path())
            rows.push_back({p.branch, p.t, p.n_negative});
          say(solvers::path_summary(rows, events(), [this](const unsigned int k) {
            return k < event_parities.size() && std::isfinite(event_parities[k]) ?
                     ", mode " + symmetry_name(event_parities[k]) :
                     std::string();
          }));
        }
      io::JSON j       = record.summary();
      j["width"]       = strip_width;
      j["thickness"]   = thickness;
      j["field_dofs"]  = n_field;
      assembly::add_state_to_summary(j, last_state, *this, *this, [this](const unsigned int k, io::JSON &x) {
        const std::string tag = Utilities::int_to_string(k + 1, 2);
        x["state_vtu"]        = "event-" + tag + ".vtu";
        if (events()[k].kind == Event::Kind::branch_point)
          x["mode_vtu"] = "event-" + tag + "-mode.vtu";
        if (k < event_parities.size() && std::isfinite(event_parities[k]))
          {
            x["mode_parity"]   = event_parities[k];
            x["mode_symmetry"] = symmetry_name(event_parities[k]);
          }
      });
      record.finish(j, timer, n_condensed_states);
    }

    void
    run_strip(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      if (!sweep.enabled())
        {
          StripProblem problem;
          problem.parse_parameters(prm);
          if (io::ranks::idle(assembly::ConstitutiveTable::enabled_in(prm)))
            return;
          problem.run(options, prm);
          return;
        }
      // A study of the strip is one of its first critical point.
      solvers::CriticalPointStudy study;
      study.application     = "strip";
      study.mode_columns    = {"mode_symmetry"};
      study.further_columns = assembly::ReducedRodProblem::critical_point_column_names();
      study.describe_mode   = [](const std::vector<double> &c) {
        return c[0] > 0 ? std::string("symmetric") :
               c[0] < 0 ? std::string("antisymmetric") : std::string("mixed");
      };
      study.make_run = [](ParameterHandler &p) {
        return std::make_unique<solvers::CriticalPointRunOf<StripProblem>>(p);
      };
      study.declare_parameters = &StripProblem::declare_parameters;
      solvers::run_critical_point_study(prm, options, sweep, study);
    }
  } // namespace strip
} // namespace cosmo
