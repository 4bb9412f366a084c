#ifndef cosmo_rod_element_h
#define cosmo_rod_element_h

#include "rod_problem.h"

#include <array>

/**
 * The rod's element kernel (doc/theory-rod.md 2-4): the energy of one
 * helicoidal element, h psi of its strains at the midpoint's natural state
 * plus the quaternions' norm penalty and the spin gauge, with its gradient
 * and Hessian in y = (chord, q_a, q_b); and the maps between y and the
 * element's 14 local unknowns (u_a, q_a, u_b, q_b). The dead loads are
 * linear in the positions and enter apart (load_energy).
 */
namespace cosmo
{
  namespace rod
  {
    constexpr unsigned int n_local = 14; ///< (u_a, q_a, u_b, q_b): displacements and quaternions
    constexpr unsigned int n_ad    = 11; ///< (chord, q_a, q_b): what the energy's curvature depends on

    /**
     * The element's energy W and its derivatives in y, by the chain rule
     * through (theta, u) (kinematics/rod_element_derivatives.h); with
     * COSMO_NESTED_AD set, by nested AD of the whole element, the reference
     * (tests/rod_validation.py 'chain_rule'). materials::LawRangeError
     * outside the law's range.
     */
    void
    element_energy_derivatives(const std::array<double, n_ad> &   y,
                               const RodElementData &             d,
                               const materials::RodLaw &          law,
                               const materials::RodNaturalState & natural,
                               unsigned int                       e,
                               bool                               with_hessian,
                               double &                           W,
                               std::array<double, n_ad> &         G,
                               std::array<double, n_ad * n_ad> &  H);

    /// Minus the dead loads' work on element e and its gradient in the local unknowns.
    double
    load_energy(const std::array<double, n_local> &x, const RodElementData &d, const Tensor<1, 3> &f,
                unsigned int e, std::array<double, n_local> &g);

    /// y from the local unknowns: the chord (the reference's plus u_b - u_a) and the quaternions.
    std::array<double, n_ad>
    chord_variables(const std::array<double, n_local> &x, const Tensor<1, 3> &reference_chord);

    /// The gradient and Hessian in y added to those in the local unknowns.
    void
    spread_to_nodes(const std::array<double, n_ad> &        gy,
                    const std::array<double, n_ad * n_ad> & Hy,
                    bool                                    jacobian,
                    std::array<double, n_local> &           g,
                    std::array<double, n_local * n_local> & H);

    /// The force and moment conjugate to a node's (r, q) gradient.
    std::array<double, 6>
    nodal_load(const double *g, const kinematics::Quaternion<double> &q);
  } // namespace rod
} // namespace cosmo

#endif
