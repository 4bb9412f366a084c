#ifndef cosmo_io_stderr_capture_h
#define cosmo_io_stderr_capture_h

#include <cstdio>
#include <string>

/**
 * What a library prints on stderr while it works, kept out of the
 * terminal. SUNDIALS' KINSOL prints an "[KINSOL ERROR]" block for every
 * failed line search, which for the continuation is a cut-back working as
 * designed, not something the user must act on; deal.II 9.4's KINSOL
 * wrapper offers no error handler of its own (its solver memory is private),
 * so file descriptor 2 is pointed at a temporary file for the solve and the
 * text is handed back to go into the log with the step it belongs to.
 */
namespace cosmo
{
  namespace io
  {
    class StderrCapture
    {
    public:
      /// From now on, what is written to file descriptor 2 is kept.
      StderrCapture();
      /// Gives stderr back (if release() was not called); the text is dropped.
      ~StderrCapture();
      StderrCapture(const StderrCapture &) = delete;
      StderrCapture &
      operator=(const StderrCapture &) = delete;

      /// Gives stderr back and returns what was written, as one line (blocks
      /// joined by "; ", white space collapsed), or "" if nothing.
      std::string
      release();

    private:
      std::FILE *file  = nullptr;
      int        saved = -1;
    };
  } // namespace io
} // namespace cosmo

#endif
