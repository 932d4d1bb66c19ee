// Closed-form face sums of a triangle (the δ, f, g sub-expressions).
//
// Parameterising the triangle P0 + u E1 + v E2 makes n dS = δ du dv with
// δ = E1 × E2, and the face integrals collapse to polynomials in the vertex
// coordinates (algorithm.md, with its erratum on the x²y term). This is the
// fast path: no normalisation, no projection, no division per triangle.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "volume_integrals.hpp"

namespace polymass::core {

namespace detail {

// f1, f2, f3 and g0, g1, g2 of one coordinate w at the three vertices:
//   f1 = w0 + w1 + w2, fn = sn(w0, w1) + w2 f(n-1), gi = f2 + wi f1 + wi².
struct TriangleCoordinateTerms {
    double f1, f2, f3;
    double g0, g1, g2;

    TriangleCoordinateTerms(double w0, double w1, double w2) {
        const double s1 = w0 + w1;
        const double w0w0 = w0 * w0;
        const double s2 = w0w0 + w1 * s1;  // w0² + w0 w1 + w1²
        f1 = s1 + w2;
        f2 = s2 + w2 * f1;
        f3 = w0 * w0w0 + w1 * s2 + w2 * f2;  // s3 + w2 f2
        g0 = f2 + w0 * (f1 + w0);
        g1 = f2 + w1 * (f1 + w1);
        g2 = f2 + w2 * (f1 + w2);
    }
};

}  // namespace detail

// Adds the triangle's face sums, each times a constant (6 for x, 12 for the
// squares, 20 for the cubes, 60 for the mixed terms) that scaled_triangle_sums()
// divides out once per batch instead of once per triangle. Returns δ, whose
// length is twice the triangle's area.
inline Eigen::Vector3d add_unscaled_triangle_sums(FaceSums& unscaled, const Eigen::Vector3d& p0,
                                         const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
    const Eigen::Vector3d delta = (p1 - p0).cross(p2 - p0);
    const detail::TriangleCoordinateTerms x(p0.x(), p1.x(), p2.x());
    const detail::TriangleCoordinateTerms y(p0.y(), p1.y(), p2.y());
    const detail::TriangleCoordinateTerms z(p0.z(), p1.z(), p2.z());

    unscaled.x += delta.x() * x.f1;
    unscaled.squares += delta.cwiseProduct(Eigen::Vector3d(x.f2, y.f2, z.f2));
    unscaled.cubes += delta.cwiseProduct(Eigen::Vector3d(x.f3, y.f3, z.f3));
    unscaled.mixed += delta.cwiseProduct(
        Eigen::Vector3d(p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2,
                        p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2,
                        p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2));
    return delta;
}

inline FaceSums scaled_triangle_sums(const FaceSums& unscaled) {
    FaceSums sums;
    sums.x = unscaled.x / 6.0;
    sums.squares = unscaled.squares / 12.0;
    sums.cubes = unscaled.cubes / 20.0;
    sums.mixed = unscaled.mixed / 60.0;
    return sums;
}

}  // namespace polymass::core
