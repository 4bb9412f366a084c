// The grown plate kinematics: compatible growth leaves no strain, polar
// growth is the tensor it claims to be, and the measures are those of the
// elastic part Fp G^-1.
#include <deal.II/base/parameter_handler.h>

#include <cosmo/materials/plate_growth.h>
#include <cosmo/materials/plate_law.h>

#include "test_tools.h"

#include <cmath>

using namespace dealii;
using namespace cosmo;
using cosmo_test::check_close;

int
main()
{
  // Isotropic growth g: the flat configuration phi = g X, d = E3 is
  // stress-free (all measures zero).
  const double                         g = 1.3;
  std::array<std::array<double, 2>, 2> Gi{{{{1 / g, 0}}, {{0, 1 / g}}}};
  const std::array<double, 3>          a1{{g, 0, 0}}, a2{{0, g, 0}}, d{{0, 0, 1}}, z{{0, 0, 0}};
  const auto                           s = materials::grown_plate_strains(a1, a2, d, z, z, Gi);
  double                               worst = 0;
  for (const double x : {s.membrane[0], s.membrane[1], s.membrane[2], s.bending[0], s.bending[1],
                         s.bending[2], s.shear[0], s.shear[1]})
    worst = std::max(worst, std::abs(x));
  check_close("isotropic growth g, phi = g X: no strain", worst, 0, 0, 1e-15);

  // Polar growth from the .prm: G e_r = g_r e_r, G e_t = g_t e_t at a point.
  ParameterHandler prm;
  materials::PlateGrowth::declare_parameters(prm);
  prm.parse_input_from_string("subsection Plate growth\n set Kind = polar\n"
                              " set Radial growth factor = 1 + 0.1*r\n"
                              " set Circumferential growth factor = 1.2\nend\n");
  materials::PlateGrowth growth;
  growth.parse_parameters(prm);
  const Point<2> X(0.3, 0.4); // r = 0.5
  const auto     G  = growth.value(X, 1.);
  const double   c = 0.6, sn = 0.8;
  check_close("G e_r = g_r e_r (g_r = 1.05)", G[0][0] * c + G[0][1] * sn, 1.05 * c, 1e-14);
  check_close("G e_t = g_t e_t (g_t = 1.2)", G[1][0] * -sn + G[1][1] * c, 1.2 * c, 1e-14);
  check_close("ramp: t = 0.5 gives 1 + (g - 1)/2", growth.factors(0.5, 0.5)[1], 1.1, 1e-14);

  // A uniaxially stretched plate under matching growth along X1 only.
  std::array<std::array<double, 2>, 2> G1i{{{{1 / 1.1, 0}}, {{0, 1}}}};
  const std::array<double, 3>          b1{{1.1, 0, 0}}, b2{{0, 1, 0}};
  const auto                           t1 = materials::grown_plate_strains(b1, b2, d, z, z, G1i);
  check_close("uniaxial growth 1.1 matched: membrane 11", t1.membrane[0], 0, 0, 1e-15);
  return cosmo_test::report();
}
