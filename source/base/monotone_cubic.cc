#include <cosmo/base/monotone_cubic.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosmo
{
  namespace base
  {
    MonotoneCubic::MonotoneCubic(const std::vector<double> &x_, const std::vector<double> &y_)
      : x(x_)
      , y(y_)
      , slope(x_.size(), 0.)
    {
      const std::size_t n = x.size();
      if (n == 0 || y.size() != n)
        throw std::invalid_argument("MonotoneCubic: as many values as nodes, at least one");
      for (std::size_t i = 1; i < n; ++i)
        if (!(x[i] > x[i - 1]))
          throw std::invalid_argument("MonotoneCubic: nodes must increase strictly");
      if (n == 1)
        return;
      std::vector<double> h(n - 1), d(n - 1); // interval widths and secants
      for (std::size_t i = 0; i + 1 < n; ++i)
        {
          h[i] = x[i + 1] - x[i];
          d[i] = (y[i + 1] - y[i]) / h[i];
        }
      if (n == 2)
        {
          slope[0] = slope[1] = d[0];
          return;
        }
      // Interior: the weighted harmonic mean of the secants where they have
      // one sign (Fritsch-Butland), zero at a local extremum of the data.
      for (std::size_t i = 1; i + 1 < n; ++i)
        if (d[i - 1] * d[i] > 0)
          {
            const double w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
            slope[i]        = (w1 + w2) / (w1 / d[i - 1] + w2 / d[i]);
          }
      // Ends: the three-point one-sided formula, kept from overshooting.
      auto end_slope = [](const double h0, const double h1, const double d0, const double d1) {
        double m = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
        if (m * d0 <= 0)
          m = 0;
        else if (d0 * d1 <= 0 && std::abs(m) > 3 * std::abs(d0))
          m = 3 * d0;
        return m;
      };
      slope[0]     = end_slope(h[0], h[1], d[0], d[1]);
      slope[n - 1] = end_slope(h[n - 2], h[n - 3], d[n - 2], d[n - 3]);
    }

    unsigned int
    MonotoneCubic::interval(const double v) const
    {
      const auto it = std::upper_bound(x.begin(), x.end(), v);
      const long i  = static_cast<long>(it - x.begin()) - 1;
      return static_cast<unsigned int>(std::clamp<long>(i, 0, static_cast<long>(x.size()) - 2));
    }

    double
    MonotoneCubic::value(const double v) const
    {
      if (x.size() == 1)
        return y[0];
      const unsigned int i = interval(v);
      const double       h = x[i + 1] - x[i], s = (v - x[i]) / h;
      const double       h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
      const double       h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
      return h00 * y[i] + h10 * h * slope[i] + h01 * y[i + 1] + h11 * h * slope[i + 1];
    }

    double
    MonotoneCubic::derivative(const double v) const
    {
      if (x.size() == 1)
        return 0;
      const unsigned int i = interval(v);
      const double       h = x[i + 1] - x[i], s = (v - x[i]) / h;
      const double       d00 = 6 * s * (s - 1) / h, d10 = (1 - s) * (1 - 3 * s);
      const double       d01 = -d00, d11 = s * (3 * s - 2);
      return d00 * y[i] + d10 * slope[i] + d01 * y[i + 1] + d11 * slope[i + 1];
    }
  } // namespace base
} // namespace cosmo
