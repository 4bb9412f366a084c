#ifndef cosmo_tests_reduced_rod_checks_h
#define cosmo_tests_reduced_rod_checks_h

// Checks shared by the part-1 and part-2 validation programs: both problems
// are ReducedRodProblems.
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/reduced_rod_problem.h>

#include <cmath>
#include <iostream>

namespace cosmo_test
{
  /**
   * max |Jv - FD| / max |Jv|, FD the central difference of the residual at
   * U along v with h = 1e-6: truncation 1e-12 |R'''|, round-off eps |R|/h
   * ~ 1e-10.
   */
  inline double
  central_difference_error(cosmo::assembly::ReducedRodProblem &p,
                           const dealii::Vector<double> &      U,
                           const dealii::Vector<double> &      v,
                           const dealii::Vector<double> &      Jv)
  {
    using dealii::Vector;
    const unsigned int n  = p.n_unknowns();
    const double       h  = 1e-6;
    Vector<double>     Up = U, Um = U, Rp(n), Rm(n);
    Up.add(h, v);
    Um.add(-h, v);
    p.residual(Up, Rp);
    p.residual(Um, Rm);
    Vector<double> d = Rp;
    d -= Rm;
    d /= 2 * h;
    d -= Jv;
    return d.linfty_norm() / Jv.linfty_norm();
  }

  /**
   * The AD tangent (the bordered Jacobian with all strains free) against
   * central differences of the residual at U moved off equilibrium, along a
   * fixed direction: returns max |J v - FD| / max |J v|. h = 1e-6: truncation
   * 1e-12 |R'''|, round-off eps |R|/h ~ 1e-10. Leaves all strains free and U
   * perturbed in `U_off` (for further checks by the caller).
   */
  inline double
  tangent_fd_error(cosmo::assembly::ReducedRodProblem &p,
                   const dealii::Vector<double> &      solution,
                   dealii::Vector<double> &            U_off)
  {
    using dealii::Vector;
    p.set_free_strains({{true, true, true, true, true, true}});
    const unsigned int n = p.n_unknowns();
    U_off                = solution;
    // Off equilibrium, so that every term of the Hessian is exercised.
    for (unsigned int i = 0; i < n; ++i)
      U_off[i] += 0.01 * std::sin(1.7 * i + 0.3);
    AssertThrow(p.setup_jacobian(U_off) == 0, dealii::ExcInternalError());
    Vector<double> v(n), Jv;
    for (unsigned int i = 0; i < n; ++i)
      v[i] = std::cos(0.9 * i);
    const auto &free = p.free_strains();
    p.bordered_system().vmult(Jv, v, std::vector<bool>(free.begin(), free.end()));
    std::cout << "tangent vs FD of the residual, " << n << " unknowns\n";
    return central_difference_error(p, U_off, v, Jv);
  }

  /**
   * store_jacobian (solvers/arclength.h, BorderedSystem::assemble_copy): the
   * Jacobian kept at another state U_other is the derivative of the
   * residual there (against central differences: max |J v - FD| / max |J
   * v| returned, resolution as tangent_fd_error's), and storing it leaves
   * the factorization and the assembled blocks in place as they were: a
   * solve and a product with them before and after agree bitwise
   * (`unchanged`). The factorization in place is J(U_off)'s.
   */
  inline double
  stored_jacobian_error(cosmo::assembly::ReducedRodProblem &p,
                        const dealii::Vector<double> &      U_off,
                        bool &                              unchanged)
  {
    using dealii::Vector;
    const unsigned int n = p.n_unknowns();
    const auto &       f = p.free_strains();
    const std::vector<bool> free(f.begin(), f.end());
    Vector<double>     v(n), b(n), x_before, x_after(n), Jv_before, Jv_after;
    for (unsigned int i = 0; i < n; ++i)
      {
        v[i] = std::cos(0.9 * i);
        b[i] = std::sin(0.4 * i + 0.1);
      }
    x_before.reinit(n);
    p.solve_with_jacobian(b, x_before);
    p.bordered_system().vmult(Jv_before, v, free);
    Vector<double> U_other = U_off;
    for (unsigned int i = 0; i < n; ++i)
      U_other[i] += 0.02 * std::cos(0.3 * i);
    AssertThrow(p.store_jacobian(U_other, 1), dealii::ExcInternalError());
    p.solve_with_jacobian(b, x_after);
    p.bordered_system().vmult(Jv_after, v, free);
    unchanged = x_before == x_after && Jv_before == Jv_after;
    Vector<double> Jv;
    p.stored_jacobian_vmult(1, v, Jv);
    p.release_stored_jacobians();
    return central_difference_error(p, U_other, v, Jv);
  }
} // namespace cosmo_test

#endif
