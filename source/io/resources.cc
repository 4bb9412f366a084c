#include <cosmo/io/parameters.h>
#include <cosmo/io/resources.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace io
  {
    double
    estimated_memory(const double n_unknowns, const unsigned int degree)
    {
      const double n = std::max(n_unknowns, 2.);
      return 0.2e9 + n * 5e3 * std::max(1., degree / 2.) * std::max(1., std::log2(n) / 16.);
    }

    double
    physical_memory()
    {
      return static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE);
    }

    void
    check_memory(const double       n_unknowns,
                 const unsigned int degree,
                 const std::string &section,
                 const std::string &entry,
                 const std::string &value)
    {
      const double need = estimated_memory(n_unknowns, degree), have = physical_memory();
      if (have > 0 && need > have)
        {
          std::ostringstream m;
          m.precision(3);
          m << "a problem that fits in this machine's memory: this one would have at least " << n_unknowns
            << " unknowns (element degree " << degree << "), estimated to need " << need / 1e9
            << " GB, more than the " << have / 1e9
            << " GB here; use fewer cells or refinements or a lower degree";
          throw InputError(section, entry, value, m.str());
        }
    }

    std::string
    format_bytes(const double bytes)
    {
      std::ostringstream m;
      m.precision(3);
      if (bytes >= 1e9)
        m << bytes / 1e9 << " GB";
      else
        m << bytes / 1e6 << " MB";
      return m.str();
    }

    double
    check_points_memory(const double       n_points,
                        const double       bytes_per_point,
                        const double       problem_bytes,
                        const std::string &section,
                        const std::string &entry,
                        const std::string &value)
    {
      const double need = n_points * bytes_per_point + problem_bytes, have = physical_memory();
      if (have > 0 && need > have)
        {
          std::ostringstream m;
          m.precision(3);
          m << "a table or study that fits in this machine's memory: " << n_points
            << " points of " << bytes_per_point << " bytes each (their results in memory, in the "
            << "CSV and HDF5 tables and the checkpoint) and the problem's "
            << format_bytes(problem_bytes) << " are estimated to need " << format_bytes(need)
            << ", more than the " << format_bytes(have) << " here; use fewer values";
          throw InputError(section, entry, value, m.str());
        }
      return need;
    }
  } // namespace io
} // namespace cosmo
