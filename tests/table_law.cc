// The rod law of a constitutive table (materials/rod_laws/table.h): on a
// table of a bicubic polynomial energy (degree 3 in each strain, which the
// bicubic Hermite interpolant reproduces exactly) the law's energy,
// resultants and tangent are the polynomial's at any point, its natural
// state is the polynomial's minimum, a hole and a strain outside the grid
// are refused naming the strain and the range, and a table whose free
// strains are held at a resultant other than zero is bad input.
#include <deal.II/base/hdf5.h>
#include <deal.II/base/mpi.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/rod_laws/table.h>

#include "test_tools.h"

#include <cmath>
#include <filesystem>

#include <unistd.h>

using namespace cosmo;
using namespace dealii;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  // Psi(x, y) = a x^2/2 + b y^2/2 + c x^2 y^2 + d x^3 y + e x y^3 (x = kappa1, y = kappa3).
  constexpr double a = 2, b = 0.5, c = 0.3, d = 0.1, e = -0.05;
  double
  psi(double x, double y)
  {
    return a * x * x / 2 + b * y * y / 2 + c * x * x * y * y + d * x * x * x * y + e * x * y * y * y;
  }
  std::array<double, 5> // psi_x, psi_y, psi_xx, psi_xy, psi_yy
  derivatives(double x, double y)
  {
    return {{a * x + 2 * c * x * y * y + 3 * d * x * x * y + e * y * y * y,
             b * y + 2 * c * x * x * y + d * x * x * x + 3 * e * x * y * y,
             a + 2 * c * y * y + 6 * d * x * y, 4 * c * x * y + 3 * d * x * x + 3 * e * y * y,
             b + 2 * c * x * x + 6 * e * x * y}};
  }
  const std::array<double, 4> others{{10, 11, 12, 13}}; // nu1, nu2, nu3, kappa2

  /// table.h5 of psi on [-1, 1] x [-0.5, 0.5], (9 x 7 points); `hole`: one point unconverged.
  std::string
  write_table(const std::string &name, const bool hole, const std::string &held = "(no free strains)")
  {
    std::vector<double> x(9), y(7);
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = -1 + 0.25 * i;
    for (unsigned int j = 0; j < y.size(); ++j)
      y[j] = -0.5 + j / 6.;
    const std::size_t   n = x.size() * y.size();
    std::vector<double> W(n), R(6 * n, 0.), K(36 * n, 0.), converged(n, 1.);
    for (unsigned int i = 0; i < x.size(); ++i)
      for (unsigned int j = 0; j < y.size(); ++j)
        {
          const std::size_t p = i * y.size() + j;
          const auto        D = derivatives(x[i], y[j]);
          W[p]                = psi(x[i], y[j]);
          R[6 * p + 3]        = D[0];
          R[6 * p + 5]        = D[1];
          double *k           = &K[36 * p];
          k[6 * 3 + 3]        = D[2];
          k[6 * 3 + 5] = k[6 * 5 + 3] = D[3];
          k[6 * 5 + 5]                = D[4];
          for (const unsigned int o : {0u, 1u, 2u, 4u})
            k[7 * o] = others[o < 3 ? o : 3];
        }
    if (hole)
      {
        converged[6 * y.size() + 5] = 0; // (x, y) = (0.5, 1/3)
        W[6 * y.size() + 5]         = NAN;
      }
    HDF5::File f(name, HDF5::File::FileAccessMode::create);
    f.set_attribute("strain_1_name", std::string("kappa1"));
    f.set_attribute("strain_2_name", std::string("kappa3"));
    f.set_attribute("free_strains", std::string(held == "(no free strains)" ? "(none)" : "nu3"));
    f.set_attribute("held_resultants", held);
    f.create_dataset<double>("strain_1", {x.size()}).write(x);
    f.create_dataset<double>("strain_2", {y.size()}).write(y);
    f.create_dataset<double>("energy", {x.size(), y.size()}).write(W);
    f.create_dataset<double>("resultants", {x.size(), y.size(), 6}).write(R);
    f.create_dataset<double>("stiffness", {x.size(), y.size(), 6, 6}).write(K);
    f.create_dataset<double>("converged", {x.size(), y.size()}).write(converged);
    return name;
  }

  /// LawRangeError's message from f() ("" if none was thrown).
  template <typename F>
  std::string
  refusal(F f)
  {
    try
      {
        f();
      }
    catch (materials::LawRangeError &error)
      {
        return error.what();
      }
    return "";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto dir = std::filesystem::temp_directory_path() / ("cosmo_table_law_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);

  materials::TableRodLaw law;
  law.read(write_table((dir / "table.h5").string(), false), "Rod/Material");
  const auto xi0 = *law.natural_strains_at(0);
  check_close("natural kappa1 at the minimum", xi0[3], 0, 0, 1e-14);
  check_close("natural kappa3 at the minimum", xi0[5], 0, 0, 1e-14);
  check_close("natural nu3 of the straight rod", xi0[2], 1, 0);

  // Reproduced at points inside cells (the interpolant is the polynomial).
  double worst_W = 0, worst_g = 0, worst_H = 0;
  for (const auto &[x, y] : std::vector<std::pair<double, double>>{{0.13, -0.21}, {-0.77, 0.41}, {0.99, 0.02}, {-0.3, -0.49}})
    {
      std::array<double, 6>  strain{{0.01, -0.02, 0.03, x, 0.04, y}}, dW;
      std::array<double, 36> ddW;
      double                 W = 0;
      law.energy_derivatives(strain, true, W, dW, ddW);
      const auto D       = derivatives(x, y);
      double     quad    = 0;
      const std::array<unsigned int, 4> o{{0, 1, 2, 4}};
      for (unsigned int k = 0; k < 4; ++k)
        quad += 0.5 * others[k] * strain[o[k]] * strain[o[k]];
      worst_W = std::max(worst_W, std::abs(W - psi(x, y) - quad));
      worst_g = std::max({worst_g, std::abs(dW[3] - D[0]), std::abs(dW[5] - D[1]), std::abs(dW[2] - 12 * 0.03)});
      worst_H = std::max({worst_H, std::abs(ddW[21] - D[2]), std::abs(ddW[23] - D[3]), std::abs(ddW[33] - D[3]),
                          std::abs(ddW[35] - D[4]), std::abs(ddW[14] - 12), std::abs(ddW[3 * 6 + 2])});
    }
  // (round-off of sums of ~30 terms of size ~1)
  check_close("energy = the polynomial's + the others' quadratic", worst_W, 0, 0, 1e-13);
  check_close("resultants = its gradient", worst_g, 0, 0, 1e-12);
  check_close("tangent = its Hessian (no coupling to the others)", worst_H, 0, 0, 1e-11);

  const std::string outside = refusal([&]() {
    std::array<double, 6>  strain{{0, 0, 1, 1.01, 0, 0}}, dW;
    std::array<double, 36> ddW;
    double                 W;
    law.energy_derivatives(strain, false, W, dW, ddW);
  });
  check("kappa1 = 1.01: refused, naming kappa1 and [-1, 1]",
        outside.find("kappa1 = 1.01") != std::string::npos && outside.find("[-1, 1]") != std::string::npos);

  materials::TableRodLaw holed;
  holed.read(write_table((dir / "holed.h5").string(), true), "Rod/Material");
  const std::string hole = refusal([&]() {
    std::array<double, 6>  strain{{0, 0, 1, 0.4, 0, 0.3}}, dW;
    std::array<double, 36> ddW;
    double                 W;
    holed.energy_derivatives(strain, false, W, dW, ddW);
  });
  check("a cell with an unconverged point: refused", hole.find("did not converge") != std::string::npos);
  {
    std::array<double, 6>  strain{{0, 0, 0, -0.4, 0, -0.3}}, dW; // (elastic strains: from the natural state)
    std::array<double, 36> ddW;
    double                 W;
    holed.energy_derivatives(strain, false, W, dW, ddW);
    check_close("a cell away from the hole: the polynomial", W, psi(-0.4, -0.3), 1e-13);
  }
  bool held = false;
  try
    {
      materials::TableRodLaw tension;
      tension.read(write_table((dir / "held.h5").string(), false, "n3 = 0.5"), "Rod/Material");
    }
  catch (io::InputError &error)
    {
      held = std::string(error.what()).find("held at zero") != std::string::npos;
    }
  check("free strains held at n3 = 0.5: bad input", held);
  std::filesystem::remove_all(dir);
  return cosmo_test::report();
}
