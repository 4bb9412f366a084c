// Link, twist and writhe of a closed framed polygon (framed_curve.h).
#include <cosmo/kinematics/framed_curve.h>

#include <cmath>

namespace cosmo
{
  namespace kinematics
  {
    namespace
    {
      Tensor<1, 3>
      unit(const Tensor<1, 3> &v)
      {
        const double n = v.norm();
        return n > 0 ? v / n : v;
      }

      /// asin(a.b) of unit vectors as atan2(a.b, |a x b|): asin's argument
      /// near 1 (nearly coplanar segments, a ring about to buckle) would turn
      /// its round-off of 1e-16 into 1e-8 of the angle.
      double
      asin_of_product(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
      {
        return std::atan2(a * b, cross_product_3d(a, b).norm());
      }

      /**
       * The signed solid angle (over 4 pi: its share of Gauss's integral)
       * under which segment p1 -> p2 sees segment p3 -> p4 (Klenin &
       * Langowski 2000, eq. 13-15); 0 for segments that touch.
       */
      double
      segment_pair(const Tensor<1, 3> &p1, const Tensor<1, 3> &p2, const Tensor<1, 3> &p3,
                   const Tensor<1, 3> &p4)
      {
        const Tensor<1, 3> r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
        const Tensor<1, 3> n1 = unit(cross_product_3d(r13, r14)), n2 = unit(cross_product_3d(r14, r24)),
                           n3 = unit(cross_product_3d(r24, r23)), n4 = unit(cross_product_3d(r23, r13));
        const double omega = asin_of_product(n1, n2) + asin_of_product(n2, n3) + asin_of_product(n3, n4) +
                             asin_of_product(n4, n1);
        const double orientation = cross_product_3d(p4 - p3, p2 - p1) * r13;
        return orientation > 0 ? omega / (4 * M_PI) : orientation < 0 ? -omega / (4 * M_PI) : 0.;
      }
    } // namespace

    double
    writhe(const std::vector<Tensor<1, 3>> &x)
    {
      const unsigned int n = x.size();
      double             w = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 2; j < n; ++j)
          {
            if (i == 0 && j == n - 1)
              continue; // adjacent across the closure
            w += 2 * segment_pair(x[i], x[(i + 1) % n], x[j], x[(j + 1) % n]);
          }
      return w;
    }

    namespace
    {
      /// The angle by which `next` is turned about t1 beyond the parallel
      /// transport of `m` from t0 to t1 (the rotation about t0 x t1 that
      /// takes t0 to t1, Rodrigues).
      double
      turn_beyond_transport(const Tensor<1, 3> &t0, const Tensor<1, 3> &t1, const Tensor<1, 3> &m,
                            const Tensor<1, 3> &next)
      {
        const Tensor<1, 3> b = cross_product_3d(t0, t1);
        const double       c = t0 * t1;
        Tensor<1, 3>       u = m;
        if (b.norm() > 1e-14)
          u = u * c + cross_product_3d(b, u) + b * ((b * u) / (1 + c));
        return std::atan2(cross_product_3d(u, next) * t1, u * next);
      }
    } // namespace

    double
    twist(const std::vector<Tensor<1, 3>> &x, const std::vector<Tensor<1, 3>> &m, const Tensor<1, 3> &closure)
    {
      const unsigned int n     = x.size();
      double             angle = 0;
      for (unsigned int e = 0; e < n; ++e)
        {
          const unsigned int p  = (e + n - 1) % n;
          const Tensor<1, 3> t0 = unit(x[e] - x[p]), t1 = unit(x[(e + 1) % n] - x[e]);
          // Across the closure the next frame is seen turned by the seam.
          const Tensor<1, 3> next = e == 0 && closure.norm() > 0 ? closure : m[e];
          angle += turn_beyond_transport(t0, t1, m[p], next);
        }
      return angle / (2 * M_PI);
    }

    double
    open_twist(const std::vector<Tensor<1, 3>> &t, const std::vector<Tensor<1, 3>> &m)
    {
      double angle = 0;
      for (unsigned int e = 0; e + 1 < t.size(); ++e)
        angle += turn_beyond_transport(t[e], t[e + 1], m[e], m[e + 1]);
      return angle / (2 * M_PI);
    }

    double
    linking_number(const std::vector<Tensor<1, 3>> &x, const std::vector<Tensor<1, 3>> &y)
    {
      double lk = 0;
      for (unsigned int i = 0; i < x.size(); ++i)
        for (unsigned int j = 0; j < y.size(); ++j)
          lk += segment_pair(x[i], x[(i + 1) % x.size()], y[j], y[(j + 1) % y.size()]);
      return lk;
    }

    double
    ribbon_link(const std::vector<Tensor<1, 3>> &x, const std::vector<Tensor<1, 3>> &m, const double epsilon)
    {
      const unsigned int        n = x.size();
      std::vector<Tensor<1, 3>> y(n);
      for (unsigned int k = 0; k < n; ++k)
        y[k] = x[k] + epsilon * unit(m[k] + m[(k + n - 1) % n]);
      return linking_number(x, y);
    }
  } // namespace kinematics
} // namespace cosmo
