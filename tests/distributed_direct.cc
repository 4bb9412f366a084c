// solvers::DistributedDirectSolver (MUMPS with distributed assembled input)
// on a matrix whose inertia and solution are known in closed form, under
// mpirun -np 1 and -np 2 (the rows split over the ranks):
// A = tridiag(-1, 2 - sigma, -1) of order n, eigenvalues
// 4 sin^2(k pi / (2 (n + 1))) - sigma, k = 1..n, so the number of negative
// eigenvalues is #{k : 4 sin^2(k pi/(2(n+1))) < sigma}; the solution of
// A x = A x* is checked by its backward error |A x - b| / (|A| |x|), which
// a backward-stable LDL^T keeps at a modest multiple of eps whatever the
// condition (tolerance 1e-13, eps = 2.2e-16: 450 eps).
// And from a distributed mesh (parallel::distributed::Triangulation, each
// rank assembling its own cells into a Trilinos matrix): K - sigma M of
// Q1 elements on the unit square, Neumann, whose inertia is the number of
// discrete eigenvalues of K x = mu M x below sigma (Sylvester). Those of the
// continuous problem are pi^2 (i^2 + j^2): 0, 1, 1, 2, 4, 4, 5, 5, 8 times
// pi^2; sigma = 3 pi^2 and 6.5 pi^2 lie mid-gap, 1 and 1.5 pi^2 from the
// nearest, while Q1 (consistent mass, h = 1/64) raises the eigenvalue
// pi^2 (i^2 + j^2) by (l_i^2 + l_j^2) h^2 / 12 to leading order (l_i = pi^2 i^2,
// the 1D ones): at most 0.0064 pi^2 up to 8 pi^2, far inside the gaps, so
// 4 and 8 negative eigenvalues.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/dofs/dof_tools.h>

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
      // (|A|_inf = |2 - sigma| + 2)
      const double backward = r.linfty_norm() / ((std::abs(2 - sigma) + 2) * x.linfty_norm());
      const bool   ok = solver.n_negative_eigenvalues() == expected && backward <= 1e-13;
      fail |= !ok;
      if (rank == 0)
        std::cout << (ok ? "  ok    " : "  FAIL  ") << size << " rank(s), sigma = " << sigma
                  << ": negative eigenvalues " << solver.n_negative_eigenvalues() << " (closed form "
                  << expected << "), backward error " << backward << " (tolerance 1e-13)\n";
      // Several right-hand sides in one solve (the bordered system's border):
      // b and 2 b, whose solutions are x* and 2 x*, each to the same backward error.
      std::vector<Vector<double>> xs(2, b);
      xs[1] *= 2.;
      solver.solve(xs);
      double worst = 0;
      for (unsigned int k = 0; k < 2; ++k)
        {
          Vector<double> rk(n), bk = b;
          bk *= double(k + 1);
          apply(xs[k], rk);
          rk -= bk;
          worst = std::max(worst, rk.linfty_norm() / ((std::abs(2 - sigma) + 2) * xs[k].linfty_norm()));
        }
      const bool several = worst <= 1e-13;
      fail |= !several;
      if (rank == 0)
        std::cout << (several ? "  ok    " : "  FAIL  ") << size << " rank(s), sigma = " << sigma
                  << ": two right-hand sides in one solve, backward error " << worst
                  << " (tolerance 1e-13)\n";
    }
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(tria);
    tria.refine_global(6);
    const FE_Q<2>   fe(1);
    DoFHandler<2>   dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    constraints.close();
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, MPI_COMM_WORLD, relevant);
    TrilinosWrappers::SparseMatrix A;
    A.reinit(owned, owned, dsp, MPI_COMM_WORLD);
    for (const double s : {3., 6.5})
      {
        const double sigma = s * M_PI * M_PI;
        A = 0;
        const QGauss<2>    quadrature(2);
        FEValues<2>        fev(fe, quadrature, update_values | update_gradients | update_JxW_values);
        FullMatrix<double> cell_matrix(4, 4);
        std::vector<types::global_dof_index> idx(4);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fev.reinit(cell);
              cell_matrix = 0;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < 4; ++i)
                  for (unsigned int j = 0; j < 4; ++j)
                    cell_matrix(i, j) += (fev.shape_grad(i, q) * fev.shape_grad(j, q) -
                                          sigma * fev.shape_value(i, q) * fev.shape_value(j, q)) *
                                         fev.JxW(q);
              cell->get_dof_indices(idx);
              constraints.distribute_local_to_global(cell_matrix, idx, A);
            }
        A.compress(VectorOperation::add);
        solver.factorize(A);
        const int  expected = s == 3. ? 4 : 8;
        const bool ok       = solver.n_negative_eigenvalues() == expected;
        fail |= !ok;
        if (rank == 0)
          std::cout << (ok ? "  ok    " : "  FAIL  ") << size << " rank(s), distributed mesh, "
                    << dof_handler.n_dofs() << " DoFs, sigma = " << s
                    << " pi^2: negative eigenvalues " << solver.n_negative_eigenvalues()
                    << " (the continuous problem's " << expected << ")\n";
      }
  }
  return Utilities::MPI::max(int(fail), MPI_COMM_WORLD);
}
