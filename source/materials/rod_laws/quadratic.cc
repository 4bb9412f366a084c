// The quadratic rod law (rod_laws/quadratic.h), its stiffness given or read
// from a part-1 (rod_cross_section) summary.json.
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/materials/rod_laws/quadratic.h>
#include <cosmo/materials/section_stiffness.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace cosmo
{
  namespace materials
  {
    namespace
    {
      /// A stiffness from a part-1 summary.json: its diagonal, the
      /// symmetric part of its couplings, and the largest coupling
      /// |K_ab| / sqrt(K_aa K_bb).
      struct FileStiffness
      {
        std::array<double, 6>                diagonal{};
        std::array<std::array<double, 6>, 6> coupling{};
        double                               largest_coupling = 0;
      };

      /// 'Stiffness file': io::InputError unless it is a symmetric
      /// positive definite 6x6 (non-positive diagonals are left to the
      /// application's check of the stiffnesses, which names them).
      FileStiffness
      read_stiffness_file(const std::string &file, const std::string &section)
      {
        const auto   K = read_summary_stiffness(file, section, "Stiffness file");
        FileStiffness rim;
        // The full matrix: its symmetric part (a summary's K is symmetric
        // to round-off), and how much its couplings weigh.
        double coupling = 0, asymmetry = 0, scale = 0;
        for (unsigned int a = 0; a < 6; ++a)
          {
            rim.diagonal[a] = K[7 * a];
            for (unsigned int b = 0; b < 6; ++b)
              {
                scale     = std::max(scale, std::abs(K[6 * a + b]));
                asymmetry = std::max(asymmetry, std::abs(K[6 * a + b] - K[6 * b + a]));
                rim.coupling[a][b] = a == b ? 0. : 0.5 * (K[6 * a + b] + K[6 * b + a]);
                if (a != b)
                  coupling = std::max(coupling, std::abs(K[6 * a + b]) /
                                                  std::sqrt(std::abs(K[7 * a] * K[7 * b])));
              }
          }
        if (asymmetry > 1e-8 * scale)
          throw io::InputError(section, "Stiffness file", file,
                               "a symmetric 6x6 stiffness (max |K_ab - K_ba| = " +
                                 io::format_number(asymmetry) + ")");
        // Positive definite: Cholesky (a stable rim needs it; a failure names the pivot).
        // (Non-positive diagonals are left to the application's check of
        // the stiffnesses, plate_rod's check_rim_stiffness, which names them.)
        const bool positive_diagonal =
          std::all_of(rim.diagonal.begin(), rim.diagonal.end(), [](double k) { return k > 0; });
        if (const unsigned int j = positive_diagonal ? indefinite_leading_block(K) : 0)
          throw io::InputError(section, "Stiffness file", file,
                               "a positive definite 6x6 stiffness (its leading " + std::to_string(j) + "x" +
                                 std::to_string(j) + " block is not)");
        rim.largest_coupling = coupling;
        return rim;
      }
    } // namespace

    void
    QuadraticRodLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Stiffnesses", "0.1, 0.1, 0.1, 1e-6, 1e-6, 1e-6",
                        Patterns::List(Patterns::Double(0), 6, 6),
                        "Law = quadratic: GA1, GA2, EA, EI1, EI2, GJ of the rod's cross-section "
                        "(the rim: d1 radial, d2 the plate normal, d3 the tangent): shear along "
                        "d1, d2, extension, bending about d1 (out of plane), about d2 (in "
                        "plane), torsion. E.g. the diagonal of a rod_cross_section stiffness.");
      prm.declare_entry("Stiffness file", "", Patterns::Anything(),
                        "Law = quadratic: if set, a rod_cross_section summary.json whose 6x6 "
                        "'stiffness' is the rod's stiffness, couplings included (about the "
                        "section's origin; for the rim its X1 is the radial axis d1, X2 the plate "
                        "normal d2); replaces 'Stiffnesses'. It must be symmetric positive "
                        "definite. The closed forms use its diagonal.");
    }

    void
    QuadraticRodLaw::parse_parameters(ParameterHandler &prm, const std::string &section)
    {
      const auto k = io::get_double_list(prm, "Stiffnesses", 6, section);
      std::copy(k.begin(), k.end(), stiffness.begin());
      coupling       = {};
      stiffness_file = prm.get("Stiffness file");
      if (!stiffness_file.empty())
        {
          const FileStiffness r = read_stiffness_file(stiffness_file, section);
          stiffness             = r.diagonal;
          coupling              = r.coupling;
        }
    }

    double
    QuadraticRodLaw::largest_coupling() const
    {
      return materials::largest_coupling(natural_stiffness());
    }

    void
    QuadraticRodLaw::energy_derivatives(const std::array<double, 6> &e,
                                        const bool                   with_hessian,
                                        double &                     W,
                                        std::array<double, 6> &      dW,
                                        std::array<double, 36> &     ddW) const
    {
      // dW = K e, W = 1/2 e . K e, ddW = K.
      W = 0;
      for (unsigned int i = 0; i < 6; ++i)
        {
          dW[i] = stiffness[i] * e[i];
          for (unsigned int j = 0; j < 6; ++j)
            if (j != i && coupling[i][j] != 0)
              dW[i] += coupling[i][j] * e[j];
          W += 0.5 * dW[i] * e[i];
          if (with_hessian)
            for (unsigned int j = 0; j < 6; ++j)
              ddW[6 * i + j] = i == j ? stiffness[i] : coupling[i][j];
        }
    }

    std::string
    QuadraticRodLaw::description() const
    {
      std::ostringstream m;
      m << "quadratic, diagonal";
      for (const double k : stiffness)
        m << " " << k;
      if (!stiffness_file.empty())
        m << " from " << stiffness_file << " (full 6x6, largest coupling K_ab / sqrt(K_aa K_bb) = "
          << largest_coupling() << ")";
      return m.str();
    }

    COSMO_REGISTER_PLUGIN(RodLaw,
                          QuadraticRodLaw,
                          "quadratic",
                          "a quadratic energy in the six strains with a full symmetric 6x6 "
                          "stiffness: 'Stiffnesses' (diagonal) or a part-1 'Stiffness file'.")
  } // namespace materials
} // namespace cosmo
