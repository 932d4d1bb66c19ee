// Classification of how two triangles meet, from exact orientation signs
// only. The rules and the interval test's justification are in
// docs/exact-predicates.md.
#include "core/triangle_contact.hpp"

#include "core/exact_predicates.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <utility>

namespace polymass::core {
namespace {

using Signs = std::array<int, 3>;

// A set of a triangle's corners: bit i for corner i.
constexpr unsigned all_corners = 7;

// Sides of the corners of t relative to the plane of `plane` (orient3d signs).
Signs sides(const Triangle& plane, const Triangle& t) {
    const PlaneSide side(plane[0], plane[1], plane[2]);
    return {side.of(t[0]), side.of(t[1]), side.of(t[2])};
}

bool all_strictly_one_side(const Signs& s) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

bool straddles(const Signs& s) {
    bool above = false, below = false;
    for (const int side : s) {
        above = above || side > 0;
        below = below || side < 0;
    }
    return above && below;
}

// Orthogonal projection onto a coordinate plane, dropping one axis.
struct Projection {
    int first;
    int second;
    Eigen::Vector2d operator()(const Eigen::Vector3d& x) const { return {x[first], x[second]}; }
};

int projected_orientation(const Triangle& t, const Projection& project) {
    return orient2d(project(t[0]), project(t[1]), project(t[2]));
}

constexpr std::array<Projection, 3> dropping_axis = {Projection{1, 2}, Projection{2, 0},
                                                     Projection{0, 1}};

// A projection that keeps t non-degenerate: dropping the axis of the largest
// normal component when its exact projected orientation is nonzero,
// otherwise another axis whose is. Any such projection maps the plane of t
// one-to-one onto the coordinate plane, so 2D predicates on points lying
// exactly in that plane give the 3D answers exactly. Returns the triangle's
// orientation in the projection (0 only for a degenerate triangle).
int plane_projection(const Triangle& t, Projection& projection) {
    const Eigen::Vector3d normal = (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs();
    int largest = 0;
    normal.maxCoeff(&largest);
    for (int k = 0; k < 3; ++k) {
        projection = dropping_axis[(largest + k) % 3];
        const int orientation = projected_orientation(t, projection);
        if (orientation != 0) return orientation;
    }
    return 0;
}

// A piece of a triangle in a coordinate plane: one corner, an edge or the
// whole triangle, projected; a triangle counter-clockwise.
struct FlatPiece {
    std::array<Eigen::Vector2d, 3> corner;
    int count;

    // The triangle t, whose projection turns as `orientation` says.
    FlatPiece(const Triangle& t, const Projection& project, int orientation)
        : corner{project(t[0]), project(t[1]), project(t[2])}, count(3) {
        if (orientation < 0) std::swap(corner[1], corner[2]);
    }

    // The corners of t in `corners` (bit i: corner i), one or two: a point
    // or a segment.
    FlatPiece(const Triangle& t, unsigned corners, const Projection& project) : corner{}, count(0) {
        for (int i = 0; i < 3; ++i)
            if (corners >> i & 1) corner[count++] = project(t[i]);
    }

    // True when x lies strictly outside the edge from corner i to corner i+1.
    bool outside_edge(int i, const Eigen::Vector2d& x) const {
        return orient2d(corner[i], corner[(i + 1) % 3], x) < 0;
    }
};

// Whether a line through an edge of s has every corner of t strictly on its
// outer side (a segment's line: strictly on either side). A point has no edge.
bool separates(const FlatPiece& s, const FlatPiece& t) {
    if (s.count == 2) {
        bool left = true, right = true;
        for (int k = 0; k < t.count; ++k) {
            const int side = orient2d(s.corner[0], s.corner[1], t.corner[k]);
            left = left && side > 0;
            right = right && side < 0;
        }
        return left || right;
    }
    if (s.count == 3) {
        for (int i = 0; i < 3; ++i) {
            bool outside = true;
            for (int k = 0; k < t.count && outside; ++k) outside = s.outside_edge(i, t.corner[k]);
            if (outside) return true;
        }
    }
    return false;
}

// Whether the closed pieces meet: two disjoint closed convex figures of the
// plane are strictly separated by a line through an edge of one of them
// (separating-axis theorem), but for a point or segment against a collinear
// segment, whose separating line may be perpendicular to them. So one piece
// must be a triangle, or their coordinate extents must overlap on both axes
// with neither axis fixed in both (then collinear pieces meet): see
// docs/exact-predicates.md.
bool meets(const FlatPiece& s, const FlatPiece& t) { return !separates(s, t) && !separates(t, s); }

// Whether the open triangles overlap: no line through an edge of either
// leaves the other on its outer side or on it (in the plane, convex figures
// whose interiors are disjoint are separated by the line of an edge of one).
bool interiors_overlap(const FlatPiece& p, const FlatPiece& q) {
    auto beyond_edge = [](const FlatPiece& t, int i, const FlatPiece& other) {
        for (const Eigen::Vector2d& x : other.corner)
            if (orient2d(t.corner[i], t.corner[(i + 1) % 3], x) > 0) return false;
        return true;
    };
    for (int i = 0; i < 3; ++i)
        if (beyond_edge(p, i, q) || beyond_edge(q, i, p)) return false;
    return true;
}

// Coplanar triangles, in a projection that keeps q (whose projection turns
// as q_turn says) and so their common plane one-to-one: coinciding when
// they overlap over an area and face the same way, touching when they face
// opposite ways (two parts resting on each other) or meet along their
// boundaries only.
Contact coplanar_contact(const Triangle& p, const Triangle& q, const Projection& projection,
                         int q_turn) {
    const int p_turn = projected_orientation(p, projection);
    const FlatPiece p_flat(p, projection, p_turn), q_flat(q, projection, q_turn);
    if (p_turn == q_turn && interiors_overlap(p_flat, q_flat)) return Contact::coinciding;
    return meets(p_flat, q_flat) ? Contact::touching : Contact::none;
}

Contact coplanar_contact(const Triangle& p, const Triangle& q) {
    Projection projection{};
    const int q_turn = plane_projection(q, projection);
    return coplanar_contact(p, q, projection, q_turn);
}

// t lies on one side of the plane of `other` with one corner or one edge on
// it (side of t's corners: `t_sides`): does that corner or edge meet `other`?
bool touches_on_plane(const Triangle& t, const Signs& t_sides, const Triangle& other) {
    Projection projection{};
    const int orientation = plane_projection(other, projection);
    unsigned on_plane = 0;
    for (int i = 0; i < 3; ++i) on_plane |= unsigned(t_sides[i] == 0) << i;
    // One corner or one edge on the plane, as the caller found. (Outside
    // the predicates' exact range - coordinates 2^640 apart in one call -
    // signs can disagree.)
    if (on_plane == all_corners)
        return coplanar_contact(t, other, projection, orientation) != Contact::none;
    return on_plane != 0 &&
           meets(FlatPiece(t, on_plane, projection), FlatPiece(other, projection, orientation));
}

// The exact coordinate extent of some corners of a triangle on an axis.
struct Extent {
    double low, high;
};

// The extent of the corners of t in `corners` (at least one) on axis.
// Inlined: a pair of faces resting on each other asks for four to six. A
// corner not in `corners` stands in as a copy of the first one that is,
// which moves neither end: three selects and two minima and maxima, in
// registers (arrays of the corners' values with infinities for the others,
// reduced by std::min of a list, went through the stack: about 46
// instructions a call, half of those of deciding faces resting on each
// other).
__attribute__((always_inline)) inline Extent extent(const Triangle& t, unsigned corners, int axis) {
    const double c0 = t[0][axis], c1 = t[1][axis], c2 = t[2][axis];
    const double first = corners & 1 ? c0 : corners & 2 ? c1 : c2;
    const double a = corners & 1 ? c0 : first;
    const double b = corners & 2 ? c1 : first;
    const double c = corners & 4 ? c2 : first;
    return {std::min(std::min(a, b), c), std::max(std::max(a, b), c)};
}

bool disjoint(const Extent& a, const Extent& b) { return a.high < b.low || b.high < a.low; }

// The value where a and b meet, if in one value only.
bool meet_once(const Extent& a, const Extent& b, double& value) {
    if (a.high != b.low && b.high != a.low) return false;
    value = a.high == b.low ? a.high : a.low;
    return true;
}

// The corners of t in `corners` whose coordinate on axis is `value`.
unsigned corners_at(const Triangle& t, unsigned corners, int axis, double value) {
    const unsigned at_value = unsigned(t[0][axis] == value) | unsigned(t[1][axis] == value) << 1 |
                              unsigned(t[2][axis] == value) << 2;
    return corners & at_value;
}

// Triangles p and q on either side of the plane x = value of plane_axis
// (one at x <= value, the other at x >= value): they do not cross, and
// their common points are those of the pieces their corners in that plane
// span (a corner, an edge, or the whole triangle). In the plane, the same
// holds on the two other axes, down to a line.
Contact contact_in_plane(const Triangle& p, const Triangle& q, int plane_axis, double value) {
    unsigned s = corners_at(p, all_corners, plane_axis, value);
    unsigned t = corners_at(q, all_corners, plane_axis, value);
    const Projection projection = dropping_axis[plane_axis];
    const int first = projection.first, second = projection.second;
    const Extent s_first = extent(p, s, first), t_first = extent(q, t, first);
    const Extent s_second = extent(p, s, second), t_second = extent(q, t, second);
    if (disjoint(s_first, t_first) || disjoint(s_second, t_second)) return Contact::none;
    double line_value = 0.0;
    const int line_axis = meet_once(s_first, t_first, line_value)     ? first
                          : meet_once(s_second, t_second, line_value) ? second
                                                                      : -1;
    if (line_axis >= 0) {
        // On the line where both coordinates are fixed: the pieces are
        // points or segments along it, which meet if their extents do.
        s = corners_at(p, s, line_axis, line_value);
        t = corners_at(q, t, line_axis, line_value);
        const int along = 3 - plane_axis - line_axis;
        return disjoint(extent(p, s, along), extent(q, t, along)) ? Contact::none
                                                                  : Contact::touching;
    }
    if (s == all_corners && t == all_corners)
        return coplanar_contact(p, q, projection, projected_orientation(q, projection));
    const auto flat = [&](const Triangle& triangle, unsigned corners) {
        if (corners != all_corners) return FlatPiece(triangle, corners, projection);
        return FlatPiece(triangle, projection, projected_orientation(triangle, projection));
    };
    return meets(flat(p, s), flat(q, t)) ? Contact::touching : Contact::none;
}

// The exact coordinate box of a triangle.
struct Bounds {
    Eigen::Array3d low, high;

    explicit Bounds(const Triangle& t)
        : low(t[0].array().min(t[1].array()).min(t[2].array())),
          high(t[0].array().max(t[1].array()).max(t[2].array())) {}
};

bool boxes_disjoint(const Bounds& p, const Bounds& q) {
    return ((p.high < q.low) || (q.high < p.low)).any();
}

// The first axis from `first` on on which overlapping boxes meet in one
// value only (one triangle at x <= c, the other at x >= c), or 3 when none
// does.
int axis_met_once(const Bounds& p, const Bounds& q, int first = 0) {
    int axis = first;
    while (axis < 3 && p.high[axis] != q.low[axis] && q.high[axis] != p.low[axis]) ++axis;
    return axis;
}

// Decides the triangles from their exact coordinate extents when these are
// disjoint on an axis (none), or meet there in one value c only (one lies
// at x <= c, the other at x >= c): then the triangles cannot cross, they
// coincide only if both lie in the plane x = c, and all they have in common
// lies in that plane (docs/exact-predicates.md). Faces of parts resting on
// each other in CAD and voxel assemblies are decided so, most without a
// predicate. Returns false, deciding nothing, when no axis does either.
bool decided_by_extents(const Triangle& p, const Triangle& q, bool shared_corner,
                        Contact& contact) {
    const Bounds p_box(p), q_box(q);
    if (boxes_disjoint(p_box, q_box)) {
        contact = Contact::none;
        return true;
    }
    const int axis = axis_met_once(p_box, q_box);
    if (axis == 3) return false;
    // Triangles meeting at a shared vertex are reported only if they cross.
    contact = shared_corner
                  ? Contact::none
                  : contact_in_plane(
                        p, q, axis,
                        p_box.high[axis] == q_box.low[axis] ? p_box.high[axis] : p_box.low[axis]);
    return true;
}

// Rotates t (keeping its orientation) so that t[0] is the corner alone on its
// side: strictly on one side, the other two on the other side or on the plane.
void rotate_lone_corner_first(Triangle& t, Signs& s) {
    int positive = 0;
    for (const int side : s) positive += side > 0 ? 1 : 0;
    const int lone_side = positive == 1 ? 1 : -1;
    while (s[0] != lone_side) {
        std::rotate(t.begin(), t.begin() + 1, t.end());
        std::rotate(s.begin(), s.begin() + 1, s.end());
    }
}

// Both triangles strictly straddle the other's plane: the segments they cut
// from the common line of the planes are compared by two orientation signs.
Contact straddling_contact(Triangle p, Signs p_sides, Triangle q, Signs q_sides) {
    rotate_lone_corner_first(p, p_sides);
    rotate_lone_corner_first(q, q_sides);
    if (orient3d(q[0], q[1], q[2], p[0]) < 0) std::swap(q[1], q[2]);
    if (orient3d(p[0], p[1], p[2], q[0]) < 0) std::swap(p[1], p[2]);
    const int first = orient3d(p[0], p[1], q[0], q[1]);
    const int second = orient3d(p[0], p[2], q[2], q[0]);
    if (first < 0 && second < 0) return Contact::crossing;
    if (first <= 0 && second <= 0) return Contact::touching;
    return Contact::none;
}

// Triangles meeting at a shared first corner cross only if each has its two
// other corners strictly on both sides of the other's plane: on a surface
// almost every pair of neighbours around a vertex fails that at the first
// two predicates, and the shared corner's own side (zero) costs none.
Contact shared_corner_contact(const Triangle& p, const Triangle& q) {
    const PlaneSide q_side(q[0], q[1], q[2]);
    const Signs p_sides{0, q_side.of(p[1]), q_side.of(p[2])};
    if (p_sides[1] * p_sides[2] >= 0) return Contact::none;
    const PlaneSide p_side(p[0], p[1], p[2]);
    const Signs q_sides{0, p_side.of(q[1]), p_side.of(q[2])};
    if (q_sides[1] * q_sides[2] >= 0) return Contact::none;
    const Contact contact = straddling_contact(p, p_sides, q, q_sides);
    return contact == Contact::crossing ? contact : Contact::none;
}

// The triangles' contact from orientation predicates (steps 1 to 5 of
// docs/exact-predicates.md), without a shared corner. Inlined into both
// callers, as it was into triangle_contact before crossing_or_coinciding.
__attribute__((always_inline)) inline Contact contact_by_orientations(const Triangle& p,
                                                                      const Triangle& q) {
    const Signs p_sides = sides(q, p);
    if (all_strictly_one_side(p_sides)) return Contact::none;
    const Signs q_sides = sides(p, q);
    if (all_strictly_one_side(q_sides)) return Contact::none;

    const bool p_straddles = straddles(p_sides);
    const bool q_straddles = straddles(q_sides);
    if (p_straddles && q_straddles) return straddling_contact(p, p_sides, q, q_sides);
    if (p_sides == Signs{0, 0, 0}) return coplanar_contact(p, q);
    // One triangle lies on one side of the other's plane with a corner or an
    // edge on it: that corner or edge is all the two can have in common.
    const bool meet =
        p_straddles ? touches_on_plane(q, q_sides, p) : touches_on_plane(p, p_sides, q);
    return meet ? Contact::touching : Contact::none;
}

}  // namespace

Contact triangle_contact(const Triangle& p, const Triangle& q, bool shared_corner) {
    if (Contact contact{}; decided_by_extents(p, q, shared_corner, contact)) return contact;
    return shared_corner ? shared_corner_contact(p, q) : contact_by_orientations(p, q);
}

Contact crossing_or_coinciding(const Triangle& p, const Triangle& q) {
    const Bounds p_box(p), q_box(q);
    if (boxes_disjoint(p_box, q_box)) return Contact::none;
    const int axis = axis_met_once(p_box, q_box);
    if (axis == 3) {
        const Contact contact = contact_by_orientations(p, q);
        return contact == Contact::touching ? Contact::none : contact;
    }
    // One triangle at x <= c, the other at x >= c: they do not cross, and
    // coincide only when both lie in the plane x = c (both flat on the axis)
    // and their extents there overlap in more than a value on both other
    // axes (else they have no common area).
    if (p_box.low[axis] != p_box.high[axis] || q_box.low[axis] != q_box.high[axis] ||
        axis_met_once(p_box, q_box, axis + 1) != 3)
        return Contact::none;
    const Projection projection = dropping_axis[axis];
    const int p_turn = turn_along(p, axis);
    const int q_turn = turn_along(q, axis);
    return p_turn == q_turn && interiors_overlap(FlatPiece(p, projection, p_turn),
                                                 FlatPiece(q, projection, q_turn))
               ? Contact::coinciding
               : Contact::none;
}

int turn_along(const Triangle& t, int axis) {
    return projected_orientation(t, dropping_axis[axis]);
}

bool is_degenerate(const Triangle& t) {
    for (const Projection& projection : dropping_axis) {
        if (projected_orientation(t, projection) != 0) return false;
    }
    return true;
}

}  // namespace polymass::core
