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

// A plane's cross product (b − a) × (c − a), rounded, and for each of its
// components the two products' magnitudes summed: what orient3d's filter
// takes of the plane when the determinant is expanded along the row of d − a.
struct PlaneNormal {
    Eigen::Vector3d normal, permanent;
};

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
    PlaneNormal plane_;
};

// The side (+1 or -1) of the plane through a, b and c on which the filter
// of PlaneSide::of (orient3d's bound) alone puts each of d0, d1 and d2, when
// it puts all three on one; else 0, which says nothing. For a caller that
// acts only on points certainly on one side (the contact search's first test
// of two triangles sharing no corner, certainly_apart): one call, the plane's and the points'
// filters inlined into it, where a PlaneSide and a call per point cost about 180 instructions
// (docs/exact-predicates.md).
int certain_common_side(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c, const Eigen::Vector3d& d0,
                        const Eigen::Vector3d& d1, const Eigen::Vector3d& d2);

// Sign of (b − a) × (c − a): +1 when a, b, c turn counter-clockwise, 0 when
// they are collinear.
int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace polymass::core
