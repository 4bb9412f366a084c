// Part 1: natural shapes and stiffnesses of morphoelastic rods.
#include <cosmo/io/parameters.h>

#include "cross_section_problem.h"

int
main(int argc, char **argv)
{
  using namespace cosmo;
  return io::run_application(
    argc, argv,
    {"rod_cross_section",
     "stress resultants, 6x6 stiffness and natural shape of a growing rod "
     "from its cross-section (helical Cauchy-Born rule)"},
    &rod::CrossSectionProblem::declare_parameters,
    &rod::run_study);
}
