#include <cosmo/io/parameter_copy.h>
#include <cosmo/io/postprocessors.h>
#include <cosmo/io/shared_libraries.h>

#include <sstream>
#include <stdexcept>

namespace cosmo
{
  namespace io
  {
    void
    declare_application_parameters(ParameterHandler &prm, const DeclareParameters &declare)
    {
      declare_shared_libraries_entry(prm);
      declare(prm);
      Postprocessors::declare_parameters(prm);
    }

    std::unique_ptr<ParameterHandler>
    copy_parameters(const ParameterHandler &prm, const DeclareParameters &declare)
    {
      if (!declare)
        throw std::logic_error("copy_parameters: no declarations given");
      // Every value as text (ShortPRM: the entries without their
      // documentation), read back into a handler declared the same way.
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      auto copy = std::make_unique<ParameterHandler>();
      declare_application_parameters(*copy, declare);
      copy->parse_input_from_string(text.str());
      return copy;
    }
  } // namespace io
} // namespace cosmo
