#include <cosmo/base/plugins.h>

namespace cosmo
{
  namespace plugins
  {
    std::vector<std::string> &
    registration_errors()
    {
      static std::vector<std::string> errors;
      return errors;
    }
  } // namespace plugins
} // namespace cosmo
