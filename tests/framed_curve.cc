// Unit tests of link, twist and writhe of closed framed polygons
// (kinematics/framed_curve.h): the Hopf link links once, a planar ribbon
// turned n times has Tw = Lk = n and Wr = 0, and on a knotted, twisted
// ribbon Tw + Wr equals its integer Lk.
#include <deal.II/base/tensor.h>

#include <cosmo/kinematics/framed_curve.h>

#include "test_tools.h"

#include <cmath>
#include <vector>

using namespace dealii;
using namespace cosmo::kinematics;
using cosmo_test::check_close;

namespace
{
  using Curve = std::vector<Tensor<1, 3>>;

  Tensor<1, 3>
  point(const double x, const double y, const double z)
  {
    Tensor<1, 3> p;
    p[0] = x;
    p[1] = y;
    p[2] = z;
    return p;
  }

  /// A trefoil (the (2,3) torus knot) through n points and the unit
  /// normals of its segments: the principal normal turned by n_turns full
  /// turns about the tangent along the curve.
  void
  trefoil(const unsigned int n, const int n_turns, Curve &x, Curve &m)
  {
    auto r = [](const double s) {
      return point((2 + std::cos(3 * s)) * std::cos(2 * s), (2 + std::cos(3 * s)) * std::sin(2 * s),
                   std::sin(3 * s));
    };
    x.resize(n);
    m.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      x[k] = r(2 * M_PI * k / n);
    for (unsigned int e = 0; e < n; ++e)
      {
        const double       s  = 2 * M_PI * (e + 0.5) / n, d = 1e-4;
        const Tensor<1, 3> t  = (x[(e + 1) % n] - x[e]) / (x[(e + 1) % n] - x[e]).norm();
        const Tensor<1, 3> a  = (r(s + d) - 2 * r(s) + r(s - d)) / (d * d); // curvature direction
        Tensor<1, 3>       nn = a - (a * t) * t;
        nn /= nn.norm();
        const Tensor<1, 3> bb = cross_product_3d(t, nn);
        const double       phi = n_turns * s;
        m[e]                   = std::cos(phi) * nn + std::sin(phi) * bb;
      }
  }
} // namespace

int
main()
{
  // Two unit circles through each other's centres: linked once.
  {
    Curve a, b;
    for (unsigned int k = 0; k < 64; ++k)
      {
        const double s = 2 * M_PI * k / 64;
        a.push_back(point(std::cos(s), std::sin(s), 0));
        b.push_back(point(1 + std::cos(s), 0, std::sin(s)));
      }
    check_close("Hopf link: |Lk| = 1", std::abs(linking_number(a, b)), 1, 0, 1e-12);
    Curve c;
    for (const auto &p : b)
      c.push_back(p + point(5, 0, 0));
    check_close("apart: Lk = 0", linking_number(a, c), 0, 0, 1e-12);
  }
  // A planar circle with its normal turned n = 3 times: Tw = Lk = 3, Wr = 0.
  {
    const unsigned int n = 200;
    Curve              x(n), m(n);
    for (unsigned int k = 0; k < n; ++k)
      x[k] = point(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0);
    for (unsigned int e = 0; e < n; ++e)
      {
        const double s = 2 * M_PI * (e + 0.5) / n, phi = 3 * s;
        // -radial and e3, turned about the tangent.
        m[e] = std::cos(phi) * point(-std::cos(s), -std::sin(s), 0) + std::sin(phi) * point(0, 0, 1);
      }
    check_close("planar ribbon: Wr = 0", writhe(x), 0, 0, 1e-12);
    // The segment normals are sampled at the midpoints: the twist is exact
    // to round-off for a uniform turn on a regular polygon.
    check_close("planar ribbon: Tw = 3", twist(x, m), 3, 0, 1e-9);
    check_close("planar ribbon: Lk = 3", ribbon_link(x, m, 0.05), 3, 0, 1e-9);
  }
  // A trefoil with its principal normal turned twice more: Lk an integer,
  // and Tw + Wr = Lk for the polygon itself -- the discrete
  // Calugareanu-White identity of a polygon whose twist is measured against
  // parallel transport (measured: 1e-14 to 1e-12, round-off of the double
  // sums), on two refinements.
  for (const unsigned int n : {200u, 400u})
    {
      Curve x, m;
      trefoil(n, 2, x, m);
      const double lk = ribbon_link(x, m, 1e-3), tw = twist(x, m), wr = writhe(x);
      check_close("trefoil " + std::to_string(n) + ": Lk an integer", lk, std::round(lk), 0, 1e-9);
      check_close("trefoil " + std::to_string(n) + ": Tw + Wr = Lk", tw + wr, std::round(lk), 0, 1e-9);
      check_close("trefoil " + std::to_string(n) + ": writhe not small", std::abs(wr) > 1 ? 1 : 0, 1, 0);
    }
  // An open straight polygon whose normal turns by 2.5 turns in 100 equal
  // steps: Tw = 2.5 (each step's angle below pi, so atan2 sees it whole);
  // bent into a planar arc with the normal kept in the plane: Tw = 0.
  {
    Curve t(101), m(101), arc_t(101), arc_m(101);
    for (unsigned int k = 0; k <= 100; ++k)
      {
        const double phi = 2.5 * 2 * M_PI * k / 100, s = 0.01 * k;
        t[k]     = point(0, 0, 1);
        m[k]     = point(std::cos(phi), std::sin(phi), 0);
        arc_t[k] = point(std::cos(s), std::sin(s), 0);
        arc_m[k] = point(-std::sin(s), std::cos(s), 0);
      }
    check_close("open straight polygon turned 2.5 times: Tw", open_twist(t, m), 2.5, 0, 1e-12);
    check_close("open planar arc, normal in the plane: Tw", open_twist(arc_t, arc_m), 0, 0, 1e-12);
  }
  return cosmo_test::report();
}
