// Rotations as the description formats write them, turned into matrices
// (Eigen, row i column j). Angles are in radians here; the MJCF parser
// converts degrees first.
#pragma once

#include <Eigen/Core>
#include <string>

namespace polymass_cli::audit {

// URDF and SDFormat roll, pitch, yaw: about the fixed x, y, z axes in turn,
// R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d rotation_from_rpy(double roll, double pitch, double yaw);

// The unit quaternion w + x i + y j + z k, normalised (MuJoCo normalises
// quaternions; so do SDFormat readers). Throws DescriptionError naming what
// when the quaternion is zero.
Eigen::Matrix3d rotation_from_quaternion(double w, double x, double y, double z,
                                         const std::string& what);

// A rotation by angle about axis (normalised; DescriptionError when zero).
Eigen::Matrix3d rotation_from_axis_angle(const Eigen::Vector3d& axis, double angle,
                                         const std::string& what);

// MuJoCo's euler with <compiler eulerseq>: three rotations in the sequence's
// order, a lower-case axis one of the rotating frame (intrinsic: applied on
// the right), an upper-case axis one of the parent frame (extrinsic: applied
// on the left). DescriptionError when the sequence is not three of xyzXYZ.
Eigen::Matrix3d rotation_from_euler(const Eigen::Vector3d& angles, const std::string& sequence,
                                    const std::string& what);

// MuJoCo's xyaxes: the frame's x axis, its y axis (made orthogonal to x),
// z = x cross y.
Eigen::Matrix3d rotation_from_xy_axes(const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                                      const std::string& what);

// MuJoCo's zaxis (and fromto): the smallest rotation taking +z to the
// direction.
Eigen::Matrix3d rotation_from_z_axis(const Eigen::Vector3d& z, const std::string& what);

}  // namespace polymass_cli::audit
