#include <cosmo/config.h>
#include <cosmo/solvers/blas_threads.h>
#include <cosmo/solvers/sparse_direct.h>

#include <dlfcn.h>

#ifdef COSMO_WITH_MUMPS
#  include <dmumps_c.h>
#  include <mpi.h>
#endif
#include "mumps_phases.h"

#ifdef COSMO_WITH_METIS
#  include <metis.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

namespace cosmo
{
  namespace solvers
  {
    double
    absolute_quadratic_form(const SparseMatrix<double> &A, const Vector<double> &v)
    {
      double s = 0;
      for (unsigned int i = 0; i < A.m(); ++i)
        for (auto it = A.begin(i); it != A.end(i); ++it)
          s += std::abs(it->value() * v[i] * v[it->column()]);
      return s;
    }

    std::vector<bool>
    dense_rows(const SparsityPattern &sp)
    {
      const std::size_t n = sp.n_rows();
      std::vector<bool> dense(n, false);
      if (n == 0)
        return dense;
      std::vector<unsigned int> length(n);
      for (std::size_t i = 0; i < n; ++i)
        length[i] = sp.row_length(i);
      std::vector<unsigned int> sorted = length;
      std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
      const unsigned int median = sorted[n / 2];
      for (std::size_t i = 0; i < n; ++i)
        dense[i] = length[i] > 8 * median;
      return dense;
    }

    std::vector<int>
    border_last_ordering(const SparsityPattern &sp)
    {
#ifdef COSMO_WITH_METIS
      const std::vector<bool> dense = dense_rows(sp);
      const std::size_t       n     = sp.n_rows();
      std::vector<idx_t>      local(n, -1);
      idx_t                   nv = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (!dense[i])
          local[i] = nv++;
      if (nv == idx_t(n) || nv < 2) // no border, or nothing but border
        return {};
      std::vector<idx_t> xadj(nv + 1, 0), adjacency;
      adjacency.reserve(sp.n_nonzero_elements());
      for (std::size_t i = 0; i < n; ++i)
        if (!dense[i])
          {
            for (auto it = sp.begin(i); it != sp.end(i); ++it)
              if (it->column() != i && !dense[it->column()])
                adjacency.push_back(local[it->column()]);
            xadj[local[i] + 1] = adjacency.size();
          }
      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      options[METIS_OPTION_NUMBERING] = 0;
      std::vector<idx_t> perm(nv), iperm(nv);
      if (METIS_NodeND(&nv, xadj.data(), adjacency.data(), nullptr, options, perm.data(), iperm.data()) !=
          METIS_OK)
        return {};
      // MUMPS' PERM_IN(i): the (1-based) position of unknown i in the pivot order.
      std::vector<int> position(n);
      int              next = nv;
      for (std::size_t i = 0; i < n; ++i)
        position[i] = dense[i] ? ++next : iperm[local[i]] + 1;
      return position;
#else
      (void)sp;
      return {};
#endif
    }

#ifdef COSMO_WITH_MUMPS
    namespace
    {
      /// A MUMPS instance: its data and whether it runs on all ranks.
      struct MumpsInstance
      {
        DMUMPS_STRUC_C id;
        bool           initialized = false;
        bool           shared      = false; // on the ranks' communicator
        int            number      = -1;    // its name in the commands to the ranks
      };

      // The ranks' communicator (a duplicate of MPI_COMM_WORLD) and rank 0's
      // shared instances alive.
      MPI_Comm                  ranks_comm = MPI_COMM_NULL;
      bool                      sharing    = false;
      int                       next_number = 0;
      unsigned int              n_shared_phases = 0;
      std::set<MumpsInstance *> alive;

      // A command to the serving ranks: the MUMPS phase (JOB) and the instance,
      // or quit.
      constexpr int quit = 1000;

      void
      broadcast_command(int job, int number)
      {
        int         command[2] = {job, number};
        MPI_Request request;
        MPI_Ibcast(command, 2, MPI_INT, 0, ranks_comm, &request);
        MPI_Wait(&request, MPI_STATUS_IGNORE);
      }

      // One MUMPS phase; on a shared instance rank 0 first tells the ranks.
      void
      run_phase(MumpsInstance &m, const int job)
      {
        if (m.shared && m.initialized)
          {
            broadcast_command(job, m.number);
            ++n_shared_phases;
          }
        m.id.job = job;
        dmumps_c(&m.id);
      }

      int
      ranks_size()
      {
        int size = 1;
        MPI_Comm_size(ranks_comm, &size);
        return size;
      }

      using mumps_phases::silence;
    } // namespace
#endif

    namespace
    {
      FactorizationMemory largest;
    }

    const FactorizationMemory &
    largest_factorization()
    {
      return largest;
    }

    void
    note_factorization(const FactorizationMemory &f)
    {
      if (f.mb_all_ranks >= largest.mb_all_ranks)
        largest = f;
    }

    namespace factorization_ranks
    {
      void
      enable()
      {
#ifdef COSMO_WITH_MUMPS
        int size = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        if (size < 2 || sharing)
          return;
        MPI_Comm_dup(MPI_COMM_WORLD, &ranks_comm);
        sharing = true;
#endif
      }

      bool
      active()
      {
#ifdef COSMO_WITH_MUMPS
        return sharing;
#else
        return false;
#endif
      }

      unsigned int
      min_unknowns()
      {
        if (const char *v = std::getenv("COSMO_PARALLEL_FACTORIZATION_MIN"))
          return static_cast<unsigned int>(std::strtoul(v, nullptr, 10));
        // Measured (benchmarks/README.md, "One path on two ranks"): below
        // this the second rank's share of a factorization does not pay for
        // the communication.
        return 20000;
      }

      unsigned int
      shared_phases()
      {
#ifdef COSMO_WITH_MUMPS
        return n_shared_phases;
#else
        return 0;
#endif
      }

      void
      serve()
      {
#ifdef COSMO_WITH_MUMPS
        MPI_Comm_dup(MPI_COMM_WORLD, &ranks_comm);
        std::map<int, std::unique_ptr<MumpsInstance>> instances;
        for (;;)
          {
            // Asleep while rank 0 assembles: poll, backing off to 1 ms.
            int         command[2];
            MPI_Request request;
            MPI_Ibcast(command, 2, MPI_INT, 0, ranks_comm, &request);
            auto pause = std::chrono::microseconds(10);
            for (int done = 0;;)
              {
                MPI_Test(&request, &done, MPI_STATUS_IGNORE);
                if (done)
                  break;
                std::this_thread::sleep_for(pause);
                pause = std::min(2 * pause, std::chrono::microseconds(1000));
              }
            const int job = command[0], number = command[1];
            if (job == quit)
              break;
            auto &m = instances[number];
            if (job == -1)
              {
                m                  = std::make_unique<MumpsInstance>();
                m->id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(ranks_comm);
                m->id.par          = 1;
                m->id.sym          = 2;
              }
            if (!m)
              throw std::logic_error("a MUMPS phase for an instance this rank does not have");
            m->id.job = job;
            dmumps_c(&m->id);
            if (job == -1)
              silence(m->id);
            if (job == -2)
              instances.erase(number);
          }
        MPI_Comm_free(&ranks_comm);
#endif
      }

      void
      release()
      {
#ifdef COSMO_WITH_MUMPS
        if (!sharing)
          return;
        // Instances still alive end on all ranks first (JOB = -2 is collective).
        for (MumpsInstance *m : std::vector<MumpsInstance *>(alive.begin(), alive.end()))
          {
            run_phase(*m, -2);
            m->initialized = false;
            alive.erase(m);
          }
        broadcast_command(quit, -1);
        MPI_Comm_free(&ranks_comm);
        sharing = false;
#endif
      }
    } // namespace factorization_ranks

    struct SparseDirectSolver::MumpsData
    {
#ifdef COSMO_WITH_MUMPS
      // Value-initialized: MUMPS's C interface takes a non-null pointer of
      // the structure (rhs, schur, sol_loc, ...) for an array given, so the
      // ones not set must be null (the constructor below is user-provided:
      // without the braces nothing would zero them).
      MumpsInstance       m{};
      DMUMPS_STRUC_C &    id = m.id;
      std::vector<int>    perm_in; // user ordering, 1-based positions
      std::vector<int>    irn, jcn; // 1-based, upper triangle
      std::vector<double> values;
      std::vector<bool>   upper; // storage position is in the upper triangle
      bool                ordering_checked = false; // (the first factorization's flops)

      // The banded Cholesky fast path (band_try()): the half-bandwidth of
      // the analysed pattern (-1: not banded enough), LAPACK's upper band
      // storage of the last matrix, and whether it holds its Cholesky factor.
      int                 band_kd = -1;
      std::vector<double> band;
      bool                band_factorized = false;

      /// JOB = -1 on MPI_COMM_SELF, or on all ranks when they share factorizations.
      explicit MumpsData(const bool on_all_ranks)
      {
        m.shared = on_all_ranks;
        if (m.shared)
          {
            m.number = next_number++;
            broadcast_command(-1, m.number);
            ++n_shared_phases;
            id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(ranks_comm);
          }
        else
          id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(MPI_COMM_SELF);
        id.par = 1;
        id.sym = 2; // symmetric, possibly indefinite: LDL^T
        id.job = -1;
        dmumps_c(&id);
        check(-1);
        m.initialized = true;
        if (m.shared)
          alive.insert(&m);
        // Silence MUMPS; errors are reported through INFOG.
        silence(id);
        // In parallel the inertia INFOG(12) is exact only without ScaLAPACK
        // on the root front.
        if (m.shared)
          id.icntl[12] = 1;
      }

      /**
       * The analysis of A's pattern with an ordering (ICNTL(7); 100:
       * METIS's nested dissection of the sparse block, the dense border
       * rows last, a user ordering); false for 100 where there is no border.
       */
      bool
      analyse(const SparseMatrix<double> &A, const int ordering, const bool nonzero_diagonal)
      {
        const SparsityPattern &sp = A.get_sparsity_pattern();
        // Extra workspace: dense border rows make the fill estimate loose.
        id.icntl[13] = 60;
        id.icntl[6]  = ordering;
        if (ordering == 100)
          {
            perm_in = border_last_ordering(sp);
            if (perm_in.empty())
              return false;
            id.perm_in  = perm_in.data();
            id.icntl[6] = 1;
          }
        // No maximum weighted matching where the caller says the diagonal has
        // no zero (set_nonzero_diagonal()) and the matrix analysed agrees
        // (later matrices of the same pattern are not checked again: a zero
        // there costs delayed pivots, not accuracy).
        if (nonzero_diagonal)
          {
            bool zero_on_diagonal = false;
            for (unsigned int row = 0; row < A.m() && !zero_on_diagonal; ++row)
              zero_on_diagonal = A.diag_element(row) == 0;
            if (!zero_on_diagonal)
              id.icntl[5] = 0;
          }
        // The upper triangle in coordinate format; the pattern is fixed,
        // so the index map is computed once.
        for (unsigned int row = 0; row < sp.n_rows(); ++row)
          for (auto it = sp.begin(row); it != sp.end(row); ++it)
            {
              upper.push_back(it->column() >= row);
              if (it->column() >= row)
                {
                  irn.push_back(row + 1);
                  jcn.push_back(it->column() + 1);
                }
            }
        values.resize(irn.size());
        id.n   = sp.n_rows();
        id.nnz = irn.size();
        id.irn = irn.data();
        id.jcn = jcn.data();
        id.a   = values.data();
        call(1); // analysis
        return true;
      }

      /// The factorization of the values in place (the caller checks INFOG(1)).
      void
      factorize()
      {
        // (delayed pivots of indefinite, saddle-point or nearly singular
        // matrices can exceed the analysis' workspace: mumps_phases.h)
        mumps_phases::factorize_enlarging_workspace(id, [&](const int job) { run(job); });
      }

      /**
       * The first factorization of a pattern that cost over 4 times the
       * flops its analysis estimated (pivots delayed up the tree: QAMD on
       * the strip's 1D mesh with its six gauge rows delays 8 300 of 911
       * pivots, 12.4 MFlop against 0.29 estimated) is made again with
       * METIS's nested dissection of the sparse block, the border rows
       * last (24 delayed, 0.31 MFlop), which replaces `current` where it at
       * least halves the flops. Once per pattern; the inertia is the
       * matrix's either way (solvers.bordered_ordering).
       */
      static void
      check_ordering(std::unique_ptr<MumpsData> &current, const SparseMatrix<double> &A)
      {
        current->ordering_checked = true;
        if (current->m.shared || std::getenv("COSMO_MUMPS_ORDERING") ||
            !(current->id.rinfog[2] > 4 * current->id.rinfog[0]))
          return;
        auto border_last = std::make_unique<MumpsData>(false);
        if (!border_last->analyse(A, 100, current->id.icntl[5] == 0))
          return;
        border_last->values = current->values;
        border_last->factorize();
        if (border_last->id.infog[0] >= 0 && border_last->id.rinfog[2] < 0.5 * current->id.rinfog[2])
          {
            border_last->band_kd          = current->band_kd;
            border_last->ordering_checked = true;
            current                       = std::move(border_last);
          }
      }

      /// One phase without the check (the factorization retries on -8, -9).
      void
      run(int job)
      {
        run_phase(m, job);
      }

      void
      call(int job)
      {
        run(job);
        check(job);
      }

      /// Throws MUMPS's error of the last phase, if any.
      void
      check(int job) const
      {
        if (id.infog[0] < 0)
          throw std::runtime_error("MUMPS failed in phase " + std::to_string(job) +
                                   " with INFOG(1) = " + std::to_string(id.infog[0]) +
                                   ", INFOG(2) = " + std::to_string(id.infog[1]) +
                                   (id.infog[0] == -10 ? " (numerically singular matrix)" : ""));
      }
      ~MumpsData()
      {
        // A shared instance rank 0 released already ended on all ranks.
        if (m.initialized)
          {
            run(-2);
            alive.erase(&m);
          }
      }
#endif
    };

#ifdef COSMO_WITH_MUMPS
    namespace
    {
      extern "C" void
      dpbtrf_(const char *uplo, const int *n, const int *kd, double *ab, const int *ldab, int *info);
      extern "C" void
      dpbtrs_(const char *uplo, const int *n, const int *kd, const int *nrhs, const double *ab,
              const int *ldab, double *b, const int *ldb, int *info);

      /**
       * The half-bandwidth of a pattern if a banded Cholesky pays, else -1.
       * An open rod's Hessian (7 unknowns a node, its neighbours') has
       * kd = 13: LAPACK's dpbtrf factorizes it in n kd^2 flops without any
       * of the multifrontal bookkeeping, 8-10x faster than MUMPS at 7e4
       * unknowns (benchmarks/README.md); bordered matrices (dense rows), a
       * ring or self-contact are not banded and stay with MUMPS. Off with
       * COSMO_BANDED_CHOLESKY=0.
       */
      int
      useful_bandwidth(const SparsityPattern &sp)
      {
        const char *v   = std::getenv("COSMO_BANDED_CHOLESKY"); // (read at each analysis)
        const bool  off = v && std::string(v) == "0";
        if (off || sp.n_rows() < 1000)
          return -1;
        std::size_t kd = 0;
        for (unsigned int row = 0; row < sp.n_rows(); ++row)
          for (auto it = sp.begin(row); it != sp.end(row); ++it)
            kd = std::max<std::size_t>(kd, it->column() > row ? it->column() - row : row - it->column());
        return kd <= 64 ? static_cast<int>(kd) : -1;
      }

      /// A's Cholesky factor in LAPACK's upper band storage (half-bandwidth
      /// kd) into `band`; false if A is not positive definite.
      bool
      banded_cholesky(const SparseMatrix<double> &A, const int kd, std::vector<double> &band)
      {
        const int n = A.m(), ldab = kd + 1;
        band.resize(static_cast<std::size_t>(ldab) * n);
        // Row `row`'s upper entries go to columns row .. row + kd, and
        // column c is first written by row c - kd: each column is zeroed
        // just before that, while it is in cache, instead of the whole band
        // (8 MB at 7e4 unknowns) up front.
        const auto zero_column = [&](const int c) {
          std::fill_n(band.begin() + static_cast<std::size_t>(c) * ldab, ldab, 0.);
        };
        for (int c = 0; c < std::min(kd, n); ++c)
          zero_column(c);
        for (int row = 0; row < n; ++row)
          {
            if (row + kd < n)
              zero_column(row + kd);
            for (auto it = A.begin(row); it != A.end(row); ++it)
              if (static_cast<int>(it->column()) >= row)
                band[static_cast<std::size_t>(it->column()) * ldab + kd + row - it->column()] = it->value();
          }
        int info = 0;
        dpbtrf_("U", &n, &kd, band.data(), &ldab, &info);
        return info == 0;
      }
    } // namespace
#endif

    namespace
    {
      using BlasThreadsGetter = int (*)();
      using BlasThreadsSetter = void (*)(int);

      /// OpenBLAS's thread count, set from the main thread only (the
      /// factorizations and solves are the main thread's; the assembly's
      /// threads make no BLAS calls).
      struct BlasThreads
      {
        BlasThreadsSetter set = nullptr;
        int               own = 1, current = 0;
        bool              pinned = false;
        // The environment's choice: OPENBLAS_NUM_THREADS is kept always,
        // OMP_NUM_THREADS by the choice per size (not by the ranks' pin,
        // which io::ranks::share_cores made before this code existed).
        const bool openblas_env = std::getenv("OPENBLAS_NUM_THREADS") != nullptr,
                   omp_env      = std::getenv("OMP_NUM_THREADS") != nullptr;

        BlasThreads()
        {
          set = reinterpret_cast<BlasThreadsSetter>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
          if (auto get = reinterpret_cast<BlasThreadsGetter>(::dlsym(RTLD_DEFAULT, "openblas_get_num_threads")))
            own = current = get();
          else
            set = nullptr;
        }
        void
        use(const int n)
        {
          if (set != nullptr && n != current)
            set(n), current = n;
        }
      };

      BlasThreads &
      blas_threads()
      {
        static BlasThreads b;
        return b;
      }
    } // namespace

    void
    blas_threads_for(const unsigned int n_rows)
    {
      auto &b = blas_threads();
      if (!b.pinned && !b.openblas_env && !b.omp_env)
        b.use(n_rows < 20000 ? 1 : b.own);
    }

    void
    pin_blas_threads(const int n)
    {
      auto &b = blas_threads();
      if (b.openblas_env)
        return;
      b.use(n);
      b.pinned = true;
    }

    SparseDirectSolver::SparseDirectSolver(const Kind kind)
      : solver_kind(kind)
    {
#ifndef COSMO_WITH_MUMPS
      if (kind == Kind::mumps)
        throw std::runtime_error("this build of cosmo has no MUMPS; use UMFPACK");
#endif
    }

    SparseDirectSolver::~SparseDirectSolver() = default;

    SparseDirectSolver::Kind
    SparseDirectSolver::default_kind()
    {
#ifdef COSMO_WITH_MUMPS
      return Kind::mumps;
#else
      return Kind::umfpack;
#endif
    }

    SparseDirectSolver::Kind
    SparseDirectSolver::kind_from_string(const std::string &name)
    {
      if (name == "MUMPS")
        return Kind::mumps;
      if (name == "UMFPACK")
        return Kind::umfpack;
      return default_kind();
    }

    std::string
    SparseDirectSolver::kind_names()
    {
#ifdef COSMO_WITH_MUMPS
      return "MUMPS|UMFPACK";
#else
      return "UMFPACK";
#endif
    }

    void
    SparseDirectSolver::factorize(const SparseMatrix<double> &A)
    {
      // (per call: the count is the process's, and each matrix's size
      // decides it, whatever was factorized before)
      blas_threads_for(A.m());
      if (solver_kind == Kind::umfpack)
        {
          if (!umfpack)
            umfpack = std::make_unique<SparseDirectUMFPACK>();
          umfpack->factorize(A);
          n_negative = -1;
          return;
        }
#ifdef COSMO_WITH_MUMPS
      const SparsityPattern &sp = A.get_sparsity_pattern();
      if (!mumps || analysed_pattern != &sp || analysed_nnz != sp.n_nonzero_elements())
        {
          mumps.reset();
          const bool shared = factorization_ranks::active() && sp.n_rows() >= factorization_ranks::min_unknowns();
          // QAMD: AMD that treats the quasi-dense constraint rows of the
          // bordered Hessians separately (measured fastest of MUMPS'
          // orderings on the 2D sections and plates, benchmarks/README.md).
          int ordering = 6;
          if (const char *o = std::getenv("COSMO_MUMPS_ORDERING"))
            ordering = std::atoi(o);
          mumps = std::make_unique<MumpsData>(shared);
          mumps->analyse(A, ordering, nonzero_diagonal);
          analysed_pattern = &sp;
          analysed_nnz     = sp.n_nonzero_elements();
          mumps->band_kd   = mumps->m.shared ? -1 : useful_bandwidth(sp);
        }
      // A symmetric positive definite banded matrix: its Cholesky factor
      // (success is the proof of definiteness: no negative eigenvalue);
      // otherwise MUMPS's LDL^T, which counts them.
      mumps->band_factorized = mumps->band_kd >= 0 && banded_cholesky(A, mumps->band_kd, mumps->band);
      if (mumps->band_factorized)
        {
          n_negative = 0;
          return;
        }
      // Values in the order of the analysed pattern: the matrix iterators walk
      // the storage in the same row-wise order as the pattern's.
      {
        std::size_t pos = 0, k = 0;
        for (auto it = A.begin(); it != A.end(); ++it, ++pos)
          if (mumps->upper[pos])
            mumps->values[k++] = it->value();
      }
      mumps->factorize();
      if (mumps->id.infog[0] < 0)
        mumps->check(2); // reports the error with its code
      // (a pattern's first factorization: another ordering where pivots were delayed)
      if (!mumps->ordering_checked)
        MumpsData::check_ordering(mumps, A);
      n_negative = mumps->id.infog[11];
      FactorizationMemory f;
      f.unknowns       = sp.n_rows();
      f.factor_entries = factor_entries();
      f.mb_per_rank    = mumps->id.infog[20];
      f.mb_all_ranks   = mumps->id.infog[21];
      f.ranks          = mumps->m.shared ? ranks_size() : 1;
      note_factorization(f);
#endif
    }

    double
    SparseDirectSolver::factorization_flops() const
    {
#ifdef COSMO_WITH_MUMPS
      if (solver_kind == Kind::mumps && mumps && mumps->band_factorized)
        {
          const double n = mumps->band.size() / (mumps->band_kd + 1.), kd = mumps->band_kd;
          return n * kd * (kd + 3); // dpbtrf's flops, about n (kd^2 + 3 kd)
        }
      if (solver_kind == Kind::mumps && mumps)
        return mumps->id.rinfog[2];
#endif
      return std::numeric_limits<double>::quiet_NaN();
    }

    double
    SparseDirectSolver::factor_entries() const
    {
#ifdef COSMO_WITH_MUMPS
      if (solver_kind == Kind::mumps && mumps && mumps->band_factorized)
        return static_cast<double>(mumps->band.size());
      if (solver_kind == Kind::mumps && mumps)
        {
          // INFOG(29); negative: millions of entries
          const int e = mumps->id.infog[28];
          return e >= 0 ? double(e) : -1e6 * e;
        }
#endif
      return 0;
    }

    void
    SparseDirectSolver::solve(Vector<double> &x) const
    {
      blas_threads_for(x.size());
      if (solver_kind == Kind::umfpack)
        {
          umfpack->solve(x);
          return;
        }
#ifdef COSMO_WITH_MUMPS
      if (mumps->band_factorized)
        {
          const int n = x.size(), kd = mumps->band_kd, ldab = kd + 1, one = 1;
          int       info = 0;
          dpbtrs_("U", &n, &kd, &one, mumps->band.data(), &ldab, x.data(), &n, &info);
          AssertThrow(info == 0, ExcMessage("dpbtrs failed"));
          return;
        }
      auto &id = mumps->id;
      id.nrhs  = 1;
      id.lrhs  = x.size();
      id.rhs   = x.data();
      mumps->call(3);
#endif
    }

    void
    SparseDirectSolver::solve(std::vector<Vector<double>> &xs) const
    {
      if (xs.empty())
        return;
      blas_threads_for(xs[0].size());
      if (solver_kind == Kind::umfpack)
        {
          for (auto &x : xs)
            umfpack->solve(x);
          return;
        }
#ifdef COSMO_WITH_MUMPS
      const std::size_t   n = xs[0].size();
      std::vector<double> block(n * xs.size());
      for (std::size_t k = 0; k < xs.size(); ++k)
        std::copy(xs[k].begin(), xs[k].end(), block.begin() + k * n);
      if (mumps->band_factorized)
        {
          const int nn = n, kd = mumps->band_kd, ldab = kd + 1, nrhs = xs.size();
          int       info = 0;
          dpbtrs_("U", &nn, &kd, &nrhs, mumps->band.data(), &ldab, block.data(), &nn, &info);
          AssertThrow(info == 0, ExcMessage("dpbtrs failed"));
        }
      else
        {
          auto &id = mumps->id;
          id.nrhs  = xs.size();
          id.lrhs  = n;
          id.rhs   = block.data();
          mumps->call(3);
        }
      for (std::size_t k = 0; k < xs.size(); ++k)
        std::copy(block.begin() + k * n, block.begin() + (k + 1) * n, xs[k].begin());
#endif
    }
  } // namespace solvers
} // namespace cosmo
