#ifndef cosmo_solvers_blas_threads_h
#define cosmo_solvers_blas_threads_h

/**
 * OpenBLAS's threads, set at run time where the BLAS in use is OpenBLAS
 * (its setter found by dlsym; any other BLAS is left alone), from the main
 * thread. OPENBLAS_NUM_THREADS set in the environment is always kept;
 * OMP_NUM_THREADS is kept by blas_threads_for().
 */
namespace cosmo
{
  namespace solvers
  {
    /**
     * BLAS threads for a factorization or solve with a matrix of n rows
     * (SparseDirectSolver calls it each time): one below
     * 20 000, OpenBLAS's own count (the cores) from there on. A small
     * matrix's fronts are a few hundred wide, where threads do not pay,
     * and OpenBLAS's workers spin (sched_yield) between calls on the cores
     * the assembly's threads need: the strip at 905 field DoFs ran 15-20 %
     * faster on one (benchmarks/README.md, "One BLAS thread for small
     * matrices"). Nothing once pin_blas_threads() has been called.
     */
    void
    blas_threads_for(unsigned int n_rows);

    /// Set the BLAS threads for the rest of the run (io::ranks::share_cores:
    /// one per rank where the ranks share the node's cores).
    void
    pin_blas_threads(int n);
  } // namespace solvers
} // namespace cosmo

#endif
