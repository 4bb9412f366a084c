// The rod's residual and Hessian with self-contact (doc/theory-rod.md 9):
// a coil whose natural pitch is less than its diameter 2a starts with its
// turns overlapping, every turn pressing on the next; at that state and at
// a perturbed one the Hessian is the derivative of the residual (central
// differences of R along random directions, solved with the factorized
// Hessian, give back the direction), and the contact's pattern holds every
// pair that touches.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "rod_problem.h"
#include "test_tools.h"

#include <cmath>
#include <random>

using namespace dealii;
using cosmo_test::check_close;

namespace
{
  /// |J v - (R(U + e v) - R(U - e v))/(2e)| / |(R(U + e v) - R(U - e v))/(2e)| for a random v.
  double
  directional_error(cosmo::rod::RodProblem &p, const Vector<double> &U, const unsigned int seed)
  {
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> uniform(-1, 1);
    Vector<double>                         v(U.size()), mask(U.size());
    p.mode_mask(mask); // (the free unknowns)
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] = mask[i] != 0 ? uniform(random) : 0.;
    const double   e = 1e-6;
    Vector<double> plus = U, minus = U, Rp(U.size()), Rm(U.size()), d(U.size()), w(U.size());
    plus.add(e, v);
    minus.add(-e, v);
    AssertThrow(p.residual(plus, Rp) == 0 && p.residual(minus, Rm) == 0, ExcMessage("residual refused"));
    d = Rp;
    d -= Rm;
    d /= 2 * e;
    AssertThrow(p.setup_jacobian(U) == 0, ExcMessage("Jacobian refused"));
    p.jacobian_vmult(v, w);
    w -= d;
    return w.l2_norm() / d.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  cosmo::rod::RodParameters::declare_parameters(prm);
  // A coil of 3 turns (kappa1 = 2 pi, kappa3 = 0.442, L = 3; radius 0.158): its natural
  // pitch 0.07 against a diameter 2a = 0.1, each turn 0.03 into the next.
  std::string input = R"(
subsection Rod
  set Length = 3
  set Number of elements = 150
  set Shape = natural
  set Natural strains = 0; 0; 1; 6.283185307179586; 0; 0.4419994866883747
  subsection Contact
    set Radius = RADIUS
    set Stiffness = 100
  end
end
subsection End A
  set Support = clamped
end
subsection End B
  set Support = free
end
subsection Output
  set Output directory = rod_contact_output
end
)";
  const char *radius = argc > 1 ? argv[1] : "0.05";
  input.replace(input.find("RADIUS"), 6, radius);
  prm.parse_input_from_string(input);
  cosmo::rod::RodProblem p;
  p.parse_parameters(prm);
  p.set_quiet(true);
  p.setup_system();
  p.set_load_parameter(0);
  Vector<double> U = p.solution;
  Vector<double> R(U.size());
  AssertThrow(p.residual(U, R) == 0, ExcMessage("residual refused"));
  const cosmo::rod::RodState s = p.describe(U, 0);
  std::cout << "  the coil at its natural shape: " << s.contact_pairs << " pairs touch, gap " << s.contact_gap
            << ", |R| = " << R.l2_norm() << "\n";
  cosmo_test::check("the turns overlap (gap < 0, many pairs)", s.contact_gap < -0.02 && s.contact_pairs > 100);
  // The central differences' truncation, e^2 |R'''|/|R'| ~ 1e-12, and
  // round-off, eps |R|/(e |R'|) ~ 1e-10 (measured 4e-11): 1e-8 is above
  // both and far below a missing or wrong term (a pair's block is O(1) of
  // the Hessian; without the contact's Hessian the error is O(1)).
  for (unsigned int k = 0; k < 3; ++k)
    check_close("J v = dR/dv at the overlapping coil, direction " + std::to_string(k),
                directional_error(p, U, k), 0, 0, 1e-8);
  // A state off the natural shape, its nodes moved by 1e-3 (pairs enter and leave).
  Vector<double> mask(U.size());
  p.mode_mask(mask);
  for (unsigned int i = 0; i < U.size(); ++i)
    U[i] += 1e-3 * std::sin(7. * i) * (mask[i] != 0);
  for (unsigned int k = 0; k < 3; ++k)
    check_close("J v = dR/dv at a perturbed coil, direction " + std::to_string(k),
                directional_error(p, U, 10 + k), 0, 0, 1e-8);
  return cosmo_test::report();
}
