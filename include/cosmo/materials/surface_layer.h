#ifndef cosmo_materials_surface_layer_h
#define cosmo_materials_surface_layer_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <cosmo/base/plugins.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

/**
 * A Gurtin-Murdoch surface layer on the lateral surface of the rod, i.e. on
 * (part of) the boundary curve of the cross-section
 * (doc/specification/rod-cross-section.md, "Energy with growth").
 *
 * The surface deformation gradient maps the reference tangent plane, spanned
 * by the boundary tangent T and the axis E3, into space: a 3x2 matrix Fs with
 * columns dw/dS and nu + kappa x w. Surface growth Fsg = diag(gT, g3) in the
 * same (T, E3) basis; the elastic part Fse = Fs Fsg^-1 has the Green strain
 * Es = (Fse^T Fse - I)/2 and the energy per unit reference area is
 *
 *   Jsg Ws(Es),   Ws = tau0 tr Es + lambda_s/2 (tr Es)^2 + mu_s Es:Es,
 *
 * Jsg = gT g3. tau0 is the surface tension of the reference state (its
 * second Piola-Kirchhoff surface stress at Es = 0 is tau0 I); lambda_s and
 * mu_s are the surface Lame moduli (force per length). Derivatives with
 * respect to the six entries of Fs are taken by Sacado, as for the bulk.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /// Surface energy density and derivatives; Fs row-major 3x2, Fs[2r+a].
    struct SurfaceEnergyDerivatives
    {
      double                 energy = 0;
      std::array<double, 6>  P{}; ///< dWs/dFs
      std::array<double, 36> C{}; ///< d2Ws/dFs2, C[6*a+b]
    };

    /**
     * A surface growth law: Fsg = diag(gT, g3) in the (boundary tangent,
     * axis) basis at a boundary point, ramped to the load t. Implementations
     * register themselves by name (COSMO_REGISTER_PLUGIN, base/plugins.h),
     * one file each in source/materials/surface_growth_laws/; the names are
     * the values of a surface layer's 'Growth kind' (doc/cookbook.md).
     */
    class SurfaceGrowthLaw
    {
    public:
      virtual ~SurfaceGrowthLaw() = default;
      /// Reads its entries in the layer's section (entered; `where` names it).
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &where) = 0;
      /// (gT, g3) at boundary point X and load t (every factor ramped by growth_ramp).
      virtual std::array<double, 2>
      growth(const Point<2> &X, double t) const = 0;
      /// e.g. "isotropic growth g = 1.1"
      virtual std::string
      description() const = 0;
    };

    class SurfaceLayer
    {
    public:

      std::string name;
      std::string section;        ///< its parameter section, for error messages
      std::string boundary_parts; ///< which boundary it covers (resolved by the application)
      double      tension  = 0;   ///< tau0
      double      lambda_s = 0;   ///< surface Lame modulus
      double      mu_s     = 0;   ///< surface shear modulus

      /// Surface growth (gT, g3) at boundary point X, ramped as 1 + t (g - 1).
      std::array<double, 2>
      growth(const Point<2> &X, double t) const;

      /// Jsg Ws and dWs/dFs (and d2Ws/dFs2 if `tangent`) for tension scaled by t_tension.
      void
      evaluate(const std::array<double, 6> &Fs,
               const std::array<double, 2> &g,
               double                       tension_factor,
               bool                         tangent,
               SurfaceEnergyDerivatives &   out) const;

      /**
       * The second Piola-Kirchhoff surface stress dWs/dEs in the (T, E3)
       * basis of the grown layer, {S_TT, S_33, S_T3} (force per length;
       * negative: compression), for output.
       */
      std::array<double, 3>
      stress(const std::array<double, 6> &Fs,
             const std::array<double, 2> &g,
             double                       tension_factor) const;

      /// The energy alone in doubles (tests, finite differences).
      double
      energy(const std::array<double, 6> &Fs,
             const std::array<double, 2> &g,
             double                       tension_factor) const;

      std::string
      description() const;

      /// The registered law its 'Growth kind' names (shared: layers are copied).
      std::shared_ptr<const SurfaceGrowthLaw> growth_law;
      /// Its 'Growth factor' text (for error messages).
      std::string growth_text;
    };

    /**
     * Surface layers by boundary part: parameter sections "Surface layer 1"
     * and "Surface layer 2"; a layer with empty 'Boundary parts' is unused.
     */
    class SurfaceLayerLibrary
    {
    public:
      static constexpr unsigned int max_layers = 2;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      const std::vector<SurfaceLayer> &
      layers() const
      {
        return active_layers;
      }
      std::vector<std::string>
      descriptions() const;

    private:
      std::vector<SurfaceLayer> active_layers;
    };
  } // namespace materials
} // namespace cosmo

namespace cosmo
{
  namespace plugins
  {
    // One registry of surface growth laws per process (instantiated in source/materials/surface_layer.cc).
    extern template class Registry<materials::SurfaceGrowthLaw>;
  } // namespace plugins
} // namespace cosmo

#endif
