#ifndef cosmo_base_monotone_cubic_h
#define cosmo_base_monotone_cubic_h

#include <vector>

/**
 * Piecewise cubic Hermite interpolation with the Fritsch-Carlson slopes
 * (PCHIP; Fritsch & Carlson, SIAM J. Numer. Anal. 17, 1980): C1, exact at
 * the nodes, exact for linear data, and without overshoot between nodes (a
 * monotone run of data stays monotone, an extremum sits at a node). Used
 * where a quantity tabulated over a parameter must be smooth in it (a rod
 * law over a family of sections: the energy's parameter derivative exists
 * and a stiffness does not overshoot into negative values).
 */
namespace cosmo
{
  namespace base
  {
    class MonotoneCubic
    {
    public:
      MonotoneCubic() = default;
      /// Nodes x (strictly increasing, at least one) and values y.
      MonotoneCubic(const std::vector<double> &x, const std::vector<double> &y);
      /// The value at x (the end values' Hermite extrapolation outside: callers check the range).
      double
      value(double x) const;
      /// The derivative at x.
      double
      derivative(double x) const;

    private:
      std::vector<double> x, y, slope;
      /// The interval [x_i, x_i+1] holding x (the first or last outside).
      unsigned int
      interval(double x) const;
    };
  } // namespace base
} // namespace cosmo

#endif
