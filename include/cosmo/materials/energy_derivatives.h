#ifndef cosmo_materials_energy_derivatives_h
#define cosmo_materials_energy_derivatives_h

#include <Sacado.hpp>

#include <array>
#include <cstddef>

/**
 * The one place where an energy density is differentiated: value, gradient
 * and (on request) Hessian with respect to N variables by nested static
 * forward-mode Sacado numbers. Included only by the translation units that
 * instantiate it (bulk and surface materials): it is what makes them
 * expensive to compile.
 */
namespace cosmo
{
  namespace materials
  {
    /// The Sacado numbers of first and second derivatives in N variables:
    /// what differentiate() evaluates an energy with.
    template <int N>
    using FirstOrderAD = Sacado::Fad::SFad<double, N>;
    template <int N>
    using SecondOrderAD = Sacado::Fad::SFad<FirstOrderAD<N>, N>;

    namespace internal
    {
      /// x as N independent variables of first (and second) order.
      template <int N>
      std::array<FirstOrderAD<N>, N>
      independent_first_order(const std::array<double, N> &x)
      {
        std::array<FirstOrderAD<N>, N> X;
        for (int a = 0; a < N; ++a)
          X[a] = FirstOrderAD<N>(N, a, x[a]);
        return X;
      }
      template <int N>
      std::array<SecondOrderAD<N>, N>
      independent_second_order(const std::array<double, N> &x)
      {
        std::array<SecondOrderAD<N>, N> X;
        for (int a = 0; a < N; ++a)
          X[a] = SecondOrderAD<N>(N, a, FirstOrderAD<N>(N, a, x[a]));
        return X;
      }

      /**
       * `energy` is a generic callable returning the energy for an array of N
       * numbers of any Sacado type (write it with `const auto &x`).
       */
      template <int N, typename Energy>
      void
      differentiate(const std::array<double, N> &x,
                    const Energy &               energy,
                    const bool                   with_hessian,
                    double &                     value,
                    std::array<double, N> &      gradient,
                    std::array<double, N * N> &  hessian)
      {
        if (with_hessian)
          {
            const SecondOrderAD<N> W = energy(independent_second_order<N>(x));
            value               = W.val().val();
            for (int a = 0; a < N; ++a)
              {
                gradient[a] = W.dx(a).val();
                for (int b = 0; b < N; ++b)
                  hessian[N * a + b] = W.dx(a).dx(b);
              }
          }
        else
          {
            const FirstOrderAD<N> W = energy(independent_first_order<N>(x));
            value              = W.val();
            for (int a = 0; a < N; ++a)
              gradient[a] = W.dx(a);
          }
      }

      /**
       * The same with respect to the M variables z[first], ..., z[first + M - 1]
       * only, the others held fixed (an energy that does not depend on some
       * local variables: the cost of nested AD grows like the square of the
       * number of variables). `energy` receives the M numbers; gradient and
       * Hessian are written into the full-size arrays, zero elsewhere.
       */
      template <int M, std::size_t N, typename Energy>
      void
      differentiate_subset(const std::array<double, N> &z,
                           const unsigned int           first,
                           const Energy &               energy,
                           const bool                   with_hessian,
                           double &                     value,
                           std::array<double, N> &      gradient,
                           std::array<double, N * N> &  hessian)
      {
        std::array<double, M>     x, gx;
        std::array<double, M * M> Hx;
        for (int k = 0; k < M; ++k)
          x[k] = z[first + k];
        differentiate<M>(x, energy, with_hessian, value, gx, Hx);
        gradient.fill(0.);
        if (with_hessian)
          hessian.fill(0.);
        for (int a = 0; a < M; ++a)
          {
            gradient[first + a] = gx[a];
            if (with_hessian)
              for (int b = 0; b < M; ++b)
                hessian[N * (first + a) + first + b] = Hx[M * a + b];
          }
      }

      /**
       * The M outputs of a map of N variables with their first and (on
       * request) second derivatives, by the same nested numbers: `map(x, y)`
       * is a generic callable that writes the outputs y (an array of M
       * numbers) from x (N numbers). gradient[m][a] = dy_m/dx_a,
       * hessian[m][N a + b] = d2y_m/dx_a dx_b (untouched without the
       * Hessian). The nonlinear part of a chain rule (a director of a few
       * rotation variables).
       */
      template <int N, int M, typename Map>
      void
      differentiate_map(const std::array<double, N> &              x,
                        const Map &                                map,
                        const bool                                 with_hessian,
                        std::array<double, M> &                    value,
                        std::array<std::array<double, N>, M> &     gradient,
                        std::array<std::array<double, N * N>, M> & hessian)
      {
        if (with_hessian)
          {
            std::array<SecondOrderAD<N>, M> Y;
            map(independent_second_order<N>(x), Y);
            for (int m = 0; m < M; ++m)
              {
                value[m] = Y[m].val().val();
                for (int a = 0; a < N; ++a)
                  {
                    gradient[m][a] = Y[m].dx(a).val();
                    for (int b = 0; b < N; ++b)
                      hessian[m][N * a + b] = Y[m].dx(a).dx(b);
                  }
              }
          }
        else
          {
            std::array<FirstOrderAD<N>, M> Y;
            map(independent_first_order<N>(x), Y);
            for (int m = 0; m < M; ++m)
              {
                value[m] = Y[m].val();
                for (int a = 0; a < N; ++a)
                  gradient[m][a] = Y[m].dx(a);
              }
          }
      }
    } // namespace internal
  }   // namespace materials
} // namespace cosmo

#endif
