// Bounds on the rounding errors of a body's mass properties, carried from the
// bounds of its integrals through the move to the centre of mass and the
// principal-axes step (docs/error_bound.md).
#pragma once

#include <Eigen/Core>

#include "principal_axes.hpp"
#include "rigid_body.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {

// Absolute bounds, in the results' units.
struct ResultBounds {
    double volume = 0.0;
    double center_of_mass = 0.0;     // of each coordinate
    double inertia = 0.0;            // of each entry of the tensor about the centre of mass
    double principal_moments = 0.0;  // of each
    // Radians, of each axis the moments determine; pi/2 when two moments are
    // closer than their bounds can tell apart. Grows as moments approach
    // each other (as the bound over their gap).
    double principal_axes = 0.0;
};

// `mass` are the mass-weighted integrals about `reference` (ρ times the volume
// integrals) with their bounds, `volume_bound` that of the volume; `body` and
// `principal` what was computed from them.
ResultBounds result_bounds(const VolumeIntegrals& mass, const IntegralBounds& mass_bounds,
                           double volume_bound, const Eigen::Vector3d& reference,
                           const RigidBody& body, const PrincipalAxes& principal);

// The principal moments' and axes' bounds from bounds.inertia (Weyl, then
// Davis–Kahan), written to bounds.
void bound_principal(ResultBounds& bounds, const PrincipalAxes& principal);

}  // namespace polymass::core
