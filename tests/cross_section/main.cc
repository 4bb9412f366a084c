// Validation of the part-1 cross-section solver against closed forms
// (doc/specification/rod-cross-section.md, anchors 1-4 and 6), one file per topic. Run as
//   test_cross_section <case> [tests/data directory]
// Each case prints measured value, reference and tolerance; the tolerances
// are justified next to each check (discretization error measured on the
// meshes used, or Newton/round-off level where the discrete answer is exact).
#include "common.h"

int
main(int argc, char **argv)
{
  const auto        mpi = cosmo::io::ranks::init_mpi(argc, argv, 1);
  cosmo_test::Cases cases;
  cross_section_test::add_closed_forms_cases(cases);
  cross_section_test::add_derivatives_cases(cases);
  cross_section_test::add_surface_layers_cases(cases);
  cross_section_test::add_meshes_and_paths_cases(cases);
  cross_section_test::add_section_properties_cases(cases);
  if (argc == 3)
    cross_section_test::data_directory = argv[2];
  return cosmo_test::run_case("test_cross_section", "[tests/data directory]", cases, argc, argv, 2, 3);
}
