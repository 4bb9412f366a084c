// The parameters of part 1: what the rod_cross_section application reads and checks.
#include <deal.II/base/utilities.h>

#include <cosmo/config.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/kinematics/section.h>

#include "cross_section_problem.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    void
    CrossSectionParameters::declare_parameters(ParameterHandler &prm)
    {
      geometry::CrossSectionGeometry::declare_parameters(prm);
      materials::MaterialLibrary::declare_parameters(prm);
      materials::SurfaceLayerLibrary::declare_parameters(prm);

      prm.enter_subsection("Finite element");
      prm.declare_entry("Polynomial degree", "2", Patterns::Integer(1, 4),
                        "Degree p of the FE_Q(p)^3 displacement of the cross-section "
                        "(and of the isoparametric mapping). p >= 2 for nearly "
                        "incompressible materials.");
      prm.declare_entry("Distributed", "false", Patterns::Bool(),
                        "Under mpirun: divide the mesh over the ranks (a "
                        "parallel::distributed::Triangulation), each rank assembling its own "
                        "cells and holding its rows of the matrix, factorized by MUMPS with "
                        "distributed input; VTUs as one .pvtu with a piece per rank. For "
                        "sections too large for one node. One path only (not a study or a "
                        "table), MUMPS only, no coarse-mesh start and no reference linear "
                        "properties (they need the whole mesh); the results agree with one "
                        "process's to round-off; resume with as many ranks as began the run "
                        "(doc/parallel-runs.md). false: rank 0 assembles on its node and "
                        "shares only large factorizations.");
      prm.leave_subsection();

      assembly::ReducedRodProblem::declare_strain_parameters(prm);

      solvers::NewtonSettings::declare_parameters(prm);
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Linear solver", solvers::SparseDirectSolver::kind_names() ==
                                             "UMFPACK" ? "UMFPACK" : "MUMPS",
                        Patterns::Selection(solvers::SparseDirectSolver::kind_names()),
                        "Sparse direct solver of the Newton systems: MUMPS (LDL^T, "
                        "gives the stability indicator) or UMFPACK (LU).");
      prm.declare_entry("Coarse-mesh start", "2", Patterns::Integer(0, 10),
                        "Nested iteration for the first continuation step: it is solved "
                        "first on the section refined this many times less (each level "
                        "started from the one below it), and the solution, interpolated, "
                        "starts Newton on the full mesh, which then needs only its last "
                        "iterations. The converged state is the full mesh's, to Newton's "
                        "tolerance, where the equilibrium at the first step's load is "
                        "unique (else Newton may reach another from any start: use 0 or "
                        "a smaller 'Initial step'). 0: start from the reference state. Used "
                        "where the coarser mesh has the same coarse cells (every built-in "
                        "shape; not a mesh shifted to its centroid), by the natural-parameter "
                        "continuation (not on arclength paths).");
      prm.leave_subsection();
      solvers::ContinuationSettings::declare_parameters(prm);
      solvers::ArclengthSettings::declare_parameters(prm);

      prm.enter_subsection("Output");
      prm.declare_entry("Output directory", "output/rod_cross_section", Patterns::Anything(),
                        "Directory for parameters.prm, summary.json, steps.csv, the VTU "
                        "series and log.txt (created if needed).");
      prm.declare_entry("Rod piece length", "0", Patterns::Double(0),
                        "Length (reference arc length) of the 3D piece of rod swept along "
                        "the helix; 0: one helical turn, at most 10 section diameters.");
      prm.declare_entry("Rod piece slices", "24", Patterns::Integer(1, 1000),
                        "Number of slices of the 3D rod piece along its length.");
      prm.declare_entry("Stiffness at every step", "true", Patterns::Bool(),
                        "Compute the 6x6 stiffness (one more factorization) at every "
                        "step, not only at the final one.");
      prm.leave_subsection();

      io::ParameterSweep::declare_parameters(prm);
      assembly::ConstitutiveTable::declare_parameters(prm);
    }

    void
    CrossSectionProblem::parse_parameters(ParameterHandler &prm)
    {
      CrossSectionParameters::parse_parameters(prm);
      parse_strain_parameters(prm);
      table.parse_parameters(prm);
      table.check_axes(strain_is_free);
    }

    void
    CrossSectionParameters::parse_parameters(ParameterHandler &prm)
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      surface_layers.parse_parameters(prm);

      prm.enter_subsection("Finite element");
      degree           = prm.get_integer("Polynomial degree");
      distributed_mesh = prm.get_bool("Distributed");
      prm.leave_subsection();

      newton_settings.parse_parameters(prm);
      prm.enter_subsection("Nonlinear solver");
      linear_solver_name = prm.get("Linear solver");
      if (distributed_mesh && linear_solver_name != "MUMPS")
        throw io::InputError("Nonlinear solver", "Linear solver", linear_solver_name,
                             "a distributed mesh ('Finite element / Distributed = true') is "
                             "factorized by MUMPS: set MUMPS");
      coarse_start_levels = prm.get_integer("Coarse-mesh start");
      {
        // The whole set, from which first_step_guess() makes the coarser copies.
        std::ostringstream text;
        prm.print_parameters(text, ParameterHandler::ShortPRM);
        parameters_text = text.str();
      }
      prm.leave_subsection();
      continuation_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);

      prm.enter_subsection("Output");
      output_directory     = prm.get("Output directory");
      rod_piece_length     = prm.get_double("Rod piece length");
      rod_piece_slices     = prm.get_integer("Rod piece slices");
      stiffness_every_step = prm.get_bool("Stiffness at every step");
      prm.leave_subsection();
    }
  } // namespace rod
} // namespace cosmo
