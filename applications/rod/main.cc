// A whole rod or ribbon: a geometrically exact special Cosserat rod on the laws the suite computes.
#include <cosmo/io/parameters.h>

#include "run.h"

int
main(int argc, char **argv)
{
  using namespace cosmo;
  return io::run_application(argc, argv,
                             {"rod",
                              "a whole special Cosserat rod or ring: shapes, paths, thresholds "
                              "and post-buckling"},
                             &rod::RodParameters::declare_parameters, &rod::run_rod);
}
