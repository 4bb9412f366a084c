// Part 2: a strip (Cosserat plate) reduced to a special Cosserat rod.
#include <cosmo/io/parameters.h>

#include "strip_problem.h"

int
main(int argc, char **argv)
{
  using namespace cosmo;
  return io::run_application(argc, argv,
                             {"strip",
                              "energy, resultants, 6x6 stiffness and cross-section shape of a "
                              "strip (Cosserat plate) under six rod strains"},
                             &strip::StripProblem::declare_parameters, &strip::run_strip);
}
