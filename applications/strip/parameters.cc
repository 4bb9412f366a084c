// The parameters of part 2: what the strip application reads and checks.
#include <deal.II/base/utilities.h>

#include <cosmo/config.h>
#include <cosmo/io/output.h>
#include <cosmo/kinematics/helix.h>

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
    StripParameters::declare_parameters(ParameterHandler &prm)
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
      prm.declare_entry("Natural curvature", "0; 0; 0", Patterns::Anything(),
                        "The curvature tensor of the stress-free plate, k11; k22; k12 (per unit "
                        "length; 1 across the width eta, 2 along the strip's axis s), as three "
                        "muparser expressions of eta and t (and pi) separated by ';': the "
                        "bending measures are taken relative to it (a bilayer, a prestrained "
                        "seed-pod valve; doc/theory-strip.md 8). k22 is the rod's kappa1 of a "
                        "flat section, k12 minus its twist kappa3. Zero at t = 0, so that the "
                        "path starts at the flat strip.");
      prm.leave_subsection();
      materials::declare_plate_law_parameters(prm);
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
      StripParameters::parse_parameters(prm);
      parse_strain_parameters(prm);
      table.parse_parameters(prm);
      table.check_axes(strain_is_free);
    }

    void
    StripParameters::parse_natural_curvature(const std::string &text)
    {
      natural_curvature.reset();
      // Only zeros, separators and blanks (the default): a flat plate, no
      // parser evaluation per point.
      if (text.find_first_not_of("0; .") == std::string::npos)
        return;
      auto f = std::make_shared<FunctionParser<2>>(3);
      try
        {
          f->initialize("eta,t", text, {{"pi", M_PI}});
          Vector<double> v(3); // muparser parses at the first evaluation
          f->vector_value(Point<2>(0.1, 0.2), v);
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw io::InputError("Strip", "Natural curvature", text,
                               "3 muparser expressions of eta and t (and pi), separated by ';'; "
                               "the parser said: " + info.str());
        }
      natural_curvature = f;
      // Finite across the width and along the path; zero at t = 0.
      for (unsigned int i = 0; i <= 20; ++i)
        {
          const double eta = strip_width * (i / 20. - 0.5);
          for (const double t : {0., 0.5, 1.})
            {
              const auto k = natural_curvature_at(eta, t);
              for (const double v : k)
                if (!std::isfinite(v) || (v != 0 && t == 0))
                  throw io::InputError("Strip", "Natural curvature", text,
                                       std::isfinite(v) ?
                                         "zero at t = 0 (the path starts at the flat strip); at eta = " +
                                           io::format_number(eta) + " it is not" :
                                         "finite across the width for t in [0, 1] (not at eta = " +
                                           io::format_number(eta) + ", t = " + io::format_number(t) + ")");
            }
        }
    }

    std::array<double, 3>
    StripParameters::natural_curvature_at(const double eta, const double t) const
    {
      if (!natural_curvature)
        return {{0., 0., 0.}};
      Vector<double> v(3);
      natural_curvature->vector_value(Point<2>(eta, t), v);
      return {{v[0], v[1], v[2]}};
    }

    void
    StripParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Strip");
      strip_width   = prm.get_double("Width");
      thickness     = prm.get_double("Thickness");
      n_cells       = prm.get_integer("Number of cells");
      mesh_kind     = prm.get("Mesh");
      degree        = prm.get_integer("Polynomial degree");
      reduced_shear = prm.get("Shear integration") == "reduced";
      parse_natural_curvature(prm.get("Natural curvature"));
      if (!(strip_width > 0))
        throw io::InputError("Strip", "Width", prm.get("Width"), "must be positive");
      if (!(thickness > 0))
        throw io::InputError("Strip", "Thickness", prm.get("Thickness"), "must be positive");
      if (!(thickness < strip_width))
        throw io::InputError("Strip", "Thickness", prm.get("Thickness"),
                             "must be smaller than the width " + prm.get("Width") +
                               " (a strip is a plate: h << w)");
      prm.leave_subsection();
      plate_law = materials::create_plate_law(prm);
      newton_settings.parse_parameters(prm);
      continuation_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      prm.leave_subsection();
    }
  } // namespace strip
} // namespace cosmo
