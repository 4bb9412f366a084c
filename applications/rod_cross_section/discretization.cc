// The section's discretization: mesh, element and DoFs, surface faces, growth at the points,
// and what is read off the mesh alone (mode parities, linear section properties).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/resources.h>
#include <cosmo/materials/growth_admissibility.h>
#include <cosmo/solvers/replicated_vector.h>

#include "discretization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace cosmo
{
  namespace rod
  {
    SectionDiscretization::SectionDiscretization(const CrossSectionParameters &parameters)
      : parameters(parameters)
    {}

    SectionDiscretization::~SectionDiscretization()
    {
      dof_handler.clear();
    }

    void
    SectionDiscretization::create_mesh()
    {
      const unsigned int degree = parameters.degree;
      this->triangulation.set_distributed(parameters.distributed_mesh);
      Triangulation<2> &triangulation = this->triangulation.get();
      // 3 displacement fields of degree p: about 3 p^2 unknowns per cell.
      const boost::signals2::scoped_connection guard(io::guard_refinement(
        triangulation, 3. * degree * degree, degree, "Cross-section", "Global refinements",
        std::to_string(parameters.geometry.refinements)));
      parameters.geometry.create_triangulation(triangulation);
    }

    std::vector<types::material_id>
    SectionDiscretization::material_ids() const
    {
      std::vector<types::material_id> ids;
      for (const auto &cell : triangulation.get().active_cell_iterators())
        if (std::find(ids.begin(), ids.end(), cell->material_id()) == ids.end())
          ids.push_back(cell->material_id());
      return ids;
    }

    void
    SectionDiscretization::distribute_dofs()
    {
      const unsigned int degree = parameters.degree;
      fe      = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 3);
      mapping = std::make_unique<MappingQ<2>>(degree);
      dof_handler.reinit(triangulation.get());
      dof_handler.distribute_dofs(*fe);
      section_properties = geometry::CrossSectionGeometry::properties(triangulation.get(), degree);
      setup_surface_faces();
      // (growth at the points of these DoFs' cells: none yet)
      growth_cached_for = std::numeric_limits<double>::quiet_NaN();
    }

    void
    SectionDiscretization::check_growth() const
    {
      const auto &    materials = parameters.materials;
      const MPI_Comm  comm      = parameters.distributed_mesh ? MPI_COMM_WORLD : MPI_COMM_SELF;
      const QGauss<2> quadrature(parameters.degree + 1);
      std::vector<types::material_id> ids = material_ids();
      // (every rank checks every material: the check is collective)
      if (parameters.distributed_mesh)
        ids = Utilities::MPI::compute_set_union(ids, comm);
      for (const auto id : ids)
        {
          const auto &material = materials.material(id);
          materials::check_growth_admissible(
            materials::growth_points(*mapping, triangulation.get(), quadrature,
                                     [id](const auto &cell) { return cell->material_id() == id; }),
            [&material](const Point<2> &X, const double t) {
              return std::vector<double>{determinant(material.growth.value(X, t))};
            },
            {material.section, "Growth factor", material.growth.factor_expression()},
            comm);
        }
      const QGauss<1> face_quadrature(parameters.degree + 1);
      for (const auto &layer : parameters.surface_layers.layers())
        {
          geometry::BoundarySelection selection;
          selection.parse(layer.boundary_parts, layer.section, "Boundary parts", parameters.geometry);
          materials::check_growth_admissible(
            materials::boundary_growth_points(*mapping, triangulation.get(), face_quadrature,
                                              [&selection](const auto &face) {
                                                return selection.contains(face);
                                              }),
            [&layer](const Point<2> &X, const double t) {
              const auto g = layer.growth(X, t);
              return std::vector<double>{g[0], g[1]};
            },
            {layer.section, "Growth factor", layer.growth_text, "each surface factor (gT, g3)"},
            comm);
        }
    }

    bool
    SectionDiscretization::update_growth_cache(const double load_parameter)
    {
      if (growth_cached_for == load_parameter)
        return true;
      // Outside [0, 1] (a trial load of Newton on an augmented system) the
      // ramp may leave det Fg > 0: an inadmissible state there (on [0, 1]
      // check_growth() has refused it at setup).
      const auto refuse = [&]() {
        growth_cached_for = std::numeric_limits<double>::quiet_NaN();
        return false;
      };
      const QGauss<2> quadrature(parameters.degree + 1);
      FEValues<2>     fev(*mapping, *fe, quadrature, update_quadrature_points);
      growth_at_qp.resize(triangulation.get().n_active_cells() * quadrature.size());
      // (on a distributed mesh: this rank's cells; assemble() decides together)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fev.reinit(cell);
          const auto &material = parameters.materials.material(cell->material_id());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, 3> Fg =
                material.growth.value(fev.quadrature_point(q), load_parameter);
              const double J = determinant(Fg);
              if (!(J > 0) || !std::isfinite(J))
                return refuse();
              growth_at_qp[cell->active_cell_index() * quadrature.size() + q] = Fg;
            }
        }

      const QGauss<1> face_quadrature(parameters.degree + 1);
      FEFaceValues<2> ffv(*mapping, *fe, face_quadrature, update_quadrature_points);
      const unsigned int nqf = face_quadrature.size();
      surface_growth_at_qp.resize(surface_faces.size() * nqf);
      for (unsigned int f = 0; f < surface_faces.size(); ++f)
        {
          const auto &sf    = surface_faces[f];
          const auto &layer = parameters.surface_layers.layers()[sf.layer];
          ffv.reinit(sf.cell, sf.face);
          for (unsigned int q = 0; q < nqf; ++q)
            {
              const Point<2> &X = ffv.quadrature_point(q);
              const auto      g = layer.growth(X, load_parameter);
              if (!(g[0] > 0 && g[1] > 0) || !std::isfinite(g[0]) || !std::isfinite(g[1]))
                return refuse();
              surface_growth_at_qp[f * nqf + q] = g;
            }
        }
      growth_cached_for = load_parameter;
      return true;
    }

    void
    SectionDiscretization::setup_surface_faces()
    {
      const auto &layers = parameters.surface_layers.layers();
      surface_faces.clear();
      surface_length.assign(layers.size(), 0.);
      const QGauss<1> face_quadrature(parameters.degree + 1);
      FEFaceValues<2> ffv(*mapping, *fe, face_quadrature, update_JxW_values);
      for (unsigned int l = 0; l < layers.size(); ++l)
        {
          const auto &layer = layers[l];
          geometry::BoundarySelection selection;
          selection.parse(layer.boundary_parts, layer.section, "Boundary parts", parameters.geometry);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() && selection.contains(cell->face(f)))
                {
                  surface_faces.push_back({cell, f, l});
                  ffv.reinit(cell, f);
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    surface_length[l] += ffv.JxW(q);
                }
        }
      // (a distributed mesh: each rank's faces, their lengths summed)
      if (parameters.distributed_mesh)
        solvers::sum_on_all_ranks(surface_length, MPI_COMM_WORLD);
      for (unsigned int l = 0; l < layers.size(); ++l)
        {
          const auto &layer = layers[l];
          if (surface_length[l] == 0)
            throw io::InputError(layer.section, "Boundary parts", layer.boundary_parts,
                                 "selects no boundary face of this section");
        }
    }

    double
    SectionDiscretization::mode_parity(const Vector<double> &mode, const unsigned int axis) const
    {
      // The half-turn about X_axis maps the section point X to its mirror
      // image about that axis (the other coordinate changes sign) and the
      // placement w by diag(+1 on X_axis, -1 on the others): a proper
      // rotation, a symmetry also of a twisted or stretched rod (a
      // reflection would reverse the twist).
      std::vector<double> signs = {-1., -1., -1.};
      signs[axis]               = 1.;
      return geometry::reflection_parity(
        dof_handler,
        geometry::mirror_dofs(*mapping, dof_handler, 1 - axis, section_properties.diameter), mode,
        signs);
    }

    analysis::LinearSectionProperties
    SectionDiscretization::linear_section_properties() const
    {
      const auto &materials = parameters.materials;
      // The small-strain moduli of each region's law, from its tangent at F = I
      // (isotropic: C_1212 = mu, C_1122 = lambda), so that any registered law works.
      std::map<types::material_id, analysis::RegionModuli> moduli;
      for (const auto &cell : triangulation.get().active_cell_iterators())
        if (moduli.count(cell->material_id()) == 0)
          {
            materials::EnergyDerivatives d;
            Tensor<2, 3>                 I;
            for (unsigned int i = 0; i < 3; ++i)
              I[i][i] = 1;
            materials.material(cell->material_id()).evaluate(I, I, true, d);
            const double mu = d.C[9 * 1 + 1], lambda = d.C[9 * 0 + 4];
            moduli[cell->material_id()] = {mu * (3 * lambda + 2 * mu) / (lambda + mu), mu,
                                           materials.material(cell->material_id()).density};
          }
      return analysis::linear_section_properties(triangulation.get(), *mapping, parameters.degree,
                                                 [&moduli](const types::material_id id) {
                                                   return moduli.at(id);
                                                 });
    }
  } // namespace rod
} // namespace cosmo
