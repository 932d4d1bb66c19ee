#include "planar_polygon.hpp"

#include <cfloat>
#include <cmath>

namespace polymass::core {

PlanarPolygon planar_polygon_from(const ProjectionIntegrals& in_units,
                                  const Eigen::Vector2d& reference, double unit_length,
                                  double extent_squared) {
    PlanarPolygon polygon;
    // A clockwise polygon gives every region integral negated.
    const double sign = in_units.one < 0 ? -1.0 : 1.0;
    polygon.orientation = int(sign);
    const ProjectionIntegrals about_reference = in_units.scaled(unit_length);
    polygon.area = sign * about_reference.one;
    polygon.zero_area = is_degenerate_face(2.0 * sign * in_units.one, extent_squared);
    if (polygon.zero_area) return polygon;

    const double area = polygon.area;
    const Eigen::Vector2d centroid(sign * about_reference.a / area,
                                   sign * about_reference.b / area);
    polygon.centroid = reference + centroid;
    const double ixx = sign * about_reference.bb - area * centroid.y() * centroid.y();
    const double iyy = sign * about_reference.aa - area * centroid.x() * centroid.x();
    const double ixy = sign * about_reference.ab - area * centroid.x() * centroid.y();
    polygon.moments = {ixx, iyy, ixy};
    const Eigen::Vector2d& c = polygon.centroid;
    polygon.moments_origin = {ixx + area * c.y() * c.y(), iyy + area * c.x() * c.x(),
                              ixy + area * c.x() * c.y()};
    polygon.polar_moment = ixx + iyy;

    // About an axis at angle θ: I(θ) = mean + half_difference cos 2θ − ixy sin 2θ,
    // smallest at 2θ = π − atan2(ixy, half_difference).
    const double mean = (ixx + iyy) / 2.0, half_difference = (ixx - iyy) / 2.0;
    const double radius = std::hypot(half_difference, ixy);
    polygon.principal_moments = {mean - radius, mean + radius};
    const double pi = 3.14159265358979323846;
    // Equal moments (a square, a regular polygon): every axis is principal; take x.
    const bool isotropic = radius <= 1e-10 * std::abs(mean);
    double angle = isotropic ? 0.0 : (pi - std::atan2(ixy, half_difference)) / 2.0;
    if (angle > pi / 2) angle -= pi;
    polygon.principal_angle = angle;
    return polygon;
}

bool fits_in_doubles(const PlanarPolygon& polygon) {
    return std::isfinite(polygon.area) && std::isfinite(polygon.polar_moment) &&
           std::isfinite(polygon.principal_angle) && polygon.area >= DBL_MIN &&
           polygon.polar_moment >= DBL_MIN && polygon.centroid.allFinite() &&
           polygon.moments.allFinite() && polygon.moments_origin.allFinite() &&
           polygon.principal_moments.allFinite();
}

}  // namespace polymass::core
