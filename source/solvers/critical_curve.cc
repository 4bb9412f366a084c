#include <cosmo/solvers/critical_curve.h>

#include <algorithm>
#include <cmath>

namespace cosmo
{
  namespace solvers
  {
    CriticalCurvePredictor::CriticalCurvePredictor(const unsigned int max_points)
      : max_points(std::max(1u, max_points))
    {}

    void
    CriticalCurvePredictor::add(const double          p,
                                const double          lambda,
                                const Vector<double> &U,
                                const Vector<double> &mode)
    {
      points.push_back({p, lambda, U, mode});
      if (points.size() > max_points)
        points.erase(points.begin());
    }

    bool
    CriticalCurvePredictor::predict(const double    p,
                                    Vector<double> &U,
                                    double &        lambda,
                                    Vector<double> &mode,
                                    unsigned int *  order) const
    {
      if (points.empty())
        return false;
      // The last points of the last point's size (a study keeps the mesh;
      // a point of another size cannot be combined).
      std::vector<const Point *> used;
      for (auto q = points.rbegin(); q != points.rend(); ++q)
        if (q->U.size() == points.back().U.size() && q->mode.size() == points.back().mode.size() &&
            q->p != p &&
            std::none_of(used.begin(), used.end(), [&](const Point *u) { return u->p == q->p; }))
          used.push_back(&*q);
      if (used.empty())
        used.push_back(&points.back());
      bool logs = p > 0;
      for (const Point *q : used)
        logs = logs && q->p > 0;
      auto x = [logs](const double v) { return logs ? std::log(v) : v; };
      // Lagrange weights of the extrapolation to p.
      std::vector<double> w(used.size(), 1.);
      for (std::size_t i = 0; i < used.size(); ++i)
        for (std::size_t j = 0; j < used.size(); ++j)
          if (i != j)
            w[i] *= (x(p) - x(used[j]->p)) / (x(used[i]->p) - x(used[j]->p));
      U.reinit(used[0]->U.size());
      mode.reinit(used[0]->mode.size());
      lambda = 0;
      for (std::size_t i = 0; i < used.size(); ++i)
        {
          U.add(w[i], used[i]->U);
          lambda += w[i] * used[i]->lambda;
          // A mode is defined up to sign: align with the last one.
          const double s = used[i]->mode * used[0]->mode < 0 ? -1. : 1.;
          mode.add(s * w[i], used[i]->mode);
        }
      if (order)
        *order = used.size();
      return true;
    }

    bool
    codimension_two_estimate(const double p0,
                             const double a0,
                             const double b0,
                             const double p1,
                             const double a1,
                             const double b1,
                             double &     p,
                             double &     lambda)
    {
      const bool   logs = p0 > 0 && p1 > 0;
      const double x0 = logs ? std::log(p0) : p0, x1 = logs ? std::log(p1) : p1;
      const double d0 = a0 - b0, d1 = a1 - b1;
      if (d0 == d1 || !std::isfinite(d0) || !std::isfinite(d1))
        return false;
      // lambda_a - lambda_b is linear in x between the points: its zero.
      const double s = d0 / (d0 - d1);
      if (s < -0.5 || s > 1.5)
        return false;
      const double x = x0 + s * (x1 - x0);
      p              = logs ? std::exp(x) : x;
      lambda         = a0 + s * (a1 - a0);
      return true;
    }
  } // namespace solvers
} // namespace cosmo
