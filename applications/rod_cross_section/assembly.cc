// The section's energy on its discretization: the bulk's and the surface layers', with the
// resultants and the derivatives (section_assembly.h).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/kinematics/rotation.h>
#include <cosmo/kinematics/section.h>

#include "section_assembly.h"

#include <algorithm>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      constexpr unsigned int n_strains = assembly::ReducedRodProblem::n_strains;

      // Sparse rows of dFbar/dU_i and dFbar/de_k: at most 5 of the 9 entries.
      struct SparseRow
      {
        unsigned int n = 0;
        unsigned int a[5];
        double       v[5];
        void
        add(unsigned int aa, double vv)
        {
          if (vv != 0.)
            {
              a[n] = aa;
              v[n] = vv;
              ++n;
            }
        }
        double
        dot(const std::array<double, 9> &x) const
        {
          double r = 0;
          for (unsigned int z = 0; z < n; ++z)
            r += x[a[z]] * v[z];
          return r;
        }
      };

      // out = C s for the 9x9 material tangent C.
      void
      apply_tangent(const std::array<double, 81> &C, const SparseRow &s, std::array<double, 9> &out)
      {
        for (unsigned int a = 0; a < 9; ++a)
          {
            double v = 0;
            for (unsigned int z = 0; z < s.n; ++z)
              v += C[9 * a + s.a[z]] * s.v[z];
            out[a] = v;
          }
      }

      /// Per-thread work space of the assembly (WorkStream scratch).
      struct AssemblyScratch
      {
        AssemblyScratch(const Mapping<2> &mapping, const FiniteElement<2> &fe, const Quadrature<2> &q)
          : fev(mapping, fe, q,
                update_values | update_gradients | update_quadrature_points | update_JxW_values)
          , U_local(fe.n_dofs_per_cell())
          , B(fe.n_dofs_per_cell())
          , CB(fe.n_dofs_per_cell())
        {}
        AssemblyScratch(const AssemblyScratch &o)
          : AssemblyScratch(o.fev.get_mapping(), o.fev.get_fe(), o.fev.get_quadrature())
        {}
        FEValues<2>                                  fev;
        std::vector<double>                          U_local;
        std::vector<SparseRow>                       B;
        std::vector<std::array<double, 9>>           CB;
        std::array<SparseRow, n_strains>             D;
        std::array<std::array<double, 9>, n_strains> CD;
        materials::EnergyDerivatives                 d;
      };

      /// The component of each DoF of a cell.
      std::vector<unsigned int>
      dof_components(const FiniteElement<2> &fe)
      {
        std::vector<unsigned int> comp(fe.n_dofs_per_cell());
        for (unsigned int i = 0; i < comp.size(); ++i)
          comp[i] = fe.system_to_component_index(i).first;
        return comp;
      }

      /// The strains and what the derivatives of Fbar need of them: [kappa]x and e_m x e_c.
      struct HelicalStrainTerms
      {
        explicit HelicalStrainTerms(const std::array<double, 6> &e)
          : nu({e[0], e[1], e[2]})
          , kappa({e[3], e[4], e[5]})
          , Kx(kinematics::skew(kappa))
        {
          for (unsigned int m = 0; m < 3; ++m)
            for (unsigned int c = 0; c < 3; ++c)
              e_x_e[m][c] = kinematics::axial_column_mixed_derivative(m, c);
        }
        Tensor<1, 3> nu, kappa;
        Tensor<2, 3> Kx;
        Tensor<1, 3> e_x_e[3][3];
      };

      /// The displacement u and its gradient (columns 0, 1: du/dX1, du/dX2) at
      /// point q of a cell whose DoFs have the values U_local (added to u, grad_u).
      void
      displacement_at_point(const FEValues<2> &              fev,
                            const unsigned int               q,
                            const std::vector<unsigned int> &comp,
                            const std::vector<double> &      U_local,
                            Tensor<1, 3> &                   u,
                            Tensor<2, 3> &                   grad_u)
      {
        for (unsigned int i = 0; i < comp.size(); ++i)
          {
            const double N = fev.shape_value(i, q);
            const auto   g = fev.shape_grad(i, q);
            u[comp[i]] += U_local[i] * N;
            grad_u[comp[i]][0] += U_local[i] * g[0];
            grad_u[comp[i]][1] += U_local[i] * g[1];
          }
      }

      /// The bulk's first variation at point q: the rows B_i = dFbar/dU_i with
      /// the residual P : B_i dA, and D_k = dFbar/de_k with the resultants
      /// P : D_k dA (the cell's scalars 1 to 6).
      void
      add_bulk_first_variation(const FEValues<2> &              fev,
                               const unsigned int               q,
                               const std::vector<unsigned int> &comp,
                               const HelicalStrainTerms &       h,
                               const Tensor<1, 3> &             w,
                               const std::array<double, 9> &    P,
                               const double                     dA,
                               AssemblyScratch &                scratch,
                               assembly::CellContribution &     out)
      {
        auto &B = scratch.B;
        auto &D = scratch.D;
        for (unsigned int i = 0; i < comp.size(); ++i)
          {
            const double       N = fev.shape_value(i, q);
            const auto         g = fev.shape_grad(i, q);
            const unsigned int c = comp[i];
            B[i].n               = 0;
            B[i].add(3 * c, g[0]);
            B[i].add(3 * c + 1, g[1]);
            for (unsigned int r = 0; r < 3; ++r)
              B[i].add(3 * r + 2, h.Kx[r][c] * N);
            out.residual[i] += B[i].dot(P) * dA;
          }
        // dFbar/d(strain k): only the third column depends on the strains.
        for (unsigned int k = 0; k < n_strains; ++k)
          {
            D[k].n                = 0;
            const Tensor<1, 3> db = kinematics::axial_column_strain_derivative(k, w);
            for (unsigned int r = 0; r < 3; ++r)
              if (k >= 3 || r == k)
                D[k].add(3 * r + 2, db[r]);
            out.scalars[1 + k] += D[k].dot(P) * dA;
          }
      }

      /// The bulk's second variation at point q, with the rows B_i, D_k of the
      /// first: the Hessian's lower triangle, the border columns (with the
      /// stress term of the curvatures) and the 6x6 border block.
      void
      add_bulk_second_variation(const FEValues<2> &                  fev,
                                const unsigned int                   q,
                                const std::vector<unsigned int> &    comp,
                                const HelicalStrainTerms &           h,
                                const materials::EnergyDerivatives & d,
                                const double                         dA,
                                AssemblyScratch &                    scratch,
                                assembly::CellContribution &         out)
      {
        const unsigned int dpc = comp.size();
        const auto &       B   = scratch.B;
        const auto &       D   = scratch.D;
        const auto &       P   = d.P;
        for (unsigned int i = 0; i < dpc; ++i)
          apply_tangent(d.C, B[i], scratch.CB[i]);
        for (unsigned int k = 0; k < n_strains; ++k)
          apply_tangent(d.C, D[k], scratch.CD[k]);

        for (unsigned int i = 0; i < dpc; ++i)
          {
            const auto &CBi = scratch.CB[i];
            for (unsigned int j = 0; j <= i; ++j)
              out.hessian(i, j) += B[j].dot(CBi) * dA;
            const double       N = fev.shape_value(i, q);
            const unsigned int c = comp[i];
            for (unsigned int k = 0; k < n_strains; ++k)
              {
                double bik = D[k].dot(CBi);
                if (k >= 3) // P : d2 Fbar / dU_i dkappa_k, column 3 = e_k x e_c N
                  {
                    const Tensor<1, 3> &ex = h.e_x_e[k - 3][c];
                    for (unsigned int r = 0; r < 3; ++r)
                      bik += P[3 * r + 2] * ex[r] * N;
                  }
                out.border(i, k) += bik * dA;
              }
          }
        for (unsigned int k = 0; k < n_strains; ++k)
          for (unsigned int l = 0; l < n_strains; ++l)
            out.border_block(k, l) += D[l].dot(scratch.CD[k]) * dA;
      }

      /// a : b for two surface deformation gradients (6 entries).
      double
      dot6(const std::array<double, 6> &a, const std::array<double, 6> &b)
      {
        double r = 0;
        for (unsigned int z = 0; z < 6; ++z)
          r += a[z] * b[z];
        return r;
      }

      /// b = C a for the 6x6 surface tangent C.
      void
      apply6(const std::array<double, 36> &C, const std::array<double, 6> &a, std::array<double, 6> &b)
      {
        for (unsigned int x = 0; x < 6; ++x)
          {
            double v = 0;
            for (unsigned int z = 0; z < 6; ++z)
              v += C[6 * x + z] * a[z];
            b[x] = v;
          }
      }

      /// Work space of the surface assembly: a face's DoF values, the
      /// derivatives dFs/dU_i, dFs/de_k of its point and their products with
      /// the tangent.
      struct SurfaceScratch
      {
        explicit SurfaceScratch(const unsigned int dofs_per_cell)
          : U_local(dofs_per_cell)
          , dF(dofs_per_cell)
          , CdF(dofs_per_cell)
        {}
        std::vector<double>                          U_local;
        std::vector<std::array<double, 6>>           dF, CdF;
        std::array<std::array<double, 6>, n_strains> D, CD;
        materials::SurfaceEnergyDerivatives          d;
      };

      /// The displacement u and its derivative du/dS along the boundary
      /// tangent T at point q of a face (added to u, du_dS).
      void
      surface_displacement_at_point(const FEFaceValues<2> &          ffv,
                                    const unsigned int               q,
                                    const Tensor<1, 2> &             T,
                                    const std::vector<unsigned int> &comp,
                                    const std::vector<double> &      U_local,
                                    Tensor<1, 3> &                   u,
                                    Tensor<1, 3> &                   du_dS)
      {
        for (unsigned int i = 0; i < comp.size(); ++i)
          {
            const auto g = ffv.shape_grad(i, q);
            u[comp[i]] += U_local[i] * ffv.shape_value(i, q);
            du_dS[comp[i]] += U_local[i] * (g * T);
          }
      }

      /// A layer's first variation at face point q: dFs/dU_i with the residual
      /// Ps : dFs/dU_i dS, and dFs/de_k with the resultants Ps : dFs/de_k dS.
      void
      add_surface_first_variation(const FEFaceValues<2> &          ffv,
                                  const unsigned int               q,
                                  const Tensor<1, 2> &             T,
                                  const std::vector<unsigned int> &comp,
                                  const HelicalStrainTerms &       h,
                                  const Tensor<1, 3> &             w,
                                  const double                     dS,
                                  SurfaceScratch &                 s,
                                  assembly::CellContribution &     out,
                                  std::array<double, 6> &          resultants)
      {
        for (unsigned int i = 0; i < comp.size(); ++i)
          {
            const unsigned int c = comp[i];
            const double       N = ffv.shape_value(i, q);
            s.dF[i].fill(0.);
            s.dF[i][2 * c] = ffv.shape_grad(i, q) * T;
            for (unsigned int r = 0; r < 3; ++r)
              s.dF[i][2 * r + 1] += h.Kx[r][c] * N;
            out.residual[i] += dot6(s.dF[i], s.d.P) * dS;
          }
        for (unsigned int k = 0; k < n_strains; ++k)
          {
            s.D[k].fill(0.);
            const Tensor<1, 3> db = kinematics::axial_column_strain_derivative(k, w);
            for (unsigned int r = 0; r < 3; ++r)
              s.D[k][2 * r + 1] = db[r];
            resultants[k] += dot6(s.D[k], s.d.P) * dS;
          }
      }

      /// A layer's second variation at face point q: the Hessian, the border
      /// columns (with the stress term of the curvatures) and, straight into E,
      /// the 6x6 border block.
      void
      add_surface_second_variation(const FEFaceValues<2> &          ffv,
                                   const unsigned int               q,
                                   const std::vector<unsigned int> &comp,
                                   const HelicalStrainTerms &       h,
                                   const double                     dS,
                                   SurfaceScratch &                 s,
                                   assembly::CellContribution &     out,
                                   FullMatrix<double> &             E)
      {
        const unsigned int dpc = comp.size();
        for (unsigned int i = 0; i < dpc; ++i)
          apply6(s.d.C, s.dF[i], s.CdF[i]);
        for (unsigned int k = 0; k < n_strains; ++k)
          apply6(s.d.C, s.D[k], s.CD[k]);
        for (unsigned int i = 0; i < dpc; ++i)
          {
            for (unsigned int j = 0; j < dpc; ++j)
              out.hessian(i, j) += dot6(s.dF[j], s.CdF[i]) * dS;
            const double       N = ffv.shape_value(i, q);
            const unsigned int c = comp[i];
            for (unsigned int k = 0; k < n_strains; ++k)
              {
                double bik = dot6(s.D[k], s.CdF[i]);
                if (k >= 3) // Ps : d2 Fs / dU_i dkappa_k (second column)
                  {
                    const Tensor<1, 3> &ex = h.e_x_e[k - 3][c];
                    for (unsigned int r = 0; r < 3; ++r)
                      bik += s.d.P[2 * r + 1] * ex[r] * N;
                  }
                out.border(i, k) += bik * dS;
              }
          }
        for (unsigned int k = 0; k < n_strains; ++k)
          for (unsigned int l = 0; l < n_strains; ++l)
            E(k, l) += dot6(s.D[l], s.CD[k]) * dS;
      }
    } // namespace

    assembly::AssemblyTotals
    assemble_bulk(const SectionDiscretization & section,
                  const CrossSectionParameters &parameters,
                  const Vector<double> &        U,
                  const std::array<double, 6> & e,
                  const assembly::AssemblyTarget &target)
    {
      const HelicalStrainTerms h(e);
      const bool               jacobian = target.jacobian;
      const FiniteElement<2> & fe       = section.get_fe();

      const QGauss<2>    quadrature(parameters.degree + 1);
      const unsigned int nq  = quadrature.size();
      const unsigned int              dpc  = fe.n_dofs_per_cell();
      const std::vector<unsigned int> comp = dof_components(fe);

      // Cells are independent: the worker runs on all cores, the copier adds
      // the contributions in cell order (so sums are reproducible).
      auto worker = [&](const typename DoFHandler<2>::active_cell_iterator &cell,
                        AssemblyScratch &                                  scratch,
                        assembly::CellContribution &                       out) {
        auto &fev = scratch.fev;
        fev.reinit(cell);
        for (unsigned int i = 0; i < dpc; ++i)
          scratch.U_local[i] = U[out.dof_indices[i]];
        const auto &material = parameters.materials.material(cell->material_id());
        auto &d = scratch.d;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const double   dA = fev.JxW(q);
            const Point<2> X  = fev.quadrature_point(q);
            Tensor<1, 3>   u;
            Tensor<2, 3>   grad_u; // columns 0, 1: du/dX1, du/dX2
            displacement_at_point(fev, q, comp, scratch.U_local, u, grad_u);
            const Tensor<1, 3> w = kinematics::section_placement(X, u);
            const Tensor<2, 3> F = kinematics::section_deformation_gradient(grad_u, w, h.nu, h.kappa);

            const Tensor<2, 3> &Fg = section.bulk_growth()[cell->active_cell_index() * nq + q];
            material.evaluate(F, Fg, jacobian, d);
            if (!d.admissible)
              {
                out.admissible = false;
                return;
              }
            out.scalars[0] += d.energy * dA;
            out.minimum = std::min(out.minimum, determinant(F) / determinant(Fg));

            add_bulk_first_variation(fev, q, comp, h, w, d.P, dA, scratch, out);
            if (jacobian)
              add_bulk_second_variation(fev, q, comp, h, d, dA, scratch, out);
          }
        if (jacobian)
          for (unsigned int i = 0; i < dpc; ++i)
            for (unsigned int j = 0; j < i; ++j)
              out.hessian(j, i) = out.hessian(i, j);
      };

      // The cell's scalars: its energy, then the six resultants dE/de.
      return assembly::EnergyAssembler<2>::assemble(
        section.get_dof_handler(), worker, AssemblyScratch(section.get_mapping(), fe, quadrature),
        assembly::CellContribution(dpc, n_strains, 1 + n_strains), target);
    }

    void
    assemble_surface_layers(const SectionDiscretization &   section,
                            const CrossSectionParameters &  parameters,
                            const double                    t,
                            const Vector<double> &          U,
                            const std::array<double, 6> &   e,
                            const assembly::AssemblyTarget &target,
                            double &                        energy,
                            std::array<double, 6> &         resultants)
    {
      // Few faces: serial, in face order.
      const HelicalStrainTerms h(e);
      const bool               jacobian      = target.jacobian;
      const auto &             surface_faces = section.get_surface_faces();
      const FiniteElement<2> & fe            = section.get_fe();
      // The 6x6 block goes into E point by point, the rest face by face.
      FullMatrix<double> &     E           = *target.border_block;
      assembly::AssemblyTarget face_target = target;
      face_target.border_block             = nullptr;

      const unsigned int              dpc  = fe.n_dofs_per_cell();
      const std::vector<unsigned int> comp = dof_components(fe);

      const QGauss<1>    face_quadrature(parameters.degree + 1);
      const unsigned int nqf = face_quadrature.size();
      FEFaceValues<2>    ffv(section.get_mapping(), fe, face_quadrature,
                          update_values | update_gradients | update_quadrature_points |
                            update_JxW_values | update_normal_vectors);
      assembly::CellContribution out(dpc, n_strains);
      SurfaceScratch             s(dpc);
      for (unsigned int f = 0; f < surface_faces.size(); ++f)
        {
          const auto &sf    = surface_faces[f];
          const auto &layer = parameters.surface_layers.layers()[sf.layer];
          ffv.reinit(sf.cell, sf.face);
          out.reset(jacobian);
          sf.cell->get_dof_indices(out.dof_indices);
          for (unsigned int i = 0; i < dpc; ++i)
            s.U_local[i] = U[out.dof_indices[i]];
          for (unsigned int q = 0; q < nqf; ++q)
            {
              const double        dS = ffv.JxW(q);
              const Point<2>      X  = ffv.quadrature_point(q);
              const Tensor<1, 2> &Nn = ffv.normal_vector(q);
              // Unit tangent of the boundary curve (counterclockwise on the
              // outer boundary; the energy is even in T).
              const Tensor<1, 2> T = kinematics::boundary_tangent(Nn);
              Tensor<1, 3>       u, du_dS;
              surface_displacement_at_point(ffv, q, T, comp, s.U_local, u, du_dS);
              const Tensor<1, 3> w  = kinematics::section_placement(X, u);
              const auto Fs = kinematics::surface_deformation_gradient(w, du_dS, T, h.nu, h.kappa);
              layer.evaluate(Fs, section.surface_growth()[f * nqf + q], t, jacobian, s.d);
              energy += s.d.energy * dS;

              add_surface_first_variation(ffv, q, T, comp, h, w, dS, s, out, resultants);
              if (jacobian)
                add_surface_second_variation(ffv, q, comp, h, dS, s, out, E);
            }
          assembly::add_cell_contribution(out, face_target);
        }
    }
  } // namespace rod
} // namespace cosmo
