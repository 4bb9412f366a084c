#ifndef cosmo_io_fault_injection_h
#define cosmo_io_fault_injection_h

#include <string>

/**
 * Faults on demand, for the robustness tests of failure handling that no
 * input provokes on purpose (a failure that is neither bad input nor a
 * driver's, on every MPI rank or on one). The environment variable
 * COSMO_FAULT = "WHERE" or "WHERE@RANK" makes inject_fault(WHERE) throw a
 * std::runtime_error, on every rank or on rank RANK of MPI_COMM_WORLD only.
 * Unset (always, outside the tests), inject_fault does nothing.
 */
namespace cosmo
{
  namespace io
  {
    /// Throw std::runtime_error("injected fault at WHERE") if COSMO_FAULT asks for it here.
    void
    inject_fault(const std::string &where);
  } // namespace io
} // namespace cosmo

#endif
