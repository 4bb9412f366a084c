// What part 3 shows of a state: the deflections and the rim's Fourier
// amplitudes, the mode classification and steps.csv's columns and rows;
// the VTU files are in vtu_output.cc.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include "diagnostics.h"

#include <algorithm>
#include <cmath>

namespace cosmo
{
  namespace plate_rod
  {
    PlateRodState
    analyse(const PlateRodDiscretization &d,
            const Vector<double> &        U,
            const double                  t,
            const unsigned int            n_modes)
    {
      const PlateRodParameters &p = d.parameters;
      PlateRodState             s;
      s.t = t;
      s.rim_w_amplitude.assign(n_modes, 0.);
      s.rim_ur_amplitude.assign(n_modes, 0.);
      const bool sector = p.domain == "sector";
      // Fourier coefficients of w and u_r on the rim in the polar angle, for
      // the mode numbers m = k step the domain admits (step = n on a sector
      // pi/n: the mirror-symmetric extension has only those).
      const unsigned int  step = d.sector_step();
      std::vector<double> aw(n_modes), bw(n_modes), ar(n_modes), br(n_modes);
      const QGauss<1>     face(p.degree + 1);
      FEFaceValues<2>     fev(*d.mapping, *d.fe, face, update_values | update_quadrature_points | update_JxW_values);
      std::vector<Vector<double>> values(face.size(), Vector<double>(6));
      double              ur_mean = 0, length = 0;
      for (const auto &cell : d.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
            {
              fev.reinit(cell, f);
              fev.get_function_values(U, values);
              for (unsigned int q = 0; q < face.size(); ++q)
                {
                  const Point<2> X  = fev.quadrature_point(q);
                  const double   r  = X.norm(), a = std::atan2(X[1], X[0]);
                  const double   da = fev.JxW(q) / r;
                  const double   w  = values[q][2];
                  const double   ur = (values[q][0] * X[0] + values[q][1] * X[1]) / r;
                  ur_mean += ur * fev.JxW(q);
                  length += fev.JxW(q);
                  for (unsigned int k = 0; k < n_modes; ++k)
                    {
                      const double m = double(k * step);
                      aw[k] += w * std::cos(m * a) * da;
                      bw[k] += w * std::sin(m * a) * da;
                      ar[k] += ur * std::cos(m * a) * da;
                      br[k] += ur * std::sin(m * a) * da;
                    }
                }
            }
      if (d.layout.distributed())
        {
          // Each rank integrated over its own rim faces.
          std::vector<double> parts = {ur_mean, length};
          for (const auto *v : {&aw, &bw, &ar, &br})
            parts.insert(parts.end(), v->begin(), v->end());
          d.layout.sum(parts);
          ur_mean = parts[0];
          length  = parts[1];
          unsigned int at = 2;
          for (auto *v : {&aw, &bw, &ar, &br})
            for (auto &x : *v)
              x = parts[at++];
        }
      const double span = sector ? M_PI / p.sector_n : 2 * M_PI;
      for (unsigned int k = 0; k < n_modes; ++k)
        {
          const double f = (k == 0 ? 1. : 2.) / span;
          s.rim_w_amplitude[k]  = f * (sector ? std::abs(aw[k]) : std::hypot(aw[k], bw[k]));
          s.rim_ur_amplitude[k] = f * (sector ? std::abs(ar[k]) : std::hypot(ar[k], br[k]));
        }
      s.rim_radial_strain = ur_mean / length / p.radius;
      // The apex carries w = 0 (gauge): the dome height is minus the rim's mean w.
      s.w_centre = -aw[0] / span;
      double wmin = 0, wmax = 0;
      for (unsigned int i = 0; i < U.size(); ++i)
        if (d.dof_component[i] == 2)
          wmin = std::min(wmin, U[i]), wmax = std::max(wmax, U[i]);
      s.max_abs_w = wmax - wmin;
      // The in-plane displacement at every node: u1 and u2 of the same support point.
      std::vector<types::global_dof_index> idx(d.fe->n_dofs_per_cell());
      const unsigned int                   nodes = d.fe->base_element(0).n_dofs_per_cell();
      for (const auto &cell : d.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          cell->get_dof_indices(idx);
          for (unsigned int k = 0; k < nodes; ++k)
            s.max_abs_inplane =
              std::max(s.max_abs_inplane, std::hypot(U[idx[d.fe->component_to_system_index(0, k)]],
                                                     U[idx[d.fe->component_to_system_index(1, k)]]));
        }
      std::vector<double> largest = {s.max_abs_inplane};
      d.layout.max(largest);
      s.max_abs_inplane = largest[0];
      return s;
    }

    std::pair<unsigned int, bool>
    classify_mode(const PlateRodDiscretization &d, const Vector<double> &mode, ModeMargins *margins)
    {
      // Mode numbers up to what the rim resolves: one per rim face over the full circle
      // (beyond, the Fourier amplitudes of the sampled rim alias).
      std::vector<double> faces(1, 0.);
      for (const auto &cell : d.triangulation.get().active_cell_iterators())
        if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
            ++faces[0];
      d.layout.sum(faces);
      const unsigned int rim_faces = static_cast<unsigned int>(faces[0]);
      const unsigned int full_circle = rim_faces * (d.parameters.domain == "sector" ? 2 * d.parameters.sector_n : 1);
      const auto s = analyse(d, mode, 0., std::max(2u, full_circle / d.sector_step() + 1));
      // Half the range of w (a mode's w is measured from the apex) against the largest
      // in-plane displacement.
      const bool   out = 0.5 * s.max_abs_w > s.max_abs_inplane;
      const auto & a   = out ? s.rim_w_amplitude : s.rim_ur_amplitude;
      unsigned int k   = 0;
      for (unsigned int j = 1; j < a.size(); ++j)
        if (a[j] > a[k])
          k = j;
      if (margins)
        {
          const double w = 0.5 * s.max_abs_w, p = s.max_abs_inplane;
          margins->type  = std::max(w, p) > 0 ? std::min(w, p) / std::max(w, p) : 0.;
          double second  = 0;
          for (unsigned int j = 0; j < a.size(); ++j)
            if (j != k)
              second = std::max(second, a[j]);
          margins->number = a[k] > 0 ? second / a[k] : 0.;
        }
      return {k * d.sector_step(), out};
    }

    std::vector<std::pair<std::string, std::string>>
    steps_columns(const PlateRodDiscretization &d)
    {
      std::vector<std::pair<std::string, std::string>> columns;
      for (const auto &c : {"step", "branch", "t", "mismatch", "plate_growth_rim", "rod_growth",
                            "newton_iterations", "energy", "plate_energy", "rod_energy",
                            "dome_height", "w_range", "max_inplane_displacement",
                            "rim_radial_strain"})
        columns.emplace_back(c, "");
      // The mode numbers the domain admits: 0, n, ..., 8 n on a sector pi/n.
      for (unsigned int k = 0; k < n_rim_modes; ++k)
        columns.emplace_back("rim_w_" + std::to_string(k * d.sector_step()), "");
      for (unsigned int k = 0; k < n_rim_modes; ++k)
        columns.emplace_back("rim_ur_" + std::to_string(k * d.sector_step()), "");
      columns.emplace_back("n_negative_eigenvalues", "");
      columns.emplace_back("smallest_eigenvalue", "");
      return columns;
    }

    std::vector<double>
    steps_row(const PlateRodParameters &p, const solvers::StepReport &report, const PlateRodState &s)
    {
      std::vector<double> row = {double(report.step), double(report.branch), report.t,
                                 p.mismatch(report.t), p.plate_growth.factors(p.radius, report.t)[1],
                                 p.rod_growth_at(report.t), double(report.newton_iterations),
                                 s.plate_energy + s.rod_energy, s.plate_energy, s.rod_energy,
                                 s.w_centre, s.max_abs_w, s.max_abs_inplane, s.rim_radial_strain};
      row.insert(row.end(), s.rim_w_amplitude.begin(), s.rim_w_amplitude.end());
      row.insert(row.end(), s.rim_ur_amplitude.begin(), s.rim_ur_amplitude.end());
      row.push_back(s.n_negative);
      row.push_back(s.smallest_eigenvalue);
      return row;
    }
  } // namespace plate_rod
} // namespace cosmo
