#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cosmo/analysis/section_properties.h>
#include <cosmo/solvers/sparse_direct.h>

#include <cmath>
#include <limits>

namespace cosmo
{
  namespace analysis
  {
    namespace
    {
      /// Angle in (-pi/2, pi/2] of the eigenvector of the larger eigenvalue
      /// of the symmetric [[a, b], [b, c]], and both eigenvalues (larger first).
      std::pair<double, std::array<double, 2>>
      principal(const double a, const double b, const double c)
      {
        const double mean = 0.5 * (a + c), radius = std::hypot(0.5 * (a - c), b);
        double       angle = 0.5 * std::atan2(2 * b, a - c);
        if (angle <= -0.5 * M_PI)
          angle += M_PI;
        // Equal eigenvalues (a circle, a square): every axis is principal;
        // the angle of round-off would mean nothing.
        if (radius <= 1e-9 * std::abs(mean))
          angle = std::numeric_limits<double>::quiet_NaN();
        return {angle, {{mean + radius, mean - radius}}};
      }

      io::JSON
      point_json(const Point<2> &p)
      {
        return io::JSON::array({p[0], p[1]});
      }

      io::JSON
      matrix_json(const FullMatrix<double> &M)
      {
        io::JSON rows = io::JSON::array();
        for (unsigned int i = 0; i < M.m(); ++i)
          {
            std::vector<double> row(M.n());
            for (unsigned int j = 0; j < M.n(); ++j)
              row[j] = M(i, j);
            rows.push_back(io::JSON::array(row));
          }
        return rows;
      }
    } // namespace


    namespace
    {
      /// Area, first moments (geometric, E- and mass-weighted) and the
      /// stiffnesses EA, GA, the mass and the three centres.
      void
      add_area_moments(const DoFHandler<2> &                                  dof_handler,
                       FEValues<2> &                                          fe_values,
                       const std::function<RegionModuli(types::material_id)> &moduli,
                       LinearSectionProperties &                              p)
      {
        const unsigned int nq = fe_values.n_quadrature_points;
        double Sx = 0, Sy = 0, ESx = 0, ESy = 0, RSx = 0, RSy = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            fe_values.reinit(cell);
            const RegionModuli m = moduli(cell->material_id());
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Point<2> &x  = fe_values.quadrature_point(q);
                const double    dA = fe_values.JxW(q);
                p.area += dA;
                Sx += x[0] * dA;
                Sy += x[1] * dA;
                p.EA += m.young * dA;
                p.GA += m.shear * dA;
                ESx += m.young * x[0] * dA;
                ESy += m.young * x[1] * dA;
                p.mass += m.density * dA;
                RSx += m.density * x[0] * dA;
                RSy += m.density * x[1] * dA;
              }
          }
        p.mass_centre = Point<2>(RSx / p.mass, RSy / p.mass);
        p.centroid       = Point<2>(Sx / p.area, Sy / p.area);
        p.elastic_centre = Point<2>(ESx / p.EA, ESy / p.EA);
      }

      /**
       * Flexure loads for unit shear forces n = e1, e2 (Poisson effect
       * neglected): the axial stress rate d sigma/dX3 = E (g1 X1 + g2 X2)
       * with [[S11, S12], [S12, S22]] g = n, S_ab = int E X_a X_b about the
       * elastic centre xe.
       */
      std::array<Vector<double>, 2>
      flexure_loads(const DoFHandler<2> &                                  dof_handler,
                    FEValues<2> &                                          fe_values,
                    const std::function<RegionModuli(types::material_id)> &moduli,
                    const Point<2> &                                       xe,
                    const double                                           S11,
                    const double                                           S12,
                    const double                                           S22)
      {
        const unsigned int n = dof_handler.n_dofs(), dpc = fe_values.dofs_per_cell,
                           nq = fe_values.n_quadrature_points;
        const double       D = S11 * S22 - S12 * S12;
        std::array<Vector<double>, 2>        flexure_rhs{{Vector<double>(n), Vector<double>(n)}};
        std::vector<types::global_dof_index> dofs(dpc);
        std::array<std::array<double, 2>, 2> g;
        g[0] = {{S22 / D, -S12 / D}};
        g[1] = {{-S12 / D, S11 / D}};
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            const RegionModuli m = moduli(cell->material_id());
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Point<2> &x  = fe_values.quadrature_point(q);
                const double    dA = fe_values.JxW(q);
                const double    X1 = x[0] - xe[0], X2 = x[1] - xe[1];
                for (unsigned int a = 0; a < 2; ++a)
                  {
                    const double f = m.young * (g[a][0] * X1 + g[a][1] * X2);
                    for (unsigned int i = 0; i < dpc; ++i)
                      flexure_rhs[a](dofs[i]) += f * fe_values.shape_value(i, q) * dA;
                  }
              }
          }
        return flexure_rhs;
      }
      /**
       * Pure Neumann problems with the matrix A, each load in balance (int f
       * = 0 at the elastic centre; the torsion load is a divergence): pinning
       * one value selects one solution of the singular system without
       * changing the others. A is changed; the loads become the solutions.
       */
      void
      solve_neumann_problems(SparseMatrix<double> &A, std::vector<Vector<double>> &solutions)
      {
        const unsigned int pin = 0;
        for (auto it = A.begin(pin); it != A.end(pin); ++it)
          if (it->column() != pin)
            {
              it->value() = 0;
              A.set(it->column(), pin, 0.);
            }
        for (auto &s : solutions)
          s(pin) = 0;
        solvers::SparseDirectSolver solver;
        solver.factorize(A);
        solver.solve(solutions);
      }

      /**
       * Pass 2 of linear_section_properties(): the bending and mass moments
       * about the elastic and mass centres into p; the G-weighted Laplacian
       * into A and the torsion load -int G p . grad v, p = (-X2, X1), into
       * torsion_rhs.
       */
      void
      add_bending_and_torsion(const DoFHandler<2> &                                  dof_handler,
                              FEValues<2> &                                          fe_values,
                              const std::function<RegionModuli(types::material_id)> &moduli,
                              LinearSectionProperties &                              p,
                              SparseMatrix<double> &                                 A,
                              Vector<double> &                                       torsion_rhs)
      {
        const unsigned int dpc = fe_values.dofs_per_cell, nq = fe_values.n_quadrature_points;
        const Point<2> &   xe = p.elastic_centre;
        std::vector<types::global_dof_index> dofs(dpc);
        FullMatrix<double>                   cell_matrix(dpc, dpc);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            cell_matrix                 = 0;
            const RegionModuli m = moduli(cell->material_id());
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Point<2> &x  = fe_values.quadrature_point(q);
                const double    dA = fe_values.JxW(q);
                const double    X1 = x[0] - xe[0], X2 = x[1] - xe[1];
                p.EI11 += m.young * X2 * X2 * dA;
                p.EI22 += m.young * X1 * X1 * dA;
                p.EI12 += m.young * X1 * X2 * dA;
                const double Y1 = x[0] - p.mass_centre[0], Y2 = x[1] - p.mass_centre[1];
                p.mass_moment11 += m.density * Y2 * Y2 * dA;
                p.mass_moment22 += m.density * Y1 * Y1 * dA;
                p.mass_moment12 += m.density * Y1 * Y2 * dA;
                const Tensor<1, 2> rot({-x[1], x[0]});
                for (unsigned int i = 0; i < dpc; ++i)
                  {
                    const Tensor<1, 2> gi = fe_values.shape_grad(i, q);
                    torsion_rhs(dofs[i]) -= m.shear * (rot * gi) * dA;
                    for (unsigned int j = 0; j < dpc; ++j)
                      cell_matrix(i, j) += m.shear * (gi * fe_values.shape_grad(j, q)) * dA;
                  }
              }
            // (one sorted insertion per cell: per entry, the matrix's row
            // search dominated this pass)
            A.add(dofs, cell_matrix);
          }
      }

      /// The integrals of the warping functions that give the shear centres,
      /// E Gamma and the shear stiffness.
      struct WarpingIntegrals
      {
        double                Iw1 = 0, Iw2 = 0;  // int E X_a omega
        double                Iw0 = 0, Iww = 0;  // int E omega, int E omega^2
        std::array<double, 2> moment{{0, 0}};    // int (x tau2 - y tau1) per load
        FullMatrix<double>    flexibility{2, 2};
      };

      /**
       * Pass 3 of linear_section_properties(): the integrals of the torsion
       * warping solutions[0] and the flexure warpings solutions[1], [2];
       * GJ is added to p.
       */
      WarpingIntegrals
      warping_integrals(const DoFHandler<2> &                                  dof_handler,
                        FEValues<2> &                                          fe_values,
                        const std::function<RegionModuli(types::material_id)> &moduli,
                        const std::vector<Vector<double>> &                    solutions,
                        LinearSectionProperties &                              p)
      {
        const unsigned int    nq    = fe_values.n_quadrature_points;
        const Point<2> &      xe    = p.elastic_centre;
        const Vector<double> &omega = solutions[0];
        WarpingIntegrals      r;
        std::vector<double>   w(nq);
        std::array<std::vector<Tensor<1, 2>>, 3> grads;
        for (auto &v : grads)
          v.resize(nq);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            fe_values.reinit(cell);
            const RegionModuli m = moduli(cell->material_id());
            fe_values.get_function_values(omega, w);
            for (unsigned int k = 0; k < 3; ++k)
              fe_values.get_function_gradients(solutions[k], grads[k]);
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Point<2> &x  = fe_values.quadrature_point(q);
                const double    dA = fe_values.JxW(q);
                const Tensor<1, 2> rot({-x[1], x[0]});
                p.GJ += m.shear * (grads[0][q] + rot).norm_square() * dA;
                r.Iw0 += m.young * w[q] * dA;
                r.Iww += m.young * w[q] * w[q] * dA;
                r.Iw1 += m.young * (x[0] - xe[0]) * w[q] * dA;
                r.Iw2 += m.young * (x[1] - xe[1]) * w[q] * dA;
                for (unsigned int a = 0; a < 2; ++a)
                  {
                    const Tensor<1, 2> tau = m.shear * grads[1 + a][q];
                    r.moment[a] += (x[0] * tau[1] - x[1] * tau[0]) * dA;
                    for (unsigned int b = 0; b < 2; ++b)
                      r.flexibility(a, b) += m.shear * (grads[1 + a][q] * grads[1 + b][q]) * dA;
                  }
              }
          }
        return r;
      }
    } // namespace

    LinearSectionProperties
    linear_section_properties(const Triangulation<2> &                                 tria,
                              const Mapping<2> &                                       mapping,
                              const unsigned int                                       degree,
                              const std::function<RegionModuli(types::material_id)> &moduli)
    {
      LinearSectionProperties p;
      const FE_Q<2>           fe(degree);
      DoFHandler<2>           dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      const unsigned int n = dof_handler.n_dofs();
      p.n_dofs             = n;
      const QGauss<2>    quadrature(degree + 1);
      FEValues<2>        fe_values(mapping, fe, quadrature,
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);

      // Pass 1: areas and first and second moments (geometric and E-weighted).
      add_area_moments(dof_handler, fe_values, moduli, p);
      const Point<2> &xe = p.elastic_centre;

      // Pass 2: bending about the elastic centre; the G-weighted Laplacian
      // (one matrix for the torsion and both flexure problems) and the
      // torsion load -int G p . grad v, p = (-X2, X1) (twist about the origin).
      DynamicSparsityPattern dsp(n, n);
      DoFTools::make_sparsity_pattern(dof_handler, dsp);
      SparsityPattern pattern;
      pattern.copy_from(dsp);
      SparseMatrix<double> A(pattern);
      Vector<double>       torsion_rhs(n);
      add_bending_and_torsion(dof_handler, fe_values, moduli, p, A, torsion_rhs);
      // Bending energy 1/2 (EI11 k1^2 - 2 EI12 k1 k2 + EI22 k2^2): the
      // stiffness in (kappa1, kappa2) is [[EI11, -EI12], [-EI12, EI22]].
      std::tie(p.principal_angle, p.principal_bending) = principal(p.EI11, -p.EI12, p.EI22);

      // Flexure loads for unit shear forces n = e1, e2 (Poisson effect
      // neglected): the axial stress rate d sigma/dX3 = E (g1 X1 + g2 X2)
      // with [[S11, S12], [S12, S22]] g = n, S_ab = int E X_a X_b.
      const double S11 = p.EI22, S22 = p.EI11, S12 = p.EI12, D = S11 * S22 - S12 * S12;
      const auto flexure_rhs = flexure_loads(dof_handler, fe_values, moduli, xe, S11, S12, S22);

      std::vector<Vector<double>> solutions{torsion_rhs, flexure_rhs[0], flexure_rhs[1]};
      solve_neumann_problems(A, solutions);

      // Pass 3: integrals of the warping functions.
      const WarpingIntegrals wi = warping_integrals(dof_handler, fe_values, moduli, solutions, p);
      const double           Iw1 = wi.Iw1, Iw2 = wi.Iw2, Iw0 = wi.Iw0, Iww = wi.Iww;
      const auto &           moment = wi.moment;
      // Trefftz: the warping about the shear centre a, omega - a2 X1 + a1 X2,
      // is orthogonal (E-weighted) to X1 and X2.
      p.shear_centre_trefftz =
        Point<2>((S12 * Iw1 - S11 * Iw2) / D, (S22 * Iw1 - S12 * Iw2) / D);
      // Vlasov's warping stiffness E Gamma = int E omega_s^2 of the warping
      // about the shear centre with zero E-weighted mean: omega less its
      // E-weighted projection onto 1, X1, X2 (the same orthogonality that
      // defines Trefftz's centre), so E Gamma = int E omega^2 minus that
      // projection's energy.
      p.EGamma = Iww - Iw0 * Iw0 / p.EA - (S22 * Iw1 * Iw1 - 2 * S12 * Iw1 * Iw2 + S11 * Iw2 * Iw2) / D;
      // The resultant n of the flexure stresses acts at s: s x n = moment.
      p.shear_centre_flexure = Point<2>(moment[1], -moment[0]);
      p.shear_stiffness.invert(wi.flexibility);
      for (unsigned int a = 0; a < 2; ++a)
        p.shear_factors[a] = p.shear_stiffness(a, a) / p.GA;
      return p;
    }


    io::JSON
    LinearSectionProperties::to_json() const
    {
      io::JSON j;
      j["description"]  = "linear-elastic Saint-Venant problems of the reference section "
                         "(small-strain moduli of each region); lengths in the section's "
                         "coordinates, angles in degrees from E1";
      j["area"]                 = area;
      j["centroid"]             = point_json(centroid);
      j["EA"]                   = EA;
      j["GA"]                   = GA;
      j["elastic_centre"]       = point_json(elastic_centre);
      j["EI11"]                 = EI11;
      j["EI22"]                 = EI22;
      j["EI12"]                 = EI12;
      j["principal_angle_deg"]  = principal_angle * 180 / M_PI;
      j["principal_bending"]    = io::JSON::array({principal_bending[0], principal_bending[1]});
      j["GJ"]                   = GJ;
      j["EGamma"]               = EGamma;
      j["shear_centre_trefftz"] = point_json(shear_centre_trefftz);
      j["shear_centre_flexure"] = point_json(shear_centre_flexure);
      j["shear_stiffness"]      = matrix_json(shear_stiffness);
      j["shear_factors"]        = io::JSON::array({shear_factors[0], shear_factors[1]});
      j["mass_per_length"]      = mass;
      j["mass_centre"]          = point_json(mass_centre);
      j["mass_moments"]         = io::JSON::array({mass_moment11, mass_moment22, mass_moment12});
      j["polar_mass_moment"]    = mass_moment11 + mass_moment22;
      j["dofs"]                 = n_dofs;
      return j;
    }


    FullMatrix<double>
    transform_stiffness(const FullMatrix<double> &K, const Point<2> &c, const double angle)
    {
      // e' = R T e; K' = (R T)^-T K (R T)^-1 = R T^-T K T^-1 R^T (R orthogonal).
      FullMatrix<double> Tinv(6, 6);
      for (unsigned int i = 0; i < 6; ++i)
        Tinv(i, i) = 1;
      // nu' = nu + kappa x c: T(nu, kappa) = A = [[0,0,-c2],[0,0,c1],[c2,-c1,0]]; T^-1 has -A.
      Tinv(0, 5) = c[1];
      Tinv(1, 5) = -c[0];
      Tinv(2, 3) = -c[1];
      Tinv(2, 4) = c[0];
      FullMatrix<double> R(6, 6);
      const double       co = std::cos(angle), si = std::sin(angle);
      for (unsigned int b = 0; b < 6; b += 3)
        {
          R(b, b)         = co;
          R(b, b + 1)     = si;
          R(b + 1, b)     = -si;
          R(b + 1, b + 1) = co;
          R(b + 2, b + 2) = 1;
        }
      FullMatrix<double> M(6, 6), KT(6, 6), out(6, 6);
      Tinv.mTmult(M, R); // T^-1 R^T
      K.mmult(KT, M);    // K T^-1 R^T
      M.Tmmult(out, KT); // (T^-1 R^T)^T K T^-1 R^T
      return out;
    }


    StiffnessAnalysis
    analyse_stiffness(const FullMatrix<double> &K)
    {
      StiffnessAnalysis s;
      // (no converged state: no stiffness to analyse)
      if (K.m() != 6 || K.n() != 6)
        return s;
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          if (a != b && K(a, a) > 0 && K(b, b) > 0)
            s.largest_coupling =
              std::max(s.largest_coupling, std::abs(K(a, b)) / std::sqrt(K(a, a) * K(b, b)));
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          if (!std::isfinite(K(a, b)))
            return s;
      s.compliance.copy_from(K);
      try
        {
          s.compliance.gauss_jordan();
        }
      catch (...)
        {
          return s;
        }
      const auto &C = s.compliance;
      for (unsigned int a = 0; a < 6; ++a)
        {
          if (!(C(a, a) > 0) || !std::isfinite(C(a, a)))
            return s; // not positive definite: no centres, no condensation
          s.condensed[a] = 1 / C(a, a);
        }
      s.invertible = true;
      // Tension centre: -c1 C(k_a, k2) + c2 C(k_a, k1) = -C(k_a, nu3), a = 1, 2.
      {
        const double m11 = -C(3, 4), m12 = C(3, 3), m21 = -C(4, 4), m22 = C(4, 3);
        const double det = m11 * m22 - m12 * m21, r1 = -C(3, 2), r2 = -C(4, 2);
        s.tension_centre = Point<2>((r1 * m22 - m12 * r2) / det, (m11 * r2 - m21 * r1) / det);
      }
      s.shear_centre = Point<2>(-C(5, 1) / C(5, 5), C(5, 0) / C(5, 5));
      // The bending stiffness with the other resultants zero: (C_bending)^-1.
      const double det = C(3, 3) * C(4, 4) - C(3, 4) * C(4, 3);
      std::tie(s.principal_angle, s.principal_bending) =
        principal(C(4, 4) / det, -C(3, 4) / det, C(3, 3) / det);
      // (Equal bending stiffnesses: every axis is principal, keep E1.)
      s.principal_stiffness =
        transform_stiffness(K, s.tension_centre, std::isfinite(s.principal_angle) ? s.principal_angle : 0.);
      return s;
    }


    io::JSON
    StiffnessAnalysis::to_json() const
    {
      io::JSON j;
      j["description"] = "from the 6x6 stiffness of this state (strains nu1, nu2, nu3, kappa1, "
                         "kappa2, kappa3); centres in the section's coordinates, angle in "
                         "degrees from E1";
      j["largest_coupling"] = largest_coupling;
      j["positive_definite"] = invertible;
      if (!invertible)
        return j;
      j["tension_centre"]      = point_json(tension_centre);
      j["shear_centre"]        = point_json(shear_centre);
      j["principal_angle_deg"] = principal_angle * 180 / M_PI;
      j["principal_bending"]   = io::JSON::array({principal_bending[0], principal_bending[1]});
      j["condensed_stiffness"] = io::JSON::array(std::vector<double>(condensed.begin(), condensed.end()));
      j["compliance"]          = matrix_json(compliance);
      j["stiffness_at_tension_centre_principal_axes"] = matrix_json(principal_stiffness);
      return j;
    }
  } // namespace analysis
} // namespace cosmo
