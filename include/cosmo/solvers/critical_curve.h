#ifndef cosmo_solvers_critical_curve_h
#define cosmo_solvers_critical_curve_h

#include <deal.II/lac/vector.h>

#include <cosmo/io/checkpoint.h>

#include <string>
#include <vector>

/**
 * Critical curves: a critical point (U*, lambda*) of R(U, lambda; p) = 0
 * continued in a second parameter p, the value of a swept entry of the
 * parameter file (doc/theory-continuation.md 7).
 *
 * Each value of p is a new problem (any numeric entry may be swept), so the
 * continuation is in the natural parameter: the critical points found so far
 * predict the next one, and Newton on the minimally augmented system
 * (critical_point.h) corrects the prediction with no path from lambda = 0.
 * The prediction is polynomial extrapolation of (U*, lambda*, mode) through
 * the last points (up to three: error O(dp^3) instead of the secant's
 * O(dp^2)), in log p where all values are positive (studies of stiffnesses
 * and thicknesses span decades). A good prediction is what makes a continued
 * point cheap: from an O(1e-4) relative guess Newton converges in two
 * iterations, i.e. two factorizations, against a path to the first
 * instability (13 to 20) for an independent run.
 *
 * Where the critical mode changes along the curve (two test functions vanish
 * at once: a codimension-2 point, e.g. n = 2 -> 3 lobes), the two critical
 * curves meet; codimension_two_estimate() intersects their secants.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    class CriticalCurvePredictor
    {
    public:
      /// At most this many of the last points enter the extrapolation.
      explicit CriticalCurvePredictor(unsigned int max_points = 3);

      /// A located critical point at the swept value p (mode: any normalization).
      void
      add(double p, double lambda, const Vector<double> &U, const Vector<double> &mode);

      /// Forget every point (the critical mode changed: start a new curve).
      void
      clear()
      {
        points.clear();
      }

      /**
       * Extrapolate (U, lambda, mode) to p from the last points of the same
       * sizes (U and mode); false if there is none. The modes are aligned in sign with the
       * last one before they are combined. order, if given, is set to the
       * number of points used (1: the last point itself).
       */
      bool
      predict(double p, Vector<double> &U, double &lambda, Vector<double> &mode,
              unsigned int *order = nullptr) const;

      /// The points, for a study's checkpoint (io/checkpoint.h).
      void
      save(io::CheckpointWriter &w) const
      {
        w.put(std::uint64_t(points.size()));
        for (const auto &x : points)
          {
            w.put(x.p);
            w.put(x.lambda);
            w.put_vector(x.U);
            w.put_vector(x.mode);
          }
      }
      void
      load(io::CheckpointReader &r)
      {
        points.resize(r.get_size());
        for (auto &x : points)
          {
            x.p      = r.get_double();
            x.lambda = r.get_double();
            r.get_vector(x.U);
            r.get_vector(x.mode);
          }
      }

    private:
      struct Point
      {
        double         p, lambda;
        Vector<double> U, mode;
      };
      unsigned int       max_points;
      std::vector<Point> points;
    };

    /**
     * Where two critical curves lambda_a(p) and lambda_b(p), each known at p0
     * and p1, cross: the intersection of their secants (in log p if both are
     * positive). Returns false if the secants do not cross in [p0, p1]
     * (extended by half the interval on either side).
     */
    bool
    codimension_two_estimate(double  p0,
                             double  a0,
                             double  b0,
                             double  p1,
                             double  a1,
                             double  b1,
                             double &p,
                             double &lambda);
  } // namespace solvers
} // namespace cosmo

#endif
