// Area, centroid and second moments of area of a simple planar polygon.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>

#include "polygon_integrals.hpp"

namespace polymass::core {

struct PlanarPolygon {
    int orientation = 1;  // +1 counter-clockwise, −1 clockwise
    double area = 0.0;    // > 0
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    // Second moments of area (Ixx = ∫y², Iyy = ∫x², Ixy = +∫xy).
    Eigen::Vector3d moments = Eigen::Vector3d::Zero();            // about the centroid
    Eigen::Vector3d moments_origin = Eigen::Vector3d::Zero();     // about (0, 0)
    double polar_moment = 0.0;                                    // about the centroid: Ixx + Iyy
    Eigen::Vector2d principal_moments = Eigen::Vector2d::Zero();  // ascending
    double principal_angle = 0.0;  // of the axis of principal_moments[0], in (−π/2, π/2]
    bool zero_area = false;        // area at rounding level: nothing else is meaningful
};

// What keeps points from being a polygon (docs/validity.md): fewer than 3 of
// them, or a coordinate that is not finite (point: the first such).
enum class PolygonDefect { none, too_few_points, non_finite };

struct PolygonCheck {
    PolygonDefect defect = PolygonDefect::none;
    std::size_t point = 0;
};

// point_at(i) returns point i as a 2-vector.
template <class PointAt>
PolygonCheck check_polygon(std::size_t count, PointAt&& point_at) {
    if (count < 3) return {PolygonDefect::too_few_points, 0};
    for (std::size_t i = 0; i < count; ++i)
        if (!point_at(i).allFinite()) return {PolygonDefect::non_finite, i};
    return {};
}

// From the region integrals of the polygon about `reference` in units of
// `unit_length` (as the caller ordered its points); `extent_squared` is, in the
// same unit, the square of the polygon's size times its point count: the
// scale of the area's rounding.
PlanarPolygon planar_polygon_from(const ProjectionIntegrals& in_units,
                                  const Eigen::Vector2d& reference, double unit_length,
                                  double extent_squared);

// Whether the properties can be answered in doubles: every value finite, and
// the area and the polar moment normal numbers (zero or subnormal ones keep
// too few digits) - the polygon's form of fits_in_doubles (mass_properties.hpp).
bool fits_in_doubles(const PlanarPolygon& polygon);

// point_at(i) returns point i as a 2-vector; the points pass check_polygon.
template <class PointAt>
PlanarPolygon planar_polygon(std::size_t count, PointAt&& point_at) {
    Eigen::AlignedBox2d bounds;
    for (std::size_t i = 0; i < count; ++i) bounds.extend(point_at(i));
    // About the centre of the bounds, so a polygon far from the origin keeps
    // its digits, and in a unit near its size, so no power overflows.
    const Eigen::Vector2d reference = bounds.center();
    const double diagonal = bounds.diagonal().stableNorm();  // norm() would overflow at 1e155
    const double unit = unit_length_near(diagonal);
    const ProjectionIntegrals integrals = projection_integrals(
        count, [&](std::size_t i) { return Eigen::Vector2d((point_at(i) - reference) / unit); });
    const double size = diagonal / unit;
    return planar_polygon_from(integrals, reference, unit, double(count) * size * size);
}

}  // namespace polymass::core
