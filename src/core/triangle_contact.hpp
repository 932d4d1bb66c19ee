// How two triangles of a surface meet: not at all, touching, or crossing.
//
// Crossing is what makes a surface bound a region twice: the open triangles
// pass through each other along a segment of positive length (each one has
// corners strictly on both sides of the other's plane, and the two pieces of
// the planes' common line that the triangles cover overlap in more than a
// point). Coinciding triangles lie in one plane, overlap over an area and
// face the same way: on two shells, the region behind both is bounded by
// each (a surface written twice, coincident parts); within one shell it is
// also how a fan over a non-convex polygon lies, whose overlaps cancel.
// Everything else where the closed triangles still meet is touching: a
// corner or an edge lying on the other triangle, two edges meeting in a
// point, coplanar triangles facing opposite ways (two parts resting on each
// other) or meeting along their boundaries only. Decided exactly: from the
// triangles' coordinate extents where these meet in one value on an axis
// (faces of parts resting on each other), otherwise with orientation
// predicates (exact_predicates.hpp); the reasoning is in
// docs/exact-predicates.md.
#pragma once

#include <Eigen/Core>
#include <array>

#include "exact_predicates.hpp"

namespace polymass::core {

enum class Contact { none, touching, crossing, coinciding };

using Triangle = std::array<Eigen::Vector3d, 3>;

// Neither triangle may be degenerate (three collinear corners). shared_corner
// says that p[0] and q[0] are the same vertex of the surface (the triangles
// meet there by construction): then only crossing is reported, never
// touching nor coinciding. The answer depends on the triangles' orientations
// only for coplanar triangles (coinciding or touching). Triangles sharing two corners (an edge) are
// not passed here.
Contact triangle_contact(const Triangle& p, const Triangle& q, bool shared_corner);

// What triangle_contact(p, q, false) answers, with touching answered none:
// for a caller to whom touching no longer matters (its report of touching
// pairs is full, and what the pair would mark is marked). Triangles whose
// extents meet in one value on an axis (faces of parts resting on each
// other) then cost a few comparisons, and an orientation or two when both
// lie in one axis-aligned plane, where the full answer tested how their
// pieces in that plane meet.
Contact crossing_or_coinciding(const Triangle& p, const Triangle& q);

// Whether p lies strictly on one side of the plane of q, as orient3d's
// filter alone certifies (certain_common_side): then the closed triangles
// have no point in common, and triangle_contact and crossing_or_coinciding
// would answer none. False says nothing. A fraction of their cost, for a
// caller that knows which pairs it is likely to decide (pairs sharing no
// corner on a curved surface: docs/exact-predicates.md, "The plane filter
// first").
inline bool certainly_apart(const Triangle& p, const Triangle& q) {
    return certain_common_side(q[0], q[1], q[2], p[0], p[1], p[2]) != 0;
}

// The turn of t seen along `axis`, in the plane of the two others (axis + 1,
// axis + 2): 1 counterclockwise, -1 clockwise, 0 when t is degenerate there.
// Exact. Two triangles flat in one plane x = c coincide only when they turn
// alike (crossing_or_coinciding): faces of parts resting on each other turn
// opposite ways, which a caller that has listed them can ask once each.
int turn_along(const Triangle& t, int axis);

// True when the three corners are collinear (exactly).
bool is_degenerate(const Triangle& t);

}  // namespace polymass::core
