// The parameters of the rod application: what it reads and checks.
#include <deal.II/base/exceptions.h>

#include <cosmo/io/nested_run.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/parameters.h>

#include "cross_section_problem.h"
#include "strip_problem.h"

#include "parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      /// n muparser expressions of s and t in `entry` of `section`; io::InputError if they do not parse.
      Expression
      parse_expression(ParameterHandler &prm, const std::string &section, const std::string &entry,
                       const unsigned int n)
      {
        const std::string text = prm.get(entry);
        auto              f    = std::make_shared<FunctionParser<2>>(n);
        try
          {
            f->initialize("s,t", text, {{"pi", M_PI}});
            Vector<double> v(n);
            f->vector_value(Point<2>(0.1, 0.2), v);
          }
        catch (ExceptionBase &e)
          {
            std::ostringstream info;
            e.print_info(info);
            throw io::InputError(section, entry, text,
                                 std::to_string(n) +
                                   " muparser expression(s) of s and t (and pi), separated by ';'; "
                                   "the parser said: " + info.str());
          }
        return f;
      }

      void
      declare_end(ParameterHandler &prm, const std::string &name, const std::string &support)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Support", support, Patterns::Selection("clamped|pinned|rotation only|free"),
                          "clamped: position and rotation prescribed; pinned: position "
                          "prescribed, the rotation free (a spherical joint); rotation only: "
                          "the rotation prescribed, the position free (a cantilever rolled up "
                          "by its end's rotation); free: nothing prescribed.");
        prm.declare_entry("Displacement", "0; 0; 0", Patterns::Anything(),
                          "Clamped or pinned: the end's displacement from its reference "
                          "position, 3 expressions of t (e.g. '0; 0; -0.1*t' pushes an end "
                          "of a rod along e3 by 0.1 t).");
        prm.declare_entry("Rotation", "0; 0; 0", Patterns::Anything(),
                          "Clamped or rotation only: the rotation vector (axis times angle, in the fixed "
                          "axes) applied to the end's reference frame, 3 expressions of t; "
                          "any angle (e.g. '0; 0; 2*pi*t' twists a rod along e3 by t turns).");
        prm.declare_entry("Force", "0; 0; 0", Patterns::Anything(),
                          "A dead force on the end (it keeps its direction), 3 expressions "
                          "of t; it works on an end whose position is free (free, rotation only).");
        prm.leave_subsection();
      }

      RodEnd
      parse_end(ParameterHandler &prm, const std::string &name)
      {
        prm.enter_subsection(name);
        RodEnd      end;
        const auto  s = prm.get("Support");
        end.support   = s == "clamped" ? RodEnd::Support::clamped :
                        s == "pinned"  ? RodEnd::Support::pinned :
                        s == "free"    ? RodEnd::Support::free :
                                         RodEnd::Support::rotation;
        end.displacement = parse_expression(prm, name, "Displacement", 3);
        end.rotation     = parse_expression(prm, name, "Rotation", 3);
        end.force        = parse_expression(prm, name, "Force", 3);
        end.force_depends_on_load = materials::expression_names(prm.get("Force"), "t");
        // A dead force does no work where the position is prescribed: say so
        // rather than ignore it.
        if (end.support == RodEnd::Support::clamped || end.support == RodEnd::Support::pinned)
          for (const double t : {0., 0.37, 1.})
            if (RodParameters::evaluate(end.force, 0, t).l2_norm() != 0)
              throw io::InputError(name, "Force", prm.get("Force"),
                                   "zero at a clamped or pinned end (its position is "
                                   "prescribed: a force there does no work)");
        prm.leave_subsection();
        return end;
      }

      /**
       * A law computed from another application's parameter file (a part-1
       * section, a part-2 table): that application runs here, in this
       * process, into the run's directory 'section' or 'table' (reused
       * while the file's parameters are the same), and the law reads it.
       */
      void
      compute_law_input(materials::RodLaw &law, const std::string &output_directory)
      {
        const auto input = law.computed_input();
        if (input.parameter_file.empty())
          return;
        const std::string directory = output_directory + "/" + input.directory;
        const auto        run =
          input.application == "strip" ?
            io::run_nested(&strip::StripProblem::declare_parameters, &strip::run_strip, input.parameter_file,
                           directory, "Rod/Material", input.entry) :
            io::run_nested(&CrossSectionProblem::declare_parameters, &rod::run_study, input.parameter_file,
                           directory, "Rod/Material", input.entry);
        law.read_computed(run.directory, run.reused ? "reused from an earlier run of the same parameters" :
                                                      "computed by this run");
      }
    } // namespace

    void
    RodParameters::check_supports(ParameterHandler &prm) const
    {
      // The supports must hold the rigid motions (the Hessian is singular
      // otherwise): a clamp, two pins (their spin is gauged), or a pin and
      // a held rotation.
      using S = RodEnd::Support;
      if (ring)
        return;
      const S a = ends[0].support, b = ends[1].support;
      const bool held = a == S::clamped || b == S::clamped || (a == S::pinned && b != S::free) ||
                        (b == S::pinned && a != S::free);
      if (!held)
        {
          prm.enter_subsection("End B");
          const std::string value = prm.get("Support");
          prm.leave_subsection();
          throw io::InputError("End B", "Support", value,
                               "supports that hold the rod's rigid motions: one end clamped, "
                               "both pinned, or one pinned and the other 'rotation only' "
                               "(End A is '" + std::string(a == S::pinned ? "pinned" : a == S::free ? "free" : "rotation only") + "')");
        }
    }

    void
    RodParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rod");
      prm.declare_entry("Length", "1", Patterns::Double(0), "Reference length L of the rod.");
      prm.declare_entry("Number of elements", "40", Patterns::Integer(1, 10000000),
                        "Two-node helicoidal elements of equal reference length L/N.");
      prm.declare_entry("Shape", "straight", Patterns::Selection("straight|natural|ring"),
                        "The reference and starting state. straight: along e3 from the "
                        "origin, directors the fixed axes; natural: the stress-free shape "
                        "of the natural strains at the path's start, element by element "
                        "(a helix for constant strains); ring: a circle of circumference L "
                        "in the (e1, e2) plane, d2 = e3 its normal, d3 its tangent, closed "
                        "on itself (no ends).");
      prm.declare_entry("Natural strains", "0; 0; 1; 0; 0; 0", Patterns::Anything(),
                        "nu1; nu2; nu3; kappa1; kappa2; kappa3 of the stress-free rod per "
                        "reference length, in the director frame: 6 expressions of s and t.");
      prm.declare_entry("Natural strain imperfection", "0; 0; 0; 0; 0; 0", Patterns::Anything(),
                        "Added to the natural strains, whether given above or by the law's "
                        "sections: 6 expressions of s and t (an imperfection that selects one "
                        "of a symmetric problem's modes, e.g. '0; 0; 0; 0; 0; 0.2*t*cos(pi*s)' "
                        "for a tendril's perversion).");
      prm.declare_entry("Growth", "1", Patterns::Anything(),
                        "The natural stretch g(s, t) (axial growth): the stress-free rod has "
                        "strains g nu0 and kappa0 and the law is applied to "
                        "(nu/g - nu0, (kappa - kappa0)/g), times g.");
      prm.declare_entry("Stiffness factors", "1; 1; 1; 1; 1; 1", Patterns::Anything(),
                        "Factors f_k(s, t) > 0 on the law's stiffness, in the order of the "
                        "strains (GA1, GA2, EA, EI1, EI2, GJ): the law is applied to the "
                        "strains weighted by sqrt(f_k), so a quadratic law's K_ab becomes "
                        "sqrt(f_a f_b) K_ab (its couplings scaled with their diagonals); a "
                        "nonlinear law is scaled so at small strains. 6 expressions of s and "
                        "t, e.g. '1; 1; 1; 1; 1; 1 - 0.6*t' to soften the torsion along a "
                        "path (a homotopy between two sections).");
      prm.declare_entry("Distributed force", "0; 0; 0", Patterns::Anything(),
                        "A dead force per reference length (weight: '0; 0; -rho*g*t'), "
                        "3 expressions of s and t.");
      prm.declare_entry("Ring twist", "0", Patterns::Anything(),
                        "Shape = ring: the twist added at the ring's seam, in turns, an "
                        "expression of t (the link of the closed rod is this number).");
      prm.declare_entry("Largest element rotation", "135", Patterns::Double(1, 179),
                        "Degrees: a state whose relative rotation between the two nodes of "
                        "an element exceeds this is refused (the step is cut); the "
                        "element's rotation must stay below 180 degrees. Refine the mesh "
                        "if the start is refused.");
      prm.enter_subsection("Material");
      materials::declare_rod_law_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Contact");
      prm.declare_entry("Radius", "0", Patterns::Double(0),
                        "The radius a of the rod's body for self-contact; 0: the rod passes "
                        "through itself. Two points of the centreline farther apart than "
                        "pi a along the rod repel each other when closer than 2a in space, "
                        "with the energy (k/3)(2a - d)^3 per length squared "
                        "(doc/theory-rod.md 9). At least twice the element length L/N; "
                        "elements of a/4 or shorter are recommended (with elements as long "
                        "as a the contact force jumps as the strands slide, and Newton stalls).");
      prm.declare_entry("Stiffness", "100", Patterns::Double(0),
                        "The penalty's k in units of B/a^6 (B the law's largest bending "
                        "stiffness): two strands crossing at right angles, pressed by a "
                        "force F, overlap by a (3 F a^2/(4 pi Stiffness B))^(1/3); 100 "
                        "overlaps by 3 % of a at F = 1e-2 B/a^2.");
      prm.leave_subsection();
      prm.leave_subsection();
      declare_end(prm, "End A", "clamped");
      declare_end(prm, "End B", "free");
      solvers::NewtonSettings::declare_parameters(prm);
      solvers::ContinuationSettings::declare_parameters(prm);
      solvers::ArclengthSettings::declare_parameters(prm);
      io::ParameterSweep::declare_parameters(prm);
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory", "output/rod", Patterns::Anything(),
                        "Directory for parameters.prm, summary.json, steps.csv, rod-NNNN.vtu "
                        "and log.txt (created if needed).");
      prm.declare_entry("Link, twist and writhe", "auto", Patterns::Selection("auto|always|never"),
                        "Of a ring, or of a rod clamped at both ends whose clamps lie on the "
                        "line of their tangents (steps.csv, summary.json; doc/theory-rod.md 8). "
                        "The writhe is a double sum over the elements, O(N^2): auto computes "
                        "them up to 2000 elements (0.1 s a state), always and never whatever N.");
      prm.declare_entry("Tube radius", "0.02", Patterns::Double(0),
                        "The rod drawn as a body: tube-NNNN.vtu (tube.pvd) with each converged "
                        "state's rod-NNNN.vtu, a tube about the centreline of this radius per "
                        "length L, its circles in the directors' (d1, d2) planes (the twist "
                        "shows), coloured by the strains and resultants; 0: none.");
      prm.declare_entry("Body", "tube", Patterns::Selection("tube|section"),
                        "How the body is drawn: tube (of 'Tube radius'); section: the "
                        "cross-section the law was computed from (Law = section, one part-1 "
                        "section or a strip), its boundary as deformed at its natural shape "
                        "(a strip's: its width line thickened by h) swept along the "
                        "centreline in each node's director frame, coloured by the section's "
                        "von Mises stress at each element's strains (section_stress: part 1's "
                        "stress linearized about its natural shape; 0 for a strip) and by the "
                        "rod's strains and resultants: body-NNNN.vtu (body.pvd).");
      prm.leave_subsection();
    }

    void
    RodParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rod");
      length     = prm.get_double("Length");
      n_elements = prm.get_integer("Number of elements");
      shape      = prm.get("Shape");
      ring       = shape == "ring";
      if (!(length > 0))
        throw io::InputError("Rod", "Length", prm.get("Length"), "must be positive");
      if (ring && n_elements < 3)
        throw io::InputError("Rod", "Number of elements", prm.get("Number of elements"),
                             "at least 3 for a ring");
      natural_strains   = parse_expression(prm, "Rod", "Natural strains", 6);
      imperfection      = parse_expression(prm, "Rod", "Natural strain imperfection", 6);
      growth            = parse_expression(prm, "Rod", "Growth", 1);
      stiffness_factors = parse_expression(prm, "Rod", "Stiffness factors", 6);
      distributed_force = parse_expression(prm, "Rod", "Distributed force", 3);
      element_data_depend_on_load = false;
      for (const char *entry : {"Natural strains", "Natural strain imperfection", "Growth", "Stiffness factors",
                                "Distributed force"})
        element_data_depend_on_load |= materials::expression_names(prm.get(entry), "t");
      seam_twist        = parse_expression(prm, "Rod", "Ring twist", 1);
      rotation_limit    = prm.get_double("Largest element rotation") * M_PI / 180.;
      prm.enter_subsection("Contact");
      contact_radius    = prm.get_double("Radius");
      contact_stiffness = prm.get_double("Stiffness");
      // The nodes are the contact's quadrature points: a pair's potential,
      // 2a wide, needs a few of them across it.
      if (contact_radius > 0 && contact_radius < 2 * length / n_elements)
        throw io::InputError("Rod/Contact", "Radius", prm.get("Radius"),
                             "0 (no contact) or at least twice the element length L/N = " +
                               std::to_string(length / n_elements) +
                               " (the contact is integrated by the nodes; h = a/4 is "
                               "recommended: refine the mesh)");
      if (contact_radius > 0 && !(contact_stiffness > 0))
        throw io::InputError("Rod/Contact", "Stiffness", prm.get("Stiffness"), "positive with a contact radius");
      prm.leave_subsection();
      prm.enter_subsection("Material");
      std::shared_ptr<materials::RodLaw> new_law = materials::create_rod_law(prm, "Rod/Material");
      prm.leave_subsection();
      // A law with natural strains of its own (part-1 sections) replaces the entry.
      if (new_law->gives_natural_strains() && prm.get("Natural strains") != "0; 0; 1; 0; 0; 0")
        throw io::InputError("Rod", "Natural strains", prm.get("Natural strains"),
                             "the default '0; 0; 1; 0; 0; 0' with 'Material / Law = section' "
                             "(the sections' natural strains are the rod's)");
      prm.leave_subsection();
      ends[0] = parse_end(prm, "End A");
      ends[1] = parse_end(prm, "End B");
      check_supports(prm);
      newton_settings.parse_parameters(prm);
      continuation_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);
      // Arclength continuation starts where the natural-parameter path would.
      start = continuation_settings.start;
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      tube_radius      = prm.get_double("Tube radius");
      section_body     = prm.get("Body") == "section";
      const std::string topology_entry = prm.get("Link, twist and writhe");
      topology = topology_entry == "always" || (topology_entry == "auto" && n_elements <= 2000);
      prm.leave_subsection();
      compute_law_input(*new_law, output_directory);
      if (section_body && new_law->section_outline().empty())
        throw io::InputError("Output", "Body", "section",
                             "a law with a cross-section to sweep (Law = section with one "
                             "rod_cross_section or strip result and its outline.csv); this law "
                             "has none: use 'tube'");
      law = new_law;
      // Positive factors at the start (later ones stop the path, named).
      for (unsigned int e = 0; e < n_elements; ++e)
        try
          {
            stiffness_weights((e + 0.5) * length / n_elements, start);
          }
        catch (materials::LawRangeError &error)
          {
            prm.enter_subsection("Rod");
            const std::string value = prm.get("Stiffness factors");
            prm.leave_subsection();
            throw io::InputError("Rod", "Stiffness factors", value,
                                 std::string("positive finite factors at the start: ") + error.what());
          }
      // The start lies in the law's range (a family's parameter at every element).
      for (unsigned int e = 0; e < n_elements; ++e)
        try
          {
            natural_state((e + 0.5) * length / n_elements, start);
          }
        catch (materials::LawRangeError &error)
          {
            prm.enter_subsection("Rod");
            prm.enter_subsection("Material");
            const std::string value = prm.get("Section parameter");
            prm.leave_subsection();
            prm.leave_subsection();
            throw io::InputError("Rod/Material", "Section parameter", value,
                                 std::string("values inside the family's range at the start: ") + error.what());
          }
    }

    Vector<double>
    RodParameters::evaluate(const Expression &f, const double s, const double t)
    {
      Vector<double> v(f->n_components);
      f->vector_value(Point<2>(s, t), v);
      return v;
    }

    materials::RodNaturalState
    RodParameters::natural_state(const double s, const double t) const
    {
      materials::RodNaturalState n;
      const Vector<double>       e = evaluate(natural_strains, s, t);
      std::copy(e.begin(), e.end(), n.reference_strains.begin());
      n.growth    = evaluate(growth, s, t)[0];
      n.parameter = law->parameter_at(s, t);
      if (const auto e = law->natural_strains_at(n.parameter))
        n.reference_strains = *e;
      const Vector<double> d = evaluate(imperfection, s, t);
      for (unsigned int k = 0; k < 6; ++k)
        n.reference_strains[k] += d[k];
      n.weights = stiffness_weights(s, t);
      return n;
    }

    std::array<double, 6>
    RodParameters::stiffness_weights(const double s, const double t) const
    {
      // psi(w e) with w = sqrt(f): a quadratic law's K_ab -> sqrt(f_a f_b) K_ab.
      const Vector<double>  f = evaluate(stiffness_factors, s, t);
      std::array<double, 6> w;
      for (unsigned int k = 0; k < 6; ++k)
        {
          if (!(f[k] > 0) || !std::isfinite(f[k]))
            throw materials::LawRangeError("'Rod / Stiffness factors' component " + std::to_string(k + 1) +
                                           " is " + io::format_number(f[k]) + " at s = " + io::format_number(s) +
                                           ", t = " + io::format_number(t) + " (a positive factor is needed)");
          w[k] = std::sqrt(f[k]);
        }
      return w;
    }

    double
    RodParameters::largest_force_stiffness() const
    {
      const auto K = law->natural_stiffness();
      return std::max({K[0], K[7], K[14]});
    }

    double
    RodParameters::largest_moment_stiffness() const
    {
      const auto K = law->natural_stiffness();
      return std::max({K[21], K[28], K[35]});
    }
  } // namespace rod
} // namespace cosmo
