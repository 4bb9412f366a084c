#include <deal.II/base/quadrature_lib.h>

#include <cosmo/assembly/assumed_shear.h>

namespace cosmo
{
  namespace assembly
  {
    namespace
    {
      std::vector<double>
      gauss_points(const unsigned int n)
      {
        std::vector<double> x;
        const QGauss<1>     q(n);
        for (const auto &p : q.get_points())
          x.push_back(p[0]);
        return x;
      }

      /// The Lagrange polynomial of node j through the nodes x, at s.
      double
      lagrange(const std::vector<double> &x, const unsigned int j, const double s)
      {
        double l = 1;
        for (unsigned int m = 0; m < x.size(); ++m)
          if (m != j)
            l *= (s - x[m]) / (x[j] - x[m]);
        return l;
      }
    } // namespace

    AssumedShear::AssumedShear(const unsigned int degree)
      : n_per_component(degree * (degree + 1))
      , low(gauss_points(degree))
      , high(gauss_points(degree + 1))
    {
      std::vector<Point<2>> p;
      // e_0: the low points along xi_0, the high points along xi_1; e_1 the transpose.
      for (unsigned int c = 0; c < 2; ++c)
        for (const double b : high)
          for (const double a : low)
            p.push_back(c == 0 ? Point<2>(a, b) : Point<2>(b, a));
      points = Quadrature<2>(p, std::vector<double>(p.size(), 1.));
    }

    FullMatrix<double>
    AssumedShear::interpolation(const Quadrature<2> &q) const
    {
      FullMatrix<double> N(q.size(), points.size());
      for (unsigned int i = 0; i < q.size(); ++i)
        {
          const Point<2> &x = q.point(i);
          unsigned int    k = 0;
          for (unsigned int c = 0; c < 2; ++c)
            for (unsigned int jb = 0; jb < high.size(); ++jb)
              for (unsigned int ja = 0; ja < low.size(); ++ja, ++k)
                N(i, k) = lagrange(low, ja, x[c]) * lagrange(high, jb, x[1 - c]);
        }
      return N;
    }
  } // namespace assembly
} // namespace cosmo
