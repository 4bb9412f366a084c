// What the cases of test_cross_section share: problems from .prm texts, the
// closed-form helpers, the checks of a stiffness.
#ifndef cosmo_tests_cross_section_common_h
#define cosmo_tests_cross_section_common_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include "cross_section_problem.h"
#include "../reduced_rod_checks.h"
#include <cosmo/assembly/reduced_rod_table.h>
#include "../test_tools.h"
#include <cosmo/analysis/section_properties.h>
#include <cosmo/io/ranks.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <map>

using namespace dealii;
using namespace cosmo;
using cosmo_test::check;
using cosmo_test::check_close;
using Strains = std::array<double, 6>;

namespace cross_section_test
{
  /// tests/data, from the command line.
  inline std::string data_directory;

  inline const Strains reference_strains = {{0, 0, 1, 0, 0, 0}};

  /// A problem from a .prm text (quiet, no output files).
  inline std::unique_ptr<rod::CrossSectionProblem>
  make_problem(const std::string &prm_text)
  {
    ParameterHandler prm;
    rod::CrossSectionProblem::declare_parameters(prm);
    // The harness' tight tolerance first, so that a test can override it.
    prm.parse_input_from_string("subsection Nonlinear solver\n set Relative tolerance = 1e-12\nend\n" + prm_text);
    auto p = std::make_unique<rod::CrossSectionProblem>();
    p->parse_parameters(prm);
    p->setup_system();
    return p;
  }

  inline std::string
  section(const std::string &shape_lines, unsigned int refinements, unsigned int degree = 2)
  {
    return "subsection Cross-section\n" + shape_lines + "\n set Global refinements = " +
           std::to_string(refinements) + "\nend\nsubsection Finite element\n set Polynomial degree = " +
           std::to_string(degree) + "\nend\n";
  }

  inline std::string
  material(unsigned int k, const std::string &regions, double E, double nu,
           const std::string &growth_lines = "")
  {
    return "subsection Material " + std::to_string(k) + "\n set Regions = " + regions +
           "\n set Young's modulus = " + std::to_string(E) + "\n set Poisson's ratio = " +
           std::to_string(nu) + "\n" + growth_lines + "\nend\n";
  }

  inline std::string
  strains_block(const std::string &mode, const Strains &e, const std::string &free = "")
  {
    std::string s = "subsection Rod strains\n set Mode = " + mode + "\n set Strains = ";
    // Full precision: std::to_string would round to 6 decimals.
    std::ostringstream values;
    values << std::setprecision(17);
    for (unsigned int k = 0; k < 6; ++k)
      values << (k ? ", " : "") << e[k];
    s += values.str();
    return s + "\n set Free strains = " + free + "\nend\n";
  }

  inline std::string
  surface_layer(unsigned int k, const std::string &parts, double tension, double lambda_s,
                double mu_s, const std::string &growth_lines = "")
  {
    std::ostringstream t;
    t << std::setprecision(17) << "subsection Surface layer " << k << "\n set Boundary parts = " << parts
      << "\n set Surface tension = " << tension << "\n set Surface Lame modulus = " << lambda_s
      << "\n set Surface shear modulus = " << mu_s << "\n" << growth_lines << "\nend\n";
    return t.str();
  }

  /// Two layers on complementary arcs with growth and tension: every
  /// surface term of the energy, resultants and tangent is exercised.
  inline const std::string general_surface =
    surface_layer(1, "arc -60 150", 0.05, 0.1, 0.2,
                  " set Growth kind = tangential and axial\n set Growth factor = 1 + 0.1*x; 1 - 0.1*y") +
    surface_layer(2, "arc 150 300", -0.02, 0.05, 0.1,
                  " set Growth kind = isotropic\n set Growth factor = 1.05");

  /// Saint-Venant torsion constant of a rectangle a x b (a >= b), series.
  inline double
  rectangle_torsion_constant(double a, double b)
  {
    if (a < b)
      std::swap(a, b);
    double sum = 0;
    for (int n = 1; n < 200; n += 2)
      sum += std::tanh(n * M_PI * a / (2 * b)) / std::pow(n, 5);
    return a * b * b * b * (1. / 3 - 64. / std::pow(M_PI, 5) * (b / a) * sum);
  }

  inline double
  off_diagonal_max(const FullMatrix<double> &K)
  {
    double m = 0;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        if (i != j)
          m = std::max(m, std::abs(K(i, j)));
    return m;
  }

  inline void
  check_symmetric_positive(const FullMatrix<double> &K, const std::string &tag)
  {
    double asym = 0, scale = 0;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        {
          asym  = std::max(asym, std::abs(K(i, j) - K(j, i)));
          scale = std::max(scale, std::abs(K(i, j)));
        }
    check_close(tag + ": stiffness symmetric, max |K - K^T| / max |K|", asym / scale, 0, 0, 1e-12);
    LAPACKFullMatrix<double> L(6, 6);
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        L(i, j) = K(i, j);
    L.compute_eigenvalues();
    double lmin = 1e300;
    for (unsigned int i = 0; i < 6; ++i)
      lmin = std::min(lmin, L.eigenvalue(i).real());
    check(tag + ": stiffness positive definite (min eigenvalue " + std::to_string(lmin) + ")",
          lmin > 0);
  }

  inline double
  max_abs(const std::array<double, 6> &v)
  {
    double m = 0;
    for (const double x : v)
      m = std::max(m, std::abs(x));
    return m;
  }

  /// The state at the given prescribed strains of a 1 x 0.5 ellipse.
  inline rod::CrossSectionState
  ellipse_state(const Strains &e)
  {
    return make_problem(section(" set Shape = ellipse\n set Semi-axes = 1, 0.5", 2) +
                        material(1, "1", 1.0, 0.3) + strains_block("prescribed strains", e))
      ->solve();
  }

  /// Each topic's cases, by name.
  void
  add_closed_forms_cases(cosmo_test::Cases &cases);
  void
  add_derivatives_cases(cosmo_test::Cases &cases);
  void
  add_surface_layers_cases(cosmo_test::Cases &cases);
  void
  add_meshes_and_paths_cases(cosmo_test::Cases &cases);
  void
  add_section_properties_cases(cosmo_test::Cases &cases);
} // namespace cross_section_test

#endif
