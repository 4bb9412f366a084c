// Validation of the part-3 solver, a growing plate bounded by a rod
// (doc/specification/plate-rod.md verification anchors 1-5, and the AD derivatives), one
// file per topic. Run as test_plate_rod <case>.
#include "common.h"

int
main(int argc, char **argv)
{
  const auto        mpi = cosmo::io::ranks::init_mpi(argc, argv);
  cosmo_test::Cases cases;
  plate_rod_test::add_states_cases(cases);
  plate_rod_test::add_thresholds_cases(cases);
  plate_rod_test::add_lobes_cases(cases);
  plate_rod_test::add_shear_convergence_cases(cases);
  return cosmo_test::run_case("test_plate_rod", "", cases, argc, argv, 2, 2);
}
