// From a solid, or a body's moments, and the mass its caller gives it to its
// mass properties with their error bounds: the one place where a density or a
// total mass becomes the body's mass.
#pragma once

#include <Eigen/Core>

#include "moments.hpp"
#include "principal_axes.hpp"
#include "result_bounds.hpp"
#include "rigid_body.hpp"
#include "surface_answer.hpp"

namespace polymass::core {

// A body's mass as its caller gives it: a uniform density, or the total mass.
// A given total mass is the answer's mass exactly, to the bit: the density is
// M / V, and (M / V) · V would round.
struct GivenMass {
    bool total = false;  // `value` is the total mass; otherwise the density
    double value = 1.0;
};

// A body's mass properties with their error bounds.
struct MassProperties {
    RigidBody body;             // inertia about the centre of mass
    double surface_area = 0.0;  // NaN: unknown (moments do not keep the surface)
    Eigen::Matrix3d inertia_about_origin = Eigen::Matrix3d::Zero();
    PrincipalAxes principal;
    ResultBounds bounds;  // rounding, widened by an approximation's bound
};

// The solid's properties with the given mass.
MassProperties mass_properties(const Body& solid, const GivenMass& mass);

// The moments with the given mass: the whole mass distribution rescaled to
// that mean density (density · volume / mass) or total mass (exactly). The
// moments' volume and mass must be positive.
Moments weighed(const Moments& moments, const GivenMass& mass);

// The properties of a body given by its moments: mass, centre of mass and
// inertia as weighted; density the mean density, mass / volume.
MassProperties mass_properties(const Moments& moments);

// Whether the properties can be answered in doubles: every value finite (the
// surface area may be unknown), and the mass, the density and the largest
// principal moment by magnitude (an unchecked non-solid can have negative
// moments) normal numbers: zero or subnormal ones keep too few digits.
bool fits_in_doubles(const MassProperties& properties);

}  // namespace polymass::core
