#ifndef cosmo_materials_plate_growth_h
#define cosmo_materials_plate_growth_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <cosmo/base/plugins.h>

#include <array>
#include <vector>
#include <memory>
#include <string>

/**
 * In-plane growth of a plate (doc/specification/plate-rod.md): G = g_r e_r (x) e_r +
 * g_t e_t (x) e_t in polar axes about the origin, the factors expressions of
 * the radius r (isotropic: g_r = g_t = g). Ramped by the load parameter as
 * 1 + t (g - 1). Section "Plate growth".
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /**
     * A law of in-plane plate growth: the factors (g_r, g_t) at radius r and
     * load t (ramped by growth_ramp). Implementations register themselves by
     * name (COSMO_REGISTER_PLUGIN, base/plugins.h), one file each in
     * source/materials/plate_growth_laws/; the names are the values of
     * 'Plate growth / Kind' (doc/cookbook.md).
     */
    class PlateGrowthLaw
    {
    public:
      virtual ~PlateGrowthLaw() = default;
      /// Reads its entries in 'Plate growth' (entered).
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;
      /// (g_r, g_t) at radius r and load t.
      virtual std::array<double, 2>
      factors(double r, double t) const = 0;
    };

    /**
     * An expression of the radius r (and pi) given in entry `entry` of
     * 'Plate growth'; an io::InputError names both if it does not parse.
     */
    std::shared_ptr<FunctionParser<1>>
    parse_expression_of_r(const std::string &text, const std::string &entry);

    /**
     * n_components muparser expressions (separated by ';') of the position
     * x, y and the radius r (and pi), given in entry `entry` of section
     * `section`: evaluate at Point<3>(x, y, r). An io::InputError names
     * both if they do not parse.
     */
    std::shared_ptr<FunctionParser<3>>
    parse_expression_of_position(const std::string &text,
                                 const std::string &section,
                                 const std::string &entry,
                                 unsigned int       n_components);

    /// The plate's growth G = g_r e_r (x) e_r + g_t e_t (x) e_t from the law 'Kind' names.
    class PlateGrowth
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// G at X (2x2 in the plate's reference axes) for load parameter t.
      std::array<std::array<double, 2>, 2>
      value(const Point<2> &X, double t) const;

      /// The factors (g_r, g_t) at radius r for load parameter t.
      std::array<double, 2>
      factors(double r, double t) const;

      /**
       * io::InputError naming the factor's entry unless both factors are
       * finite and positive at the given points (every vertex and quadrature
       * point of the plate's mesh) for 0 <= t <= 1
       * (materials::check_growth_admissible).
       */
      void
      check_admissible(const std::vector<Point<2>> &points, MPI_Comm comm) const;

      /**
       * The natural (target) curvature of the grown plate at X for load
       * parameter t, (k11, k22, k12) in the plate's axes: t times 'Natural
       * curvature', the bending strain at which the plate is free of
       * moments (growth or heating that differs through the thickness).
       */
      std::array<double, 3>
      natural_curvature(const Point<2> &X, double t) const;
      /// Whether 'Natural curvature' is not the default 0; 0; 0.
      bool
      has_natural_curvature() const
      {
        return curvature != nullptr;
      }
      /// io::InputError unless 'Natural curvature' is finite at the given points.
      void
      check_natural_curvature(const std::vector<Point<2>> &points) const;

    private:
      std::shared_ptr<const PlateGrowthLaw> law;
      std::string                           radial_text, circumferential_text, curvature_text;
      std::shared_ptr<FunctionParser<3>>    curvature; ///< null: no natural curvature
    };
  } // namespace materials
} // namespace cosmo

namespace cosmo
{
  namespace plugins
  {
    // One registry of plate growth laws per process (instantiated in source/materials/plate_growth.cc).
    extern template class Registry<materials::PlateGrowthLaw>;
  } // namespace plugins
} // namespace cosmo

#endif
