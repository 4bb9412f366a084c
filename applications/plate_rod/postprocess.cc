// What part 3 reports: the converged steps and the located events and the
// closed forms; the checkpoint and the run's summary are in run.cc, what a
// state shows in diagnostics.cc, the VTU files in vtu_output.cc.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <cosmo/config.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/solvers/newton.h>

#include "plate_rod_problem.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {

    analysis::PlateRod
    PlateRodParameters::closed_form_setting() const
    {
      analysis::PlateRod p;
      p.radius    = radius;
      p.thickness = thickness;
      p.young     = plate_law->young();
      p.poisson   = plate_law->poisson();
      p.rod_EA    = rod_stiffness[2];
      p.rod_EI1   = rod_stiffness[3];
      p.rod_EI2   = rod_stiffness[4];
      p.rod_GJ    = rod_stiffness[5];
      return p;
    }

    void
    PlateRodProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution = U;
      load_parameter = report.t;
      PlateRodState s = analyse(discretization, U, load_parameter);
      s.n_negative    = report.n_negative;
      s.branch        = report.branch;
      s.constraint_violation = discretization.constraint_violation(U);
      // The driver has just factorized at this state (or at its predictor,
      // one small Newton step away), unless it located an event since.
      if (!factorization.with_last && !report.factorized_at_predictor &&
          !factorization.here(U, load_parameter))
        setup_jacobian(U);
      factorization.with_last = false;
      if (!energy_assembly.assembled(U, load_parameter))
        {
          Vector<double> R;
          energy_assembly.assemble(U, load_parameter, &R, false);
        }
      s.plate_energy = energy_assembly.energies()[0];
      s.rod_energy   = energy_assembly.energies()[1];
      {
        io::PhaseTimer::Scope scope(timer, "stability (smallest eigenvalue)");
        Vector<double>        mask, mode;
        mode_mask(mask);
        // Reported, not acted on: an iterate that moves by less than 1e-4
        // gives the eigenvalue to ~1e-8 (a Rayleigh quotient), or to the
        // width of a cluster of eigenvalues if the iterate still turns
        // within it; 3 to 9 solves per state on the dome's sector instead
        // of 5 to 22 to 1e-12.
        s.smallest_eigenvalue = solvers::smallest_eigenvalue(*this, mask, mode, 30, {}, 1e-4);
      }
      states.push_back(s);
      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  branch " << report.branch
           << "  t = " << std::setprecision(8) << std::setw(10) << report.t << "  Delta = "
           << std::setprecision(5) << mismatch(report.t) << "  Newton " << report.newton_iterations
           << "  dome " << std::setprecision(4) << s.w_centre << "  neg.eig. " << s.n_negative
           << "  min|eig| " << std::setprecision(3) << s.smallest_eigenvalue
           << record.progress(solvers::path_fraction(report, arclength_settings), report.step);
      record.say(line.str());
      steps_row = plate_rod::steps_row(*this, report, s);
    }

    std::vector<std::pair<std::string, std::string>>
    PlateRodProblem::write_fields(const std::string &tag) const
    {
      io::PhaseTimer::Scope scope(timer, "output");
      return {{"plate", write_plate(discretization, "plate-" + tag, solution, load_parameter)},
              {"rim", write_rim(discretization, "rim-" + tag, solution, load_parameter)}};
    }

    void
    PlateRodProblem::located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode)
    {
      solvers::EventRecord r;
      r.event = e;
      r.state.assign(U.begin(), U.end());
      if (mode)
        r.mode.assign(mode->begin(), mode->end());
      located_events.push_back(r);
    }

    std::vector<std::pair<std::string, std::string>>
    PlateRodProblem::write_event_fields(const std::string &   tag,
                                        const Vector<double> &U,
                                        const Vector<double> *mode) const
    {
      return write_event(discretization, tag, U, mode, load_parameter);
    }

    io::JSON
    PlateRodParameters::closed_forms(double &first_mismatch, std::string &text) const
    {
      io::JSON     closed = io::JSON::object();
      const double Delta1 = mismatch(1.);
      first_mismatch      = NAN;
      // The closed forms are for a flat plate of uniform thickness on a naturally circular rim.
      const bool natural_curvature = plate_growth.has_natural_curvature() ||
                                     rim_growth->natural_curvature(1.) != std::array<double, 3>{{0., 0., 0.}};
      if (!std::isfinite(Delta1) || Delta1 == 0 || thickness_profile || natural_curvature)
        {
          if (thickness_profile || natural_curvature)
            text = "  no closed form: it assumes a uniform thickness and no natural curvature\n";
          return closed;
        }
      const auto p = closed_form_setting();
      // t at which the mismatch reaches Delta (linear ramps).
      const double a = plate_growth.factors(0, 1.)[0] - 1, b = rim_growth->final_factor() - 1;
      auto         t_of = [&](const double D) { return analysis::load_parameter_at_mismatch(D, a, b); };
      auto         entry = [&](const unsigned int n, const double D) {
        io::JSON x    = io::JSON::object();
        x["n"]        = n;
        x["mismatch"] = D;
        x["t"]        = t_of(D);
        return x;
      };
      std::ostringstream c;
      c << std::setprecision(6);
      if (Delta1 > 0)
        {
          const double D                     = analysis::axisymmetric_critical_mismatch(p);
          closed["axisymmetric"]["mismatch"] = D;
          closed["axisymmetric"]["t"]        = t_of(D);
          // In-plane only, the dome (out of plane) is absent: no first threshold.
          first_mismatch                     = in_plane_only ? NAN : D;
          c << "  closed form (Kirchhoff, small strain): axisymmetric buckling at Delta = " << D
            << ", t = " << t_of(D) << (in_plane_only ? " (out of plane: absent here)" : "");
        }
      else
        {
          // The lobed families, over the mode numbers the domain admits (a sector pi/n keeps
          // the multiples of n).
          const unsigned int step = domain == "sector" ? sector_n : 1;
          const unsigned int n0    = step >= 2 ? step : 2;
          const unsigned int n_max = std::max(12u, n0 + 4 * step);
          c << "  closed forms (Kirchhoff, small strain), out-of-plane lobes:";
          for (unsigned int n = n0; n <= n_max; n += step)
            {
              const double D = analysis::out_of_plane_critical_mismatch(p, n);
              closed["out_of_plane"].push_back(entry(n, D));
              if (n <= n0 + 3 * step)
                c << " n = " << n << ": Delta = " << D << " (t = " << t_of(D) << ")";
            }
          const auto         out      = analysis::first_out_of_plane(p, n_max, step);
          const auto         planar   = analysis::first_planar(p, 200, step);
          const double       best_out = out.mismatch, best_planar = planar.mismatch;
          const unsigned int n_out = out.n, n_planar = planar.n;
          closed["first_out_of_plane"] = entry(n_out, best_out);
          closed["first_planar"]       = entry(n_planar, best_planar);
          // In-plane only, the out-of-plane family is absent.
          first_mismatch = in_plane_only ? best_planar : std::max(best_out, best_planar);
          c << "\n  first out-of-plane mode n = " << n_out << " at Delta = " << best_out
            << "; first planar mode n = " << n_planar << " at Delta = " << best_planar << " (t = "
            << t_of(best_planar) << ")";
        }
      closed["first"]["mismatch"] = first_mismatch;
      closed["first"]["t"]        = t_of(first_mismatch);
      text                        = c.str();
      return closed;
    }
  } // namespace plate_rod
} // namespace cosmo
