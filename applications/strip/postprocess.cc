// What part 2 reports: the steps table, the mode's width-wise symmetry, the
// strip swept along its helix and the cross-section VTU files.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <cosmo/config.h>
#include <cosmo/io/output.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/kinematics/strip.h>
#include <cosmo/geometry/field_on_line.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/kinematics/rotation.h>

#include "strip_problem.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace strip
  {
    void
    StripProblem::save_progress(io::CheckpointWriter &w) const
    {
      ReducedRodProblem::save_progress(w);
      w.put_vector(solution);
      w.put_vector(event_parities);
      w.put_vector(steps_row);
      save_postprocessors(w);
    }

    void
    StripProblem::load_progress(io::CheckpointReader &r)
    {
      ReducedRodProblem::load_progress(r);
      r.get_vector(solution);
      event_parities = r.get_vector();
      steps_row = r.get_vector();
      load_postprocessors(r);
      if (solution.size() != n_unknowns())
        throw std::runtime_error("the checkpoint's state has another number of unknowns");
      // The state reported last (the summary's, should no step follow).
      last_state = condensed_state(solution);
      say("  going on after step " + std::to_string(visited.size() - 1) + " at t = " +
          io::format_number(load_parameter));
    }

    void
    StripProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution   = U;
      last_state = condensed_state(solution);
      const auto &s = last_state;
      // The eigenvalue of smallest magnitude of the Hessian on the
      // constrained field space (free strains condensed): the one that
      // crosses zero where the section buckles. Reported, not acted on (the
      // count is): an iterate that moves by less than 1e-4 gives it to
      // ~1e-8 (a Rayleigh quotient), or to the width of a cluster; on the
      // strip's 90-cell threshold run 221 solves in all instead of 431.
      Vector<double> mask, mode;
      mode_mask(mask);
      const double smallest = solvers::smallest_eigenvalue(*this, mask, mode, 30, {}, 1e-4);
      record_state(report, s);
      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  t = " << std::setw(8) << report.t
           << "  Newton " << std::setw(2) << report.newton_iterations << "  Psi = "
           << std::setprecision(8) << s.energy << "  neg.eig. " << s.n_negative
           << "  min|eig| " << std::setprecision(3) << smallest << "  strains (";
      for (unsigned int k = 0; k < 6; ++k)
        line << (k ? ", " : "") << std::setprecision(6) << s.strains[k];
      line << ")" << record.progress(solvers::path_fraction(report, arclength_settings), report.step);
      say(line.str());
      std::vector<double> row = {double(report.step), double(report.branch), report.t,
                                 double(report.newton_iterations), report.residual_norm, s.energy};
      row.insert(row.end(), s.strains.begin(), s.strains.end());
      row.insert(row.end(), s.resultants.begin(), s.resultants.end());
      for (unsigned int k = 0; k < 6; ++k)
        row.push_back(s.stiffness(k, k));
      row.push_back(s.n_negative);
      row.push_back(smallest);
      {
        const Vector<double> field(solution.begin(), solution.begin() + n_field);
        Vector<double>       value(fe->n_components());
        for (const double eta : {-0.5 * strip_width, 0., 0.5 * strip_width})
          {
            geometry::value_on_line(dof_handler, field, eta, value);
            row.push_back(value[1]);
          }
      }
      steps_row = std::move(row);
    }

    std::vector<std::pair<std::string, std::string>>
    StripProblem::write_fields(const std::string &tag) const
    {
      write_section(output_directory + "/section-" + tag + ".vtu", solution);
      write_outline(solution);
      write_piece(output_directory + "/strip-" + tag + ".vtu");
      return {{"section", "section-" + tag + ".vtu"}, {"strip", "strip-" + tag + ".vtu"}};
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
      io::VTUPatches<2> vtu({{"eta", 1}, {"arc_length", 1}, {"displacement", 3}, {"director", 3}});
      const unsigned int np = degree + 1;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(field, values);
          for (unsigned int slice = 0; slice < n_slices; ++slice)
            {
              vtu.begin_patch(degree);
              for (unsigned int j = 0; j < np; ++j)
                {
                  const double                     X3 = L * (slice + double(j) / degree) / n_slices;
                  const kinematics::HelixPlacement helix(strains, X3);
                  for (unsigned int i = 0; i < np; ++i)
                    {
                      const double       eta = fev.quadrature_point(i)[0];
                      const Tensor<1, 3> q   = kinematics::strip_director(values[i][3], values[i][4]);
                      const Tensor<1, 3> y({eta + values[i][0], values[i][1], values[i][2]});
                      const Tensor<1, 3> d = helix.R * q;
                      // Reference points: the flat strip (eta, 0, X3); Warp By
                      // Vector by the displacement gives the strip on its helix.
                      const Tensor<1, 3> x = helix.place(y);
                      vtu.set_values(j * np + i, {eta, X3, x[0] - eta, x[1], x[2] - X3, d[0], d[1], d[2]});
                      vtu.set_position(j * np + i, Point<3>(eta, 0, X3));
                    }
                }
              vtu.end_patch();
            }
        }
      vtu.set_time(load_parameter);
      vtu.write(file);
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
    }

    std::vector<std::pair<std::string, std::string>>
    StripProblem::write_event_fields(const std::string &   tag,
                                     const Vector<double> &U,
                                     const Vector<double> *mode) const
    {
      std::vector<std::pair<std::string, std::string>> files = {{"event", "event-" + tag + ".vtu"}};
      write_section(output_directory + "/" + files[0].second, U);
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
          files.emplace_back("event mode", "event-" + tag + "-mode.vtu");
          write_section(output_directory + "/" + files[1].second, V);
        }
      return files;
    }

    void
    StripProblem::write_outline(const Vector<double> &U) const
    {
      // outline.csv (rod_cross_section's format): the section's boundary as
      // one closed loop, the face zeta = -h/2 along the width and zeta = +h/2
      // back, each point's placement w = (eta, 0, 0) + displacement + zeta q
      // in the director frame. The rod sweeps it along its centreline
      // (Output / Body = section on a strip's law: a ribbon). The plate law
      // gives no von Mises stress here: the column is 0.
      std::vector<Point<1>> unit;
      for (unsigned int i = 0; i < degree; ++i)
        unit.emplace_back(double(i) / degree);
      FEValues<1>                 fev(*fe, Quadrature<1>(unit), update_values | update_quadrature_points);
      const Vector<double>        field(U.begin(), U.begin() + n_field);
      std::vector<Vector<double>> values(unit.size(), Vector<double>(5));
      std::vector<std::array<double, 4>> line; // eta and the midline's placement
      std::vector<Tensor<1, 3>>          director;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(field, values);
          for (unsigned int k = 0; k < unit.size(); ++k)
            {
              const double eta = fev.quadrature_point(k)[0];
              line.push_back({{eta, eta + values[k][0], values[k][1], values[k][2]}});
              director.push_back(kinematics::strip_director(values[k][3], values[k][4]));
            }
        }
      Vector<double> end(fe->n_components());
      geometry::value_on_line(dof_handler, field, 0.5 * strip_width, end);
      line.push_back({{0.5 * strip_width, 0.5 * strip_width + end[0], end[1], end[2]}});
      director.push_back(kinematics::strip_director(end[3], end[4]));
      std::ostringstream csv;
      csv << "loop,X1,X2,w1,w2,w3,von_Mises_stress\n" << std::setprecision(17);
      for (const double zeta : {-0.5 * thickness, 0.5 * thickness})
        for (std::size_t j = 0; j < line.size(); ++j)
          {
            const std::size_t i = zeta < 0 ? j : line.size() - 1 - j;
            csv << "0," << line[i][0] << ',' << zeta;
            for (unsigned int c = 0; c < 3; ++c)
              csv << ',' << line[i][1 + c] + zeta * director[i][c];
            csv << ",0\n";
          }
      io::write_file_atomically(output_directory + "/outline.csv", [&csv](std::ostream &o) { o << csv.str(); });
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
      io::VTUPatches<1> vtu({{"eta", 1}, {"displacement", 3}, {"director", 3}});
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(field, values);
          vtu.begin_patch(degree);
          for (unsigned int k = 0; k < nodes.size(); ++k)
            {
              const double       eta = fev.quadrature_point(k)[0];
              const Tensor<1, 3> q   = kinematics::strip_director(values[k][3], values[k][4]);
              // Reference points (eta, 0, 0) + displacement (Warp By Vector: the section).
              vtu.set_values(k, {eta, values[k][0], values[k][1], values[k][2], q[0], q[1], q[2]});
              vtu.set_position(k, Point<3>(eta, 0, 0));
            }
          vtu.end_patch();
        }
      vtu.set_time(load_parameter);
      vtu.write(file);
    }
  } // namespace strip
} // namespace cosmo
