// What part 1 reports: the steps table, the checkpoints' progress, summary.json and
// the words of a state (section_output.h; the VTU files: vtu_output.cc).
#include <deal.II/base/utilities.h>

#include <cosmo/config.h>
#include <cosmo/io/ranks.h>
#include <cosmo/kinematics/helix.h>

#include "cross_section_problem.h"
#include "section_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    void
    CrossSectionProblem::save_progress(io::CheckpointWriter &w) const
    {
      ReducedRodProblem::save_progress(w);
      w.put_vector(solution);
      w.put_vector(steps_row);
      save_postprocessors(w);
      io::ranks::put_mesh_ranks(w, distributed_mesh);
    }

    void
    CrossSectionProblem::load_progress(io::CheckpointReader &r)
    {
      ReducedRodProblem::load_progress(r);
      r.get_vector(solution);
      steps_row = r.get_vector();
      load_postprocessors(r);
      io::ranks::check_mesh_ranks(r, distributed_mesh, "Finite element", "Distributed");
      if (distributed_mesh)
        io::ranks::check_checkpoints_agree(visited.size(), "their last step");
      if (solution.size() != n_unknowns())
        throw std::runtime_error("the checkpoint's state has another number of unknowns");
      // The state reported last (the summary's, should no step follow).
      last_state = current_state();
      say("  going on after step " + std::to_string(visited.size() - 1) + " at t = " +
          io::format_number(load_parameter));
    }

    void
    CrossSectionProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution = U;
      const bool with_stiffness = stiffness_every_step || report.final;
      if (with_stiffness)
        last_state = current_state();
      else
        {
          FieldIntegrals a;
          assemble(solution, nullptr, false, &a);
          last_state.t             = load_parameter;
          last_state.energy        = a.energy;
          last_state.min_elastic_J = a.min_elastic_J;
          last_state.resultants    = a.resultants;
          last_state.strains       = strains_of(solution);
          for (unsigned int k = 0; k < n_gauge; ++k)
            last_state.multipliers[k] = solution[discretization.n_u() + k];
          last_state.n_negative = -1;
        }
      const CrossSectionState &s = last_state;
      record_state(report, s);

      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  t = " << std::setw(8)
           << io::format_significant(report.t, 5) << "  Newton " << std::setw(2) << report.newton_iterations
           << "  |R| " << std::scientific << std::setprecision(1) << report.residual_norm
           << std::defaultfloat << "  Psi = " << io::format_significant(s.energy, 8) << "  neg.eig. "
           << s.n_negative;
      if (std::any_of(strain_is_free.begin(), strain_is_free.end(), [](bool b) { return b; }))
        {
          line << "  strains (";
          for (unsigned int k = 0; k < 6; ++k)
            line << (k ? ", " : "") << io::format_significant(s.strains[k], 6);
          line << ")";
        }
      line << record.progress(solvers::path_fraction(report, arclength_settings), report.step);
      say(line.str());

      std::vector<double> row = {double(report.step), double(report.branch), report.t,
                                 double(report.newton_iterations), report.residual_norm,
                                 double(report.cutbacks), s.energy};
      row.insert(row.end(), s.strains.begin(), s.strains.end());
      row.insert(row.end(), s.resultants.begin(), s.resultants.end());
      row.insert(row.end(), s.multipliers.begin(), s.multipliers.end());
      for (unsigned int k = 0; k < 6; ++k)
        row.push_back(with_stiffness ? s.stiffness(k, k) : NAN);
      row.push_back(s.n_negative);
      row.push_back(s.min_elastic_J);
      steps_row = std::move(row);
    }

    void
    CrossSectionProblem::write_summary() const
    {
      using io::JSON;
      JSON j                  = record.summary();
      j["mode"]               = mode;
      JSON free               = JSON::array();
      for (unsigned int k = 0; k < 6; ++k)
        if (strain_is_free[k])
          free.push_back(kinematics::strain_names[k]);
      j["free_strains"]       = free;
      j["load_parameter"]     = last_state.t;
      JSON &mesh              = j["mesh"];
      mesh["shape"]           = geometry.shape;
      mesh["cells"]           = discretization.get_mesh().get().n_global_active_cells();
      if (distributed_mesh)
        j["distributed_mesh_ranks"] = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      const auto &section     = discretization.properties();
      mesh["field_dofs"]      = discretization.n_u();
      mesh["degree"]          = degree;
      mesh["area"]            = section.area;
      mesh["I11"]             = section.I11;
      mesh["I22"]             = section.I22;
      mesh["diameter"]        = section.diameter;
      mesh["centroid_shift"]  = JSON::array({geometry.applied_shift[0], geometry.applied_shift[1]});
      JSON mats               = JSON::array();
      for (const auto &s : materials.descriptions())
        mats.push_back(s);
      j["materials"]          = mats;
      JSON layers             = JSON::array();
      for (const auto &s : surface_layers.descriptions())
        layers.push_back(s);
      j["surface_layers"]     = layers;
      assembly::add_state_to_summary(j, last_state, *this, *this);
      JSON &props             = j["section_properties"];
      if (!distributed_mesh) // (not computed on a distributed mesh)
        props["reference_linear"] = reference_properties.to_json();
      props["this_state"]       = analysis::analyse_stiffness(last_state.stiffness).to_json();
      j["min_elastic_J"]              = last_state.min_elastic_J;
      const auto h = kinematics::helix_geometry(kinematics::RodStrains(last_state.strains));
      JSON &helix  = j["helix"];
      helix["description"] = h.description();
      helix["radius"]      = h.radius;
      helix["pitch"]       = h.pitch; // inf -> null for a straight rod
      helix["handedness"]  = h.handedness;
      helix["axis"]        = JSON::array({h.axis[0], h.axis[1], h.axis[2]});
      helix["curvature"]   = h.curvature;
      helix["torsion"]     = h.torsion;
      j["newton_iterations"] = total_newton_iterations;
      record.finish(j, timer, n_condensed_states);
    }

    namespace
    {
      std::string
      axis_angle(const double radians)
      {
        return std::isfinite(radians) ? "at " + io::format_significant(radians * 180 / M_PI, 4) + " deg" :
                                         std::string("any (equal bending stiffnesses)");
      }
    } // namespace

    void
    say_reference_properties(const analysis::LinearSectionProperties &        p,
                             const std::function<void(const std::string &)> &say)
    {
      auto pt = [](const Point<2> &x) {
        return "(" + io::format_significant(x[0], 4) + ", " + io::format_significant(x[1], 4) + ")";
      };
      std::ostringstream out;
      out << "  linear section properties (reference, small-strain moduli):\n"
          << "    EA " << io::format_significant(p.EA, 5) << ", elastic centre " << pt(p.elastic_centre)
          << ", centroid " << pt(p.centroid) << "\n"
          << "    EI11 " << io::format_significant(p.EI11, 5) << ", EI22 " << io::format_significant(p.EI22, 5)
          << ", EI12 " << io::format_significant(p.EI12, 5) << "; principal axis "
          << axis_angle(p.principal_angle) << " (EI "
          << io::format_significant(p.principal_bending[0], 5) << ", "
          << io::format_significant(p.principal_bending[1], 5) << ")\n"
          << "    GJ " << io::format_significant(p.GJ, 5) << ", warping stiffness E Gamma "
          << io::format_significant(p.EGamma, 5) << "; shear centre " << pt(p.shear_centre_flexure)
          << " (Trefftz " << pt(p.shear_centre_trefftz) << "); shear factors "
          << io::format_significant(p.shear_factors[0], 4) << ", " << io::format_significant(p.shear_factors[1], 4)
          << "\n    mass per length " << io::format_significant(p.mass, 5) << ", mass centre "
          << pt(p.mass_centre) << ", polar mass moment " << io::format_significant(p.mass_moment11 + p.mass_moment22, 5);
      say(out.str());
    }

    void
    say_result(const assembly::ReducedRodState &                s,
               const io::PhaseTimer &                           timer,
               const std::function<void(const std::string &)> &say)
    {
      say("");
      say("Result at t = " + io::format_significant(s.t) + ":");
      std::ostringstream out;
      out << "  energy per unit length  " << io::format_significant(s.energy, 10) << "\n  strains    ";
      for (unsigned int k = 0; k < 6; ++k)
        out << " " << kinematics::strain_names[k] << " = " << io::format_significant(s.strains[k], 10);
      out << "\n  resultants ";
      for (unsigned int k = 0; k < 6; ++k)
        out << " " << kinematics::resultant_names[k] << " = " << io::format_significant(s.resultants[k], 6);
      out << "\n  multipliers";
      for (unsigned int k = 0; k < 6; ++k)
        out << " " << io::format_significant(s.multipliers[k], 3);
      out << "\n  stiffness (nu1, nu2, nu3, kappa1, kappa2, kappa3):\n";
      for (unsigned int a = 0; a < 6; ++a)
        {
          out << "   ";
          for (unsigned int b = 0; b < 6; ++b)
            out << std::setw(14) << io::format_significant(s.stiffness(a, b), 6);
          out << "\n";
        }
      const auto a = analysis::analyse_stiffness(s.stiffness);
      if (a.invertible)
        {
          auto pt = [](const Point<2> &p) {
            return "(" + io::format_significant(p[0], 4) + ", " + io::format_significant(p[1], 4) + ")";
          };
          out << "  from this stiffness: tension centre " << pt(a.tension_centre) << ", shear centre "
              << pt(a.shear_centre) << ", principal bending axis "
              << axis_angle(a.principal_angle) << " (EI "
              << io::format_significant(a.principal_bending[0], 4) << ", "
              << io::format_significant(a.principal_bending[1], 4)
              << "), torsional stiffness with the other resultants zero "
              << io::format_significant(a.condensed[5], 4) << "\n";
        }
      else
        out << "  this stiffness is not positive definite: no centres or principal axes\n";
      out << "  natural/current centreline: "
          << kinematics::helix_geometry(kinematics::RodStrains(s.strains)).description() << "\n";
      out << "  timings [s]:";
      for (const auto &p : timer.phases())
        out << "  " << p << " " << io::format_significant(timer.seconds(p), 3);
      say(out.str());
    }
  } // namespace rod
} // namespace cosmo
