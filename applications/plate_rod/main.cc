// Part 3: a growing circular Cosserat plate bounded by a Cosserat rod.
#include <cosmo/io/parameters.h>

#include "run.h"

int
main(int argc, char **argv)
{
  using namespace cosmo;
  return io::run_application(argc, argv,
                             {"plate_rod",
                              "growth-induced buckling of a circular plate bounded by a rod: "
                              "flat branch, stability, critical growth, buckled branches"},
                             &plate_rod::PlateRodProblem::declare_parameters,
                             &plate_rod::run_plate_rod);
}
