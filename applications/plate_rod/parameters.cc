// The parameters of part 3: what the plate_rod application reads and checks.
#include <deal.II/base/utilities.h>

#include <cosmo/config.h>

#include "plate_rod_problem.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include <fstream>

namespace cosmo
{
  namespace plate_rod
  {
    namespace
    {
      /// 'Plate', the plate's material and growth, 'Rim rod'.
      void
      declare_plate_and_rim(ParameterHandler &prm)
      {
        prm.enter_subsection("Plate");
        prm.declare_entry("Radius", "1", Patterns::Double(0), "Radius R of the disc.");
        prm.declare_entry("Thickness", "0.01", Patterns::Double(0),
                          "Thickness h of the plate (h < R); with a Thickness profile, its "
                          "reference value h0.");
        prm.declare_entry("Thickness profile", "1", Patterns::Anything(),
                          "The thickness is h0 f(x, y, r): f a muparser expression of the "
                          "position (x, y) and the radius r (and pi), positive at every "
                          "quadrature point of the plate, e.g. '1 - r^2' for a lenticular disc. "
                          "The closed forms assume f = 1.");
        prm.leave_subsection();
        materials::declare_plate_law_parameters(prm);
        materials::PlateGrowth::declare_parameters(prm);
        prm.enter_subsection("Rim rod");
        materials::declare_rod_law_parameters(prm);
        materials::declare_rod_growth_parameters(prm);
        prm.leave_subsection();
      }

      /// 'Model' (the registered plate models and their entries) and 'Mesh'.
      void
      declare_model_and_mesh(ParameterHandler &prm)
      {
        prm.enter_subsection("Model");
        using Models = plugins::Registry<kinematics::PlateModel>;
        prm.declare_entry("Model", "cosserat", Patterns::Selection(Models::names()),
                          "The plate model (the registered models, "
                          "source/kinematics/plate_models/). " + Models::documentation());
        Models::declare_parameters(prm);
        prm.declare_entry("Shear integration", "assumed strain",
                          Patterns::Selection("assumed strain|automatic|interior tying|stabilized|reduced"),
                          "Transverse shear of the plate. assumed strain (default; automatic is "
                          "the same): the MITC family, covariant shear strains reduced to the "
                          "rotated Raviart-Thomas space Q_{p-1,p} x Q_{p,p-1} by their values on "
                          "the cell's edges (tangential, p Gauss points per edge) and interior "
                          "moments, i.e. the plate element of Bathe, Brezzi and Cho (MITC9 for "
                          "p = 2), integrated fully: locking-free, no spurious modes, no "
                          "consistency error, and its error on coarse distorted cells does not "
                          "grow as the plate thins (doc/theory-plate-rod.md section 7). Kept for "
                          "comparison with earlier results: interior tying, the same space tied at "
                          "p x (p + 1) interior Gauss points (the MITC9 shell element of Bucalem "
                          "and Bathe; up to 14 times the default's error on the coarsest meshes "
                          "at h/R = 0.001 or with the kirchhoff model); stabilized, full "
                          "Gauss integration with the shear stiffness times t^2/(t^2 + alpha "
                          "h_K^2) (h_K the cell diameter; t^2 divided by the penalty in the "
                          "kirchhoff model), whose consistency error O(alpha h_K^2/t^2) of the "
                          "shear compliance biases the Cosserat - Kirchhoff comparison on coarse "
                          "meshes; reduced, p Gauss points (Q2 then has a spurious transverse "
                          "mode with little shear energy, which membrane compression "
                          "destabilizes on fine meshes: measured at h_K ~ 3 h).");
        prm.declare_entry("Shear stabilization", "0.03", Patterns::Double(0),
                          "alpha of the stabilized shear integration (0.03: the smallest "
                          "threshold errors on coarse meshes, doc/theory-plate-rod.md).");
        prm.declare_entry("Deformation", "full", Patterns::Selection("full|in-plane only"),
                          "full: the plate and the rim deform in 3D. in-plane only: the "
                          "out-of-plane displacement u3 and the plate's rotations theta1, "
                          "theta2 are held at 0 everywhere (the rim keeps its in-plane "
                          "rotation alpha), so that planar lobing is studied by itself: at "
                          "the flat state the in-plane and out-of-plane problems decouple "
                          "(reflection through the plate's plane), so the planar critical "
                          "points are those of the full model, and the out-of-plane ones "
                          "are absent.");
        prm.leave_subsection();
        prm.enter_subsection("Mesh");
        prm.declare_entry("Domain", "full disc", Patterns::Selection("full disc|sector"),
                          "full disc, or the sector 0 <= theta <= Sector angle with mirror "
                          "conditions on both radial edges (keeps the modes cos(k n theta)).");
        prm.declare_entry("Sector angle", "90", Patterns::Double(0, 360),
                          "Sector angle in degrees: 180/n for an integer n >= 1.");
        prm.declare_entry("Sector mesh", "stretched", Patterns::Selection("stretched|mirrored"),
                          "stretched: the quarter disc's mesh (3 cells) refined and stretched in "
                          "angle onto the sector. mirrored: two mirror images of the stretched "
                          "mesh of the half sector (Sector angle/2), joined along its edge, twice "
                          "as many cells: the states of the sector symmetric about its bisector "
                          "are then exactly those of the half sector on its own mesh, so that the "
                          "two symmetry reductions can be compared to round-off.");
        prm.declare_entry("Global refinements", "3", Patterns::Integer(0, 8),
                          "Refinements of the coarse disc (5 cells) or sector (3 cells).");
        prm.declare_entry("Polynomial degree", "2", Patterns::Integer(2, 4),
                          "Degree p of FE_Q(p) for all fields and of the mapping of the rim; "
                          "shear terms and the rod are integrated with p Gauss points.");
        prm.declare_entry("Distributed", "false", Patterns::Bool(),
                          "Under mpirun: divide the mesh over the ranks (a "
                          "parallel::distributed::Triangulation), each rank assembling its own "
                          "cells and holding its rows of the matrix, factorized by MUMPS with "
                          "distributed input; plate VTUs as one .pvtu with a piece per rank. For "
                          "plates too large for one node's memory or cores. The located thresholds "
                          "agree with one process's to their resolution, not bitwise; resume with "
                          "as many ranks as began the run (doc/parallel-runs.md). false: rank 0 "
                          "assembles on its node and shares only large factorizations.");
        prm.leave_subsection();
      }

      /// 'Growth path', the drivers' sections and 'Output'.
      void
      declare_path_and_output(ParameterHandler &prm)
      {
        prm.enter_subsection("Growth path");
        prm.declare_entry("Start", "0", Patterns::Double(0, 1),
                          "Load parameter t where the path starts (growth is ramped from "
                          "t = 0, none, to t = 1, the factors given); the flat state there "
                          "must be stable.");
        prm.declare_entry("Stop at first event", "false", Patterns::Bool(),
                          "Stop where the first change of stability is located (critical "
                          "growth only: studies, quick checks); the same as 'Arclength "
                          "continuation / Stop at first event'.");
        prm.leave_subsection();
        io::ParameterSweep::declare_parameters(prm);
        solvers::NewtonSettings::declare_parameters(prm);
        solvers::ArclengthSettings::declare_parameters(prm);
        // The growth path's own range, t from 0 (no growth) to 1 (the factors
        // given), instead of the driver's unbounded default: a parameter file
        // that sets nothing runs a short, bounded job.
        prm.enter_subsection("Arclength continuation");
        prm.declare_entry("Parameter range", "0, 1", Patterns::List(Patterns::Double(), 2, 2),
                          "A branch ends when its load parameter t leaves [min, max] (t = 0: no "
                          "growth, t = 1: the growth factors given).");
        prm.leave_subsection();
        prm.enter_subsection("Output");
        prm.declare_entry("Output directory", "output/plate_rod", Patterns::Anything(),
                          "Directory for parameters.prm, summary.json, steps.csv, plate.pvd, "
                          "rim.pvd with their VTU files, event VTUs and log.txt.");
        prm.declare_entry("Sector as full disc", "false", Patterns::Bool(),
                          "With Domain = sector: write the plate VTUs as the full disc, the "
                          "sector's mirror images (reflected about its edge theta = 0 and "
                          "rotated by multiples of twice the sector angle; vectors turned with "
                          "them, N_rt and M_rt change sign under a reflection), and the rim VTUs "
                          "as the full ring (under a reflection the ring's direction reverses: "
                          "d3, the shears nu1, nu2, the twist kappa3 and n1, n2, m3 change sign).");
        prm.leave_subsection();
      }

      /// 'Plate / Radius' and 'Thickness' (section 'Plate' entered): positive, h < R and
      /// h/R not below what double precision resolves.
      void
      check_plate_dimensions(const ParameterHandler &prm, const double radius, const double thickness)
      {
        if (!(radius > 0))
          throw io::InputError("Plate", "Radius", prm.get("Radius"), "must be positive");
        if (!(thickness > 0) || !(thickness < radius))
          throw io::InputError("Plate", "Thickness", prm.get("Thickness"),
                               "must be positive and smaller than the radius " +
                                 prm.get("Radius"));
        // The stability test's round-off grows like (R/h)^3 (doc/theory-plate-rod.md
        // section 9: at h/R = 1e-4 it is 3e-3 to 1 of the threshold, by mesh); below
        // 1e-5 no digit of a threshold would be significant.
        if (thickness < 1e-5 * radius)
          throw io::InputError("Plate", "Thickness", prm.get("Thickness"),
                               "h/R >= 1e-5 (here " + std::to_string(thickness / radius) +
                                 "): in double precision the stability of thinner plates cannot "
                                 "be resolved (doc/theory-plate-rod.md section 9)");
      }

      /// The diagonal of the 6x6 stiffness K (row-major) into `diagonal`; returns its
      /// largest coupling |K_ab| / sqrt(|K_aa K_bb|).
      double
      diagonal_and_coupling(const std::array<double, 36> &K, std::array<double, 6> &diagonal)
      {
        for (unsigned int a = 0; a < 6; ++a)
          diagonal[a] = K[7 * a];
        return materials::largest_coupling(K);
      }

      /// n of 'Mesh / Sector angle' = 180/n degrees (section 'Mesh' entered), an integer >= 1.
      unsigned int
      sector_divisor(const ParameterHandler &prm)
      {
        const double angle = prm.get_double("Sector angle");
        const double n     = 180. / angle;
        if (!(angle > 0) || std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
          throw io::InputError("Mesh", "Sector angle", prm.get("Sector angle"),
                               "the sector must be pi/n: 180/n degrees for an integer n >= 1 "
                               "(180, 90, 60, 45, 36, 30, ...)");
        return static_cast<unsigned int>(std::round(n));
      }
    } // namespace

    void
    PlateRodParameters::declare_parameters(ParameterHandler &prm)
    {
      declare_plate_and_rim(prm);
      declare_model_and_mesh(prm);
      declare_path_and_output(prm);
    }

    void
    PlateRodParameters::check_rim_stiffness(const std::string &entry, const std::string &text) const
    {
      // The rim against the plate: beyond 1e8 times the plate's own stiffness
      // the coupled Hessian loses every digit of the plate's contribution in
      // double precision (the rigid limit is reached to 1e-8 long before).
      const double Eh = plate_law->young() * thickness;
      const double D  = plate_law->bending_stiffness(thickness);
      const char * names[6] = {"GA1", "GA2", "EA", "EI1", "EI2", "GJ"};
      for (unsigned int i = 0; i < 6; ++i)
        {
          const double scale = i < 3 ? Eh * radius : D * radius;
          if (!(rod_stiffness[i] > 0))
            throw io::InputError("Rim rod", entry, text,
                                 std::string("every stiffness must be positive (") + names[i] +
                                   " = " + io::format_number(rod_stiffness[i]) + " is not)");
          if (rod_stiffness[i] > 1e8 * scale)
            {
              std::ostringstream m;
              m << names[i] << " = " << rod_stiffness[i] << " is " << rod_stiffness[i] / scale
                << " times the plate's " << (i < 3 ? "E h R" : "D R")
                << ": stiffer than representable next to the plate in double precision (at "
                   "most 1e8 times); a rim 1e6 times stiffer is already rigid to 1e-6";
              throw io::InputError("Rim rod", entry, text, m.str());
            }
        }
    }

    void
    PlateRodParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate");
      radius    = prm.get_double("Radius");
      thickness = prm.get_double("Thickness");
      check_plate_dimensions(prm, radius, thickness);
      thickness_profile_text = prm.get("Thickness profile");
      thickness_profile =
        thickness_profile_text == "1" ?
          nullptr :
          materials::parse_expression_of_position(thickness_profile_text, "Plate",
                                                  "Thickness profile", 1);
      prm.leave_subsection();
      plate_law = materials::create_plate_law(prm);
      plate_growth.parse_parameters(prm);

      prm.enter_subsection("Rim rod");
      rim_law    = materials::create_rod_law(prm, "Rim rod");
      // The rim's natural state is the plate's edge: a law with natural
      // strains of its own, or varying along the rod, would be ignored.
      if (rim_law->gives_natural_strains())
        throw io::InputError("Rim rod", "Law", prm.get("Law"),
                             "a law without natural strains of its own (the rim's natural state is "
                             "the plate's edge): quadratic, with a part-1 'Stiffness file' for a "
                             "section's stiffness");
      rim_growth = materials::create_rod_growth(prm, "Rim rod");
      stiffness_coupling = diagonal_and_coupling(rim_law->natural_stiffness(), rod_stiffness);
      // The stiffnesses in use are named by the quadratic law's entry they
      // come from (the file's if one is given), by 'Law' for another law.
      stiffness_file = prm.get("Law") == "quadratic" ? prm.get("Stiffness file") : "";
      if (prm.get("Law") != "quadratic")
        check_rim_stiffness("Law", prm.get("Law"));
      else if (stiffness_file.empty())
        check_rim_stiffness("Stiffnesses", prm.get("Stiffnesses"));
      else
        check_rim_stiffness("Stiffness file", stiffness_file);
      prm.leave_subsection();

      prm.enter_subsection("Model");
      const std::string m = prm.get("Model");
      model = plugins::Registry<kinematics::PlateModel>::create(m);
      model->parse_parameters(prm);
      {
        const std::string si = prm.get("Shear integration");
        shear_integration    = si == "stabilized"     ? ShearIntegration::stabilized :
                               si == "reduced"        ? ShearIntegration::reduced :
                               si == "interior tying" ? ShearIntegration::interior_tying :
                                                        ShearIntegration::assumed_strain;
      }
      shear_stabilization = prm.get_double("Shear stabilization");
      in_plane_only       = prm.get("Deformation") == "in-plane only";
      prm.leave_subsection();

      prm.enter_subsection("Mesh");
      domain = prm.get("Domain");
      sector_n = sector_divisor(prm);
      sector_mesh = prm.get("Sector mesh");
      if (sector_mesh == "mirrored" && domain != "sector")
        throw io::InputError("Mesh", "Sector mesh", sector_mesh,
                             "stretched with Domain = full disc (mirrored makes a sector)");
      refinements = prm.get_integer("Global refinements");
      if (domain == "full disc" && refinements == 0)
        throw io::InputError("Mesh", "Global refinements", "0",
                             "at least 1 for the full disc (its coarse mesh has no vertex at the "
                             "centre for the gauge conditions)");
      degree      = prm.get_integer("Polynomial degree");
      distributed_mesh = prm.get_bool("Distributed");
      prm.leave_subsection();

      prm.enter_subsection("Growth path");
      path_start          = prm.get_double("Start");
      stop_at_first_event = prm.get_bool("Stop at first event");
      prm.leave_subsection();
      newton_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);
      arclength_settings.enabled = true; // the plate is always followed by arclength
      // 'Growth path / Stop at first event' is the library's entry under the
      // plate's name: either stops the first branch at its first event.
      arclength_settings.stop_at_first_event =
        arclength_settings.stop_at_first_event || stop_at_first_event;
      prm.enter_subsection("Output");
      output_directory    = prm.get("Output directory");
      sector_as_full_disc = prm.get_bool("Sector as full disc");
      prm.leave_subsection();

    }
    void
    PlateRodProblem::parse_parameters(ParameterHandler &prm)
    {
      energy_assembly.clear();
      PlateRodParameters::parse_parameters(prm);
    }
  } // namespace plate_rod
} // namespace cosmo
