#include <cosmo/io/fault_injection.h>
#include <cosmo/io/ranks.h>

#include <cstdlib>
#include <stdexcept>

namespace cosmo
{
  namespace io
  {
    void
    inject_fault(const std::string &where)
    {
      static const char *fault = std::getenv("COSMO_FAULT");
      if (fault == nullptr)
        return;
      const std::string spec(fault);
      const auto        at = spec.find('@');
      if (spec.substr(0, at) != where)
        return;
      if (at != std::string::npos && std::to_string(ranks::rank()) != spec.substr(at + 1))
        return;
      throw std::runtime_error("injected fault at " + where + " (COSMO_FAULT)");
    }
  } // namespace io
} // namespace cosmo
