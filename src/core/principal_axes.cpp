#include "principal_axes.hpp"

#include <Eigen/Eigenvalues>

namespace polymass::core {
namespace {

// Moments closer than this, relative to the largest, are taken as equal: the
// integrals carry ~1e-15 relative rounding, and eigenvectors of nearly equal
// eigenvalues are dominated by it.
constexpr double coincidence = 1e-10;

// The sign that makes the largest-magnitude component positive.
Eigen::Vector3d canonical_sign(const Eigen::Vector3d& axis) {
    Eigen::Index largest = 0;
    axis.cwiseAbs().maxCoeff(&largest);
    return axis[largest] < 0 ? Eigen::Vector3d(-axis) : axis;
}

// A unit vector perpendicular to `axis`: the coordinate axis least aligned
// with it, with the `axis` component removed.
Eigen::Vector3d perpendicular_from_coordinate_axes(const Eigen::Vector3d& axis) {
    Eigen::Index least = 0;
    axis.cwiseAbs().minCoeff(&least);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(least);
    return (e - axis * axis.dot(e)).normalized();
}

}  // namespace

PrincipalAxes principal_axes(const Eigen::Matrix3d& inertia) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
    PrincipalAxes result{solver.eigenvalues(), Eigen::Matrix3d::Identity()};
    const Eigen::Matrix3d& vectors = solver.eigenvectors();
    const Eigen::Vector3d& m = result.moments;
    const double tolerance = coincidence * m.cwiseAbs().maxCoeff();
    const bool low_pair = m[1] - m[0] <= tolerance;
    const bool high_pair = m[2] - m[1] <= tolerance;
    Eigen::Matrix3d& axes = result.axes;

    if (low_pair && high_pair) return result;  // a sphere-like body: any frame; take xyz
    if (low_pair) {
        // Only the third axis is determined.
        axes.col(2) = canonical_sign(vectors.col(2));
        axes.col(0) = perpendicular_from_coordinate_axes(axes.col(2));
        axes.col(1) = axes.col(2).cross(axes.col(0));
    } else if (high_pair) {
        // Only the first axis is determined.
        axes.col(0) = canonical_sign(vectors.col(0));
        axes.col(1) = perpendicular_from_coordinate_axes(axes.col(0));
        axes.col(2) = axes.col(0).cross(axes.col(1));
    } else {
        axes.col(0) = canonical_sign(vectors.col(0));
        axes.col(1) = canonical_sign(vectors.col(1));
        axes.col(2) = axes.col(0).cross(axes.col(1));
    }
    return result;
}

}  // namespace polymass::core
