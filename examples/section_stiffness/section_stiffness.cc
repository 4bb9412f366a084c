// The example of doc/cookbook.md, "Write your own application": a small
// application built out of tree against the installed suite. From a
// parameter file it meshes a registered cross-section shape (any shape of
// 'Cross-section / Shape', also one loaded from a plugin library) and
// computes its linear-elastic rod stiffnesses (tension, bending, torsion,
// shear) with the library's Saint-Venant solver, into summary.json.
//
// What the library gives it: the command line (--help, --print-parameters,
// exit status 1 with the file and entry of bad input), 'Additional shared
// libraries', the output directory with parameters.prm, the shapes and
// their meshes, the solver.
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <cosmo/analysis/section_properties.h>
#include <cosmo/geometry/cross_section.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>

#include <iostream>

using namespace dealii;
using namespace cosmo;

namespace
{
  void
  declare(ParameterHandler &prm)
  {
    geometry::CrossSectionGeometry::declare_parameters(prm);
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus", "1", Patterns::Double(0), "E.");
    prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-1, 0.5), "nu; G = E / (2 (1 + nu)).");
    prm.leave_subsection();
    prm.enter_subsection("Finite element");
    prm.declare_entry("Degree", "2", Patterns::Integer(1, 4), "Degree of the elements and the mapping.");
    prm.leave_subsection();
    // Every application has 'Output / Output directory' (io::run_application).
    prm.enter_subsection("Output");
    prm.declare_entry("Output directory", "output/section_stiffness", Patterns::DirectoryName(),
                      "Directory for parameters.prm, log.txt and summary.json.");
    prm.leave_subsection();
  }

  void
  run(ParameterHandler &prm, const io::RunOptions &options)
  {
    geometry::CrossSectionGeometry geometry;
    geometry.parse_parameters(prm);
    prm.enter_subsection("Material");
    const double young = prm.get_double("Young's modulus");
    const double nu    = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    prm.enter_subsection("Finite element");
    const unsigned int degree = prm.get_integer("Degree");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    const std::string directory = prm.get("Output directory");
    prm.leave_subsection();

    auto log = io::open_run_directory(directory, prm, options.quiet);
    Triangulation<2> tria;
    geometry.create_triangulation(tria);
    (*log)("section '" + geometry.shape + "', " + std::to_string(tria.n_active_cells()) + " cells");
    const MappingQ<2> mapping(degree);
    const auto        p = analysis::linear_section_properties(tria, mapping, degree, [&](types::material_id) {
      return analysis::RegionModuli{young, young / (2 * (1 + nu)), 1.};
    });
    (*log)("EA = " + std::to_string(p.EA) + ", EI11 = " + std::to_string(p.EI11) +
             ", EI22 = " + std::to_string(p.EI22) + ", GJ = " + std::to_string(p.GJ));
    io::JSON summary   = io::JSON::object();
    summary["status"]  = io::JSON("converged");
    summary["section"] = p.to_json();
    io::write_file_atomically(directory + "/summary.json", [&](std::ostream &o) { summary.print(o); });
  }
} // namespace

int
main(int argc, char **argv)
{
  return io::run_application(argc, argv,
                             {"section_stiffness", "linear-elastic rod stiffnesses of a cross-section"},
                             &declare, &run);
}
