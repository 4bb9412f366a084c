#ifndef cosmo_io_parameter_copy_h
#define cosmo_io_parameter_copy_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>

/**
 * Copies of a run's parameters. A study varies one entry from point to
 * point: each point gets a copy of the study's parameters with its value
 * set, so the handler the study was given is never written to (and a point
 * sees no other point's values). deal.II's ParameterHandler cannot be
 * copied: a copy is a new handler with the same declarations and every
 * value of the original.
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    /// An application's own declarations.
    using DeclareParameters = std::function<void(ParameterHandler &)>;

    /**
     * Declares what every application's file has, as run_application does:
     * the top-level 'Additional shared libraries', the application's own
     * entries (`declare`), and the section 'Postprocess'.
     */
    void
    declare_application_parameters(ParameterHandler &prm, const DeclareParameters &declare);

    /**
     * A new handler declared by declare_application_parameters(`declare`)
     * with every value of `prm` (which must have been declared the same
     * way). std::logic_error if `declare` is empty.
     */
    std::unique_ptr<ParameterHandler>
    copy_parameters(const ParameterHandler &prm, const DeclareParameters &declare);
  } // namespace io
} // namespace cosmo

#endif
