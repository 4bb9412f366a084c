#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/materials/section_stiffness.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace cosmo
{
  namespace materials
  {
    std::array<double, 36>
    read_summary_stiffness(const std::string &file, const std::string &section, const std::string &entry)
    {
      std::ifstream in(file);
      if (!in)
        throw io::InputError(section, entry, file, "a readable rod_cross_section summary.json (cannot open it)");
      std::stringstream buffer;
      buffer << in.rdbuf();
      std::vector<double> K; // the finite numbers of "stiffness", row by row
      std::size_t         rows = 0, non_square = 0;
      try
        {
          const io::JSON  summary = io::JSON::parse(buffer.str());
          const io::JSON *k       = summary.find("stiffness");
          if (k && k->is_array())
            for (rows = 0; rows < k->size(); ++rows)
              {
                non_square += k->at(rows).size() != 6;
                for (std::size_t b = 0; b < k->at(rows).size(); ++b)
                  if (std::isfinite(k->at(rows).at(b).as_number()))
                    K.push_back(k->at(rows).at(b).as_number());
              }
        }
      catch (std::runtime_error &e)
        {
          throw io::InputError(section, entry, file, "a rod_cross_section summary.json (" + std::string(e.what()) + ")");
        }
      if (K.size() != 36 || rows != 6 || non_square > 0)
        throw io::InputError(section, entry, file,
                             "a rod_cross_section summary.json with a 6x6 \"stiffness\" of finite numbers (found " +
                               std::to_string(K.size()) + " numbers in " + std::to_string(rows) + " rows)");
      std::array<double, 36> out;
      std::copy(K.begin(), K.end(), out.begin());
      return out;
    }

    unsigned int
    indefinite_leading_block(const std::array<double, 36> &K)
    {
      std::array<double, 36> L{};
      for (unsigned int j = 0; j < 6; ++j)
        {
          double d = K[7 * j];
          for (unsigned int k = 0; k < j; ++k)
            d -= L[6 * j + k] * L[6 * j + k];
          if (!(d > 1e-12 * std::abs(K[7 * j])))
            return j + 1;
          L[7 * j] = std::sqrt(d);
          for (unsigned int i = j + 1; i < 6; ++i)
            {
              double v = 0.5 * (K[6 * i + j] + K[6 * j + i]);
              for (unsigned int k = 0; k < j; ++k)
                v -= L[6 * i + k] * L[6 * j + k];
              L[6 * i + j] = v / L[7 * j];
            }
        }
      return 0;
    }
  } // namespace materials
} // namespace cosmo
