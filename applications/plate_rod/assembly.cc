// The plate and rim energies of part 3 and their assembly: the energies are
// differentiated here (Sacado, 15 and 12 local variables), the heavy
// translation unit of part 3.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/assumed_shear.h>
#include <cosmo/assembly/local_variables.h>
#include <cosmo/config.h>
#include <cosmo/io/ranks.h>
#include <cosmo/materials/energy_derivatives.h>

#include "assembly.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {
    namespace
    {
      constexpr int n_plate = kinematics::plate_local_variables;
      constexpr int n_rim   = kinematics::rim_local_variables;

      using assembly::Drive;
      using ShearIntegration = PlateRodParameters::ShearIntegration;

      Drive
      plate_drive(const unsigned int c, const double N, const Tensor<1, 2> &g)
      {
        Drive d;
        if (c < 3)
          d = {3, {c, 3 + c, 6 + c}, {N, g[0], g[1]}};
        else if (c < 5)
          d = {3, {9 + c - 3, 11 + c - 3, 13 + c - 3}, {N, g[0], g[1]}};
        return d; // alpha: not a plate variable
      }

      Drive
      rim_drive(const unsigned int c, const double N, const double dS)
      {
        if (c < 3)
          return {2, {c, 3 + c, 0}, {N, dS, 0}};
        if (c < 5)
          return {2, {6 + c - 3, 8 + c - 3, 0}, {N, dS, 0}};
        return {2, {10, 11, 0}, {N, dS, 0}};
      }

      // COSMO_PLATE_NESTED_AD=1: nested AD of the plate energy even where the
      // model has a chain rule (to measure against, benchmarks/README.md).
      const bool nested_ad_only = std::getenv("COSMO_PLATE_NESTED_AD") != nullptr;

      /// The covariant shear strain of component comp_k at a tying point (local variables z,
      /// Jacobian J) with its gradient (and with `jacobian` its Hessian) in the local variables.
      void
      tied_strain_derivatives(const kinematics::PlateModel &         model,
                              const std::array<double, n_plate> &    z,
                              const Tensor<2, 2> &                   J,
                              const unsigned int                     comp_k,
                              const bool                             jacobian,
                              double &                               strain,
                              std::array<double, n_plate> &          gradient,
                              std::array<double, n_plate * n_plate> &hessian)
      {
        // The model's own chain rule if it has one; else nested AD: the
        // shear depends on du/dX and theta, local variables 3 to 10.
        if (nested_ad_only ||
            !model.covariant_shear_strain_derivatives(z, J, comp_k, jacobian, strain, gradient, hessian))
          {
            materials::internal::differentiate_subset<8>(
              z, 3,
              [&](const auto &x) {
                using Number = std::decay_t<decltype(x[0])>;
                std::array<Number, n_plate> y;
                for (unsigned int m = 0; m < n_plate; ++m)
                  y[m] = m >= 3 && m < 11 ? x[m - 3] : Number(z[m]);
                return kinematics::covariant_shear_strain(y, model, J, comp_k);
              },
              jacobian, strain, gradient, hessian);
          }
      }

      /// Column k of V = de/dU: the gradient of the tied strain e_k in the local variables,
      /// through the drives of its tying location.
      void
      set_strain_column(FullMatrix<double> &               V,
                        const unsigned int                 k,
                        const std::vector<Drive> &         drives,
                        const std::array<double, n_plate> &gradient)
      {
        for (unsigned int i = 0; i < drives.size(); ++i)
          {
            double v = 0;
            for (unsigned int p = 0; p < drives[i].n; ++p)
              v += drives[i].w[p] * gradient[drives[i].var[p]];
            V(i, k) = v;
          }
      }

      /// sum_k mu_k (de_k/dU, d2e_k/dU2) of the `strains` tied at one location (their
      /// derivatives in the local variables summed) into c, through the location's drives.
      void
      add_tied_strain_terms(const std::vector<Drive> &                                drives,
                            const std::vector<unsigned int> &                         strains,
                            const std::vector<double> &                               mu,
                            const std::vector<std::array<double, n_plate>> &          gradients,
                            const std::vector<std::array<double, n_plate * n_plate>> &hessians,
                            const bool                                                jacobian,
                            assembly::CellContribution &                              c)
      {
        std::array<double, n_plate>           g;
        std::array<double, n_plate * n_plate> H; // (read by add_point only with the Jacobian)
        g.fill(0.);
        if (jacobian)
          H.fill(0.);
        for (const unsigned int k : strains)
          {
            for (unsigned int m = 0; m < n_plate; ++m)
              g[m] += mu[k] * gradients[k][m];
            if (jacobian)
              for (unsigned int m = 0; m < n_plate * n_plate; ++m)
                H[m] += mu[k] * hessians[k][m];
          }
        assembly::add_point<n_plate>(drives, g, H, 1., jacobian, c.residual, c.hessian);
      }
    } // namespace

    /// Per-thread work space of the cell loop (WorkStream scratch).
    struct PlateRodAssembly::Scratch
    {
      Scratch(const Mapping<2> &     mapping,
              const FiniteElement<2> &fe,
              const Quadrature<2> &   full,
              const Quadrature<2> &   reduced,
              const Quadrature<1> &   face,
              const Quadrature<2> &   tying)
        : fev_full(mapping, fe, full,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values | update_inverse_jacobians)
        , fev_reduced(mapping, fe, reduced,
                      update_values | update_gradients | update_quadrature_points |
                        update_JxW_values)
        , fev_face(mapping, fe, face,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values | update_normal_vectors)
        , fev_tying(mapping, fe, tying, update_values | update_gradients | update_jacobians)
        , U_local(fe.n_dofs_per_cell())
      {}
      Scratch(const Scratch &o)
        : Scratch(o.fev_full.get_mapping(), o.fev_full.get_fe(), o.fev_full.get_quadrature(),
                  o.fev_reduced.get_quadrature(), o.fev_face.get_quadrature(),
                  o.fev_tying.get_quadrature())
      {}
      FEValues<2>         fev_full, fev_reduced;
      FEFaceValues<2>     fev_face;
      FEValues<2>         fev_tying;
      std::vector<double> U_local;
      std::vector<Drive>  drives;
      /// Assumed shear: per tying point its drives, the covariant strain and its derivatives
      /// in the local variables; V(i, k) = d e_k / d U_i; the energy's derivatives in the e_k.
      std::vector<std::vector<Drive>>                                    tying_drives; ///< per location
      std::vector<std::array<double, kinematics::plate_local_variables>> tying_z; ///< per location
      std::vector<double>                                                tying_strain;
      std::vector<std::array<double, kinematics::plate_local_variables>> tying_gradient;
      std::vector<std::array<double, kinematics::plate_local_variables *
                                       kinematics::plate_local_variables>>
                         tying_hessian;
      FullMatrix<double> V, M, VM;
      std::vector<double> mu;

      /// The assumed shear's work space for the cell fev_full is on, zeroed.
      void
      prepare_tying(const unsigned int n_locations,
                    const unsigned int n_tying,
                    const unsigned int dpc,
                    const bool         jacobian)
      {
        fev_tying.reinit(fev_full.get_cell());
        tying_drives.resize(n_locations);
        tying_z.resize(n_locations);
        tying_strain.resize(n_tying);
        tying_gradient.resize(n_tying);
        tying_hessian.resize(n_tying);
        V.reinit(dpc, n_tying);
        mu.assign(n_tying, 0.);
        if (jacobian)
          {
            M.reinit(n_tying, n_tying);
            VM.reinit(dpc, n_tying);
          }
      }
    };

    /// What every cell of one assembly shares: the load, the laws at it, the
    /// assumed shear's tying points and weights.
    struct PlateRodAssembly::CellLoopData
    {
      CellLoopData(const PlateRodAssembly &a, const Quadrature<2> &full, const double t,
                   const bool jacobian)
        : dpc(a.discretization.fe->n_dofs_per_cell())
        , comp(dpc)
        , assumed_shear(a.parameters.degree,
                        a.parameters.shear_integration != ShearIntegration::interior_tying)
        , tying_weights(assumed_shear.interpolation(full))
        , n_tying(assumed_shear.n_tying_points())
        , n_locations(assumed_shear.tying_points().size())
        , strains_at(n_locations)
        , t(t)
        , rim_natural_curvature(a.parameters.rim_growth->natural_curvature(t))
        , shear_scale(a.parameters.model->shear_scale())
        , jacobian(jacobian)
      {
        for (unsigned int i = 0; i < dpc; ++i)
          comp[i] = a.discretization.fe->system_to_component_index(i).first;
        // The tied strains at each location (e_0 and e_1 share some), once per assembly.
        for (unsigned int k = 0; k < n_tying; ++k)
          strains_at[assumed_shear.location_of(k)].push_back(k);
      }
      const unsigned int        dpc;
      std::vector<unsigned int> comp;
      /// The assumed shear's tying points and their weights at the full quadrature.
      const assembly::AssumedShear           assumed_shear;
      const FullMatrix<double>               tying_weights;
      const unsigned int                     n_tying, n_locations;
      std::vector<std::vector<unsigned int>> strains_at;
      const double                           t;
      const std::array<double, 3>            rim_natural_curvature;
      const double                           shear_scale;
      const bool                             jacobian;
    };

    // The transverse shear of one cell with assumed covariant strains (fev_full reinit on it):
    // the energy E = sum_q W_q(e(q)) JxW_q, e(q) = sum_k N_qk e_k, depends on the DoFs through
    // the tying points' strains e_k only, so its gradient is sum_k mu_k de_k/dU and its Hessian
    // V M V^T + sum_k mu_k d2e_k/dU2, with mu_k = dE/de_k, M_kl = d2E/de_k de_l, V = de/dU.
    double
    PlateRodAssembly::assumed_shear_of_cell(const CellLoopData &        d,
                                            Scratch &                   sc,
                                            assembly::CellContribution &c) const
    {
      const unsigned int dpc = d.dpc, n_tying = d.n_tying, n_locations = d.n_locations;
      const auto &       comp          = d.comp;
      const auto &       assumed_shear = d.assumed_shear;
      const auto &       tying_weights = d.tying_weights;
      const auto &       strains_at    = d.strains_at;
      const double       t = d.t, shear_scale = d.shear_scale;
      const bool         jacobian = d.jacobian;
      sc.prepare_tying(n_locations, n_tying, dpc, jacobian);
      // The fields at each location (e_0 and e_1 share some), then each tied strain.
      for (unsigned int l = 0; l < n_locations; ++l)
        {
          auto &drives = sc.tying_drives[l];
          drives.resize(dpc);
          for (unsigned int i = 0; i < dpc; ++i)
            drives[i] = plate_drive(comp[i], sc.fev_tying.shape_value(i, l),
                                    sc.fev_tying.shape_grad(i, l));
          sc.tying_z[l].fill(0.);
          assembly::gather_local_variables<n_plate>(drives, sc.U_local, sc.tying_z[l]);
        }
      // Location by location: the strains tied at one location follow each other, so that
      // the model's shear derivatives can reuse its director there.
      for (unsigned int location = 0; location < n_locations; ++location)
        for (const unsigned int k : strains_at[location])
          {
            tied_strain_derivatives(*parameters.model, sc.tying_z[location],
                                    sc.fev_tying.jacobian(location), assumed_shear.component(k),
                                    jacobian, sc.tying_strain[k], sc.tying_gradient[k],
                                    sc.tying_hessian[k]);
            set_strain_column(sc.V, k, sc.tying_drives[location], sc.tying_gradient[k]);
          }
      double energy = 0;
      const FEValues<2> &fev = sc.fev_full;
      for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
        {
          std::array<double, 2> e{{0., 0.}};
          for (unsigned int k = 0; k < n_tying; ++k)
            e[assumed_shear.component(k)] += tying_weights(q, k) * sc.tying_strain[k];
          const auto         gr   = parameters.growth_at(fev.quadrature_point(q), t);
          const Tensor<2, 2> Kinv = fev.inverse_jacobian(q);
          const auto         law  = parameters.plate_law_at(fev.quadrature_point(q));
          double                W = 0;
          std::array<double, 2> dW;
          std::array<double, 4> ddW;
          materials::internal::differentiate<2>(
            e,
            [&](const auto &x) {
              return kinematics::assumed_shear_energy(x, Kinv, gr, law, shear_scale);
            },
            jacobian, W, dW, ddW);
          energy += W * fev.JxW(q);
          for (unsigned int k = 0; k < n_tying; ++k)
            {
              const double a = fev.JxW(q) * tying_weights(q, k);
              sc.mu[k] += a * dW[assumed_shear.component(k)];
              if (jacobian)
                for (unsigned int l = 0; l < n_tying; ++l)
                  sc.M(k, l) += a * tying_weights(q, l) *
                                ddW[2 * assumed_shear.component(k) + assumed_shear.component(l)];
            }
        }
      // sum_k mu_k (de_k/dU, d2e_k/dU2) through the drives, one pass per location (the
      // strains tied there summed), then V M V^T.
      for (unsigned int l = 0; l < n_locations; ++l)
        add_tied_strain_terms(sc.tying_drives[l], strains_at[l], sc.mu, sc.tying_gradient,
                              sc.tying_hessian, jacobian, c);
      if (jacobian)
        {
          sc.V.mmult(sc.VM, sc.M);
          sc.VM.mTmult(c.hessian, sc.V, true);
        }
      return energy;
    }

    void
    PlateRodAssembly::plate_of_cell(const CellLoopData &                         d,
                                    const DoFHandler<2>::active_cell_iterator &cell,
                                    Scratch &                                    sc,
                                    assembly::CellContribution &                 c) const
    {
      const unsigned int dpc  = d.dpc;
      const auto &       comp = d.comp;
      const double       t = d.t, shear_scale = d.shear_scale;
      const bool         jacobian = d.jacobian;
      sc.drives.resize(dpc);
      std::array<double, n_plate>           z, g;
      std::array<double, n_plate * n_plate> H;
      const auto shear_integration = parameters.shear_integration;
      const bool stabilized_shear  = shear_integration == ShearIntegration::stabilized;
      for (const bool membrane_bending : {true, false})
        {
          if (!membrane_bending && (shear_integration == ShearIntegration::assumed_strain ||
                                    shear_integration == ShearIntegration::interior_tying))
            {
              c.scalars[0] += assumed_shear_of_cell(d, sc, c);
              continue;
            }
          FEValues<2> &fev =
            membrane_bending || stabilized_shear ? sc.fev_full : sc.fev_reduced;
          const double cell_shear_scale =
            !membrane_bending && stabilized_shear ?
              kinematics::stabilized_shear_scale(parameters.thickness_at(cell->center()),
                                                 shear_scale, parameters.shear_stabilization,
                                                 cell->diameter()) :
              shear_scale;
          fev.reinit(cell);
          for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
            {
              z.fill(0.);
              for (unsigned int i = 0; i < dpc; ++i)
                sc.drives[i] = plate_drive(comp[i], fev.shape_value(i, q), fev.shape_grad(i, q));
              assembly::gather_local_variables<n_plate>(sc.drives, sc.U_local, z);
              const auto gr  = parameters.growth_at(fev.quadrature_point(q), t);
              const auto law = parameters.plate_law_at(fev.quadrature_point(q));
              double     W   = 0;
              // The plate energy depends on the gradients of u, on theta and (membrane and
              // bending only) on its gradients: 12 resp. 8 of the 15 local variables are
              // differentiated (the cost of nested AD grows like the square).
              auto energy_of = [&](const auto &x) {
                using Number = std::decay_t<decltype(x[0])>;
                std::array<Number, n_plate> y;
                for (unsigned int k = 0; k < n_plate; ++k)
                  y[k] = k >= 3 && k < 3 + x.size() ? x[k - 3] : Number(z[k]);
                return kinematics::plate_energy(y, gr, law, *parameters.model, membrane_bending,
                                                cell_shear_scale);
              };
              // The model's own chain rule if it has one (the Cosserat kinematics).
              if (nested_ad_only ||
                  !parameters.model->plate_energy_derivatives(z, gr, law, membrane_bending, cell_shear_scale,
                                                   jacobian, W, g, H))
                {
                  if (membrane_bending)
                    materials::internal::differentiate_subset<12>(z, 3, energy_of, jacobian, W, g, H);
                  else
                    materials::internal::differentiate_subset<8>(z, 3, energy_of, jacobian, W, g, H);
                }
              c.scalars[0] += W * fev.JxW(q);
              assembly::add_point<n_plate>(sc.drives, g, H, fev.JxW(q), jacobian, c.residual,
                                           c.hessian);
            }
        }
    }

    void
    PlateRodAssembly::rim_of_cell(const CellLoopData &                         d,
                                  const DoFHandler<2>::active_cell_iterator &cell,
                                  Scratch &                                    sc,
                                  assembly::CellContribution &                 c) const
    {
      const unsigned int dpc      = d.dpc;
      const auto &       comp     = d.comp;
      const auto &       rim_natural_curvature = d.rim_natural_curvature;
      const bool         jacobian = d.jacobian;
      // The rim rod on the cell's rim faces.
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
          {
            sc.fev_face.reinit(cell, f);
            std::array<double, n_rim>         zr, gr;
            std::array<double, n_rim * n_rim> Hr;
            for (unsigned int q = 0; q < sc.fev_face.n_quadrature_points; ++q)
              {
                const Point<2> X     = sc.fev_face.quadrature_point(q);
                const auto     frame = kinematics::circular_rim_frame(X, sc.fev_face.normal_vector(q));
                const Tensor<1, 2> t2({frame.tangent[0], frame.tangent[1]});
                zr.fill(0.);
                for (unsigned int i = 0; i < dpc; ++i)
                  sc.drives[i] = rim_drive(comp[i], sc.fev_face.shape_value(i, q),
                                           sc.fev_face.shape_grad(i, q) * t2);
                assembly::gather_local_variables<n_rim>(sc.drives, sc.U_local, zr);
                const auto ring = parameters.rim_natural_state(X, frame, d.t);
                double     W    = 0;
                materials::internal::differentiate<n_rim>(
                  zr,
                  [&](const auto &x) {
                    return kinematics::rim_rod_energy(x, frame, *parameters.rim_law, ring,
                                                      *parameters.model,
                                                      rim_natural_curvature);
                  },
                  jacobian, W, gr, Hr);
                c.scalars[1] += W * sc.fev_face.JxW(q);
                assembly::add_point<n_rim>(sc.drives, gr, Hr, sc.fev_face.JxW(q), jacobian,
                                           c.residual, c.hessian);
              }
          }
    }

    int
    PlateRodAssembly::assemble(const Vector<double> &U,
                               const double          t,
                               Vector<double> *      R,
                               const bool            jacobian)
    {
      const unsigned int degree = parameters.degree;
      const QGauss<2>    full(degree + 1), reduced(degree);
      const QGauss<1>    face(degree);
      const CellLoopData data(*this, full, t, jacobian);
      // The cell's scalars: the plate's energy and the rim's.
      auto worker = [&](const typename DoFHandler<2>::active_cell_iterator &cell,
                        Scratch &                                           sc,
                        assembly::CellContribution &                        c) {
        for (unsigned int i = 0; i < data.dpc; ++i)
          sc.U_local[i] = U[c.dof_indices[i]];
        plate_of_cell(data, cell, sc, c);
        rim_of_cell(data, cell, sc, c);
      };

      // A Jacobian assembly computes the residual at its state as well (the
      // local gradients are at hand): it is kept for the drivers' next request.
      Vector<double> jacobian_residual;
      if (!R)
        R = &jacobian_residual;
      R->reinit(discretization.n_dofs());
      if (jacobian)
        system.clear();
      assembly::AssemblyTarget target;
      target.residual    = R;
      target.jacobian    = jacobian;
      target.system      = &system;
      target.constraints = &discretization.constraints;
      const auto totals  = assembly::EnergyAssembler<2>::assemble(
        discretization.dof_handler, worker,
        Scratch(*discretization.mapping, *discretization.fe, full, reduced, face,
                data.assumed_shear.tying_points()),
        assembly::CellContribution(data.dpc, 0, 2), target);
      double plate_energy = totals.scalars[0], rod_energy = totals.scalars[1];
      if (parameters.distributed_mesh)
        {
          // Every rank holds the whole residual and energies, the same bits on each.
          if (jacobian)
            system.distributed_matrix.compress(VectorOperation::add);
          discretization.layout.sum_parts(*R);
          std::vector<double> e = {plate_energy, rod_energy};
          discretization.layout.sum(e);
          plate_energy = e[0];
          rod_energy   = e[1];
        }
      // Every assembly evaluates the energy: keep it with its state, so that the
      // output of a converged step need not assemble once more.
      assembled_at       = U;
      assembled_load     = t;
      assembled_energy   = {{plate_energy, rod_energy}};
      residuals.store(U, t, *R, {plate_energy, rod_energy});
      return std::isfinite(plate_energy + rod_energy) ? 0 : 1;
    }

  } // namespace plate_rod
} // namespace cosmo
