// Integrals over planar polygons by Green's theorem (docs/integrals.md, section 2).
//
// A polygon face is projected onto the coordinate plane (a, b) most nearly
// parallel to it (the normal's largest component is the dropped axis c), its
// region integrals are edge sums, and the face integrals follow by lifting the
// projection back onto the plane n·p + w = 0. The same edge sums are the area,
// centroid and second moments of a 2D polygon (the shoelace sums, docs/integrals.md
// section 2, and their higher-order siblings), so the 2D API uses them too.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "volume_integrals.hpp"

namespace polymass::core {

// Signed integrals over a polygon's region in its (a, b) plane of
// 1, a, b, a², ab, b², a³, a²b, ab², b³: positive for a counter-clockwise polygon.
struct ProjectionIntegrals {
    double one = 0, a = 0, b = 0, aa = 0, ab = 0, bb = 0, aaa = 0, aab = 0, abb = 0, bbb = 0;

    // The integrals of the polygon measured in `unit` (a power of two;
    // dimensions L² to L⁵) in the caller's unit.
    ProjectionIntegrals scaled(double unit) const {
        auto times = [unit](double value, int power) {
            return times_unit_power(value, unit, power);
        };
        return {times(one, 2), times(a, 3),   times(b, 3),   times(aa, 4),  times(ab, 4),
                times(bb, 4),  times(aaa, 5), times(aab, 5), times(abb, 5), times(bbb, 5)};
    }
};

// Green's theorem on each edge (a0, b0) → (a1, b1), written with the shoelace
// cross term c = a0 b1 − a1 b0: integral of a^p b^q over the region is the sum
// over edges of c times a symmetric polynomial of the edge's ends (exact for a
// closed polygon, convex or not). point_at(i) returns the i-th point as a 2-vector.
template <class PointAt>
ProjectionIntegrals projection_integrals(std::size_t count, PointAt&& point_at) {
    ProjectionIntegrals sums;
    Eigen::Vector2d p0 = point_at(count - 1);
    for (std::size_t i = 0; i < count; ++i) {
        const Eigen::Vector2d p1 = point_at(i);
        const double a0 = p0.x(), b0 = p0.y(), a1 = p1.x(), b1 = p1.y();
        const double c = a0 * b1 - a1 * b0;
        const double a0a0 = a0 * a0, a1a1 = a1 * a1, b0b0 = b0 * b0, b1b1 = b1 * b1;
        const double a_sq = a0a0 + a0 * a1 + a1a1;  // a0² + a0 a1 + a1²
        const double b_sq = b0b0 + b0 * b1 + b1b1;
        sums.one += c;
        sums.a += c * (a0 + a1);
        sums.b += c * (b0 + b1);
        sums.aa += c * a_sq;
        sums.bb += c * b_sq;
        sums.ab += c * (2.0 * (a0 * b0 + a1 * b1) + a0 * b1 + a1 * b0);
        sums.aaa += c * (a0 + a1) * (a0a0 + a1a1);  // a0³ + a0² a1 + a0 a1² + a1³
        sums.bbb += c * (b0 + b1) * (b0b0 + b1b1);
        sums.aab += c * (b0 * (3.0 * a0a0 + 2.0 * a0 * a1 + a1a1) +
                         b1 * (a0a0 + 2.0 * a0 * a1 + 3.0 * a1a1));
        sums.abb += c * (a0 * (3.0 * b0b0 + 2.0 * b0 * b1 + b1b1) +
                         a1 * (b0b0 + 2.0 * b0 * b1 + 3.0 * b1b1));
        p0 = p1;
    }
    sums.one /= 2.0;
    sums.a /= 6.0;
    sums.b /= 6.0;
    sums.aa /= 12.0;
    sums.bb /= 12.0;
    sums.ab /= 24.0;
    sums.aaa /= 20.0;
    sums.bbb /= 20.0;
    sums.aab /= 60.0;
    sums.abb /= 60.0;
    return sums;
}

// The plane of a polygon face from its vertices (relative to the reference point).
struct FacePlane {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, outward; zero if degenerate
    double area = 0.0;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // mean of the vertices: on the plane
    double extent = 0.0;  // largest distance of a vertex from the centroid
    bool degenerate = true;
};

// Newell's method: the sum of (p_i − p_0) × (p_{i+1} − p_0) is twice the
// vector area of any planar polygon, convex or not, and the best-fit normal
// direction of a slightly non-planar one. vertex_at(i) returns a 3-vector.
template <class VertexAt>
FacePlane face_plane(std::size_t count, VertexAt&& vertex_at) {
    FacePlane plane;
    const Eigen::Vector3d p0 = vertex_at(0);
    Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();  // p_0 − p_0
    for (std::size_t i = 1; i < count; ++i) {
        const Eigen::Vector3d current = vertex_at(i) - p0;
        twice_area += previous.cross(current);
        sum += current;
        previous = current;
    }
    plane.centroid = p0 + sum / double(count);
    for (std::size_t i = 0; i < count; ++i)
        plane.extent = std::max(plane.extent, (vertex_at(i) - plane.centroid).norm());
    // stableNorm: the squares of a tiny face's area vector underflow (a face
    // 1e-150 across would have no area), as the triangle path also avoids.
    const double twice_area_norm = twice_area.stableNorm();
    plane.area = twice_area_norm / 2.0;
    plane.degenerate = is_degenerate_face(twice_area_norm, 4.0 * plane.extent * plane.extent);
    if (!plane.degenerate) plane.normal = twice_area / twice_area_norm;
    return plane;
}

// Largest distance of a vertex from the face's plane.
template <class VertexAt>
double plane_deviation(const FacePlane& plane, std::size_t count, VertexAt&& vertex_at) {
    double deviation = 0.0;
    for (std::size_t i = 0; i < count; ++i)
        deviation = std::max(deviation, std::abs(plane.normal.dot(vertex_at(i) - plane.centroid)));
    return deviation;
}

// Lifts the projected integrals onto the face's plane and weights them by the
// normal: the face's contribution to the ten face sums. c is the dropped axis,
// (a, b, c) a cyclic permutation of (x, y, z).
FaceSums lift_projection(const FacePlane& plane, int c, const ProjectionIntegrals& projected);

// The face sums of one non-degenerate planar polygon face.
template <class VertexAt>
FaceSums polygon_face_sums(const FacePlane& plane, std::size_t count, VertexAt&& vertex_at) {
    Eigen::Index dropped = 2;
    plane.normal.cwiseAbs().maxCoeff(&dropped);
    const int c = int(dropped);
    const int a = (c + 1) % 3, b = (a + 1) % 3;
    const ProjectionIntegrals projected = projection_integrals(count, [&](std::size_t i) {
        const Eigen::Vector3d p = vertex_at(i);
        return Eigen::Vector2d(p[a], p[b]);
    });
    return lift_projection(plane, c, projected);
}

}  // namespace polymass::core
