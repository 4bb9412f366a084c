// The one admissibility check of growth laws (materials/growth_admissibility.h):
// a quantity positive at the four nodes of the ramp but negative between them
// is refused at its minimum; a positive one passes; a non-finite value is
// refused at its point; the points are every vertex and quadrature point of
// every level of the mesh.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth_admissibility.h>

#include "test_tools.h"

#include <cmath>
#include <regex>

using namespace dealii;
using namespace cosmo;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  /// The message of the refusal, or "" if the check passes.
  std::string
  refusal(const std::vector<Point<2>> &points,
          const std::function<std::vector<double>(const Point<2> &, double)> &q)
  {
    try
      {
        materials::check_growth_admissible(points, q, {"Material 1", "Growth factor", "test"});
      }
    catch (io::InputError &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

int
main()
{
  const std::vector<Point<2>> one = {Point<2>(0.25, 0.5)};
  // (t - 0.44)(t - 0.45)/(0.44 0.45): 1 at t = 0, positive at 1/3, 2/3, 1 and at
  // every multiple of 1/64, negative only on (0.44, 0.45), least at t = 0.445
  // (-1.26e-4). A sampled check misses it; the cubic's exact minimum does not.
  const auto narrow = [](const Point<2> &, const double t) {
    return std::vector<double>{(t - 0.44) * (t - 0.45) / (0.44 * 0.45)};
  };
  const std::string m = refusal(one, narrow);
  std::smatch       at;
  const bool        found = std::regex_search(m, at, std::regex("at load t = ([0-9.e+-]+)"));
  check("a dip below 0 between the nodes is refused (" + m.substr(0, 160) + ")", found);
  if (found)
    check_close("  ... at its minimum t = 0.445", std::stod(at[1]), 0.445, 0, 1e-6);
  check("  ... naming the entry and the point", m.find("Growth factor") != std::string::npos &&
                                                 m.find("(0.25, 0.5)") != std::string::npos);

  // det of diag(1 + t (g - 1)) with g = 1.5, 0.5, 2: positive on [0, 1].
  const auto positive = [](const Point<2> &, const double t) {
    return std::vector<double>{(1 + 0.5 * t) * (1 - 0.5 * t) * (1 + t)};
  };
  check("a positive cubic passes", refusal(one, positive).empty());
  // 1 + 0.1/(x^2 + y^2) at the origin: inf.
  const std::vector<Point<2>> origin = {Point<2>(0.5, 0), Point<2>(0, 0)};
  const auto                  singular = [](const Point<2> &X, const double t) {
    const double g = 1 + t * 0.1 / X.norm_square();
    return std::vector<double>{g * g * g};
  };
  const std::string s = refusal(origin, singular);
  check("a law infinite at a point is refused there (" + s.substr(0, 120) + ")",
        s.find("at (0, 0)") != std::string::npos);

  // The points: a disc refined twice has 5 + 20 + 80 cells on its three
  // levels; 4 vertices and 9 Gauss points (Q2 rule) each.
  Triangulation<2> tria;
  GridGenerator::hyper_ball(tria);
  tria.refine_global(2);
  const MappingQ<2> mapping(2);
  const auto        points =
    materials::growth_points(mapping, tria, QGauss<2>(3), [](const auto &) { return true; });
  check("every level's vertices and quadrature points (" + std::to_string(points.size()) +
          " = 105 x 13)",
        points.size() == (5 + 20 + 80) * 13);
  bool centre = false;
  for (const auto &X : points)
    centre = centre || X.norm() < 1e-14;
  check("  ... the centre among them (a vertex of the level-1 cells)", centre);
  return cosmo_test::report();
}
