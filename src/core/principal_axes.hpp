// Principal moments and axes of an inertia tensor.
#pragma once

#include <Eigen/Core>

namespace polymass::core {

struct PrincipalAxes {
    Eigen::Vector3d moments;  // ascending
    Eigen::Matrix3d axes;     // columns; a proper rotation (det = +1)
};

// Eigen-decomposition made deterministic: each axis's largest component is
// positive (the third axis is the cross product of the first two), and where
// moments coincide to rounding the free axes are taken from the coordinate
// axes, so symmetric bodies get the same answer on every machine.
PrincipalAxes principal_axes(const Eigen::Matrix3d& inertia);

}  // namespace polymass::core
