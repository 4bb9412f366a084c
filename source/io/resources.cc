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
  } // namespace io
} // namespace cosmo
