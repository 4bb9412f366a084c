#include <deal.II/base/quadrature_lib.h>

#include <cosmo/assembly/assumed_shear.h>

#include <cmath>

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

    AssumedShear::AssumedShear(const unsigned int degree, const bool edge_tying)
      : n_per_component(degree * (degree + 1))
      , low(gauss_points(degree))
      , high(gauss_points(degree + 1))
      , edges(edge_tying)
    {
      if (edges)
        {
          // Along the tied direction: the values at the two edges and the
          // moments against P_{p-2} by p Gauss points (exact for a degree-p e).
          // (p = 1: the edge midpoints only, MITC4 of Bathe and Dvorkin.)
          along = {0., 1.};
          const QGauss<1> q(degree);
          if (degree >= 2)
            for (const auto &x : q.get_points())
              along.push_back(x[0]);
          const unsigned int n = degree + 1;
          FullMatrix<double> A(n, n), B(n, along.size());
          for (unsigned int m = 0; m < n; ++m)
            {
              A(0, m) = m == 0 ? 1. : 0.;
              A(1, m) = 1.;
            }
          B(0, 0) = 1.;
          B(1, 1) = 1.;
          for (unsigned int r = 0; r + 2 < n; ++r)
            {
              for (unsigned int m = 0; m < n; ++m)
                A(2 + r, m) = 1. / (m + r + 1); // int_0^1 s^m s^r ds
              for (unsigned int g = 0; g < q.size(); ++g)
                B(2 + r, 2 + g) = q.weight(g) * std::pow(q.point(g)[0], r);
            }
          A.gauss_jordan();
          coefficients.reinit(n, along.size());
          A.mmult(coefficients, B);
          n_per_component = degree * along.size();
        }
      // e_0: the low points along xi_0, the high (or edge) points along xi_1; e_1 the transpose.
      const std::vector<double> &second = edges ? along : high;
      for (unsigned int c = 0; c < 2; ++c)
        for (const double b : second)
          for (const double a : low)
            tied.push_back(c == 0 ? Point<2>(a, b) : Point<2>(b, a));
      // The distinct locations (the same coordinates bitwise: both come from one list).
      std::vector<Point<2>> distinct;
      for (const auto &x : tied)
        {
          unsigned int j = 0;
          while (j < distinct.size() && !(distinct[j][0] == x[0] && distinct[j][1] == x[1]))
            ++j;
          if (j == distinct.size())
            distinct.push_back(x);
          location.push_back(j);
        }
      points = Quadrature<2>(distinct, std::vector<double>(distinct.size(), 1.));
    }

    FullMatrix<double>
    AssumedShear::interpolation(const Quadrature<2> &q) const
    {
      FullMatrix<double> N(q.size(), tied.size());
      for (unsigned int i = 0; i < q.size(); ++i)
        {
          const Point<2> &x = q.point(i);
          unsigned int    k = 0;
          if (!edges)
            for (unsigned int c = 0; c < 2; ++c)
              for (unsigned int jb = 0; jb < high.size(); ++jb)
                for (unsigned int ja = 0; ja < low.size(); ++ja, ++k)
                  N(i, k) = lagrange(low, ja, x[c]) * lagrange(high, jb, x[1 - c]);
          else
            {
              for (unsigned int c = 0; c < 2; ++c)
                for (unsigned int jb = 0; jb < along.size(); ++jb)
                  for (unsigned int ja = 0; ja < low.size(); ++ja, ++k)
                    {
                      double f = 0;
                      for (unsigned int m = 0; m < coefficients.m(); ++m)
                        f += coefficients(m, jb) * std::pow(x[1 - c], m);
                      N(i, k) = lagrange(low, ja, x[c]) * f;
                    }
            }
        }
      return N;
    }
  } // namespace assembly
} // namespace cosmo
