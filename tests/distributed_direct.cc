// solvers::DistributedDirectSolver (MUMPS with distributed assembled input)
// on a matrix whose inertia and solution are known in closed form, under
// mpirun -np 1 and -np 2 (the rows split over the ranks):
// A = tridiag(-1, 2 - sigma, -1) of order n, eigenvalues
// 4 sin^2(k pi / (2 (n + 1))) - sigma, k = 1..n, so the number of negative
// eigenvalues is #{k : 4 sin^2(k pi/(2(n+1))) < sigma}; the solution of
// A x = A x* is checked by its backward error |A x - b| / (|A| |x|), which
// a backward-stable LDL^T keeps at a modest multiple of eps whatever the
// condition (tolerance 1e-13, eps = 2.2e-16: 450 eps).
#include <deal.II/base/mpi.h>

#include <cosmo/solvers/distributed_direct.h>

#include <cmath>
#include <iostream>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int size = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const unsigned int n    = 3000;
  bool               fail = false;
  cosmo::solvers::DistributedDirectSolver solver(MPI_COMM_WORLD);
  // Two shifts: the second factorization reuses the analysis.
  for (const double sigma : {0.05, 0.3})
    {
      std::vector<unsigned int> rows, columns;
      std::vector<double>       values;
      const unsigned int        begin = rank * n / size, end = (rank + 1) * n / size;
      for (unsigned int i = begin; i < end; ++i)
        {
          rows.push_back(i), columns.push_back(i), values.push_back(2 - sigma);
          if (i + 1 < n)
            rows.push_back(i), columns.push_back(i + 1), values.push_back(-1);
        }
      solver.factorize(n, rows, columns, values);
      int expected = 0;
      for (unsigned int k = 1; k <= n; ++k)
        expected += 4 * std::pow(std::sin(k * M_PI / (2. * (n + 1))), 2) < sigma;
      Vector<double> x_star(n), b(n), x(n);
      for (unsigned int i = 0; i < n; ++i)
        x_star[i] = std::sin(0.01 * i) + 0.1 * std::cos(0.37 * i);
      auto apply = [&](const Vector<double> &v, Vector<double> &w) {
        for (unsigned int i = 0; i < n; ++i)
          w[i] = (2 - sigma) * v[i] - (i > 0 ? v[i - 1] : 0.) - (i + 1 < n ? v[i + 1] : 0.);
      };
      apply(x_star, b);
      x = b;
      solver.solve(x);
      Vector<double> r(n);
      apply(x, r);
      r -= b;
      const double backward = r.linfty_norm() / ((4 + sigma) * x.linfty_norm());
      // Every rank holds the same solution (replicated vectors): bitwise.
      double checksum = 0;
      for (unsigned int i = 0; i < n; ++i)
        checksum += x[i] * (i + 1);
      const bool same = Utilities::MPI::max(checksum, MPI_COMM_WORLD) ==
                        Utilities::MPI::min(checksum, MPI_COMM_WORLD);
      const bool ok = solver.n_negative_eigenvalues() == expected && backward <= 1e-13 && same;
      fail |= !ok;
      if (rank == 0)
        std::cout << (ok ? "  ok    " : "  FAIL  ") << size << " rank(s), sigma = " << sigma
                  << ": negative eigenvalues " << solver.n_negative_eigenvalues() << " (closed form "
                  << expected << "), backward error " << backward << " (tolerance 1e-13), "
                  << (same ? "the same solution on every rank" : "DIFFERENT solutions on the ranks") << "\n";
    }
  return Utilities::MPI::max(int(fail), MPI_COMM_WORLD);
}
