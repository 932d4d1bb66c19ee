// How far an approximate answer (a repaired surface, a convex hull) can be
// from the solid the caller meant, derived from where the answer's surface may
// differ from the true one (docs/repair.md, "From regions to results").
//
// Each change that is not exact leaves a region of space between the surface
// integrated and the true one: a cap over a hole, the wedge between two
// triangulations of a bent polygon, the hull's excess. A region is known by a
// bound on its volume and a ball containing it; nothing else is needed to
// bound the volume, the centre of mass and the inertia of the true solid.
#pragma once

#include <Eigen/Core>
#include <memory_resource>
#include <vector>

#include "principal_axes.hpp"
#include "result_bounds.hpp"
#include "rigid_body.hpp"

namespace polymass::core {

struct UncertainRegion {
    double volume = 0.0;  // bound on the volume between the two surfaces there
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0.0;  // the region lies in the ball (centre, radius)
};

// Absolute bounds on the geometry of the answer (unit density): its volume,
// each coordinate of its centroid, each entry of its inertia about the
// centroid. Infinite when the uncertain volume could be the whole volume.
struct ApproximationBound {
    double volume = 0.0;
    double center_of_mass = 0.0;
    double inertia = 0.0;  // at unit density
};

// `solid` is the answer at unit density (volume, centroid, inertia).
ApproximationBound approximation_bound(const std::pmr::vector<UncertainRegion>& regions,
                                       const RigidBody& solid);

// The bound on each entry of the inertia (about the centre of mass) of
// `body`, the answer with its density or mass applied; mass_given says the
// caller fixed the mass (the density then follows the uncertain volume).
double approximation_inertia(const ApproximationBound& approximation, const RigidBody& body,
                             bool mass_given);

// The rounding bounds of a body widened by the approximation's: `body` is the
// answer with its density or mass applied; mass_given says the caller fixed
// the mass (the density then follows the uncertain volume). The principal
// moments' and axes' bounds are taken again from the widened inertia bound.
ResultBounds widen(const ResultBounds& rounding, const ApproximationBound& approximation,
                   const RigidBody& body, bool mass_given, const PrincipalAxes& principal);

}  // namespace polymass::core
