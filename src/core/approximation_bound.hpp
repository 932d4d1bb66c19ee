// How far an approximate answer (a repaired surface, a thin sheet standing
// for a wall, a convex hull standing for a solid) can be from the body it
// stands for (docs/approximations.md, docs/repair.md).
//
// Repair knows where its surface may differ from the true one: each change
// that is not exact (a cap over a hole, the wedge between two triangulations
// of a bent polygon) leaves a region of space known by a bound on its volume
// and a ball containing it; nothing else is needed to bound the volume, the
// centre of mass and the inertia of the true solid.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory_resource>
#include <vector>

#include "principal_axes.hpp"
#include "result_bounds.hpp"
#include "rigid_body.hpp"

namespace polymass::core {

// Absolute bounds in the caller's units, for unit density (a density ρ
// multiplies the volume's mass counterpart and the inertia bound by ρ; the
// centre of mass is unchanged). Infinite when nothing useful can be said.
struct ApproximationBound {
    double volume = 0.0;
    double center_of_mass = 0.0;  // of each coordinate
    double inertia = 0.0;         // of each entry of the tensor about the centre of mass
};

// The bound for an answer computed from a body of volume `answer_volume`
// when the true body differs from it by a region of total volume at most
// `changed_volume` (added, removed, or counted twice), everything lying within
// `span` of everything else (a diameter). docs/approximations.md derives it.
ApproximationBound bound_of_changed_volume(double changed_volume, double answer_volume,
                                           double span);

struct UncertainRegion {
    double volume = 0.0;  // bound on the volume between the two surfaces there
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0.0;  // the region lies in the ball (centre, radius)
};

// `solid` is the answer at unit density (volume, centroid, inertia), whose
// surface lies in `box`.
ApproximationBound approximation_bound(const std::pmr::vector<UncertainRegion>& regions,
                                       const RigidBody& solid, const Eigen::AlignedBox3d& box);

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
