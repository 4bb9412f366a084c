// The surface layer's Sacado instantiation lives here, apart from the bulk's
// (material.cc), so that each heavy translation unit stays small.
#include <deal.II/base/utilities.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>
#include <cosmo/materials/surface_layer.h>

#include <cmath>

#include <cosmo/materials/energy_derivatives.h>

#include <sstream>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::SurfaceGrowthLaw>;
  } // namespace plugins

  namespace materials
  {
    namespace
    {
      /// Jsg Ws(Es) with Fse = Fs diag(1/gT, 1/g3), in any number type.
      template <typename Number>
      Number
      surface_energy(const std::array<Number, 6> &Fs,
                     const std::array<double, 2> &g,
                     const double                 tension,
                     const double                 lambda_s,
                     const double                 mu_s)
      {
        // Cse = Fse^T Fse (2x2, symmetric)
        Number c00 = Fs[0] * Fs[0];
        c00 += Fs[2] * Fs[2];
        c00 += Fs[4] * Fs[4];
        Number c11 = Fs[1] * Fs[1];
        c11 += Fs[3] * Fs[3];
        c11 += Fs[5] * Fs[5];
        Number c01 = Fs[0] * Fs[1];
        c01 += Fs[2] * Fs[3];
        c01 += Fs[4] * Fs[5];
        const Number e00 = 0.5 * (c00 / (g[0] * g[0]) - 1.);
        const Number e11 = 0.5 * (c11 / (g[1] * g[1]) - 1.);
        const Number e01 = 0.5 * c01 / (g[0] * g[1]);
        const Number tr  = e00 + e11;
        Number       EE  = e00 * e00;
        EE += 2. * e01 * e01;
        EE += e11 * e11;
        Number W = tension * tr;
        W += 0.5 * lambda_s * tr * tr;
        W += mu_s * EE;
        return (g[0] * g[1]) * W;
      }
    } // namespace

    std::array<double, 2>
    SurfaceLayer::growth(const Point<2> &X, const double t) const
    {
      return growth_law ? growth_law->growth(X, t) : std::array<double, 2>{{1., 1.}};
    }

    void
    SurfaceLayer::evaluate(const std::array<double, 6> &Fs,
                           const std::array<double, 2> &g,
                           const double                 tension_factor,
                           const bool                   tangent,
                           SurfaceEnergyDerivatives &   out) const
    {
      const double tau = tension_factor * tension;
      internal::differentiate<6>(
        Fs,
        [&](const auto &x) { return surface_energy(x, g, tau, lambda_s, mu_s); },
        tangent, out.energy, out.P, out.C);
    }

    double
    SurfaceLayer::energy(const std::array<double, 6> &Fs,
                         const std::array<double, 2> &g,
                         const double                 tension_factor) const
    {
      return surface_energy(Fs, g, tension_factor * tension, lambda_s, mu_s);
    }

    std::array<double, 3>
    SurfaceLayer::stress(const std::array<double, 6> &Fs,
                         const std::array<double, 2> &g,
                         const double                 tension_factor) const
    {
      const double c00 = Fs[0] * Fs[0] + Fs[2] * Fs[2] + Fs[4] * Fs[4];
      const double c11 = Fs[1] * Fs[1] + Fs[3] * Fs[3] + Fs[5] * Fs[5];
      const double c01 = Fs[0] * Fs[1] + Fs[2] * Fs[3] + Fs[4] * Fs[5];
      const double e00 = 0.5 * (c00 / (g[0] * g[0]) - 1.), e11 = 0.5 * (c11 / (g[1] * g[1]) - 1.),
                   e01 = 0.5 * c01 / (g[0] * g[1]);
      const double p = tension_factor * tension + lambda_s * (e00 + e11);
      return {{p + 2 * mu_s * e00, p + 2 * mu_s * e11, 2 * mu_s * e01}};
    }

    std::string
    SurfaceLayer::description() const
    {
      std::ostringstream s;
      s << name << " on '" << boundary_parts << "': tau0 = " << tension
        << ", lambda_s = " << lambda_s << ", mu_s = " << mu_s << ", ";
      s << (growth_law ? growth_law->description() : std::string("no growth"));
      return s.str();
    }

    void
    SurfaceLayerLibrary::declare_parameters(ParameterHandler &prm)
    {
      for (unsigned int k = 1; k <= max_layers; ++k)
        {
          prm.enter_subsection("Surface layer " + std::to_string(k));
          prm.declare_entry("Boundary parts", "", Patterns::Anything(),
                            "Which part of the section's boundary curve (the rod's "
                            "lateral surface) carries this layer: a comma-separated list "
                            "of 'all', boundary part names ('outer'; annulus: 'inner'; "
                            "rectangle and bilayer: 'left', 'right', 'bottom', 'top'; gmsh: "
                            "the names of physical curves) and arcs 'arc A B' (the faces "
                            "whose midpoint has polar angle in [A, B) degrees about the "
                            "centroid, counterclockwise from X1). Empty: no layer.");
          prm.declare_entry("Name", "surface layer " + std::to_string(k), Patterns::Anything(),
                            "A name for output.");
          prm.declare_entry("Surface tension", "0", Patterns::Double(),
                            "tau0, the surface stress of the reference state (force per "
                            "length); ramped with the load parameter t like growth.");
          prm.declare_entry("Surface Lame modulus", "0", Patterns::Double(),
                            "lambda_s of Ws = tau0 tr Es + lambda_s/2 (tr Es)^2 + mu_s Es:Es "
                            "(force per length).");
          prm.declare_entry("Surface shear modulus", "0", Patterns::Double(0),
                            "mu_s of the surface law (force per length); the layer's "
                            "in-plane Young's modulus times thickness is "
                            "4 mu_s (lambda_s + mu_s)/(lambda_s + 2 mu_s).");
          using Laws = plugins::Registry<SurfaceGrowthLaw>;
          prm.declare_entry("Growth kind", "none", Patterns::Selection(Laws::names()),
                            "Surface growth Fsg = diag(gT, g3) in the (boundary tangent, "
                            "axis) basis (the registered surface growth laws, "
                            "source/materials/surface_growth_laws/). " + Laws::documentation());
          prm.declare_entry("Growth factor", "1", Patterns::Anything(),
                            "Surface growth factor(s) as muparser expressions of the "
                            "boundary point x, y: one expression (isotropic) or two "
                            "separated by ';' (gT along the boundary; g3 along the axis). "
                            "Ramped as 1 + t (g - 1).");
          Laws::declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    void
    SurfaceLayerLibrary::parse_parameters(ParameterHandler &prm)
    {
      active_layers.clear();
      for (unsigned int k = 1; k <= max_layers; ++k)
        {
          const std::string section = "Surface layer " + std::to_string(k);
          prm.enter_subsection(section);
          SurfaceLayer l;
          l.section        = section;
          l.boundary_parts = Utilities::trim(prm.get("Boundary parts"));
          if (!l.boundary_parts.empty())
            {
              l.name     = prm.get("Name");
              l.tension  = prm.get_double("Surface tension");
              l.lambda_s = prm.get_double("Surface Lame modulus");
              l.mu_s     = prm.get_double("Surface shear modulus");
              for (const std::string entry :
                   {"Surface tension", "Surface Lame modulus", "Surface shear modulus"})
                if (!(std::abs(prm.get_double(entry)) <= 1e100))
                  throw io::InputError(section, entry, prm.get(entry),
                                       "a number of magnitude at most 1e100 (its products "
                                       "with itself and the lengths must stay finite)");
              // Ws is convex near Es = 0 iff mu_s >= 0 and lambda_s + mu_s >= 0
              // (the 2D bulk modulus); a negative one would be an unstable layer.
              if (l.lambda_s + l.mu_s < 0)
                throw io::InputError(section, "Surface Lame modulus",
                                     prm.get("Surface Lame modulus"),
                                     "lambda_s + mu_s must be >= 0 (the layer's areal "
                                     "modulus); mu_s = " + prm.get("Surface shear modulus"));
              l.growth_text = prm.get("Growth factor");
              auto law      = plugins::Registry<SurfaceGrowthLaw>::create(prm.get("Growth kind"));
              law->parse_parameters(prm, section);
              l.growth_law = std::move(law);
              active_layers.push_back(std::move(l));
            }
          prm.leave_subsection();
        }
    }

    std::vector<std::string>
    SurfaceLayerLibrary::descriptions() const
    {
      std::vector<std::string> d;
      for (const auto &l : active_layers)
        d.push_back(l.description());
      return d;
    }
  } // namespace materials
} // namespace cosmo
