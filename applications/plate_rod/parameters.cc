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
        materials::NaghdiPlateLaw::declare_parameters(prm);
        materials::PlateGrowth::declare_parameters(prm);
        prm.enter_subsection("Rim rod");
        prm.declare_entry("Stiffnesses", "0.1, 0.1, 0.1, 1e-6, 1e-6, 1e-6",
                          Patterns::List(Patterns::Double(0), 6, 6),
                          "GA1, GA2, EA, EI1, EI2, GJ of the rim's cross-section (d1 radial, d2 "
                          "the plate normal, d3 the tangent): shear along d1, d2, extension, "
                          "bending about d1 (out of plane), about d2 (in plane), torsion. E.g. the "
                          "diagonal of a rod_cross_section stiffness.");
        prm.declare_entry("Stiffness file", "", Patterns::Anything(),
                          "If set: a rod_cross_section summary.json whose 6x6 'stiffness' is "
                          "the rim's stiffness, couplings included (about the section's origin; "
                          "its X1 is the rim's radial axis d1, X2 the plate normal d2); replaces "
                          "'Stiffnesses'. It must be symmetric positive definite. The closed "
                          "forms use its diagonal.");
        prm.declare_entry("Natural curvature", "0, 0, 0", Patterns::Anything(),
                          "Change of the rim's stress-free curvature reached at t = 1 (ramped as "
                          "t dk) from the rim's own growth through its section: dk1, dk2, dk3 in "
                          "the rim's frame d1 = e_r, d2 = E3, d3 = -e_theta (dk1 bends the rim "
                          "out of the plate's plane, dk2 changes its in-plane curvature, dk3 is "
                          "a natural twist), per unit length.");
        prm.declare_entry("Growth factor", "1", Patterns::Double(0),
                          "Axial growth g of the rim at t = 1 (ramped as 1 + t (g - 1)); the "
                          "stress-free rim is a ring of radius g R.");
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
    } // namespace

    void
    PlateRodProblem::declare_parameters(ParameterHandler &prm)
    {
      declare_plate_and_rim(prm);
      declare_model_and_mesh(prm);
      declare_path_and_output(prm);
    }

    namespace
    {
      /**
       * The 6x6 "stiffness" of a rod_cross_section summary.json, row by row;
       * io::InputError naming 'Rim rod / Stiffness file' if the file is not
       * one or the matrix is not 6x6 of finite numbers.
       */
      std::vector<double>
      read_section_stiffness(const std::string &file)
      {
        std::ifstream in(file);
        if (!in)
          throw io::InputError("Rim rod", "Stiffness file", file,
                               "a readable rod_cross_section summary.json (cannot open it)");
        std::stringstream buffer;
        buffer << in.rdbuf();
        std::vector<double> K; // the finite numbers of "stiffness", row by row
        std::size_t         rows = 0, non_square = 0;
        try
          {
            const io::JSON  summary = io::JSON::parse(buffer.str());
            const io::JSON *k       = summary.find("stiffness");
            if (k && k->is_array())
              for (rows = 0; rows < k->size(); ++rows)
                {
                  non_square += k->at(rows).size() != 6;
                  for (std::size_t b = 0; b < k->at(rows).size(); ++b)
                    if (std::isfinite(k->at(rows).at(b).as_number()))
                      K.push_back(k->at(rows).at(b).as_number());
                }
          }
        catch (std::runtime_error &e)
          {
            throw io::InputError("Rim rod", "Stiffness file", file,
                                 "a rod_cross_section summary.json (" + std::string(e.what()) + ")");
          }
        if (K.size() != 36 || rows != 6 || non_square > 0)
          throw io::InputError("Rim rod", "Stiffness file", file,
                               "a rod_cross_section summary.json with a 6x6 \"stiffness\" of "
                               "finite numbers (found " + std::to_string(K.size()) +
                                 " numbers in " + std::to_string(rows) + " rows)");
        return K;
      }
    } // namespace

    void
    PlateRodProblem::check_rim_stiffness(const std::string &entry, const std::string &text) const
    {
      // The rim against the plate: beyond 1e8 times the plate's own stiffness
      // the coupled Hessian loses every digit of the plate's contribution in
      // double precision (the rigid limit is reached to 1e-8 long before).
      const double Eh = plate_law.young * thickness;
      const double D  = plate_law.bending_stiffness();
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

    namespace
    {
      /// A rim stiffness from a part-1 summary.json: its diagonal, the
      /// symmetric part of its couplings, and the largest coupling
      /// |K_ab| / sqrt(K_aa K_bb).
      struct RimStiffness
      {
        std::array<double, 6>                diagonal{};
        std::array<std::array<double, 6>, 6> coupling{};
        double                               largest_coupling = 0;
      };

      /// 'Rim rod / Stiffness file': io::InputError unless it is a symmetric
      /// positive definite 6x6 (non-positive diagonals are left to
      /// check_rim_stiffness(), which names them).
      RimStiffness
      read_rim_stiffness(const std::string &file)
      {
        const auto   K = read_section_stiffness(file);
        RimStiffness rim;
        // The full matrix: its symmetric part (a summary's K is symmetric
        // to round-off), and how much its couplings weigh.
        double coupling = 0, asymmetry = 0, scale = 0;
        for (unsigned int a = 0; a < 6; ++a)
          {
            rim.diagonal[a] = K[7 * a];
            for (unsigned int b = 0; b < 6; ++b)
              {
                scale     = std::max(scale, std::abs(K[6 * a + b]));
                asymmetry = std::max(asymmetry, std::abs(K[6 * a + b] - K[6 * b + a]));
                rim.coupling[a][b] = a == b ? 0. : 0.5 * (K[6 * a + b] + K[6 * b + a]);
                if (a != b)
                  coupling = std::max(coupling, std::abs(K[6 * a + b]) /
                                                  std::sqrt(std::abs(K[7 * a] * K[7 * b])));
              }
          }
        if (asymmetry > 1e-8 * scale)
          throw io::InputError("Rim rod", "Stiffness file", file,
                               "a symmetric 6x6 stiffness (max |K_ab - K_ba| = " +
                                 io::format_number(asymmetry) + ")");
        // Positive definite: Cholesky (a stable rim needs it; a failure names the pivot).
        // (Non-positive diagonals are left to check_rim_stiffness(), which names them.)
        std::array<std::array<double, 6>, 6> L{};
        const bool positive_diagonal =
          std::all_of(rim.diagonal.begin(), rim.diagonal.end(), [](double k) { return k > 0; });
        for (unsigned int j = 0; positive_diagonal && j < 6; ++j)
          {
            double d = K[7 * j];
            for (unsigned int k = 0; k < j; ++k)
              d -= L[j][k] * L[j][k];
            if (!(d > 1e-12 * K[7 * j]))
              throw io::InputError("Rim rod", "Stiffness file", file,
                                   "a positive definite 6x6 stiffness (its leading " +
                                     std::to_string(j + 1) + "x" + std::to_string(j + 1) +
                                     " block is not)");
            L[j][j] = std::sqrt(d);
            for (unsigned int i = j + 1; i < 6; ++i)
              {
                double v = 0.5 * (K[6 * i + j] + K[6 * j + i]);
                for (unsigned int k = 0; k < j; ++k)
                  v -= L[i][k] * L[j][k];
                L[i][j] = v / L[j][j];
              }
          }
        rim.largest_coupling = coupling;
        return rim;
      }
    } // namespace

    void
    PlateRodProblem::parse_parameters(ParameterHandler &prm)
    {
      residuals.clear();
      prm.enter_subsection("Plate");
      radius    = prm.get_double("Radius");
      thickness = prm.get_double("Thickness");
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
      thickness_profile_text = prm.get("Thickness profile");
      thickness_profile =
        thickness_profile_text == "1" ?
          nullptr :
          materials::parse_expression_of_position(thickness_profile_text, "Plate",
                                                  "Thickness profile", 1);
      prm.leave_subsection();
      plate_law.parse_parameters(prm);
      plate_law.thickness = thickness;
      plate_growth.parse_parameters(prm);

      prm.enter_subsection("Rim rod");
      const auto k = io::get_double_list(prm, "Stiffnesses", 6, "Rim rod");
      std::copy(k.begin(), k.end(), rod_stiffness.begin());
      stiffness_file = prm.get("Stiffness file");
      if (!stiffness_file.empty())
        {
          const RimStiffness r = read_rim_stiffness(stiffness_file);
          rod_stiffness        = r.diagonal;
          rod_coupling         = r.coupling;
          stiffness_coupling   = r.largest_coupling;
        }
      {
        const auto k = io::get_double_list(prm, "Natural curvature", 3, "Rim rod");
        for (unsigned int i = 0; i < 3; ++i)
          rod_natural_curvature[i] = k[i];
      }
      rod_growth = prm.get_double("Growth factor");
      if (!(rod_growth > 0))
        throw io::InputError("Rim rod", "Growth factor", prm.get("Growth factor"),
                             "must be positive");
      // The stiffnesses in use are the file's if one is given: its entry is named.
      if (stiffness_file.empty())
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
      {
        const double angle = prm.get_double("Sector angle");
        const double n     = 180. / angle;
        if (!(angle > 0) || std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
          throw io::InputError("Mesh", "Sector angle", prm.get("Sector angle"),
                               "the sector must be pi/n: 180/n degrees for an integer n >= 1 "
                               "(180, 90, 60, 45, 36, 30, ...)");
        sector_n = static_cast<unsigned int>(std::round(n));
      }
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
  } // namespace plate_rod
} // namespace cosmo
