// What the rod shows of a state: steps.csv's row, the VTU of its
// centreline with directors, strains and resultants, the located events.
#include <deal.II/base/utilities.h>

#include <cosmo/io/vtu_patches.h>
#include <cosmo/kinematics/framed_curve.h>
#include <cosmo/kinematics/helix.h>

#include "rod_problem.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <cmath>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      const std::array<const char *, 6> strain_names{{"nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"}};
    } // namespace

    RodState
    RodProblem::describe(const Vector<double> &U, const double t)
    {
      RodState s;
      s.t = t;
      // A converged state's residual was assembled by the driver's last
      // check: its energy and the supports' loads are kept with it.
      const auto *cached = residuals.find(U, t);
      if (cached == nullptr)
        {
          Vector<double> R;
          AssertThrow(assemble(U, t, &R, false) == 0, ExcMessage("a converged state that cannot be evaluated"));
          cached = residuals.find(U, t);
        }
      s.energy = cached->scalars[0];
      for (unsigned int k = 0; k < 2; ++k)
        std::copy(cached->scalars.begin() + 1 + 6 * k, cached->scalars.begin() + 7 + 6 * k, s.end_loads[k].begin());
      const Vector<double> X = configuration(U, t);
      s.end_position         = position(X, ring ? n_nodes() / 2 : n_nodes() - 1);
      for (unsigned int e = 0; e < n_elements; ++e)
        {
          const auto strain = element_strains(X, e, t);
          s.max_rotation    = std::max(s.max_rotation, element_length() *
                                                      std::sqrt(strain[3] * strain[3] + strain[4] * strain[4] +
                                                                strain[5] * strain[5]));
        }
      if (ring && topology)
        {
          std::vector<Tensor<1, 3>> x, m;
          const Tensor<1, 3>        closure = ribbon(X, t, x, m);
          // The frame is continuous across the seam up to its turn by
          // 2 pi Tw0: the link is Tw0 (plus the reference's, 0 for the
          // circle), the topology's; twist and writhe are measured.
          s.twist  = kinematics::twist(x, m, closure);
          s.writhe = kinematics::writhe(x);
          s.link   = evaluate(seam_twist, 0, t)[0];
        }
      else if (reports_link())
        clamped_link(X, t, s);
      if (contact)
        {
          const auto x    = node_positions(X);
          s.contact_gap   = contact->smallest_gap(x);
          for (const auto &term : contact->terms(x))
            {
              ++s.contact_pairs;
              s.contact_force += term.gradient_i.norm();
            }
        }
      return s;
    }

    Tensor<1, 3>
    RodProblem::ribbon(const Vector<double> &X, const double t, std::vector<Tensor<1, 3>> &x,
                       std::vector<Tensor<1, 3>> &m) const
    {
      auto normal = [](const Tensor<1, 3> &d, const Tensor<1, 3> &tangent) {
        Tensor<1, 3> n = d - (d * tangent) * tangent;
        return Tensor<1, 3>(n / n.norm());
      };
      Tensor<1, 3> closure;
      x.resize(n_nodes());
      m.resize(n_elements);
      for (unsigned int k = 0; k < n_nodes(); ++k)
        x[k] = position(X, k);
      for (unsigned int e = 0; e < n_elements; ++e)
        {
          const kinematics::RodStrains xi(element_strains(X, e, t));
          const Tensor<2, 3> R = kinematics::quaternion_rotation(quaternion(X, e)) *
                                 kinematics::helix_rotation(xi.kappa, 0.5 * element_length());
          Tensor<1, 3> t_e = x[(e + 1) % n_nodes()] - x[e], d1;
          t_e /= t_e.norm();
          for (unsigned int i = 0; i < 3; ++i)
            d1[i] = R[i][0];
          m[e] = normal(d1, t_e);
          if (e == 0)
            {
              // The last element's frame continues into node 0's turned by
              // the seam's 2 pi Tw0: m_0 turned by that angle about the
              // segment (not about d3, which shear tilts from it: so that
              // Tw + Wr = Tw0 holds for the polygon, theory-rod.md 8).
              const double a = 2 * M_PI * evaluate(seam_twist, 0, t)[0];
              closure        = std::cos(a) * m[e] + std::sin(a) * cross_product_3d(t_e, m[e]);
            }
        }
      return closure;
    }

    void
    RodProblem::clamped_link(const Vector<double> &X, const double t, RodState &s) const
    {
      // The clamps' frames continue the rod as segments along the line
      // joining them; the writhe is that of the rod closed by a planar
      // rectangle far from it, out along that line from both ends. The
      // closure's frame, transported round it, comes back unturned, so Tw +
      // Wr is the turns the clamps impose, conserved unless the rod passes
      // through itself (theory-rod.md 8.1).
      std::vector<Tensor<1, 3>> x, m;
      ribbon(X, t, x, m);
      const unsigned int N    = n_elements;
      Tensor<1, 3>       axis = x[N] - x[0];
      if (!(axis.norm() > 0))
        return;
      axis /= axis.norm();
      std::array<Tensor<1, 3>, 2> d1;
      for (const unsigned int end : {0u, 1u})
        {
          const Tensor<2, 3> R = kinematics::quaternion_rotation(quaternion(X, end * N));
          Tensor<1, 3>       d3;
          for (unsigned int i = 0; i < 3; ++i)
            {
              d1[end][i] = R[i][0];
              d3[i]      = R[i][2];
            }
          if (d3 * axis < 1 - 1e-9)
            return; // (an end not along the line of the clamps: no closure)
          d1[end] -= (d1[end] * axis) * axis;
          d1[end] /= d1[end].norm();
        }
      std::vector<Tensor<1, 3>> tangents{axis}, normals{d1[0]};
      for (unsigned int e = 0; e < N; ++e)
        {
          tangents.push_back((x[e + 1] - x[e]) / (x[e + 1] - x[e]).norm());
          normals.push_back(m[e]);
        }
      tangents.push_back(axis);
      normals.push_back(d1[1]);
      s.twist = kinematics::open_twist(tangents, normals);
      // Any normal to the axis for the rectangle's plane; far enough that
      // the rod, within L of its ends, cannot cross it.
      unsigned int k = 0;
      for (unsigned int i = 1; i < 3; ++i)
        if (std::abs(axis[i]) < std::abs(axis[k]))
          k = i;
      Tensor<1, 3> p;
      p[k] = 1;
      p -= (p * axis) * axis;
      p /= p.norm();
      const double far = 10 * (length + (x[N] - x[0]).norm());
      x.push_back(x[N] + far * axis);
      x.push_back(x[N] + far * (axis + p));
      x.push_back(x[0] + far * (p - axis));
      x.push_back(x[0] - far * axis);
      s.writhe = kinematics::writhe(x);
      s.link   = s.twist + s.writhe;
    }

    std::vector<std::pair<std::string, std::string>>
    RodProblem::quantity_columns() const
    {
      std::vector<std::pair<std::string, std::string>> c;
      for (const char *n : {"step", "branch", "t", "newton_iterations", "energy", "end_x", "end_y", "end_z"})
        c.emplace_back(n, "");
      for (const char *end : {"A", "B"})
        for (const char *q : {"force", "moment"})
          for (const char *x : {"x", "y", "z"})
            c.emplace_back(std::string(q) + "_" + end + "_" + x, "");
      c.emplace_back("max_element_rotation", "rad");
      if (reports_link())
        for (const char *n : {"link", "twist", "writhe"})
          c.emplace_back(n, "turns");
      if (contact_radius > 0)
        {
          c.emplace_back("contact_gap", "");
          c.emplace_back("contact_pairs", "");
          c.emplace_back("contact_force", "");
        }
      c.emplace_back("n_negative_eigenvalues", "");
      return c;
    }

    void
    RodProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution       = U;
      load_parameter = report.t;
      RodState s     = describe(U, report.t);
      // The inertia of the state's own factorization, or of the predictor's
      // one Newton step away (report.n_negative), as the drivers give it.
      s.n_negative = report.n_negative;
      s.branch     = report.branch;
      states.push_back(s);
      steps_row = {double(report.step), double(report.branch), report.t, double(report.newton_iterations),
                   s.energy, s.end_position[0], s.end_position[1], s.end_position[2]};
      for (unsigned int k = 0; k < 2; ++k)
        steps_row.insert(steps_row.end(), s.end_loads[k].begin(), s.end_loads[k].end());
      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  branch " << report.branch << "  t = " << std::setprecision(8)
           << std::setw(10) << report.t << "  Newton " << report.newton_iterations << "  end " << std::setprecision(4)
           << s.end_position[0] << " " << s.end_position[1] << " " << s.end_position[2] << "  neg.eig. " << s.n_negative
           << record.progress(solvers::path_fraction(report, arclength_settings), report.step);
      record.say(line.str());
      steps_row.push_back(s.max_rotation);
      if (reports_link())
        steps_row.insert(steps_row.end(), {s.link, s.twist, s.writhe});
      if (contact)
        steps_row.insert(steps_row.end(), {s.contact_gap, double(s.contact_pairs), s.contact_force});
      steps_row.push_back(s.n_negative);
    }

    void
    RodProblem::located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode)
    {
      solvers::EventRecord r;
      r.event = e;
      r.state.assign(U.begin(), U.end());
      if (mode)
        r.mode.assign(mode->begin(), mode->end());
      located_events.push_back(r);
      // (an assembly of the residual at the event: the factorization in place stays)
      event_states.push_back(describe(U, e.lambda));
    }

    namespace
    {
      /**
       * What the output shows of element e at its three points (node a, the
       * midpoint on its helicoid H_a exp(xi h / 2), node b as the element
       * sees it: a ring's seam turned back): positions, frames, the
       * element's strains and resultants (constant on it).
       */
      struct ElementSample
      {
        std::array<Point<3>, 3>     x;
        std::array<Tensor<2, 3>, 3> frames;
        std::array<double, 6>       strain, resultants;
        materials::RodNaturalState  natural; ///< at the element's midpoint
      };

      ElementSample
      sample(const RodProblem &p, const Vector<double> &X, const unsigned int e, const double t)
      {
        const double  h = p.element_length();
        ElementSample out;
        out.strain                   = p.element_strains(X, e, t);
        out.natural                  = p.natural_state((e + 0.5) * h, t);
        out.resultants               = materials::grown_rod_resultants(*p.law, out.strain, out.natural);
        const Tensor<2, 3> R_a       = kinematics::quaternion_rotation(p.quaternion(X, e));
        const kinematics::RodStrains xi(out.strain);
        out.frames = {{R_a, R_a * kinematics::helix_rotation(xi.kappa, 0.5 * h), R_a * kinematics::helix_rotation(xi.kappa, h)}};
        out.x      = {{Point<3>(p.position(X, e)),
                       Point<3>(p.position(X, e) + R_a * kinematics::helix_position(xi.nu, xi.kappa, 0.5 * h)),
                       Point<3>(p.position(X, (e + 1) % p.n_nodes()))}};
        return out;
      }

      /// The strains, then the force and moment in the fixed axes (n = R (n1, n2, n3)) at point k.
      std::vector<double>
      strains_and_resultants(const ElementSample &m, const unsigned int k)
      {
        std::vector<double> v(m.strain.begin(), m.strain.end());
        for (unsigned int i = 0; i < 6; ++i)
          {
            double s = 0;
            for (unsigned int j = 0; j < 3; ++j)
              s += m.frames[k][i % 3][j] * m.resultants[3 * (i / 3) + j];
            v.push_back(s);
          }
        return v;
      }

      std::vector<std::pair<std::string, unsigned int>>
      strain_and_resultant_fields()
      {
        std::vector<std::pair<std::string, unsigned int>> fields;
        for (const char *n : strain_names)
          fields.emplace_back(n, 1);
        fields.emplace_back("force", 3);
        fields.emplace_back("moment", 3);
        return fields;
      }

      /**
       * The centreline as quadratic Lagrange curves, one per element, its
       * midpoint on the element's helicoid: the directors at the nodes and
       * the midpoint, the element's strains and resultants; with a mode,
       * the mode's displacement.
       */
      io::VTUPatches<1>
      centreline(const RodProblem &p, const Vector<double> &X, const double t, const Vector<double> *mode)
      {
        std::vector<std::pair<std::string, unsigned int>> fields = {{"d1", 3}, {"d2", 3}, {"d3", 3}};
        for (const auto &f : strain_and_resultant_fields())
          fields.push_back(f);
        if (mode)
          fields.emplace_back("mode_displacement", 3);
        io::VTUPatches<1> out(fields);
        out.set_time(t);
        for (unsigned int e = 0; e < p.n_elements; ++e)
          {
            const unsigned int b = (e + 1) % p.n_nodes();
            const auto         m = sample(p, X, e, t);
            out.begin_patch(2);
            for (unsigned int k = 0; k < 3; ++k)
              {
                std::vector<double> v;
                for (unsigned int d = 0; d < 3; ++d)
                  for (unsigned int i = 0; i < 3; ++i)
                    v.push_back(m.frames[k][i][d]);
                const auto sr = strains_and_resultants(m, k);
                v.insert(v.end(), sr.begin(), sr.end());
                if (mode)
                  for (unsigned int i = 0; i < 3; ++i)
                    v.push_back(k == 1 ? 0.5 * (p.displacement(*mode, e)[i] + p.displacement(*mode, b)[i]) :
                                         p.displacement(*mode, k == 0 ? e : b)[i]);
                // (points in lexicographic order: node a, the midpoint, node b)
                out.set_position(k, m.x[k]);
                out.set_values(k, v);
              }
            out.end_patch();
          }
        return out;
      }

      /**
       * The rod drawn as a body: a tube of radius rho about the centreline,
       * its circle in the (d1, d2) plane of each point, so that its twist
       * shows; per element 8 biquadratic patches around (each a quarter of
       * a quadrant: the circle to 1e-4 of rho), with the element's strains
       * and resultants.
       */
      io::VTUPatches<2>
      tube(const RodProblem &p, const Vector<double> &X, const double t, const double rho)
      {
        io::VTUPatches<2> out(strain_and_resultant_fields());
        out.set_time(t);
        constexpr unsigned int sectors = 8;
        for (unsigned int e = 0; e < p.n_elements; ++e)
          {
            const auto m = sample(p, X, e, t);
            for (unsigned int sector = 0; sector < sectors; ++sector)
              {
                out.begin_patch(2);
                for (unsigned int j = 0; j < 3; ++j)
                  {
                    const double phi = 2 * M_PI * (sector + 0.5 * j) / sectors;
                    for (unsigned int i = 0; i < 3; ++i)
                      {
                        Tensor<1, 3> radial;
                        for (unsigned int c = 0; c < 3; ++c)
                          radial[c] = std::cos(phi) * m.frames[i][c][0] + std::sin(phi) * m.frames[i][c][1];
                        out.set_position(i + 3 * j, m.x[i] + rho * radial);
                        out.set_values(i + 3 * j, strains_and_resultants(m, i));
                      }
                  }
                out.end_patch();
              }
          }
        return out;
      }

      /**
       * The section's von Mises stress at an outline point P at the elastic
       * strains e: part 1's Cauchy stress linearized about the state it was
       * computed at, sigma + dsigma/de e (theory-rod.md 10), where P carries
       * the linearization; else the stress P was written with (a strip's
       * outline: 0).
       */
      double
      section_stress(const std::vector<double> &P, const std::array<double, 6> &e)
      {
        if (P.size() < 48)
          return P[5];
        std::array<double, 6> sigma;
        for (unsigned int c = 0; c < 6; ++c)
          {
            sigma[c] = P[6 + c];
            for (unsigned int k = 0; k < 6; ++k)
              sigma[c] += P[12 + 6 * k + c] * e[k];
          }
        const double mean = (sigma[0] + sigma[1] + sigma[2]) / 3;
        double       J2   = 0;
        for (unsigned int c = 0; c < 3; ++c)
          J2 += 0.5 * (sigma[c] - mean) * (sigma[c] - mean) + sigma[3 + c] * sigma[3 + c];
        return std::sqrt(3 * J2);
      }

      /**
       * The rod drawn as its own cross-section: each outline segment of the
       * law's section (points P with placement w(P) in the director frame
       * at the natural state) swept along each element, x = r + R w at its
       * nodes, bilinear patches; the section's stress there at the
       * element's strains and the element's strains and resultants as
       * fields.
       */
      io::VTUPatches<2>
      swept_section(const RodProblem &p, const Vector<double> &X, const double t,
                    const materials::RodLaw::SectionOutline &outline)
      {
        auto fields = strain_and_resultant_fields();
        fields.emplace_back("section_stress", 1);
        io::VTUPatches<2> out(fields);
        out.set_time(t);
        for (unsigned int e = 0; e < p.n_elements; ++e)
          {
            const auto m = sample(p, X, e, t);
            // The strains the section sees (of its natural state, unweighted by
            // 'Stiffness factors': the stress of the section itself).
            auto natural    = m.natural;
            natural.weights = {{1, 1, 1, 1, 1, 1}};
            const auto elastic = materials::elastic_rod_strains(m.strain, natural);
            for (const auto &loop : outline)
              for (std::size_t j = 0; j < loop.size(); ++j)
                {
                  out.begin_patch(1);
                  for (unsigned int k = 0; k < 4; ++k)
                    {
                      const unsigned int i = k % 2 == 0 ? 0 : 2; // node a, node b
                      const auto &       P = loop[(j + k / 2) % loop.size()];
                      Point<3>           x = m.x[i];
                      for (unsigned int c = 0; c < 3; ++c)
                        for (unsigned int d = 0; d < 3; ++d)
                          x[c] += m.frames[i][c][d] * P[2 + d];
                      auto v = strains_and_resultants(m, i);
                      v.push_back(section_stress(P, elastic));
                      out.set_position(k, x);
                      out.set_values(k, v);
                    }
                  out.end_patch();
                }
          }
        return out;
      }
    } // namespace

    std::vector<std::pair<std::string, std::string>>
    RodProblem::write_fields(const std::string &tag) const
    {
      io::PhaseTimer::Scope scope(timer, "output");
      const Vector<double> X = configuration(solution, load_parameter);
      std::vector<std::pair<std::string, std::string>> files = {
        {"rod", centreline(*this, X, load_parameter, nullptr).write_output(output_directory, "rod-" + tag, false)}};
      if (section_body)
        files.emplace_back("body", swept_section(*this, X, load_parameter, law->section_outline())
                                     .write_output(output_directory, "body-" + tag, false));
      else if (tube_radius > 0)
        files.emplace_back("tube", tube(*this, X, load_parameter, tube_radius * length)
                                     .write_output(output_directory, "tube-" + tag, false));
      return files;
    }

    std::vector<std::pair<std::string, std::string>>
    RodProblem::write_event_fields(const std::string &tag, const Vector<double> &U, const Vector<double> *mode) const
    {
      io::PhaseTimer::Scope scope(timer, "output");
      const double          t     = load_parameter;
      const Vector<double>  X     = configuration(U, t);
      std::vector<std::pair<std::string, std::string>> files = {
        {"event", centreline(*this, X, t, mode).write_output(output_directory, "event-" + tag, false)}};
      if (mode)
        {
          // The mode added to the state, its largest displacement a tenth of the length.
          double m = 0;
          for (unsigned int k = 0; k < n_nodes(); ++k)
            m = std::max(m, displacement(*mode, k).norm());
          Vector<double> V = X;
          if (m > 0)
            V.add(0.1 * length / m, *mode);
          files.emplace_back("event mode", centreline(*this, configuration(V, t), t, nullptr)
                                             .write_output(output_directory, "event-" + tag + "-mode", false));
        }
      return files;
    }
  } // namespace rod
} // namespace cosmo
