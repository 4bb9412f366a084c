#ifndef cosmo_materials_plate_growth_h
#define cosmo_materials_plate_growth_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
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

    private:
      std::string                        kind = "none";
      std::shared_ptr<FunctionParser<1>> radial, circumferential;
    };
  } // namespace materials
} // namespace cosmo

#endif
