// The strip's energy is differentiated here (Sacado, 16 local variables):
// the heavy translation unit of part 2.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/config.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/kinematics/rotation.h>
#include <cosmo/kinematics/strip.h>
#include <cosmo/materials/energy_derivatives.h>

#include "strip_problem.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace strip
  {
    namespace
    {
      constexpr int n_local = kinematics::strip_local_variables;

      /// Which local variables a shape function of component c drives: value and derivative.
      std::pair<unsigned int, unsigned int>
      local_indices(const unsigned int c)
      {
        if (c < 3)
          return {c, 3 + c};
        return {c == 3 ? 6u : 7u, c == 3 ? 8u : 9u};
      }
    } // namespace

    StripProblem::StripProblem() = default;
    StripProblem::~StripProblem()
    {
      dof_handler.clear();
    }

    void
    StripProblem::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Strip");
      prm.declare_entry("Width", "1", Patterns::Double(0), "Width w of the strip (length unit).");
      prm.declare_entry("Thickness", "0.01", Patterns::Double(0),
                        "Thickness h of the plate; h < w.");
      prm.declare_entry("Number of cells", "40", Patterns::Integer(1, 100000),
                        "Cells across the width.");
      prm.declare_entry("Mesh", "graded", Patterns::Selection("graded|uniform"),
                        "graded: vertices at eta = (w/2) sin(pi xi/2), xi uniform in "
                        "[-1, 1], finer toward the free edges where the boundary layers "
                        "are; uniform: equal cells.");
      prm.declare_entry("Polynomial degree", "2", Patterns::Integer(1, 4),
                        "Degree p of FE_Q(p) for u and theta.");
      prm.declare_entry("Shear integration", "reduced", Patterns::Selection("reduced|full"),
                        "reduced: the transverse shear energy with p Gauss points (against "
                        "shear locking, doc/specification/strip.md); full: p + 1 like the rest.");
      prm.leave_subsection();
      materials::NaghdiPlateLaw::declare_parameters(prm);
      assembly::ReducedRodProblem::declare_strain_parameters(prm);
      solvers::NewtonSettings::declare_parameters(prm);
      solvers::ContinuationSettings::declare_parameters(prm);
      solvers::ArclengthSettings::declare_parameters(prm);
      assembly::ConstitutiveTable::declare_parameters(prm);
      io::ParameterSweep::declare_parameters(prm);
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory", "output/strip", Patterns::Anything(),
                        "Directory for parameters.prm, summary.json, steps.csv, "
                        "section-NNNN.vtu and log.txt (created if needed).");
      prm.leave_subsection();
    }

    void
    StripProblem::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Strip");
      strip_width   = prm.get_double("Width");
      thickness     = prm.get_double("Thickness");
      n_cells       = prm.get_integer("Number of cells");
      mesh_kind     = prm.get("Mesh");
      degree        = prm.get_integer("Polynomial degree");
      reduced_shear = prm.get("Shear integration") == "reduced";
      if (!(strip_width > 0))
        throw io::InputError("Strip", "Width", prm.get("Width"), "must be positive");
      if (!(thickness > 0))
        throw io::InputError("Strip", "Thickness", prm.get("Thickness"), "must be positive");
      if (!(thickness < strip_width))
        throw io::InputError("Strip", "Thickness", prm.get("Thickness"),
                             "must be smaller than the width " + prm.get("Width") +
                               " (a strip is a plate: h << w)");
      prm.leave_subsection();
      law.parse_parameters(prm);
      law.thickness = thickness;
      parse_strain_parameters(prm);
      newton_settings.parse_parameters(prm);
      continuation_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);
      table.parse_parameters(prm);
      if (table.enabled())
        for (const unsigned int k : {table.first, table.second})
          if (strain_is_free[k])
            throw io::InputError("Constitutive table",
                                 k == table.first ? "First strain" : "Second strain",
                                 kinematics::strain_names[k],
                                 "a prescribed strain: this one is free ('Rod strains / Mode' "
                                 "or 'Free strains'), so its value would be ignored");
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      prm.leave_subsection();
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
      force  = law.young * strip_width * thickness;
    }

    void
    StripProblem::gauge_weights(std::array<double, 6> &w) const
    {
      const double W = strip_width;
      // int u (L^2), int eta u (L^3), int theta1 (L)
      w = {{1 / (W * W), 1 / (W * W), 1 / (W * W), 1 / (W * W * W), 1 / (W * W * W), 1 / W}};
    }

    int
    StripProblem::load_derivative(const Vector<double> &, const double lambda, Vector<double> &dR)
    {
      dR.reinit(n_unknowns());
      const auto rate = prescribed_strain_rate(lambda);
      for (unsigned int k = 0; k < n_strains; ++k)
        if (!strain_is_free[k])
          dR[n_field + n_gauge + k] = -rate[k];
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
        {}
        StripScratch(const StripScratch &o)
          : StripScratch(o.fev_full.get_fe(), o.fev_full.get_quadrature(), o.fev_reduced.get_quadrature())
        {}
        FEValues<1>                               fev_full, fev_reduced;
        std::vector<double>                       U_local;
        std::array<double, n_local>               z, g;
        std::array<double, n_local * n_local>     H;
      };

      /// One cell's contributions (WorkStream copy data).
      struct StripCellContribution
      {
        explicit StripCellContribution(const unsigned int dpc)
          : idx(dpc)
          , r(dpc)
          , K(dpc, dpc)
          , B(dpc, 6)
          , E(6, 6)
        {}
        std::vector<types::global_dof_index> idx;
        Vector<double>                       r;
        FullMatrix<double>                   K, B, E;
        double                               energy = 0;
        std::array<double, 6>                resultants{};
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

      // Cells are independent: the worker runs on all cores, the copier adds
      // the contributions in cell order (so sums are reproducible).
      auto worker = [&](const typename DoFHandler<1>::active_cell_iterator &cell,
                        StripScratch &                                      sc,
                        StripCellContribution &                             c) {
        cell->get_dof_indices(c.idx);
        for (unsigned int i = 0; i < dpc; ++i)
          sc.U_local[i] = U[c.idx[i]];
        c.r      = 0;
        c.energy = 0;
        c.resultants.fill(0.);
        if (jacobian)
          {
            c.K = 0;
            c.B = 0;
            c.E = 0;
          }
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
                  {
                    const auto [v, d] = local_indices(comp[i]);
                    z[v] += sc.U_local[i] * fev.shape_value(i, q);
                    z[d] += sc.U_local[i] * fev.shape_grad(i, q)[0];
                  }
                for (unsigned int k = 0; k < n_strains; ++k)
                  z[10 + k] = e[k];
                const double eta = fev.quadrature_point(q)[0];
                const double dA  = fev.JxW(q);
                double       W   = 0;
                materials::internal::differentiate<n_local>(
                  z,
                  [&](const auto &x) { return kinematics::strip_energy(x, eta, law, membrane_bending); },
                  jacobian,
                  W,
                  g,
                  H);
                c.energy += W * dA;
                for (unsigned int k = 0; k < n_strains; ++k)
                  c.resultants[k] += g[10 + k] * dA;
                for (unsigned int i = 0; i < dpc; ++i)
                  {
                    const auto [vi, di] = local_indices(comp[i]);
                    const double Ni = fev.shape_value(i, q), Di = fev.shape_grad(i, q)[0];
                    c.r[i] += (g[vi] * Ni + g[di] * Di) * dA;
                    if (!jacobian)
                      continue;
                    for (unsigned int j = 0; j < dpc; ++j)
                      {
                        const auto [vj, dj] = local_indices(comp[j]);
                        const double Nj = fev.shape_value(j, q), Dj = fev.shape_grad(j, q)[0];
                        c.K(i, j) += (H[n_local * vi + vj] * Ni * Nj + H[n_local * vi + dj] * Ni * Dj +
                                      H[n_local * di + vj] * Di * Nj + H[n_local * di + dj] * Di * Dj) *
                                     dA;
                      }
                    for (unsigned int k = 0; k < n_strains; ++k)
                      c.B(i, k) += (H[n_local * vi + 10 + k] * Ni + H[n_local * di + 10 + k] * Di) * dA;
                  }
                if (jacobian)
                  for (unsigned int k = 0; k < n_strains; ++k)
                    for (unsigned int l = 0; l < n_strains; ++l)
                      c.E(k, l) += H[n_local * (10 + k) + 10 + l] * dA;
              }
          }
      };

      out.energy = 0;
      out.resultants.fill(0.);
      auto copier = [&](const StripCellContribution &c) {
        out.energy += c.energy;
        for (unsigned int k = 0; k < n_strains; ++k)
          out.resultants[k] += c.resultants[k];
        add_local_contribution(c.idx, c.r, c.K, c.B, &c.E, R, jacobian, E);
      };
      WorkStream::run(dof_handler.begin_active(), dof_handler.end(), worker, copier,
                      StripScratch(*fe, full, reduced), StripCellContribution(dpc));
      out.min_elastic_J = 0;
      return 0;
    }

    assembly::ReducedRodState
    StripProblem::solve()
    {
      solvers::NaturalParameterContinuation driver(continuation_settings, newton_settings);
      driver.progress = [this](const std::string &s) { say(s); };
      driver.run(*this, solution);
      return last_state;
    }

    assembly::ReducedRodState
    StripProblem::resolve(const std::array<double, 6> &strains)
    {
      set_target_strains(strains);
      set_load_parameter(1.);
      solvers::newton_solve(*this, solution, newton_settings);
      last_state = condensed_state(solution);
      return last_state;
    }

    void
    StripProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution   = U;
      last_state = condensed_state(solution);
      const auto &s = last_state;
      // The eigenvalue of smallest magnitude of the Hessian on the
      // constrained field space (free strains condensed): the one that
      // crosses zero where the section buckles.
      Vector<double> mask, mode;
      mode_mask(mask);
      const double smallest = solvers::smallest_eigenvalue(*this, mask, mode, 50);
      record_state(report, s);
      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  t = " << std::setw(8) << report.t
           << "  Newton " << std::setw(2) << report.newton_iterations << "  Psi = "
           << std::setprecision(8) << s.energy << "  neg.eig. " << s.n_negative
           << "  min|eig| " << std::setprecision(3) << smallest << "  strains (";
      for (unsigned int k = 0; k < 6; ++k)
        line << (k ? ", " : "") << std::setprecision(6) << s.strains[k];
      line << ")";
      say(line.str());
      if (!write_output)
        return;
      std::vector<double> row = {double(report.step), double(report.branch), report.t,
                                 double(report.newton_iterations), report.residual_norm, s.energy};
      row.insert(row.end(), s.strains.begin(), s.strains.end());
      row.insert(row.end(), s.resultants.begin(), s.resultants.end());
      for (unsigned int k = 0; k < 6; ++k)
        row.push_back(s.stiffness(k, k));
      row.push_back(s.n_negative);
      row.push_back(smallest);
      steps_table.add_row(row);
      steps_table.write(output_directory + "/steps.csv");
      write_section(output_directory + "/section-" + Utilities::int_to_string(report.step, 4) +
                      ".vtu",
                    solution);
      write_piece(output_directory + "/strip-" + Utilities::int_to_string(report.step, 4) +
                  ".vtu");
    }

    void
    StripProblem::write_piece(const std::string &file) const
    {
      // A piece of the strip in 3D: the mid-surface phi(eta, s) = r(s) + R(s)
      // y(eta) swept along the helix of the current strains, over one turn or
      // three widths (whichever is shorter), 24 slices; fields eta, s and the
      // director d = R q.
      const auto                   e = strains_of(solution);
      const kinematics::RodStrains strains(e);
      const double                 k = strains.kappa.norm();
      const double                 L = k > 0 ? std::min(2 * M_PI / k, 3 * strip_width) : 3 * strip_width;
      const unsigned int           n_slices = 24;
      std::vector<Point<1>>        unit;
      for (unsigned int i = 0; i <= degree; ++i)
        unit.emplace_back(double(i) / degree);
      const Quadrature<1>         nodes(unit);
      FEValues<1>                 fev(*fe, nodes, update_values | update_quadrature_points);
      Vector<double>              field(solution.begin(), solution.begin() + n_field);
      std::vector<Vector<double>> values(nodes.size(), Vector<double>(5));
      std::vector<DataOutBase::Patch<2, 3>> patches;
      const unsigned int                    np = degree + 1;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(field, values);
          for (unsigned int slice = 0; slice < n_slices; ++slice)
            {
              DataOutBase::Patch<2, 3> patch;
              patch.n_subdivisions       = degree;
              patch.reference_cell       = ReferenceCells::Quadrilateral;
              patch.points_are_available = true;
              patch.data.reinit(5 + 3, np * np);
              for (unsigned int j = 0; j < np; ++j)
                {
                  const double X3 = L * (slice + double(j) / degree) / n_slices;
                  const auto   R  = kinematics::helix_rotation(strains.kappa, X3);
                  const auto   r  = kinematics::helix_position(strains.nu, strains.kappa, X3);
                  for (unsigned int i = 0; i < np; ++i)
                    {
                      const unsigned int   pt  = j * np + i;
                      const double         eta = fev.quadrature_point(i)[0];
                      Tensor<1, 3, double> theta;
                      theta[0]                = values[i][3];
                      theta[2]                = values[i][4];
                      const auto         Q    = kinematics::rotation_exp(theta);
                      const Tensor<1, 3> y({eta + values[i][0], values[i][1], values[i][2]});
                      const Tensor<1, 3> q({Q[0][1], Q[1][1], Q[2][1]});
                      const Tensor<1, 3> x = r + R * y, d = R * q;
                      patch.data(0, pt)    = eta;
                      patch.data(1, pt)    = X3;
                      for (unsigned int c = 0; c < 3; ++c)
                        {
                          patch.data(2 + c, pt) = d[c];
                          patch.data(5 + c, pt) = x[c];
                        }
                    }
                }
              for (unsigned int v = 0; v < 4; ++v)
                {
                  const unsigned int pt = ((v & 2) ? degree * np : 0) + ((v & 1) ? degree : 0);
                  patch.vertices[v] =
                    Point<3>(patch.data(5, pt), patch.data(6, pt), patch.data(7, pt));
                }
              patch.patch_index = patches.size();
              patches.push_back(std::move(patch));
            }
        }
      std::vector<std::tuple<unsigned int, unsigned int, std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>
        vectors = {{2, 4, "director", DataComponentInterpretation::component_is_part_of_vector}};
      DataOutBase::VtkFlags flags;
      io::write_file_atomically(file, [&](std::ostream &o) {
        DataOutBase::write_vtu(patches, {"eta", "arc_length", "director", "director", "director"},
                               vectors, flags, o);
      });
    }

    double
    StripProblem::mode_parity(const Vector<double> &mode) const
    {
      // The out-of-plane displacement u2 (component 1) alone: a mesh not
      // symmetric about eta = 0 has no parity (NaN).
      return geometry::reflection_parity(
        dof_handler, geometry::mirror_dofs(MappingQ1<1>(), dof_handler, 0, strip_width), mode,
        {0., 1.});
    }

    std::vector<double>
    StripProblem::classify_critical_mode(const Vector<double> &mode) const
    {
      // +1 symmetric, -1 antisymmetric about the centre line, 0 mixed
      const double p = mode_parity(mode);
      return {p > 0.5 ? 1. : p < -0.5 ? -1. : std::isfinite(p) ? 0. : NAN};
    }

    std::string
    StripProblem::symmetry_name(const double parity)
    {
      return parity > 0.5 ? "symmetric" : parity < -0.5 ? "antisymmetric" : "mixed";
    }

    void
    StripProblem::located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode)
    {
      ReducedRodProblem::located_event(e, U, mode);
      event_parities.push_back(mode ? mode_parity(*mode) : NAN);
      if (mode)
        {
          std::ostringstream m;
          m << "  mode " << symmetry_name(event_parities.back())
            << " about the centre line (parity " << std::setprecision(3) << event_parities.back()
            << ")";
          say(m.str());
        }
      if (!write_output)
        return;
      const std::string tag = Utilities::int_to_string(located_events.size(), 2);
      write_section(output_directory + "/event-" + tag + ".vtu", U);
      if (mode)
        {
          // The mode as a perturbation of the state at the event, scaled to
          // a tenth of the width, so that its shape can be seen.
          Vector<double> V = U;
          double         m = 0;
          for (unsigned int i = 0; i < n_field; ++i)
            m = std::max(m, std::abs((*mode)[i]));
          if (m > 0)
            V.add(0.1 * strip_width / m, *mode);
          write_section(output_directory + "/event-" + tag + "-mode.vtu", V);
        }
    }

    std::vector<solvers::EventRecord>
    StripProblem::follow_branches()
    {
      follow_path(arclength_settings, newton_settings, solution,
                  [this](const std::string &s) { say(s); });
      return event_records();
    }

    void
    StripProblem::write_section(const std::string &file, const Vector<double> &U) const
    {
      // The deformed cross-section curve y(eta) in the director frame, with
      // the thickness-line director q as a vector field: line cells.
      const QGauss<1> points(degree + 1); // any points along each cell
      std::vector<Point<1>> unit;
      for (unsigned int i = 0; i <= degree; ++i)
        unit.emplace_back(double(i) / degree);
      const Quadrature<1>         nodes(unit);
      FEValues<1>                 fev(*fe, nodes, update_values | update_quadrature_points);
      Vector<double>              field(U.begin(), U.begin() + n_field);
      std::vector<Vector<double>> values(nodes.size(), Vector<double>(5));
      std::vector<DataOutBase::Patch<1, 3>> patches;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(field, values);
          DataOutBase::Patch<1, 3> patch;
          patch.n_subdivisions       = degree;
          patch.reference_cell       = ReferenceCells::Line;
          patch.points_are_available = true;
          patch.data.reinit(4 + 3, nodes.size());
          for (unsigned int k = 0; k < nodes.size(); ++k)
            {
              const double         eta = fev.quadrature_point(k)[0];
              Tensor<1, 3, double> theta;
              theta[0]             = values[k][3];
              theta[2]             = values[k][4];
              const auto R         = kinematics::rotation_exp(theta);
              patch.data(0, k)     = eta;
              for (unsigned int c = 0; c < 3; ++c)
                patch.data(1 + c, k) = R[c][1];
              patch.data(4, k) = eta + values[k][0];
              patch.data(5, k) = values[k][1];
              patch.data(6, k) = values[k][2];
            }
          for (unsigned int v = 0; v < 2; ++v)
            {
              const unsigned int k = v == 0 ? 0 : degree;
              patch.vertices[v] = Point<3>(patch.data(4, k), patch.data(5, k), patch.data(6, k));
            }
          patch.patch_index = patches.size();
          patches.push_back(std::move(patch));
        }
      std::vector<std::tuple<unsigned int, unsigned int, std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>
        vectors = {{1, 3, "director", DataComponentInterpretation::component_is_part_of_vector}};
      DataOutBase::VtkFlags flags;
      io::write_file_atomically(file, [&](std::ostream &o) {
        DataOutBase::write_vtu(patches, {"eta", "director", "director", "director"}, vectors,
                               flags, o);
      });
    }

    void
    StripProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      write_output = true;
      record.open(output_directory, prm, options);
      setup_system();
      std::ostringstream info;
      info << "  strip w = " << strip_width << ", h = " << thickness << " (w/h = "
           << strip_width / thickness << "), " << n_cells << " " << mesh_kind << " cells, Q"
           << degree << ", " << n_field << " field DoFs; E = " << law.young
           << ", Poisson " << law.poisson << ", shear " << (reduced_shear ? "reduced" : "full");
      say(info.str());
      for (const auto &c : {"step", "branch", "t", "newton_iterations", "residual"})
        steps_table.add_column(c);
      steps_table.add_column("energy", "E w h");
      for (const auto &s : kinematics::strain_names)
        steps_table.add_column(s, s[0] == 'n' ? "1" : "1/L");
      for (unsigned int k = 0; k < 6; ++k)
        steps_table.add_column(kinematics::resultant_names[k], k < 3 ? "E w h" : "E w h L");
      for (const auto &s : kinematics::strain_names)
        steps_table.add_column("K_" + s + "_" + s);
      steps_table.add_column("n_negative_eigenvalues");
      steps_table.add_column("smallest_eigenvalue");

      record.attempt([&]() {
        if (table.enabled())
          {
            io::PhaseTimer::Scope scope(timer, "constitutive table");
            write_output = false; // no per-point files
            set_load_parameter(1.);
            Vector<double> checkpoint;
            table.run(target_strains, strains_of(solution),
                      [this](const std::array<double, 6> &e) { return resolve(e); },
                      [&]() { checkpoint = solution; },
                      [&]() { solution = checkpoint; },
                      output_directory,
                      record.reporter());
            write_output = true;
          }
        else if (arclength_settings.enabled)
          follow_branches();
        else
          solve();
      });
      io::JSON j       = record.summary();
      j["width"]       = strip_width;
      j["thickness"]   = thickness;
      j["field_dofs"]  = n_field;
      add_state_to_summary(j, last_state, [this](const unsigned int k, io::JSON &x) {
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
      record.finish(j, timer);
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
      solvers::run_critical_point_study(prm, options, sweep, study);
    }
  } // namespace strip
} // namespace cosmo
