// The arclength / bifurcation driver (solvers/arclength.h) on problems with
// known answers: a pitchfork, a fold, and the buckling of a discrete
// cantilever (elastica) whose critical load, mode and post-buckled branch
// are known in closed form. Run as test_continuation <case>.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <cosmo/io/ranks.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_estimate.h>
#include <cosmo/solvers/newton.h>
#include <cosmo/solvers/sparse_direct.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "test_tools.h"

#include <cmath>
#include <tuple>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>

using namespace dealii;
using namespace cosmo;
using cosmo_test::check;
using cosmo_test::check_close;

namespace
{
  /// A small problem with an analytic gradient R and Hessian H of an energy.
  class DenseProblem : public solvers::BifurcationProblem
  {
  public:
    struct Point
    {
      double              lambda;
      unsigned int        branch;
      int                 n_negative;
      std::vector<double> U;
    };
    std::vector<Point>                   history;
    std::vector<solvers::BifurcationProblem::Event> events;

    explicit DenseProblem(unsigned int n)
      : n(n)
      , J(n, n)
    {}
    unsigned int
    n_unknowns() const override
    {
      return n;
    }
    void
    set_load_parameter(double l) override
    {
      lambda = l;
    }
    int
    residual(const Vector<double> &U, Vector<double> &R) override
    {
      ++residuals;
      R.reinit(n);
      FullMatrix<double> H(n, n);
      evaluate(U, lambda, R, H);
      return 0;
    }
    int
    setup_jacobian(const Vector<double> &U) override
    {
      ++setups;
      Vector<double>     R(n);
      FullMatrix<double> H(n, n);
      evaluate(U, lambda, R, H);
      LAPACKFullMatrix<double> E(n, n);
      E = H;
      E.compute_eigenvalues_symmetric(-1e300, 1e300, 1e-14, eigenvalues, eigenvectors);
      negative = 0;
      for (unsigned int i = 0; i < eigenvalues.size(); ++i)
        negative += eigenvalues[i] < 0;
      J = H;
      H_last = H;
      try
        {
          J.compute_lu_factorization();
        }
      catch (std::exception &)
        {
          return 1; // exactly singular: the driver steps around it
        }
      return 0;
    }
    int
    solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) override
    {
      dst = rhs;
      J.solve(dst);
      return 0;
    }
    int
    n_negative_eigenvalues() override
    {
      return negative;
    }
    bool
    solves_exactly() const override
    {
      return exact_solves;
    }
    bool         exact_solves = false; ///< declare the (exact, LAPACK) solves exact
    unsigned int residuals    = 0;     ///< residual() calls
    unsigned int setups       = 0;     ///< setup_jacobian() calls (factorizations)
    unsigned int at_predictor = 0;     ///< states reported with the predictor's factorization
    bool
    chord_steps_on_path() const override
    {
      return true;
    }
    double
    jacobian_abs_form(const Vector<double> &v) const override
    {
      double s = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          s += std::abs(H_last(i, j) * v[i] * v[j]);
      return s;
    }
    void
    converged_step(const Vector<double> &U, const solvers::StepReport &r) override
    {
      history.push_back({r.t, r.branch, r.n_negative, std::vector<double>(U.begin(), U.end())});
      at_predictor += r.factorized_at_predictor;
    }
    void
    located_event(const Event &e, const Vector<double> &, const Vector<double> *) override
    {
      events.push_back(e);
    }
    /// store_jacobian: the Hessian at U (if offer_stored_jacobians)
    bool
    store_jacobian(const Vector<double> &U, const unsigned int slot) override
    {
      if (!offer_stored_jacobians)
        return false;
      Vector<double> R(n);
      stored[slot].reinit(n, n);
      evaluate(U, lambda, R, stored[slot]);
      return true;
    }
    void
    stored_jacobian_vmult(const unsigned int slot, const Vector<double> &x, Vector<double> &y) const override
    {
      y.reinit(n);
      stored[slot].vmult(y, x);
    }
    bool offer_stored_jacobians = false;

  protected:
    virtual void
    evaluate(const Vector<double> &U, double lambda, Vector<double> &R, FullMatrix<double> &H) = 0;

    unsigned int             n;
    double                   lambda = 0;
    LAPACKFullMatrix<double> J;
    Vector<double>           eigenvalues;
    FullMatrix<double>       eigenvectors;
    int                      negative = 0;
    FullMatrix<double>       H_last;
    FullMatrix<double>       stored[3];
  };

  /// The event was located by Newton on the augmented system, with at most 8
  /// factorizations, to a resolution below a fifth of the tolerance used on it
  /// (the locator's own tolerance is 1e-13 (|lambda| + bracket): 1.1e-13 at
  /// lambda = 1 with a bracket up to 0.1, a ninth of the 1e-12 used there).
  void
  check_location(const solvers::BifurcationProblem::Event &e, const double tolerance)
  {
    std::cout << "  located by " << (e.located_by_newton ? "Newton" : "bisection") << " in "
              << e.newton_iterations << " iterations, " << e.factorizations
              << " factorizations, resolution " << solvers::event_resolution(e) << "\n";
    check("located by Newton on the augmented system", e.located_by_newton);
    check("at most 8 factorizations from detection to location (" +
            std::to_string(e.factorizations) + ")",
          e.factorizations <= 8);
    check("resolution below a fifth of the tolerance", solvers::event_resolution(e) < 0.2 * tolerance);
  }

  solvers::ArclengthSettings
  settings(double lambda_min, double lambda_max)
  {
    solvers::ArclengthSettings s;
    s.lambda_min      = lambda_min;
    s.lambda_max      = lambda_max;
    s.initial_step    = 0.05;
    s.maximum_step    = 0.1;
    s.event_tolerance = 1e-10;
    return s;
  }

  solvers::NewtonSettings
  newton()
  {
    solvers::NewtonSettings n;
    n.relative_tolerance = 1e-12;
    return n;
  }

  // E = (1 - lambda) x^2/2 + x^4/4 + y^2/2: the trivial branch x = 0 loses
  // stability at lambda = 1, where the branches x^2 = lambda - 1 bifurcate.
  class Pitchfork : public DenseProblem
  {
  public:
    Pitchfork()
      : DenseProblem(2)
    {}

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      R[0]    = (1 - l) * U[0] + U[0] * U[0] * U[0];
      R[1]    = U[1];
      H(0, 0) = 1 - l + 3 * U[0] * U[0];
      H(1, 1) = 1;
      H(0, 1) = H(1, 0) = 0;
    }
  };

  // E = (1 - l) x^2/2 + x^4/4 + (2 - l) y^2/2 + y^4/4 + c x^2 y^2/2, c = 1/2:
  // the trivial branch has branch points at l = 1 (x) and 2 (y); on the
  // x-branch x^2 = l - 1 the y-stiffness 2 - l + c x^2 = (3 - l)/2 vanishes
  // at l = 3, a secondary branch point, from which the mixed branch
  // x^2 + c y^2 = l - 1, y^2 + c x^2 = l - 2 starts.
  class TwoModes : public DenseProblem
  {
  public:
    static constexpr double c = 0.5;
    TwoModes()
      : DenseProblem(2)
    {}

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      const double x = U[0], y = U[1];
      R[0]    = (1 - l) * x + x * x * x + c * x * y * y;
      R[1]    = (2 - l) * y + y * y * y + c * x * x * y;
      H(0, 0) = 1 - l + 3 * x * x + c * y * y;
      H(1, 1) = 2 - l + 3 * y * y + c * x * x;
      H(0, 1) = H(1, 0) = 2 * c * x * y;
    }
  };

  void
  secondary_bifurcation()
  {
    TwoModes                   p;
    solvers::ArclengthSettings s = settings(0, 4);
    s.maximum_depth              = 2;
    s.maximum_branches           = 6;
    solvers::ArclengthContinuation driver(s, newton());
    driver.progress = [](const std::string &m) { std::cout << m << "\n"; };
    Vector<double> U(2);
    const auto     events = driver.run(p, U, 0.);
    // The secondary branch point: on a branch switched to from the first.
    double secondary = NAN, secondary_resolution = 0;
    for (const auto &e : events)
      if (e.event.branch != 0 && e.event.kind == solvers::BifurcationProblem::Event::Kind::branch_point &&
          std::abs(e.state[0]) > 0.1)
        {
          secondary            = e.event.lambda;
          secondary_resolution = solvers::event_resolution(e.event);
        }
    // (within twice its stated precision: the Newton iteration ends at the
    // round-off floor here, 1.5e-10 -- its last two updates -- although it
    // lands on 3 to round-off)
    check_close("secondary branch point on the x-branch at l = 3", secondary, 3, 0,
                std::max(1e-12, 2 * secondary_resolution));
    // A branch of depth 2 (mixed: x, y != 0) lies on the closed form.
    double       worst = 0;
    unsigned int mixed = 0;
    for (const auto &pt : p.history)
      if (std::abs(pt.U[0]) > 1e-3 && std::abs(pt.U[1]) > 1e-3)
        {
          ++mixed;
          const double x2 = pt.U[0] * pt.U[0], y2 = pt.U[1] * pt.U[1];
          worst = std::max({worst, std::abs(x2 + TwoModes::c * y2 - (pt.lambda - 1)),
                            std::abs(y2 + TwoModes::c * x2 - (pt.lambda - 2))});
        }
    check("the mixed branch (depth 2) was followed (" + std::to_string(mixed) + " states)", mixed > 5);
    check_close("mixed branch on x^2 + c y^2 = l - 1, y^2 + c x^2 = l - 2", worst, 0, 0, 1e-10);
  }

  void
  pitchfork()
  {
    // By default the -phi half of the symmetric pitchfork is recognized as
    // the mirror image of the +phi half and not followed.
    {
      Pitchfork                      q;
      solvers::ArclengthContinuation d(settings(-1, 2), newton());
      Vector<double>                 U(2);
      d.run(q, U, 0.);
      unsigned int branches = 0;
      for (const auto &pt : q.history)
        branches = std::max(branches, pt.branch + 1);
      check("mirror image recognized: the trivial branch and one half (" +
              std::to_string(branches) + " branches)",
            branches == 2);
    }
    Pitchfork                  p;
    solvers::ArclengthSettings both = settings(-1, 2);
    both.follow_mirror_images       = true;
    solvers::ArclengthContinuation driver(both, newton());
    driver.progress = [](const std::string &s) { std::cout << s << "\n"; };
    Vector<double> U(2);
    const auto     events = driver.run(p, U, 0.);
    check("one event on the first branch, and it is a branch point",
          events.size() == 1 &&
            events[0].event.kind == solvers::BifurcationProblem::Event::Kind::branch_point);
    if (events.empty())
      return;
    // Located by Newton: the resolution (printed; the last update, 4e-14,
    // bounds it here) is below a fifth of the tolerance.
    check_close("branch point at lambda = 1", events[0].event.lambda, 1, 0, 1e-12);
    check_location(events[0].event, 1e-12);
    check_close("mode = +-(1, 0): |phi_y|", std::abs(events[0].mode[1]), 0, 0, 1e-12);
    check_close("eigenvalue of J along the mode ~ 0", events[0].event.eigenvalue, 0, 0, 1e-8);
    double worst = 0, worst_trivial = 0;
    unsigned int on_new = 0, unstable = 0, wrong_stability = 0, branches_up = 0, branches_down = 0;
    for (const auto &pt : p.history)
      if (pt.branch == 0)
        {
          worst_trivial = std::max(worst_trivial, std::abs(pt.U[0]));
          wrong_stability += (pt.n_negative != (pt.lambda > 1 ? 1 : 0));
          unstable += (pt.n_negative == 1);
        }
      else
        {
          ++on_new;
          worst = std::max(worst, std::abs(pt.U[0] * pt.U[0] - (pt.lambda - 1)));
          wrong_stability += (pt.n_negative != 0);
          branches_up += pt.U[0] > 0;
          branches_down += pt.U[0] < 0;
        }
    std::cout << "  " << p.history.size() << " states, " << on_new << " on the new branches\n";
    check_close("first branch stays on x = 0", worst_trivial, 0, 0, 1e-12);
    check("new branches: both signs followed (" + std::to_string(branches_up) + " with x > 0, " +
            std::to_string(branches_down) + " with x < 0)",
          branches_up > 5 && branches_down > 5);
    check_close("new branches lie on x^2 = lambda - 1", worst, 0, 0, 1e-10);
    check("stability: x = 0 unstable exactly beyond lambda = 1, bifurcated branches stable (" +
            std::to_string(wrong_stability) + " wrong, " + std::to_string(unstable) + " unstable)",
          wrong_stability == 0 && unstable > 0);
  }

  // E = x^3/3 - lambda x + y^2/2: x^2 = lambda, a fold at lambda = 0 where
  // the unstable branch x < 0 turns into the stable one x > 0.
  class Fold : public DenseProblem
  {
  public:
    Fold()
      : DenseProblem(2)
    {}

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      R[0]    = U[0] * U[0] - l;
      R[1]    = U[1];
      H(0, 0) = 2 * U[0];
      H(1, 1) = 1;
      H(0, 1) = H(1, 0) = 0;
    }
  };

  /// The fold's curved branch x^2 = lambda from (1, 1) down to lambda =
  /// 0.01 (no event on it), with or without the corrector's chord steps:
  /// its states, the factorizations, the largest |x^2 - lambda| + |y|.
  struct CurvedBranch
  {
    bool         no_event;
    unsigned int states, setups;
    double       worst;
  };

  CurvedBranch
  fold_curved_branch(const bool reuse)
  {
    Fold p;
    auto s                = settings(0.01, 1);
    s.direction           = -1;
    s.reuse_factorization = reuse;
    solvers::ArclengthContinuation driver(s, newton());
    Vector<double>                 U(2);
    U[0]              = 1;
    const auto events = driver.run(p, U, 1.);
    double     worst  = 0;
    for (const auto &pt : p.history)
      worst = std::max(worst, std::abs(pt.U[0] * pt.U[0] - pt.lambda) + std::abs(pt.U[1]));
    return {events.empty(), static_cast<unsigned int>(p.history.size()), p.setups, worst};
  }

  void
  fold()
  {
    Fold p;
    auto s      = settings(-1, 1);
    s.direction = -1; // from (x, lambda) = (-1, 1) towards the fold
    solvers::ArclengthContinuation driver(s, newton());
    driver.progress = [](const std::string &m) { std::cout << m << "\n"; };
    Vector<double> U(2);
    U[0]              = -1;
    const auto events = driver.run(p, U, 1.);
    check("one event, a fold", events.size() == 1 &&
                                 events[0].event.kind == solvers::BifurcationProblem::Event::Kind::fold);
    if (events.empty())
      return;
    // The fold is located to arclength 1e-10 in x; lambda = x^2 there.
    check_close("fold at x = 0", events[0].state[0], 0, 0, 1e-9);
    // (this toy lands exactly on x = 0 where J is singular: 10 iterations; no
    // factorization count is asserted here)
    check_close("fold at lambda = 0", events[0].event.lambda, 0, 0, 1e-12);
    check("located by Newton on the augmented system", events[0].event.located_by_newton);
    double worst = 0, final_lambda = 0, final_x = 0;
    unsigned int wrong = 0;
    for (const auto &pt : p.history)
      {
        worst = std::max(worst, std::abs(pt.U[0] * pt.U[0] - pt.lambda));
        wrong += pt.n_negative != (pt.U[0] < 0 ? 1 : 0);
        final_lambda = pt.lambda;
        final_x      = pt.U[0];
      }
    check_close("every state on x^2 = lambda", worst, 0, 0, 1e-10);
    check("passed the fold: last state on x > 0 with lambda back at the end of the range (x = " +
            std::to_string(final_x) + ", lambda = " + std::to_string(final_lambda) + ")",
          final_x > 0.9 && final_lambda >= 1);
    check("stability count 1 on x < 0, 0 on x > 0 (" + std::to_string(wrong) + " wrong)", wrong == 0);
    check("no branch switching at a fold", std::all_of(p.history.begin(), p.history.end(),
                                                       [](const auto &pt) { return pt.branch == 0; }));
  }

  /// E = x^2/2 + c x^4/4 - lambda x + y^2/2: the nearly straight branch
  /// x + c x^3 = lambda; with_pitchfork: (1 - lambda) y^2/2 + y^4/4 for the
  /// y-part, a pitchfork at lambda = 1 on the branch y = 0.
  class NearlyLinear : public DenseProblem
  {
  public:
    NearlyLinear(const double c, const bool with_pitchfork = false)
      : DenseProblem(2)
      , c(c)
      , pitchfork(with_pitchfork)
    {}

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      const double k = pitchfork ? 1 - l : 1, q = pitchfork ? 1 : 0;
      R[0]    = U[0] + c * std::pow(U[0], 3) - l;
      R[1]    = k * U[1] + q * std::pow(U[1], 3);
      H(0, 0) = 1 + 3 * c * U[0] * U[0];
      H(1, 1) = k + 3 * q * U[1] * U[1];
      H(0, 1) = H(1, 0) = 0;
    }
    const double c;
    const bool   pitchfork;
  };

  /// LAPACK's eigenvalues of a symmetric dense matrix: how many are
  /// negative, the smallest and the largest magnitude.
  std::tuple<int, double, double>
  dense_spectrum(const FullMatrix<double> &dense)
  {
    LAPACKFullMatrix<double> L(dense.m(), dense.n());
    L = dense;
    L.compute_eigenvalues();
    int    negative = 0;
    double smallest = 1e300, largest = 0;
    for (unsigned int i = 0; i < dense.m(); ++i)
      {
        const double lambda = L.eigenvalue(i).real();
        negative += lambda < 0;
        smallest = std::min(smallest, std::abs(lambda));
        largest  = std::max(largest, std::abs(lambda));
      }
    return {negative, smallest, largest};
  }

  /**
   * The corrector's predictor step (ArclengthContinuation::correct). On
   * the nearly straight branch x + c x^3 = lambda (c = 1e-7) the tangent
   * predictor misses by ~3 c x ds^2 ~ 1e-9: below the tolerance 1e-8, above
   * the 1e-10 at which KINSOL would take it. Each converged state then costs
   * one factorization (the predictor's, kept by the analysis; before, two:
   * KINSOL's iteration and the analysis), and the Newton step from the
   * predictor keeps the states on the branch to round-off. On the curved
   * branch x^2 = lambda of the fold the predictor misses by O(ds^2), far
   * above the tolerance, and Newton runs as before (at least two
   * factorizations per state).
   */
  void
  predictor_step()
  {
    NearlyLinear            p(1e-7);
    solvers::NewtonSettings loose = newton();
    loose.relative_tolerance      = 1e-8;
    // (the predictor step alone: no chord steps, solvers.arclength_chord)
    solvers::ArclengthSettings straight = settings(-1, 1.5);
    straight.reuse_factorization        = false;
    solvers::ArclengthContinuation driver(straight, loose);
    Vector<double>                 U(2);
    const auto                     events = driver.run(p, U, 0.);
    double                         off    = 0;
    for (const auto &pt : p.history)
      off = std::max(off, std::abs(pt.U[0] + 1e-7 * std::pow(pt.U[0], 3) - pt.lambda) +
                            std::abs(pt.U[1]));
    std::cout << "  nearly straight branch: " << p.history.size() << " states, " << p.setups
              << " factorizations, " << p.at_predictor
              << " states with the predictor's, |x + c x^3 - lambda| + |y| <= " << off << "\n";
    check("nearly straight branch: one factorization per converged state, most the predictor's",
          events.empty() && p.history.size() >= 10 && p.setups == p.history.size() &&
            2 * p.at_predictor >= p.history.size());
    check_close("nearly straight branch: on x + c x^3 = lambda", off, 0, 0, 1e-14);

    // The count and the event from the predictors' factorizations: the
    // stability count of every state (1 past lambda = 1), and the branch
    // point located from a step's end whose factorization is its
    // predictor's (resolution ~1e-16 here).
    NearlyLinear                   q(1e-7, true);
    solvers::ArclengthSettings     no_switch = settings(-1, 1.5);
    no_switch.switch_branches                = false;
    no_switch.reuse_factorization            = false;
    solvers::ArclengthContinuation e(no_switch, loose);
    Vector<double>                 W(2);
    const auto                     located = e.run(q, W, 0.);
    unsigned int                   wrong   = 0;
    for (const auto &pt : q.history)
      wrong += pt.n_negative != (pt.lambda > 1 ? 1 : 0);
    std::cout << "  with a pitchfork: " << q.history.size() << " states, " << q.at_predictor
              << " with the predictor's factorization, " << wrong << " wrong counts\n";
    check("with a pitchfork: every count right, most states with the predictor's factorization",
          wrong == 0 && q.history.size() >= 10 && 2 * q.at_predictor >= q.history.size());
    check("with a pitchfork: one branch point", located.size() == 1);
    if (located.size() == 1)
      {
        check_close("with a pitchfork: the branch point at lambda = 1", located[0].event.lambda, 1, 0,
                    1e-12);
        check_location(located[0].event, 1e-12);
      }

    const CurvedBranch f = fold_curved_branch(false);
    std::cout << "  curved branch: " << f.states << " states, " << f.setups
              << " factorizations, |x^2 - lambda| + |y| <= " << f.worst << "\n";
    check("curved branch: Newton as before (at least two factorizations per state after the first)",
          f.no_event && f.states >= 5 && f.setups >= 2 * f.states - 1);
    check_close("curved branch: x^2 = lambda", f.worst, 0, 0, 1e-10);
  }

  // A clamped-free chain of n rigid links (bending stiffness 1, length 1)
  // under a dead compressive end load lambda:
  //   E = sum_i (theta_i - theta_{i-1})^2 / (2h) + lambda h sum_i cos(theta_i),
  // theta_0 = 0. The straight state loses stability at the discrete Euler load
  // lambda_c = (2 - 2 cos(pi/(2n+1))) / h^2, with the mode sin(pi i/(2n+1));
  // the post-buckled branch tends to the elastica, lambda/(pi^2/4) =
  // (2 K(k)/pi)^2, k = sin(theta_tip/2), as h -> 0.
  /// The chain's k-th critical load (Cantilever, MovingPrestress: the
  /// discrete Euler loads of n links of length h = 1/n, in closed form).
  double
  chain_critical_load(const unsigned int n, const unsigned int k = 1)
  {
    return (2 - 2 * std::cos((2 * k - 1) * M_PI / (2 * n + 1))) * n * n;
  }

  class Cantilever : public DenseProblem
  {
  public:
    explicit Cantilever(unsigned int n)
      : DenseProblem(n)
      , h(1. / n)
    {}
    const double h;

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      H = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double left = (i == 0) ? 0. : U[i - 1];
          R[i]              = (U[i] - left) / h - l * h * std::sin(U[i]);
          H(i, i)           = 1 / h - l * h * std::cos(U[i]);
          if (i > 0)
            H(i, i - 1) = -1 / h;
          if (i + 1 < n)
            {
              R[i] -= (U[i + 1] - U[i]) / h;
              H(i, i) += 1 / h;
              H(i, i + 1) = -1 / h;
            }
        }
    }
  };

  double
  elliptic_K(const double k)
  {
    double a = 1, b = std::sqrt(1 - k * k);
    for (int i = 0; i < 40; ++i)
      {
        const double an = 0.5 * (a + b);
        b               = std::sqrt(a * b);
        a               = an;
      }
    return M_PI / (2 * a);
  }

  void
  cantilever()
  {
    const unsigned int n = 40;
    Cantilever         p(n);
    auto               s = settings(0, 6);
    s.both_directions    = true;
    s.switch_amplitude   = 1e-3;
    solvers::ArclengthContinuation driver(s, newton());
    driver.progress = [](const std::string &m) { std::cout << m << "\n"; };
    Vector<double> U(n);
    const auto     events   = driver.run(p, U, 0.);
    const double   lambda_c = chain_critical_load(n);
    check("first event is a simple branch point", !events.empty() &&
                                                     events[0].event.kind ==
                                                       solvers::BifurcationProblem::Event::Kind::branch_point &&
                                                     events[0].event.n_negative_after == 1);
    if (events.empty())
      return;
    // Resolution eps |v|.|J||v| / |dg/dlambda| = 1.4e-12 (6e-13 relative, printed).
    check_close("critical load = discrete Euler load", events[0].event.lambda, lambda_c, 1e-10);
    check_location(events[0].event, 1e-10 * lambda_c);
    std::cout << "  (discrete " << lambda_c << ", continuum pi^2/4 = " << M_PI * M_PI / 4 << ")\n";
    // The mode against sin(pi i/(2n+1)), both normalized, sign fixed.
    double dot = 0, nm = 0, ne = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double e = std::sin(M_PI * (i + 1) / (2 * n + 1));
        dot += e * events[0].mode[i];
        nm += events[0].mode[i] * events[0].mode[i];
        ne += e * e;
      }
    check_close("mode = sin(pi i/(2n+1)): 1 - |cos angle|", 1 - std::abs(dot) / std::sqrt(nm * ne), 0, 0, 1e-10);

    double       worst = 0;
    unsigned int n_new = 0, wrong = 0;
    double       max_tip = 0;
    for (const auto &pt : p.history)
      {
        if (pt.branch == 0)
          {
            wrong += pt.n_negative != (pt.lambda > lambda_c ? 1 : 0);
            continue;
          }
        ++n_new;
        wrong += pt.n_negative != 0;
        const double tip = std::abs(pt.U[n - 1]);
        max_tip          = std::max(max_tip, tip);
        if (tip < 0.2)
          continue; // near the branch point the comparison is dominated by 0/0
        const double K       = elliptic_K(std::sin(tip / 2));
        const double elastic = M_PI * M_PI / 4 * std::pow(2 * K / M_PI, 2);
        worst                = std::max(worst, std::abs(pt.lambda / elastic - lambda_c / (M_PI * M_PI / 4)));
      }
    std::cout << "  " << n_new << " post-buckled states, tip rotation up to " << max_tip << "\n";
    // lambda / elastica, relative to the discrete/continuum ratio of the
    // critical load: the O(h^2) discretization error, measured 2e-4.
    check_close("post-buckled branch on the elastica (relative to lambda_c,h / lambda_c)", worst, 0, 0, 1e-3);
    check("post-buckled branch reaches large rotations", max_tip > 1.5);
    check("stability: straight unstable beyond lambda_c, buckled stable (" + std::to_string(wrong) + " wrong)",
          wrong == 0);
  }

  // The corrector's chord steps from the last state's factorization
  // ('Arclength continuation / Reuse factorization'), with and without them
  // on the fold's curved branch x^2 = lambda: from (1, 1) down to lambda =
  // 0.01 (no event), and from (-1, 1) to the fold at lambda = 0, on the way
  // to which they are used. Every state solves R = 0 to the Newton
  // tolerance either way (the chord steps change only how), the fold is
  // the same, and the chord steps need fewer factorizations per state.
  void
  arclength_chord()
  {
    double per_state[2], fold_at[2];
    for (const bool reuse : {false, true})
      {
        const CurvedBranch c = fold_curved_branch(reuse);
        per_state[reuse]     = double(c.setups) / c.states;
        std::cout << "  " << (reuse ? "with" : "without") << " chord steps: " << c.states << " states, " << c.setups
                  << " factorizations, |x^2 - lambda| + |y| <= " << c.worst << "\n";
        check(std::string(reuse ? "with" : "without") + " chord steps: no event, states down to lambda = 0.01",
              c.no_event && c.states >= 5);
        // (Newton's stopping test: max |R_i| <= 1e-12 for each of the two
        // equations, so their sum within 2e-12)
        check_close(std::string(reuse ? "with" : "without") + " chord steps: every state on x^2 = lambda",
                    c.worst, 0, 0, 2e-12);

        Fold q;
        auto t                = settings(-1, 1);
        t.direction           = -1;
        t.stop_at_first_event = true;
        t.reuse_factorization = reuse;
        solvers::ArclengthContinuation to_fold(t, newton());
        Vector<double>                 W(2);
        W[0]                = -1;
        const auto located  = to_fold.run(q, W, 1.);
        fold_at[reuse]      = located.empty() ? NAN : located[0].event.lambda;
        check(std::string(reuse ? "with" : "without") + " chord steps: the fold located",
              located.size() == 1 && located[0].event.kind == solvers::BifurcationProblem::Event::Kind::fold);
      }
    // (the fold test's bound: lambda = 0 to 1e-12)
    check_close("the fold at lambda = 0 with chord steps", fold_at[1], 0, 0, 1e-12);
    check_close("the fold at lambda = 0 without", fold_at[0], 0, 0, 1e-12);
    check("fewer factorizations per state with chord steps (" + std::to_string(per_state[1]) + " against " +
            std::to_string(per_state[0]) + ")",
          per_state[1] < 0.8 * per_state[0]);
  }

  // The bordered ordering (solvers/sparse_direct.h): a grid Laplacian with
  // free boundaries (singular: the constants), shifted by -sigma so that it
  // is indefinite, bordered by a gauge row (the mean) and a dense coupling
  // row, like the Hessians of the sections. The border rows are found; the
  // LDL^T with METIS's nested dissection of the block and the border last
  // solves as QAMD's does (to round-off times the condition) and has the
  // inertia of the whole matrix (LAPACK's eigenvalues), for shifts that make
  // the block singular (sigma = 0: MUMPS delays the null pivot into the
  // border's front) and indefinite.
  void
  bordered_ordering()
  {
    const unsigned int m = 30, n_block = m * m, n = n_block + 2;
    for (const double sigma : {0., 0.35})
      {
        DynamicSparsityPattern dsp(n, n);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            {
              const unsigned int k = i * m + j;
              dsp.add(k, k);
              if (i + 1 < m)
                dsp.add(k, k + m), dsp.add(k + m, k);
              if (j + 1 < m)
                dsp.add(k, k + 1), dsp.add(k + 1, k);
              for (const unsigned int b : {n_block, n_block + 1})
                dsp.add(k, b), dsp.add(b, k);
            }
        dsp.add(n_block + 1, n_block + 1);
        SparsityPattern sp;
        sp.copy_from(dsp);
        SparseMatrix<double> A(sp);
        FullMatrix<double>   dense(n, n);
        auto                 set = [&](const unsigned int a, const unsigned int b, const double v) {
          A.add(a, b, v);
          dense(a, b) += v;
        };
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            {
              const unsigned int k = i * m + j;
              set(k, k, -sigma);
              if (i + 1 < m)
                set(k, k, 1), set(k + m, k + m, 1), set(k, k + m, -1), set(k + m, k, -1);
              if (j + 1 < m)
                set(k, k, 1), set(k + 1, k + 1, 1), set(k, k + 1, -1), set(k + 1, k, -1);
              set(k, n_block, 1. / n_block), set(n_block, k, 1. / n_block);
              const double c = 0.01 * std::sin(0.7 * k);
              set(k, n_block + 1, c), set(n_block + 1, k, c);
            }
        set(n_block + 1, n_block + 1, 2.);
        const auto found = solvers::dense_rows(sp);
        unsigned int n_found = 0;
        for (unsigned int i = 0; i < n; ++i)
          n_found += found[i];
        check("bordered ordering: the two border rows found, no other", n_found == 2 && found[n_block] && found[n_block + 1]);
        // the ordering exists (METIS is in the build), or the comparison below would be QAMD with itself
        const auto position = solvers::border_last_ordering(sp);
        check("bordered ordering: METIS's order, the border last",
              position.size() == n && position[n_block] > int(n_block) && position[n_block + 1] > int(n_block));
        Vector<double> b(n);
        for (unsigned int i = 0; i < n; ++i)
          b[i] = std::cos(0.3 * i);
        std::vector<Vector<double>> x;
        std::vector<int>            negative;
        for (const char *ordering : {"6", "100"})
          {
            setenv("COSMO_MUMPS_ORDERING", ordering, 1);
            solvers::SparseDirectSolver solver;
            solver.factorize(A);
            Vector<double> y = b;
            solver.solve(y);
            x.push_back(y);
            negative.push_back(solver.n_negative_eigenvalues());
          }
        unsetenv("COSMO_MUMPS_ORDERING");
        const auto [lapack_negative, smallest, largest] = dense_spectrum(dense);
        (void)largest;
        Vector<double> d = x[1];
        d -= x[0];
        std::cout << "sigma = " << sigma << ": negative pivots QAMD " << negative[0] << ", bordered ND "
                  << negative[1] << ", LAPACK " << lapack_negative << " (smallest |eigenvalue| " << smallest
                  << "); solutions differ by " << d.linfty_norm() / x[0].linfty_norm() << "\n";
        check("bordered ordering: the inertia of the whole matrix", negative[1] == lapack_negative &&
                                                                       negative[0] == lapack_negative);
        // round-off eps times the condition number (|lambda|max ~ 8 over the smallest)
        check("bordered ordering: the same solution as QAMD",
              d.linfty_norm() <= 1e3 * 2.2e-16 * 8 / smallest * x[0].linfty_norm());
      }
  }

  /**
   * solvers::dq_point_of, which recognizes KINSOL's difference-quotient point
   * u + sigma p (newton_solve answers J p there from the solve): found with
   * KINSOL's sigma, sigma recovered; any other point not.
   */
  void
  dq_point()
  {
    const unsigned int n = 1000;
    Vector<double>     u(n), p(n), v(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        u[i] = 1e3 * std::sin(0.37 * i) + (i % 7 == 0 ? 0. : 1.);
        p[i] = 1e-4 * std::cos(1.1 * i);
      }
    // kinLsDQJtimes (SUNDIALS 6, unit scaling): sign(u.p) sqrt(uround)
    // max(|u.p|, ||p||_1) / ||p||^2.
    const double up    = u * p;
    const double sigma = (up >= 0 ? 1. : -1.) * std::sqrt(std::numeric_limits<double>::epsilon()) *
                         std::max(std::abs(up), p.l1_norm()) / p.norm_sqr();
    for (unsigned int i = 0; i < n; ++i)
      v[i] = u[i] + sigma * p[i];
    double found = 0;
    check("dq point: u + sigma p is found", solvers::dq_point_of(v, u, p, found));
    check_close("dq point: KINSOL's sigma", found, sigma, 1e-12);
    // Found at any size of u: the rounding of u + sigma p grows with |u|
    // (here 1e10 |p| / sigma |p| ~ 1e2 of the step), the check with it.
    {
      Vector<double> U = u, V(n);
      U *= 1e7;
      const double uP = U * p;
      const double s  = (uP >= 0 ? 1. : -1.) * std::sqrt(std::numeric_limits<double>::epsilon()) *
                       std::max(std::abs(uP), p.l1_norm()) / p.norm_sqr();
      for (unsigned int i = 0; i < n; ++i)
        V[i] = U[i] + s * p[i];
      check("dq point: found for |u| = 1e10 too", solvers::dq_point_of(V, U, p, found));
    }
    // Off the line by 1e-3 of sigma p in one entry: a different point.
    Vector<double> w = v;
    w[17] += 1e-3 * sigma * p.linfty_norm();
    check("dq point: a point off u + sigma p is not", !solvers::dq_point_of(w, u, p, found));
    // A line search's point u + t p is on the line but not KINSOL's
    // difference quotient: it must be assembled, never answered from the
    // linear model (which would make a full Newton step look converged).
    for (const double t : {1., 0.25, 1e-3, 2 * sigma})
      {
        Vector<double> z = u;
        z.add(t, p);
        check("dq point: a line search point u + " + std::to_string(t) + " p is not",
              !solvers::dq_point_of(z, u, p, found));
      }
    check("dq point: u itself is not", !solvers::dq_point_of(u, u, p, found));
  }

  /// R(U) = A U + U^3 - f (A the 1-D Laplacian plus 1, the energy's
  /// Hessian A + 3 diag(U^2)): a small Newton problem whose solves are exact
  /// (LAPACK), for newton_solve's J p (lambda plays no part).
  class Cubic : public DenseProblem
  {
  public:
    using DenseProblem::DenseProblem;

  protected:
    void
    evaluate(const Vector<double> &U, double, Vector<double> &R, FullMatrix<double> &H) override
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          R[i] = 3 * U[i] + std::pow(U[i], 3) - (1 + std::sin(0.3 * i));
          H(i, i) = 3 + 3 * U[i] * U[i];
          for (const unsigned int k : {i - 1, i + 1})
            if (k < n)
              R[i] -= U[k], H(i, k) = -1;
        }
    }
  };

  /**
   * newton_solve with exact solves answers every J p of KINSOL from the
   * solve (each iteration, so the installed KINSOL uses the sigma
   * dq_point_of knows), one residual assembly fewer per iteration, and the
   * same iterates as with the difference quotient.
   */
  void
  newton_exact_jp()
  {
    const unsigned int      n = 50;
    solvers::NewtonSettings settings;
    settings.relative_tolerance = 1e-12;
    std::vector<Vector<double>>      U(2, Vector<double>(n));
    std::vector<solvers::NewtonResult> r(2);
    std::vector<unsigned int>        residuals(2);
    for (const bool exact : {false, true})
      {
        Cubic system(n);
        system.exact_solves = exact;
        for (unsigned int i = 0; i < n; ++i)
          U[exact][i] = 2 * std::cos(0.7 * i); // far enough for 5 or more iterations
        r[exact]         = solvers::newton_solve(system, U[exact], settings);
        residuals[exact] = system.residuals;
      }
    Vector<double> d = U[1];
    d -= U[0];
    std::cout << "Newton: " << r[0].iterations << " / " << r[1].iterations << " iterations, "
              << residuals[0] << " / " << residuals[1] << " residuals, " << r[1].exact_jacobian_products
              << " J p from the solve; states differ by " << d.linfty_norm() << "\n";
    check("exact J p: as many iterations", r[0].iterations == r[1].iterations && r[1].iterations >= 4);
    check("exact J p: every iteration's J p from the solve",
          r[1].exact_jacobian_products == r[1].iterations && r[0].exact_jacobian_products == 0);
    check("exact J p: one residual fewer per iteration", residuals[1] + r[1].iterations == residuals[0]);
    // Both converge quadratically far below the tolerance: the states agree
    // to round-off of |U| ~ 1 (the difference quotient's line-search values
    // differ from the exact ones only in the last digits).
    check("exact J p: the same solution", d.linfty_norm() <= 1e-13);
  }

  /// R(U) = atan(U - c) + 0.1 (U - c) coupled to its neighbours: full
  /// Newton steps from 3 away overshoot (atan's), so a start there needs a
  /// line search.
  class Arctan : public DenseProblem
  {
  public:
    using DenseProblem::DenseProblem;

  protected:
    void
    evaluate(const Vector<double> &U, double, Vector<double> &R, FullMatrix<double> &H) override
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          const double x = U[i] - std::sin(0.5 * i);
          R[i]           = std::atan(x) + 0.1 * x;
          H(i, i)        = 1 / (1 + x * x) + 0.1;
          for (const unsigned int k : {i - 1, i + 1})
            if (k < n)
              R[i] += 0.1 * (x - (U[k] - std::sin(0.5 * k))), H(i, i) += 0.1, H(i, k) = -0.1;
        }
    }
  };

  /**
   * newton_solve with reuse_factorization (chord steps): from a start near
   * the solution it reaches exact Newton's solution to round-off with fewer
   * factorizations (each step it keeps one contracts the residual tenfold
   * or more); from a start far off, the same solution; where a fresh step
   * does not decrease the residual (atan's overshoot from 3 away), KINSOL's
   * line search from there, to the same solution as without reuse.
   */
  void
  newton_chord()
  {
    const unsigned int      n = 50;
    solvers::NewtonSettings exact;
    exact.relative_tolerance = 1e-12;
    solvers::NewtonSettings chord = exact;
    chord.reuse_factorization     = true;
    auto solve = [&](DenseProblem &&system, Vector<double> U, const solvers::NewtonSettings &s,
                     solvers::NewtonResult &r, unsigned int &setups) {
      system.exact_solves = true;
      r                   = solvers::newton_solve(system, U, s);
      setups              = system.setups;
      return U;
    };
    // Near: the solution less 1e-3 in every entry (a residual ~3e-3).
    Vector<double> far(n), near(n);
    for (unsigned int i = 0; i < n; ++i)
      far[i] = 2 * std::cos(0.7 * i);
    solvers::NewtonResult r_exact, r_chord;
    unsigned int          f_exact = 0, f_chord = 0;
    // The reference: exact Newton to the round-off floor (weighted |R| ~ 5e-16).
    solvers::NewtonSettings tight = exact;
    tight.relative_tolerance      = 1e-15;
    const Vector<double> solution = solve(Cubic(n), far, tight, r_exact, f_exact);
    for (unsigned int i = 0; i < n; ++i)
      near[i] = solution[i] - 1e-3 * std::cos(1.3 * i);
    unsigned int f_near_exact = 0, f_near_chord = 0, near_chord_steps = 0, near_iterations = 0;
    for (const auto &[name, start] : {std::make_pair("near", near), std::make_pair("far", far)})
      {
        const Vector<double> U_exact = solve(Cubic(n), start, exact, r_exact, f_exact);
        const Vector<double> U_chord = solve(Cubic(n), start, chord, r_chord, f_chord);
        Vector<double>       d = U_chord, e = U_exact;
        d -= solution;
        e -= solution;
        std::cout << "chord, " << name << " start: " << r_chord.iterations << " iterations ("
                  << r_chord.chord_steps << " chord steps), " << f_chord << " factorizations, against "
                  << r_exact.iterations << " and " << f_exact << "; errors " << d.linfty_norm() << " and "
                  << e.linfty_norm()
                  << ", residual " << r_chord.residual_norm << "\n";
        // The chord's converged state is polished while its steps contract
        // tenfold: at least as exact as exact Newton's at this tolerance
        // (measured 2e-13 off from the near start: it stops once below the
        // tolerance), or within 1e-13 (|U| ~ 1, the condition ~3, the
        // round-off floor ~1e-15).
        check(std::string("chord: the solution, as exact as exact Newton's, ") + name,
              d.linfty_norm() <= std::max(1e-13, e.linfty_norm()));
        check(std::string("chord: no more factorizations, ") + name, f_chord <= f_exact);
        if (std::string(name) == "near")
          f_near_exact = f_exact, f_near_chord = f_chord, near_chord_steps = r_chord.chord_steps,
          near_iterations = r_chord.iterations;
      }
    // From near, one factorization does the work of two or more.
    check("chord from near: fewer factorizations, chord steps counted",
          f_near_chord < f_near_exact && near_chord_steps >= 1 && near_iterations > near_chord_steps);
    // atan's overshoot: the fresh step from 3 away increases |R|; KINSOL's
    // line search takes over and converges to c.
    Vector<double> start(n), c(n);
    for (unsigned int i = 0; i < n; ++i)
      c[i] = std::sin(0.5 * i), start[i] = c[i] + 3;
    for (const auto *s : {&exact, &chord})
      {
        Vector<double> U = solve(Arctan(n), start, *s, r_chord, f_chord);
        U -= c;
        std::cout << (s == &chord ? "chord" : "exact") << ", atan from 3 away: " << r_chord.iterations
                  << " iterations, " << f_chord << " factorizations, error " << U.linfty_norm() << "\n";
        check(std::string("atan from 3 away converges: ") + (s == &chord ? "chord" : "exact"),
              U.linfty_norm() <= 1e-12);
      }
  }

  /**
   * newton_solve with take_guess takes a guess that passes its stopping
   * test (the weighted max-norm of R at most the tolerance) as the
   * solution, without a factorization; without take_guess (and for a guess
   * that does not pass) KINSOL iterates, and the guess's residual is
   * evaluated once (KINSOL's first residual is that one).
   */
  void
  newton_guess()
  {
    const unsigned int      n = 50;
    solvers::NewtonSettings settings;
    settings.relative_tolerance = 1e-12;
    Vector<double> U(n);
    for (unsigned int i = 0; i < n; ++i)
      U[i] = 2 * std::cos(0.7 * i);
    {
      Cubic system(n);
      solvers::newton_solve(system, U, settings);
    }
    // Guesses off the solution along a fixed direction e, scaled so that
    // the residual R ~ J e delta is a given multiple of the tolerance (J is
    // diagonally dominant, |J e| within a factor 2 of 3 |e| here: the
    // multiples 0.1 and 100 stay on their sides of 1).
    auto guess = [&](const double multiple, unsigned int &residuals, unsigned int &setups,
                     solvers::NewtonResult &r, Vector<double> &V, const bool take = true) {
      V = U;
      for (unsigned int i = 0; i < n; ++i)
        V[i] += multiple * settings.relative_tolerance / 3. * std::sin(1.1 * i + 0.3);
      Cubic system(n);
      system.exact_solves = true;
      r                   = solvers::newton_solve(system, V, settings, take);
      residuals           = system.residuals;
      setups              = system.setups;
    };
    unsigned int          residuals = 0, setups = 0;
    solvers::NewtonResult r;
    Vector<double>        V;
    guess(0.1, residuals, setups, r, V);
    Vector<double> start = U;
    for (unsigned int i = 0; i < n; ++i)
      start[i] += 0.1 * settings.relative_tolerance / 3. * std::sin(1.1 * i + 0.3);
    std::cout << "guess at 0.1 tol: " << r.iterations << " iterations, " << setups
              << " factorizations, " << residuals << " residuals, residual " << r.residual_norm
              << "\n";
    check("guess within the tolerance: taken, no factorization",
          r.iterations == 0 && setups == 0 && residuals == 1 && V == start &&
            r.residual_norm <= settings.relative_tolerance && r.residual_norm > 0);
    guess(0.1, residuals, setups, r, V, false);
    std::cout << "guess at 0.1 tol, not taken: " << r.iterations << " iterations, " << setups
              << " factorizations, " << residuals << " residuals\n";
    check("guess within the tolerance, not taken: KINSOL iterates (it takes 1/100 of it)",
          r.iterations >= 1 && setups == r.iterations && residuals == 1 + r.iterations);
    guess(100, residuals, setups, r, V);
    std::cout << "guess at 100 tol: " << r.iterations << " iterations, " << setups
              << " factorizations, " << residuals << " residuals, residual " << r.residual_norm
              << "\n";
    check("guess beyond the tolerance: Newton, the guess's residual once",
          r.iterations >= 1 && setups == r.iterations && residuals == 1 + r.iterations &&
            r.residual_norm <= settings.relative_tolerance);
  }
  /**
   * A chain's lateral stiffness K (the cantilever's) under a compression
   * u h that a stiff axial unknown u carries, u following the load:
   * E = a/2 (u - lambda)^2 + 1/2 w.K w - u h/2 w.w. On the path w = 0,
   * u = lambda, the Hessian's w block is K - lambda h I: linear in the load
   * along the tangent (du = 1) but independent of it at a fixed state, so
   * the estimate sees the critical load only through the state's motion.
   */
  class MovingPrestress : public DenseProblem
  {
  public:
    explicit MovingPrestress(unsigned int n)
      : DenseProblem(n + 1)
      , h(1. / n)
    {}
    const double h;
    const double a = 1e3;

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      H                   = 0;
      const unsigned int m = n - 1; // lateral unknowns w_i = U[1 + i]
      R[0]                 = a * (U[0] - l);
      H(0, 0)              = a;
      for (unsigned int i = 0; i < m; ++i)
        {
          const double w = U[1 + i], left = (i == 0) ? 0. : U[i];
          R[0] -= 0.5 * h * w * w;
          H(0, 1 + i) = H(1 + i, 0) = -h * w;
          R[1 + i]                  = (w - left) / h - U[0] * h * w;
          H(1 + i, 1 + i)           = 1 / h - U[0] * h;
          if (i > 0)
            H(1 + i, i) = -1 / h;
          if (i + 1 < m)
            {
              R[1 + i] -= (U[2 + i] - w) / h;
              H(1 + i, 1 + i) += 1 / h;
              H(1 + i, 2 + i) = -1 / h;
            }
        }
    }
  };

  /// The cantilever's chain with the load entering as g(lambda) = lambda + c lambda^2.
  class QuadraticLoad : public Cantilever
  {
  public:
    QuadraticLoad(unsigned int n, double c)
      : Cantilever(n)
      , c(c)
    {}
    const double c;

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      Cantilever::evaluate(U, l + c * l * l, R, H);
    }
  };

  /// Uncoupled modes of stiffness k_i = 1 + 0.4 i under one load:
  /// critical loads 1, 1.4, 1.8, ..., a cluster (the second less than
  /// twice the first).
  class Cluster : public DenseProblem
  {
  public:
    using DenseProblem::DenseProblem;

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      H = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          H(i, i) = 1 + 0.4 * i - l;
          R[i]    = H(i, i) * U[i];
        }
    }
  };

  /// MovingPrestress with the axial unknown u = lambda + c lambda^2: the
  /// lateral Hessian K - u h I is quadratic in the load only through the
  /// path's curvature d2u = 2c.
  class CurvedPrestress : public MovingPrestress
  {
  public:
    CurvedPrestress(unsigned int n, double c)
      : MovingPrestress(n)
      , c(c)
    {}
    const double c;

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      MovingPrestress::evaluate(U, l + c * l * l, R, H);
    }
  };

  /// Pairs of modes (k_i = 1 + 0.4 i) coupled at first order in the load
  /// (b t, indefinite) and softened at second order (-c t^2), like the
  /// twisted strip's: H_i(t) = [[k_i - c t^2, b t], [b t, k_i - c t^2]].
  /// The linear model's singular loads k_i / b cluster; the pair is
  /// singular where k_i - c t^2 = b t, t_i = (sqrt(b^2 + 4 c k_i) - b)/(2c).
  /// With e != 0 softened at fourth order too (-e t^4 on the diagonal),
  /// which the second-order model misses (the twisted strip's eigenvalue,
  /// ~ mu0 - a t^2 - b t^4, misses it so): t_i then by bisection.
  class TwistPairs : public DenseProblem
  {
  public:
    TwistPairs(unsigned int pairs, double b, double c, double e = 0)
      : DenseProblem(2 * pairs)
      , b(b)
      , c(c)
      , e(e)
    {}
    const double b, c, e;
    double
    critical(const unsigned int i) const
    {
      const double k = 1 + 0.4 * i;
      if (e == 0)
        return (std::sqrt(b * b + 4 * c * k) - b) / (2 * c);
      double lo = 0, hi = k / b;
      for (int it = 0; it < 200; ++it)
        {
          const double t = 0.5 * (lo + hi);
          (k - c * t * t - e * t * t * t * t - b * t > 0 ? lo : hi) = t;
        }
      return 0.5 * (lo + hi);
    }

  protected:
    void
    evaluate(const Vector<double> &U, double t, Vector<double> &R, FullMatrix<double> &H) override
    {
      H = 0;
      for (unsigned int i = 0; 2 * i < n; ++i)
        {
          const unsigned int p = 2 * i, q = p + 1;
          H(p, p) = H(q, q) = 1 + 0.4 * i - c * t * t - e * t * t * t * t;
          H(p, q) = H(q, p) = b * t;
          R[p]              = H(p, p) * U[p] + H(p, q) * U[q];
          R[q]              = H(q, p) * U[p] + H(q, q) * U[q];
        }
    }
  };

  void
  critical_estimate_second_order()
  {
    // The second-order estimate (solvers/critical_estimate.h) is exact
    // where the Hessian along the path is quadratic in the load: through
    // the load itself, through the path's curvature, and with the linear
    // model's loads a cluster; by differences of residuals and from
    // stored Jacobians. Its resolution: J2 by second differences over
    // h = 1e-2 (1 + |lambda0|) of products, round-off ~1e-16 |J|/h^2 with
    // stored Jacobians (~1e-12 relative here) and ~1e-16 |J| |x|/(eps h^2)
    // of the internal forces by residuals at these trivial states (~1e-10);
    // the Arnoldi run to 1e-10: tolerances 1e-6.
    const unsigned int                n        = 40;
    const double                      lambda_1 = chain_critical_load(n);
    solvers::CriticalEstimateSettings qep;
    qep.max_steps = 90;
    qep.tolerance = 1e-10;
    for (const bool stored : {false, true})
      {
        const std::string route = stored ? " (stored Jacobians)" : " (differences of residuals)";
        {
          const double   c = 0.5 / lambda_1, lambda0 = 0.3 * lambda_1;
          QuadraticLoad  p(n, c);
          Vector<double> U(n), dU(n), mask(n);
          mask                     = 1.;
          p.offer_stored_jacobians = stored;
          p.set_load_parameter(lambda0);
          p.setup_jacobian(U);
          const auto e = solvers::estimate_first_critical_point_second_order(p, U, lambda0, dU, mask, 1., qep);
          const double exact = (std::sqrt(1 + 4 * c * lambda_1) - 1) / (2 * c);
          std::cout << "  quadratic load" << route << ": lambda " << e.lambda << " (exact " << exact << "), "
                    << e.steps << " Arnoldi steps, " << e.residuals << " residuals, " << e.jacobians
                    << " Jacobians\n";
          check("quadratic load" + route + ": found, converged", e.found && e.converged);
          check_close("quadratic load" + route + ": the critical load", e.lambda, exact, 1e-6);
          check("quadratic load" + route + ": the route taken", stored ? e.jacobians == 3 : e.jacobians == 0);
        }
        {
          const double    c = 0.3 / lambda_1;
          CurvedPrestress p(n, c);
          Vector<double>  U(n + 1), dU(n + 1), mask(n + 1);
          mask                     = 1.;
          p.offer_stored_jacobians = stored;
          p.set_load_parameter(0.);
          p.setup_jacobian(U);
          dU[0]        = 1; // (du/dlambda at 0; the curvature 2c is the estimate's to find)
          const auto e = solvers::estimate_first_critical_point_second_order(p, U, 0., dU, mask, 1., qep);
          const double exact = (std::sqrt(1 + 4 * c * lambda_1) - 1) / (2 * c);
          std::cout << "  curved prestress" << route << ": lambda " << e.lambda << " (exact " << exact << ")\n";
          check("curved prestress" + route + ": found", e.found);
          check_close("curved prestress" + route + ": the critical load", e.lambda, exact, 1e-6);
          check_close("curved prestress" + route + ": the predicted state u = lambda + c lambda^2", e.U[0],
                      exact + c * exact * exact, 1e-6);
        }
        {
          TwistPairs     p(20, 5., 4.);
          Vector<double> U(40), dU(40), mask(40);
          mask                     = 1.;
          p.offer_stored_jacobians = stored;
          p.set_load_parameter(0.);
          p.setup_jacobian(U);
          const auto linear = solvers::estimate_first_critical_point(p, U, 0., dU, mask);
          const auto e = solvers::estimate_first_critical_point_second_order(p, U, 0., dU, mask, linear.lambda, qep);
          std::cout << "  twist pairs" << route << ": linear " << linear.lambda << ", next " << linear.next_lambda
                    << "; second order " << e.lambda << " (exact " << p.critical(0) << "), next " << e.next_lambda
                    << " (" << p.critical(1) << "), " << e.steps << " Arnoldi steps\n";
          check("twist pairs" + route + ": the linear estimates a cluster",
                linear.found && linear.next_lambda < 2 * linear.lambda);
          // (J' the forward difference over delta = 1e-4: [[-c delta, b], [b,
          // -c delta]], singular with J0 = I at 1/(b + c delta), not k_0/b)
          check_close("twist pairs" + route + ": the linear estimate 1/(b + c delta)", linear.lambda,
                      1. / (p.b + p.c * 1e-4), 1e-6);
          check_close("twist pairs" + route + ": the first critical load", e.lambda, p.critical(0), 1e-6);
          check_close("twist pairs" + route + ": the second", e.next_lambda, p.critical(1), 1e-6);
          // the mode: J(t_0) v = 0, against |J(0)| |v| = (1 + 0.4 * 19) |v|
          Vector<double> R(40), v = e.mode;
          p.set_load_parameter(e.lambda);
          p.residual(v, R);
          check("twist pairs" + route + ": the mode is the critical pair's (|J(t_0) v| <= 1e-6 |J| |v|)",
                R.l2_norm() <= 1e-6 * 8.6 * v.l2_norm());
        }
      }
    // The driver ('Stop at first event'): the linear estimates cluster, the
    // second-order one is taken, and the branch point is located from it at
    // t_0, to the location's tolerance, with no crossing below it.
    TwistPairs p(20, 5., 4.);
    p.offer_stored_jacobians = true;
    auto t                   = settings(0, 2);
    t.stop_at_first_event    = true;
    solvers::ArclengthContinuation run(t, newton());
    Vector<double>                 U(40);
    const auto                     located = run.run(p, U, 0.);
    std::cout << "  twist pairs, the driver: " << (located.empty() ? NAN : located[0].event.lambda) << " (exact "
              << p.critical(0) << "), " << p.setups << " factorizations in all, " << p.history.size()
              << " states\n";
    check("twist pairs, the driver: one branch point",
          located.size() == 1 && located[0].event.kind == solvers::BifurcationProblem::Event::Kind::branch_point);
    if (located.size() == 1)
      check_close("twist pairs, the driver: at t_0", located[0].event.lambda, p.critical(0), 0, 1e-10);
    check("twist pairs, the driver: from the estimate (no state followed beyond the start)", p.history.size() == 1);
  }

  /// MovingPrestress with the axial unknown u = g(lambda) = lambda + c
  /// lambda^2 + d lambda^3: the path's third-order term, which the
  /// second-order model misses. Critical where g(lambda) = lambda_1.
  class CubicPrestress : public MovingPrestress
  {
  public:
    CubicPrestress(unsigned int n, double c, double d)
      : MovingPrestress(n)
      , c(c)
      , d(d)
    {}
    const double c, d;
    /// the root of g(lambda) = target by Newton, to round-off
    double
    load_where(const double target) const
    {
      double l = 0;
      for (int k = 0; k < 60; ++k)
        l -= (l + c * l * l + d * l * l * l - target) / (1 + 2 * c * l + 3 * d * l * l);
      return l;
    }

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      MovingPrestress::evaluate(U, l + c * l * l + d * l * l * l, R, H);
    }
  };

  /// x^2 = 1 - lambda from x = 1 at lambda = 0: a fold ahead at lambda =
  /// 1, where J = 2x ~ sqrt(1 - lambda); no state beyond it.
  class FoldAhead : public DenseProblem
  {
  public:
    FoldAhead()
      : DenseProblem(2)
    {}

  protected:
    void
    evaluate(const Vector<double> &U, double l, Vector<double> &R, FullMatrix<double> &H) override
    {
      R[0]    = U[0] * U[0] - (1 - l);
      R[1]    = U[1];
      H(0, 0) = 2 * U[0];
      H(1, 1) = 1;
      H(0, 1) = H(1, 0) = 0;
    }
  };

  void
  critical_estimate_refined()
  {
    // The second-order estimate refined with the start's factorization
    // alone (solvers::refine_critical_estimate, 'Refine estimate'): where
    // the path (a cubic axial state) or the Hessian (a quartic softening)
    // goes beyond the second-order model, whose estimate is then 14-16 %
    // off, the refined one is the critical load. Its resolution: Newton on
    // mu stops at |mu| <= 1e-4 and takes one more step, off by about
    // (mu''/2mu') dt^2 ~ 1e-8 relative on these O(1) problems; tolerance
    // 1e-6. Without another factorization: setup_jacobian() is not called.
    const unsigned int                n        = 40;
    const double                      lambda_1 = chain_critical_load(n);
    solvers::CriticalEstimateSettings qep;
    qep.max_steps = 90;
    qep.tolerance = 1e-10;
    auto refine   = [&](solvers::BifurcationProblem &p, DenseProblem &dense, const Vector<double> &dU,
                      const double scale, const double exact, const std::string &what) {
      Vector<double> U(dU.size()), mask(dU.size());
      mask = 1.;
      p.set_load_parameter(0.);
      p.setup_jacobian(U);
      const unsigned int setups = dense.setups;
      const auto         e      = solvers::estimate_first_critical_point_second_order(p, U, 0., dU, mask, scale, qep);
      auto               r      = e;
      const auto         report = solvers::refine_critical_estimate(p, U, 0., dU, mask, r);
      std::cout << "  " << what << ": second order " << e.lambda << ", refined " << r.lambda << " (exact " << exact
                << "), " << report.evaluations << " states, " << report.solves << " solves\n";
      check(what + ": the second-order estimate at least 1 % off (else this tests nothing)",
            e.found && std::abs(e.lambda - exact) >= 1e-2 * exact);
      check(what + ": refined", report.refined);
      check_close(what + ": the refined estimate", r.lambda, exact, 1e-6);
      check(what + ": no other factorization", dense.setups == setups);
    };
    for (const bool stored : {false, true})
      {
        const std::string route = stored ? " (stored Jacobians)" : " (differences of residuals)";
        {
          CubicPrestress p(n, 0.3 / lambda_1, 0.5 / (lambda_1 * lambda_1));
          p.offer_stored_jacobians = stored;
          Vector<double> dU(n + 1);
          dU[0] = 1; // (du/dlambda at 0)
          refine(p, p, dU, 1., p.load_where(lambda_1), "cubic prestress" + route);
        }
        {
          TwistPairs p(20, 1., 4., 16.);
          p.offer_stored_jacobians = stored;
          Vector<double> dU(40);
          refine(p, p, dU, 0.4, p.critical(0), "quartic twist pairs" + route);
        }
      }
    {
      // Where it fails: the fold's second-order estimate (x = 1 - t/2 -
      // t^2/8 singular at t = 2 sqrt(3) - 2 = 1.46) lies past the fold,
      // where no state converges. The estimate and the load stay as they
      // were.
      FoldAhead      p;
      Vector<double> U(2), dU(2), mask(2), R(2);
      U[0]  = 1;
      dU[0] = -0.5;
      mask  = 1.;
      p.set_load_parameter(0.);
      p.setup_jacobian(U);
      const auto e      = solvers::estimate_first_critical_point_second_order(p, U, 0., dU, mask, 1., qep);
      auto       r      = e;
      const auto report = solvers::refine_critical_estimate(p, U, 0., dU, mask, r);
      p.residual(U, R); // (at the problem's load: R_0 = 0 at lambda0 = 0 only)
      std::cout << "  fold ahead: second order " << e.lambda << " (exact 2 sqrt(3) - 2 = " << 2 * std::sqrt(3.) - 2
                << "), refinement: " << report.message << "\n";
      // (d2U by second differences over h = 1e-2 of a path that is not
      // polynomial: truncation O(h^2) = 1e-4; measured 2e-7)
      check_close("fold ahead: the second-order estimate", e.lambda, 2 * std::sqrt(3.) - 2, 1e-4);
      check("fold ahead: not refined", e.found && !report.refined && !report.message.empty());
      check("fold ahead: the estimate as it was",
            r.lambda == e.lambda && r.U == e.U && r.mode == e.mode && r.tangent == e.tangent);
      check("fold ahead: the load back at lambda0", R[0] == 0.);
    }
  }

  void
  critical_estimate()
  {
    // The first critical load ahead from one eigenproblem
    // (solvers/critical_estimate.h). Its resolution: J' by differences of
    // residuals, round-off ~1e-16 |R|/(eps delta |J' v|), ~1e-8 relative
    // on these chains (eps = 1e-6, delta = 1e-4, h^2 = 6e-4): tolerances
    // 1e-6, a hundred times that.
    const unsigned int n        = 40;
    const double       h        = 1. / n;
    const double       lambda_1 = chain_critical_load(n);
    const double       lambda_2 = chain_critical_load(n, 2);
    {
      // The trivial state of the cantilever: J = K - lambda h I, exact.
      Cantilever     p(n);
      Vector<double> U(n), dU(n), mask(n);
      mask = 1.;
      p.set_load_parameter(0.);
      p.setup_jacobian(U);
      const auto e = solvers::estimate_first_critical_point(p, U, 0., dU, mask);
      std::cout << "  cantilever: lambda " << e.lambda << " (exact " << lambda_1 << "), next " << e.next_lambda
                << " (" << lambda_2 << "), " << e.steps << " Lanczos steps, " << e.residuals << " residuals, "
                << e.solves << " solves\n";
      check("cantilever: found and converged", e.found && e.converged);
      check_close("cantilever: the first critical load", e.lambda, lambda_1, 1e-6);
      check_close("cantilever: the second", e.next_lambda, lambda_2, 1e-6);
      // The mode: K v = lambda_1 h v, its residual against |K v|.
      Vector<double>     R(n);
      FullMatrix<double> H(n, n);
      p.set_load_parameter(lambda_1);
      Vector<double> zero(n), Kv(n);
      p.residual(zero, R);
      Vector<double> v = e.mode;
      v *= 1e-8; // (the residual is linear in so small a v: sin(x) = x to 1e-17)
      p.residual(v, Kv);
      check("cantilever: the mode is the critical mode (|J(lambda_1) v| / |v|/h^2 below 1e-6)",
            Kv.l2_norm() <= 1e-6 * v.l2_norm() / (h * h));
      check("cantilever: the predicted state U0 + tau dU is the trivial one", e.U.linfty_norm() == 0);
    }
    {
      // The compression carried by a state that moves with the load: the
      // estimate is exact along the tangent (du = 1), and finds nothing
      // with a tangent that misses the motion.
      MovingPrestress p(n);
      Vector<double>  U(n + 1), dU(n + 1), mask(n + 1);
      mask = 1.;
      p.set_load_parameter(0.);
      p.setup_jacobian(U);
      const auto none = solvers::estimate_first_critical_point(p, U, 0., dU, mask);
      check("moving prestress, the tangent without the motion: no critical point ahead", !none.found);
      dU[0]        = 1;
      const auto e = solvers::estimate_first_critical_point(p, U, 0., dU, mask);
      std::cout << "  moving prestress: lambda " << e.lambda << " (exact " << lambda_1 << "), " << e.steps
                << " Lanczos steps\n";
      check("moving prestress: found", e.found && e.converged);
      check_close("moving prestress: the first critical load", e.lambda, lambda_1, 1e-6);
      check_close("moving prestress: the predicted state u = lambda", e.U[0], e.lambda, 1e-14);
    }
    {
      // A load entering nonlinearly, g = lambda + c lambda^2: from lambda0
      // the estimate is the linear prediction, one Newton step on
      // g(lambda) = lambda_1 with g' the difference over the load step
      // delta = 1e-4 (1 + lambda0): exactly that, not the critical load.
      const double   c = 0.5 / lambda_1, lambda0 = 0.3 * lambda_1, delta = 1e-4 * (1 + lambda0);
      QuadraticLoad  p(n, c);
      Vector<double> U(n), dU(n), mask(n);
      mask = 1.;
      p.set_load_parameter(lambda0);
      p.setup_jacobian(U);
      const auto e     = solvers::estimate_first_critical_point(p, U, lambda0, dU, mask);
      auto       g     = [c](const double l) { return l + c * l * l; };
      const double newton = lambda0 + (lambda_1 - g(lambda0)) * delta / (g(lambda0 + delta) - g(lambda0));
      std::cout << "  quadratic load: lambda " << e.lambda << ", the linear prediction " << newton
                << ", the critical load " << (std::sqrt(1 + 4 * c * lambda_1) - 1) / (2 * c) << "\n";
      check_close("quadratic load: the linear prediction", e.lambda, newton, 1e-6);
    }
    {
      // A cluster: the Lanczos run asked to stop once the second critical
      // load is certain to lie less than twice as far (cluster_factor 2)
      // stops before the full run, and both tell the same: a second load
      // less than twice as far (the full run's 1.4, to 1e-6).
      Cluster        p(n);
      Vector<double> U(n), dU(n), mask(n);
      mask = 1.;
      p.set_load_parameter(0.);
      p.setup_jacobian(U);
      const auto                        full = solvers::estimate_first_critical_point(p, U, 0., dU, mask);
      solvers::CriticalEstimateSettings early_settings;
      early_settings.cluster_factor = 2;
      const auto early              = solvers::estimate_first_critical_point(p, U, 0., dU, mask, early_settings);
      std::cout << "  cluster: full run " << full.lambda << ", next " << full.next_lambda << " (" << full.steps
                << " steps); stopped early " << early.lambda << ", next " << early.next_lambda << " ("
                << early.steps << " steps)\n";
      check_close("cluster, full run: the first critical load", full.lambda, 1, 1e-6);
      check_close("cluster, full run: the second", full.next_lambda, 1.4, 1e-6);
      check("cluster: stopped early, in fewer steps", early.cluster && early.steps < full.steps);
      check("cluster: both runs find the second load less than twice as far",
            full.next_lambda < 2 * full.lambda && early.next_lambda < 2 * early.lambda);
    }
  }

} // namespace

  /**
   * The solver's banded Cholesky (an open rod's Hessian: 7 unknowns a node,
   * coupled to the neighbours, half-bandwidth 13) against MUMPS's LDL^T
   * (COSMO_BANDED_CHOLESKY=0) and LAPACK's eigenvalues: K - sigma I, K a
   * block-tridiagonal SPD matrix; sigma below its spectrum (positive
   * definite: the banded path, no negative eigenvalue) and inside it (the
   * Cholesky fails, MUMPS counts them). The solutions of the two
   * factorizations differ by round-off: eps times the condition number.
   */
  void
  banded_cholesky()
  {
    constexpr unsigned int per_node = 7, nodes = 150, n = per_node * nodes;
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int k = 0; k < nodes; ++k)
      for (unsigned int a = 0; a < 2 * per_node && per_node * k + a < n; ++a)
        for (unsigned int b = 0; b < 2 * per_node && per_node * k + b < n; ++b)
          dsp.add(per_node * k + a, per_node * k + b);
    SparsityPattern sp;
    sp.copy_from(dsp);
    for (const double sigma : {-0.05, 0.3})
      {
        SparseMatrix<double> A(sp);
        FullMatrix<double>   dense(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (auto it = sp.begin(i); it != sp.end(i); ++it)
            {
              const unsigned int j = it->column();
              const bool same_node = i / per_node == j / per_node, same_slot = i % per_node == j % per_node;
              // a chain of springs per slot (eigenvalues in [0, 4] times the slot's
              // weight) plus a small symmetric coupling within each node
              double v = same_node ? (i == j ? 2. : 0.001 * std::sin(1. + i + j)) : (same_slot ? -1. : 0.);
              v *= 1 + 0.1 * (i % per_node) * (j % per_node == i % per_node);
              if (i == j)
                v += 0.02 - sigma;
              A.set(i, j, v);
              dense(i, j) = v;
            }
        Vector<double> b(n);
        for (unsigned int i = 0; i < n; ++i)
          b[i] = std::cos(0.3 * i);
        std::vector<Vector<double>> x;
        std::vector<int>            negative;
        for (const char *banded : {"1", "0"})
          {
            setenv("COSMO_BANDED_CHOLESKY", banded, 1);
            solvers::SparseDirectSolver solver;
            solver.factorize(A);
            std::vector<Vector<double>> y = {b, b};
            y[1] *= 2.;
            solver.solve(y); // several right-hand sides
            Vector<double> z = b;
            solver.solve(z); // one
            y[1] *= 0.5;
            y[1] -= z;
            check("banded: one right-hand side as several", y[1].linfty_norm() <= 1e-14 * z.linfty_norm());
            x.push_back(z);
            negative.push_back(solver.n_negative_eigenvalues());
          }
        unsetenv("COSMO_BANDED_CHOLESKY");
        const auto [lapack_negative, smallest, largest] = dense_spectrum(dense);
        Vector<double> d = x[0];
        d -= x[1];
        std::cout << "sigma = " << sigma << ": negative eigenvalues banded path " << negative[0] << ", MUMPS "
                  << negative[1] << ", LAPACK " << lapack_negative << "; solutions differ by "
                  << d.linfty_norm() / x[1].linfty_norm() << " (condition " << largest / smallest << ")\n";
        check("banded: the inertia", negative[0] == lapack_negative && negative[1] == lapack_negative);
        check("banded: the solution of MUMPS's",
              d.linfty_norm() <= 1e2 * 2.2e-16 * largest / smallest * x[1].linfty_norm());
      }
  }

int
main(int argc, char **argv)
{
  const auto mpi = cosmo::io::ranks::init_mpi(argc, argv, 1);
  const cosmo_test::Cases cases = {{"banded_cholesky", banded_cholesky}, {"pitchfork", pitchfork}, {"fold", fold}, {"cantilever", cantilever},
                                   {"secondary_bifurcation", secondary_bifurcation},
                                   {"bordered_ordering", bordered_ordering},
                                   {"dq_point", dq_point}, {"newton_exact_jp", newton_exact_jp},
                                   {"newton_guess", newton_guess}, {"newton_chord", newton_chord},
                                   {"predictor_step", predictor_step},
                                   {"critical_estimate", critical_estimate}, {"arclength_chord", arclength_chord},
                                   {"critical_estimate_second_order", critical_estimate_second_order},
                                   {"critical_estimate_refined", critical_estimate_refined}};
  return cosmo_test::run_case("test_continuation", "", cases, argc, argv, 2, 2);
}
