// Orientation predicates whose sign is exact for finite double inputs whose
// nonzero coordinates lie within a factor 2^640 (about 4.6e192) of one
// another (orient2d: 2^990); docs/exact-predicates.md states the precise
// range and what happens beyond it.
//
// Deciding whether two faces cross depends, for faces that touch or nearly
// touch, on the last bit of a determinant. Each predicate first evaluates the
// determinant in double precision with an error bound (the filter: almost
// every call ends there) and only when the result is within that bound
// recomputes it exactly with floating-point expansions (sums of doubles whose
// magnitudes do not overlap), scaled by a power of two so that no partial
// product overflows or underflows. The derivation of the bound and of the
// expansion arithmetic is in docs/exact-predicates.md.
#pragma once

#include <Eigen/Core>

namespace polymass::core {

// Sign (−1, 0 or +1) of det[b − a, c − a, d − a] = ((b − a) × (c − a)) · (d − a):
// +1 when d lies on the side the normal of the triangle abc (right-hand rule)
// points to, 0 when the four points are coplanar.
int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d);

// orient3d(a, b, c, d) for one plane abc and many points d: the same exact
// sign, with the plane's cross product, which every orient3d call would
// compute again, computed once (the filter expanded along the row of d − a,
// with the same bound: docs/exact-predicates.md). The points must outlive it.
class PlaneSide {
public:
    PlaneSide(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);
    int of(const Eigen::Vector3d& d) const;

private:
    const Eigen::Vector3d &a_, &b_, &c_;
    Eigen::Vector3d normal_;  // (b − a) × (c − a), rounded
    // |the two products| summed, for each component of normal_.
    Eigen::Vector3d normal_permanent_;
};

// Sign of (b − a) × (c − a): +1 when a, b, c turn counter-clockwise, 0 when
// they are collinear.
int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace polymass::core
