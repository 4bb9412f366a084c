#ifndef cosmo_source_solvers_mumps_phases_h
#define cosmo_source_solvers_mumps_phases_h

// What the two MUMPS drivers of the library share (sparse_direct.cc: the
// centralized matrix of one process or of rank 0; distributed_direct.cc: a
// matrix assembled on several ranks). Internal to source/solvers.

#include <cosmo/config.h>

#ifdef COSMO_WITH_MUMPS
#  include <dmumps_c.h>

namespace cosmo
{
  namespace solvers
  {
    namespace mumps_phases
    {
      /// No output from MUMPS (errors come back in INFOG and are reported by the caller).
      inline void
      silence(DMUMPS_STRUC_C &id)
      {
        id.icntl[0] = -1;
        id.icntl[1] = -1;
        id.icntl[2] = -1;
        id.icntl[3] = 0;
      }

      /**
       * The factorization, run by `run_phase(2)` (however the caller runs a
       * phase: on its ranks, or broadcast to serving ones). Indefinite
       * matrices can exceed the workspace estimated in the analysis
       * (INFOG(1) = -8, -9: too small a work array): the workspace is
       * enlarged and the factorization run again, at most 6 times. The
       * caller checks INFOG(1) afterwards.
       */
      template <typename RunPhase>
      void
      factorize_enlarging_workspace(DMUMPS_STRUC_C &id, const RunPhase &run_phase)
      {
        for (unsigned int attempt = 0;; ++attempt)
          {
            run_phase(2);
            if ((id.infog[0] == -8 || id.infog[0] == -9) && attempt < 6)
              id.icntl[13] = 2 * id.icntl[13] + 100;
            else
              return;
          }
      }
    } // namespace mumps_phases
  }   // namespace solvers
} // namespace cosmo
#endif

#endif
