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

// A triangle in a coordinate plane, counter-clockwise.
struct Triangle2d {
    std::array<Eigen::Vector2d, 3> corner;

    Triangle2d(const Triangle& t, const Projection& project, int orientation)
        : corner{project(t[0]), project(t[1]), project(t[2])} {
        if (orientation < 0) std::swap(corner[1], corner[2]);
    }

    // True when x lies strictly outside the edge from corner i to corner i+1.
    bool outside_edge(int i, const Eigen::Vector2d& x) const {
        return orient2d(corner[i], corner[(i + 1) % 3], x) < 0;
    }
};

bool contains(const Triangle2d& t, const Eigen::Vector2d& x) {
    return !t.outside_edge(0, x) && !t.outside_edge(1, x) && !t.outside_edge(2, x);
}

// Closed segment ab against a closed triangle: disjoint iff a line through an
// edge of either separates them (separating-axis theorem in the plane).
bool meets(const Triangle2d& t, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    for (int i = 0; i < 3; ++i) {
        if (t.outside_edge(i, a) && t.outside_edge(i, b)) return false;
    }
    const Signs side = {orient2d(a, b, t.corner[0]), orient2d(a, b, t.corner[1]),
                        orient2d(a, b, t.corner[2])};
    return !all_strictly_one_side(side);
}

bool meets(const Triangle2d& p, const Triangle2d& q) {
    for (int i = 0; i < 3; ++i) {
        if (p.outside_edge(i, q.corner[0]) && p.outside_edge(i, q.corner[1]) &&
            p.outside_edge(i, q.corner[2]))
            return false;
        if (q.outside_edge(i, p.corner[0]) && q.outside_edge(i, p.corner[1]) &&
            q.outside_edge(i, p.corner[2]))
            return false;
    }
    return true;
}

// Whether the open triangles overlap: no line through an edge of either
// leaves the other on its outer side or on it (in the plane, convex figures
// whose interiors are disjoint are separated by the line of an edge of one).
bool interiors_overlap(const Triangle2d& p, const Triangle2d& q) {
    auto beyond_edge = [](const Triangle2d& t, int i, const Triangle2d& other) {
        for (const Eigen::Vector2d& x : other.corner)
            if (orient2d(t.corner[i], t.corner[(i + 1) % 3], x) > 0) return false;
        return true;
    };
    for (int i = 0; i < 3; ++i)
        if (beyond_edge(p, i, q) || beyond_edge(q, i, p)) return false;
    return true;
}

// Coplanar triangles: coinciding when they overlap over an area and face the
// same way, touching when they face opposite ways (two parts resting on each
// other) or meet along their boundaries only.
Contact coplanar_contact(const Triangle& p, const Triangle& q) {
    Projection projection{};
    const int q_turn = plane_projection(q, projection);
    const int p_turn = projected_orientation(p, projection);
    const Triangle2d p_flat(p, projection, p_turn), q_flat(q, projection, q_turn);
    if (p_turn == q_turn && interiors_overlap(p_flat, q_flat)) return Contact::coinciding;
    return meets(p_flat, q_flat) ? Contact::touching : Contact::none;
}

// t lies on one side of the plane of `other` with one corner or one edge on
// it (side of t's corners: `t_sides`): does that corner or edge meet `other`?
bool touches_on_plane(const Triangle& t, const Signs& t_sides, const Triangle& other) {
    Projection projection{};
    const int orientation = plane_projection(other, projection);
    const Triangle2d face(other, projection, orientation);
    int on_plane[3];
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        if (t_sides[i] == 0) on_plane[count++] = i;
    }
    // One corner or one edge on the plane, as the caller found. (Outside
    // the predicates' exact range - coordinates 2^640 apart in one call -
    // signs can disagree; no index may then run past the corners.)
    if (count == 1) return contains(face, projection(t[on_plane[0]]));
    if (count == 2) return meets(face, projection(t[on_plane[0]]), projection(t[on_plane[1]]));
    return count == 3 && coplanar_contact(t, other) != Contact::none;
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

}  // namespace

Contact triangle_contact(const Triangle& p, const Triangle& q, bool shared_corner) {
    if (shared_corner) return shared_corner_contact(p, q);
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

bool is_degenerate(const Triangle& t) {
    for (const Projection& projection : dropping_axis) {
        if (projected_orientation(t, projection) != 0) return false;
    }
    return true;
}

}  // namespace polymass::core
