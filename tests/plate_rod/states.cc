// test_plate_rod: the plate's states and derivatives: the flat (Lame) state, the natural-curvature cap, the tangent against differences, the in-plane problem, a stiffness file, a thick plate.
#include "common.h"

using namespace plate_rod_test;

namespace
{

  // Anchor 1: the flat pre-buckled (Lame) state, plate compliance in series
  // with the rim's hoop compliance.
  void
  lame_state()
  {
    for (const std::string model : {"kirchhoff", "cosserat", "von karman"})
      for (const double EA : {1e-3, 1e-2, 1.})
        {
          Setup s;
          s.model        = model;
          s.EA           = EA;
          s.plate_growth = 1 + 2e-5;
          s.rod_growth   = 1 - 1e-5;
          s.refinements  = 2;
          auto p         = make(s);
          p->solve_flat_state(1.);
          const auto &problem = p->get_problem();
          const auto  st = plate_rod::analyse(problem.get_discretization(), problem.current_solution(), 1.);
          // Small strain: growth strains 2e-5 and -1e-5.
          const auto   ref = analysis::prebuckled_state(s.closed_form(), 2e-5, -1e-5);
          std::ostringstream what;
          what << model << ", EA/(E h R) = " << EA / (E * s.h * R) << ": radial strain";
          check_close(what.str(), st.rim_radial_strain, ref.radial_strain, 2e-4);
          check_close(model + ": stays flat (w range / R)", st.max_abs_w, 0, 0, 1e-14);
          check_close(model + ": stays circular (rim u_r, n >= 1)",
                      *std::max_element(st.rim_ur_amplitude.begin() + 1, st.rim_ur_amplitude.end()),
                      0, 0, 1e-12);
        }
  }

  // Growth through the thickness, linear limit. A free plate (rim
  // stiffnesses 1e-12) with the isotropic natural curvature c I takes it
  // without moments, w = c r^2/2, whatever its thickness profile (M = D(r)
  // (k - c I) = 0 is in equilibrium and free at the edge). Dome height
  // |w(R) - w(0)| = c R^2/2 for c = 1e-4, h/R = 0.01, to 1e-3: the
  // membrane coupling is of relative order (c R^2/h)^2 = 1e-4 and Q2 on the
  // curved mesh interpolates r^2 to ~1e-5 (2 refinements).
  /// |dome height| at t = 1 of a state linear in t: along the path in steps of 0.25 (the
  /// moments are ~D c = 1e-11, below what KINSOL's scaled stopping test on a Newton solve
  /// from zero resolves), interpolated linearly to t = 1 (linear to O(c R^2/h)^2).
  double
  dome_height_at_t1(Setup s)
  {
    s.t_max        = 1.2;
    s.initial_step = 0.25;
    s.maximum_step = 0.25;
    auto p         = make(s);
    first_event(*p);
    const auto &path = p->get_problem().path();
    for (unsigned int i = 1; i < path.size(); ++i)
      if (path[i - 1].t < 1 && path[i].t >= 1)
        {
          const double f = (1 - path[i - 1].t) / (path[i].t - path[i - 1].t);
          return std::abs((1 - f) * path[i - 1].w_centre + f * path[i].w_centre);
        }
    return NAN;
  }

  void
  natural_curvature_cap()
  {
    const double c = 1e-4;
    for (const std::string model : {"cosserat", "kirchhoff", "von karman"})
      for (const std::string profile : {"1", "1 - 0.5*r^2"})
        {
          Setup s;
          s.model        = model;
          s.refinements  = 2;
          s.sector_angle = 90;
          s.EA = s.GA = s.EI1 = s.EI2 = s.GJ = 1e-12;
          std::ostringstream extra;
          extra << std::setprecision(17) << "subsection Plate growth\n set Natural curvature = " << c
                << "; " << c << "; 0\nend\nsubsection Plate\n set Thickness profile = " << profile
                << "\nend\n";
          s.extra = extra.str();
          check_close(model + ", thickness profile " + profile + ": dome height = c R^2/2",
                      dome_height_at_t1(s), c * R * R / 2, 1e-3);
        }
    // The rim's natural curvature dk1 about e_r: the rim wants to roll its
    // sections by R dk1; welded to the plate, whose edge slope that is, the
    // pair bends spherically. With kappa the plate's curvature, the energy
    // pi R^2 D (1 + v) kappa^2 + pi R EI1 (kappa - dk1)^2 is least at
    // kappa = rho dk1/(rho + 1 + v), rho = EI1/(R D): dome height kappa R^2/2.
    // Same tolerance (linear limit, a constant curvature).
    for (const std::string model : {"cosserat", "kirchhoff", "von karman"})
      for (const double rho : {0.1, 10.})
        {
          Setup s;
          s.model        = model;
          s.refinements  = 2;
          s.sector_angle = 90;
          s.EA = s.GA = 0.1;
          s.EI1          = rho * R * plate_D(s.h);
          s.EI2 = s.GJ   = 1e-6;
          std::ostringstream extra;
          extra << std::setprecision(17) << "subsection Rim rod\n set Natural curvature = " << c
                << ", 0, 0\nend\n";
          s.extra            = extra.str();
          const double kappa = rho * c / (rho + 1 + poisson);
          check_close(model + ", rim natural curvature, rho = " + std::to_string(rho) +
                        ": dome height = rho/(rho + 1 + v) dk1 R^2/2",
                      dome_height_at_t1(s), kappa * R * R / 2, 1e-3);
        }
  }

  // The AD Hessian against central differences of the AD residual, and its
  // symmetry, for the three models at a general state (polar plate growth,
  // natural curvature of plate and rim, variable thickness, rim growth,
  // finite rotations).
  void
  tangent_fd()
  {
    for (const std::string model : {"cosserat", "kirchhoff", "von karman"})
      {
        Setup s;
        s.model       = model;
        s.domain      = "full disc";
        s.refinements = 1;
        s.rod_growth  = 0.97;
        s.extra = "subsection Plate growth\n set Kind = polar\n set Radial growth factor = 1.05\n"
                  " set Circumferential growth factor = 1 + 0.1*r^2\n"
                  " set Natural curvature = 0.3*x; 0.1 - 0.2*y; 0.05*r\nend\n"
                  "subsection Plate\n set Thickness profile = 1 - 0.5*r^2 + 0.1*x\nend\n"
                  "subsection Rim rod\n set Natural curvature = 0.2, -0.1, 0.3\nend\n";
        auto  run     = make(s);
        auto &problem = run->get_problem();
        problem.set_load_parameter(1.);
        const unsigned int n = problem.n_unknowns();
        std::mt19937       gen(42);
        std::uniform_real_distribution<double> d(-1, 1);
        Vector<double> U(n), V(n);
        for (unsigned int i = 0; i < n; ++i)
          U[i] = 0.05 * d(gen), V[i] = d(gen);
        problem.get_discretization().constraints.distribute(U);
        problem.get_discretization().constraints.distribute(V);
        problem.setup_jacobian(U);
        Vector<double> JV(n), Rp(n), Rm(n), Up = U, Um = U;
        problem.system_matrix().vmult(JV, V);
        const double eps = 1e-6;
        Up.add(eps, V);
        Um.add(-eps, V);
        problem.residual(Up, Rp);
        problem.residual(Um, Rm);
        double err = 0, scale = 0;
        for (unsigned int i = 0; i < n; ++i)
          if (!problem.get_discretization().constraints.is_constrained(i))
            {
              err   = std::max(err, std::abs(JV[i] - (Rp[i] - Rm[i]) / (2 * eps)));
              scale = std::max(scale, std::abs(JV[i]));
            }
        check_close(model + ": |J v - FD| / |J v|", err / scale, 0, 0, 1e-7);
        // The residual is the gradient of the energy: R(U).v against the
        // central difference of E along v (the constraints homogeneous, v
        // distributed). Central difference with eps = 1e-6: truncation
        // ~eps^2 |E'''| and round-off ~1e-16 |E| / eps ~ 1e-10 of |R.v|
        // (measured: 4e-11 to 1.4e-10); tolerance 1e-8.
        {
          Vector<double> R0(n);
          problem.residual(U, R0);
          const double Rv = R0 * V;
          const double dE = (problem.energy(Up) - problem.energy(Um)) / (2 * eps);
          std::cout << std::setprecision(12) << "  " << model << ": R.v " << Rv << ", dE/d(eps) "
                    << dE << "\n";
          check_close(model + ": R.v = dE along v (central difference)", dE, Rv, 1e-8, 0);
        }
        // The residual a Jacobian assembly keeps (solvers::ResidualCache) against a
        // residual-only assembly at the same state: second- against first-order AD and
        // another order of the sums, so equal to round-off, a few eps of R's terms (here,
        // at a state with every field of order 1, of max |R|; measured: 0, bitwise, for the
        // three models on the full disc); tolerance 1e-12.
        {
          Vector<double> R_residual(n), R_jacobian(n);
          problem.residual(U, R_residual); // (assembled above, without a Jacobian)
          problem.setup_jacobian(U);
          problem.residual(U, R_jacobian); // kept from the Jacobian assembly
          double d = 0, m = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              d = std::max(d, std::abs(R_residual[i] - R_jacobian[i]));
              m = std::max(m, std::abs(R_residual[i]));
            }
          std::cout << "  " << model << ": residual of the Jacobian assembly against the residual's: "
                    << d / m << " of max |R|\n";
          check_close(model + ": residual kept from the Jacobian assembly", d / m, 0, 0, 1e-12);
        }
        double asym = 0, big = 0;
        const auto &J = problem.system_matrix();
        for (unsigned int i = 0; i < n; ++i)
          for (auto it = J.begin(i); it != J.end(i); ++it)
            {
              asym = std::max(asym, std::abs(it->value() - J.el(it->column(), i)));
              big  = std::max(big, std::abs(it->value()));
            }
        check_close(model + ": Hessian symmetric", asym / big, 0, 0, 1e-12);
      }
  }

  // 'Model / Deformation = in-plane only' (u3 = theta = 0): planar lobing by
  // itself. On the sector pi/16 (n = 16, 32, ...) with EA = 1 and all bending
  // and torsion stiffnesses 1e-6, the out-of-plane n = 16 mode comes first in
  // 3D (closed form Delta = -0.0196) and the planar n = 16 mode later (-0.0477).
  // (a) In-plane only, the first critical point is the planar n = 16 mode, near
  // its small-strain closed form. (b) At the flat state the in-plane and the
  // out-of-plane problems decouple (reflection through the plate's plane), so
  // the full model, followed along its flat branch past the out-of-plane
  // points, has a planar critical point at the same load to the resolution of
  // the two locations.
  void
  in_plane_only()
  {
    Setup s;
    s.EA = s.GA = 1, s.EI1 = s.GJ = s.EI2 = 1e-6;
    s.sector_angle = 180. / 16;
    s.refinements  = 2;
    const double planar   = analysis::planar_critical_mismatch(s.closed_form(), 16);
    const double out      = analysis::out_of_plane_critical_mismatch(s.closed_form(), 16);
    s.rod_growth          = 1 + 2 * (1 / (1 + planar) - 1); // Delta = planar at t = 1/2
    s.t_max               = 0.6;
    s.initial_step        = 0.02;
    s.maximum_step        = 0.05;
    s.steps               = 80;
    std::cout << "  closed forms: planar n = 16 at Delta = " << planar << ", out of plane n = 16 at "
              << out << "\n";
    check("out of plane first in 3D (closed forms)", out > planar);

    Setup in_plane = s;
    in_plane.extra = stop_at_first_event + "subsection Model\n set Deformation = in-plane only\nend\n";
    auto       p = make(in_plane);
    const auto e = first_event(*p);
    check("in-plane only: a critical point", !p->event_records().empty());
    if (p->event_records().empty())
      return;
    Vector<double> mode(p->event_records().front().mode.begin(), p->event_records().front().mode.end());
    const auto     c = classify(*p, mode);
    check("in-plane only: the first mode is planar with n = 16", c.first == 16 && !c.second);
    std::cout << "  in-plane only (" << p->n_unknowns() << " DoFs): Delta = " << e.second
              << ", closed form " << planar << " (relative " << e.second / planar - 1 << ")\n";
    // The closed form linearizes the prestress: O(|Delta|) relative (planar_lobes measures
    // 5.9 % at this |Delta| = 0.048 on this mesh); 2 |Delta| relative.
    check_close("in-plane only: planar n = 16 near the closed form", e.second, planar, 0,
                2 * std::abs(planar) * std::abs(planar));

    Setup full = s;
    auto  q    = make(full);
    q->solve_flat_state(0.);
    q->follow_branches();
    const solvers::EventRecord *twin = nullptr;
    for (const auto &x : q->event_records())
      if (!x.mode.empty())
        {
          Vector<double> m(x.mode.begin(), x.mode.end());
          const auto     k = classify(*q, m);
          std::cout << "  full model: " << x.event.name() << " at t = " << x.event.lambda << ", n = "
                    << k.first << (k.second ? " out of plane" : " planar") << "\n";
          if (!k.second && !twin)
            twin = &x;
        }
    check("full model: the out-of-plane n = 16 point before any planar point",
          !q->event_records().empty() && q->event_records().front().event.lambda < p->event_records().front().event.lambda);
    check("full model: a planar critical point on the flat branch", twin != nullptr);
    if (twin)
      {
        const double resolution = solvers::event_resolution(twin->event) +
                                  solvers::event_resolution(p->event_records().front().event);
        std::cout << "  planar point: full " << twin->event.lambda << ", in-plane only "
                  << p->event_records().front().event.lambda << ", difference "
                  << twin->event.lambda - p->event_records().front().event.lambda
                  << " (resolutions summed " << resolution << ")\n";
        check_close("the same planar critical load in both models", twin->event.lambda,
                    p->event_records().front().event.lambda, 0, 2 * resolution);
      }
  }

  // The rim's stiffness read from a part-1 summary.json: its full 6x6, the
  // couplings included (the closed forms take the diagonal).
  void
  stiffness_file()
  {
    {
      std::ofstream f("rim_summary.json");
      f << "{\n  \"stiffness\": [\n"
        << "    [0.1, 0, 0, 0, 0, 1e-9],\n    [0, 0.2, 0, 0, 0, 0],\n    [0, 0, 0.3, 1e-7, 0, 0],\n"
        << "    [0, 0, 1e-7, 4e-6, 0, 0],\n    [0, 0, 0, 0, 5e-6, 0],\n    [1e-9, 0, 0, 0, 0, 6e-6]\n"
        << "  ],\n  \"stiffness_order\": \"nu1, nu2, nu3, kappa1, kappa2, kappa3\"\n}\n";
    }
    Setup s;
    s.refinements = 1;
    s.extra       = "subsection Rim rod\n set Stiffness file = rim_summary.json\nend\n";
    const auto run     = make(s);
    const auto p       = run->get_problem().closed_form_setting();
    const auto K       = run->get_problem().rod_law().natural_stiffness();
    // Exact copies (the file's symmetric part of a symmetric matrix).
    check_close("coupling K(nu3, kappa1) from the file", K[6 * 2 + 3], 1e-7, 0, 0);
    check_close("coupling K(kappa1, nu3) from the file", K[6 * 3 + 2], 1e-7, 0, 0);
    check_close("no coupling where the file has none", K[6 * 1 + 4], 0, 0, 0);
    // The shear rows carry the model's shear factor f as weights sqrt(f) on
    // the shear strains: GA1 = f 0.1, its couplings sqrt(f) times the file's.
    for (const std::string model : {"cosserat", "kirchhoff"})
      {
        Setup sm = s;
        sm.model = model;
        const auto pm    = make(sm);
        const auto Km    = pm->get_problem().rod_law().natural_stiffness();
        const auto frame = kinematics::circular_rim_frame(Point<2>(1, 0), Tensor<1, 2>({1., 0.}));
        const auto ring  = pm->get_problem().rim_natural_state(Point<2>(1, 0), frame, 0.);
        const double GA1 = ring.weights[0] * ring.weights[0] * Km[0];
        const double K05 = ring.weights[0] * ring.weights[5] * Km[5];
        std::cout << "  " << model << ": effective GA1 " << GA1 << ", K(nu1, kappa3) " << K05 << "\n";
        check_close(model + ": K(nu1, kappa3) = sqrt(f) x the file's", K05, 1e-9 * std::sqrt(GA1 / 0.1), 1e-14);
        // cosserat: no penalty (f = 1); kirchhoff: a shear penalty f > 1.
        if (model == "cosserat")
          check_close("cosserat: f = 1", GA1 / 0.1, 1, 1e-14);
        else
          check("kirchhoff: f > 1 (the shear penalty)", GA1 / 0.1 > 1);
      }
    check_close("EA from the file", p.rod_EA, 0.3, 0, 0);
    check_close("EI1 from the file", p.rod_EI1, 4e-6, 0, 0);
    check_close("EI2 from the file", p.rod_EI2, 5e-6, 0, 0);
    check_close("GJ from the file", p.rod_GJ, 6e-6, 0, 0);
  }

  // A moderately thick plate (h/R = 0.05) on a fine quarter disc (h_K ~ 3 h):
  // with reduced integration of the shear, Q2 has a spurious transverse mode
  // that the membrane compression destabilized at t = 0.0917 instead of
  // 0.121 (measured); the assumed-strain shear (default) has none, and the
  // Cosserat threshold sits below Kirchhoff's (penalty p = 100) by Mindlin's
  // -(1 - 1/p) r/(1 + r): within 2 % (first order in r = 3e-3, and the
  // O(Delta) = 1e-3 of the prestress on both models alike; measured 0.3 %).
  void
  thick_plate()
  {
    Setup s;
    s.h            = 0.05;
    s.EI1          = 1e-6;
    s.EA = s.GA    = 0.1;
    s.sector_angle = 90;
    s.refinements  = 3;
    s.plate_growth = 1.01;
    s.t_max        = 0.3;
    s.initial_step = 0.05;
    const auto m = cosserat_and_kirchhoff(s);
    check_close("Kirchhoff threshold against the closed form (O(Delta) = 1e-3 apart)", m.D_kirchhoff,
                analysis::axisymmetric_critical_mismatch(s.closed_form()), 3e-3);
    check_close("Cosserat/Kirchhoff - 1 = -(1 - 1/p) r/(1 + r)", m.D_cosserat / m.D_kirchhoff - 1,
                m.mindlin * (1 - 1. / 100), 0.02);
    const auto &c = m.cosserat;
    if (!c->event_records().empty())
      {
        Vector<double> mode(c->event_records().front().mode.begin(), c->event_records().front().mode.end());
        const auto     m = classify(*c, mode);
        check("Cosserat: the axisymmetric mode", m.first == 0 && m.second);
      }
  }
} // namespace

void
plate_rod_test::add_states_cases(cosmo_test::Cases &cases)
{
  cases["lame_state"] = lame_state;
  cases["natural_curvature_cap"] = natural_curvature_cap;
  cases["tangent_fd"] = tangent_fd;
  cases["in_plane_only"] = in_plane_only;
  cases["stiffness_file"] = stiffness_file;
  cases["thick_plate"] = thick_plate;
}
