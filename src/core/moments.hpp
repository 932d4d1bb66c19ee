// Moments: the mass integrals of a body about its own reference point, a value
// that composes. Parts add and subtract (a bore removed from a block), move
// rigidly, scale (per axis; negative factors mirror), take a density or a
// total mass, and become a rigid body about any point. Every value keeps its
// own reference point near the body, so a part far from the origin keeps its
// digits; combining re-expresses one operand about the other's reference with
// the parallel-axis identities (docs/moments.md derives them).
#pragma once

#include <Eigen/Core>

#include "result_bounds.hpp"
#include "rigid_body.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {

struct Moments {
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    // The solid's volume (signed: a difference can be negative).
    double volume = 0.0;
    // ∫ρ dm-weighted integrals of 1, r, r rᵀ with r measured from `reference`:
    // mass.volume is the mass, mass.first the first moments, and so on.
    VolumeIntegrals mass;
    // Bounds on the rounding errors carried so far (docs/error_bound.md): of
    // each coordinate of the reference, of the volume, of the mass integrals.
    double reference_bound = 0.0;
    double volume_bound = 0.0;
    IntegralBounds mass_bounds;

    // A solid of uniform `density` from its volume integrals about `reference`
    // and their rounding bounds.
    static Moments of_solid(const VolumeIntegrals& integrals, const IntegralBounds& bounds,
                            const Eigen::Vector3d& reference, double density = 1.0);

    // The same body measured from another reference point (parallel-axis identities).
    Moments about(const Eigen::Vector3d& point) const;

    // The body as rigidly moved: r -> rotation r + translation. A rotation of
    // determinant -1 mirrors; the result is the mirrored solid (positive volume).
    Moments transformed(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) const;

    // The body stretched by factors[i] along axis i about the origin (negative
    // factors mirror); the density is kept, so mass scales with the volume.
    Moments scaled(const Eigen::Vector3d& factors) const;

    // Every mass integral times `factor` (a density ratio, or a mass over the mass).
    Moments weighted(double factor) const;

    // Mass, centre of mass and inertia (about the centre of mass); density is
    // the mean density, mass / volume.
    RigidBody rigid_body() const;

    // The bounds of rigid_body()'s results (with `principal` from its inertia).
    ResultBounds result_bounds(const RigidBody& body, const PrincipalAxes& principal) const;
};

// The union of two disjoint bodies, about a's reference point.
Moments operator+(const Moments& a, const Moments& b);
// a with b removed (b inside a), about a's reference point.
Moments operator-(const Moments& a, const Moments& b);

}  // namespace polymass::core
