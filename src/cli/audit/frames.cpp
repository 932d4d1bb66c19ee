#include "audit/frames.hpp"

#include <Eigen/Geometry>

#include "audit/description.hpp"

namespace polymass_cli::audit {
namespace {

Eigen::Vector3d unit(const Eigen::Vector3d& v, const std::string& what) {
    const double norm = v.norm();
    if (!(norm > 0.0)) throw DescriptionError(what + ": a zero-length axis");
    return v / norm;
}

}  // namespace

Eigen::Matrix3d rotation_from_rpy(double roll, double pitch, double yaw) {
    return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

Eigen::Matrix3d rotation_from_quaternion(double w, double x, double y, double z,
                                         const std::string& what) {
    Eigen::Quaterniond q(w, x, y, z);
    if (!(q.norm() > 0.0)) throw DescriptionError(what + ": a zero quaternion");
    return q.normalized().toRotationMatrix();
}

Eigen::Matrix3d rotation_from_axis_angle(const Eigen::Vector3d& axis, double angle,
                                         const std::string& what) {
    return Eigen::AngleAxisd(angle, unit(axis, what)).toRotationMatrix();
}

Eigen::Matrix3d rotation_from_euler(const Eigen::Vector3d& angles, const std::string& sequence,
                                    const std::string& what) {
    if (sequence.size() != 3) {
        throw DescriptionError(what + ": eulerseq '" + sequence + "' is not three axes");
    }
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; ++i) {
        const char c = sequence[static_cast<std::size_t>(i)];
        const int axis = (c | 0x20) - 'x';  // lower-cased
        if (axis < 0 || axis > 2) {
            throw DescriptionError(what + ": eulerseq '" + sequence + "' is not three of xyzXYZ");
        }
        const Eigen::Matrix3d turn =
            Eigen::AngleAxisd(angles[i], Eigen::Vector3d::Unit(axis)).toRotationMatrix();
        rotation = (c >= 'a') ? Eigen::Matrix3d(rotation * turn) : Eigen::Matrix3d(turn * rotation);
    }
    return rotation;
}

Eigen::Matrix3d rotation_from_xy_axes(const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                                      const std::string& what) {
    const Eigen::Vector3d ex = unit(x, what);
    const Eigen::Vector3d ey = unit(y - y.dot(ex) * ex, what);
    Eigen::Matrix3d rotation;
    rotation << ex, ey, ex.cross(ey);
    return rotation;
}

Eigen::Matrix3d rotation_from_z_axis(const Eigen::Vector3d& z, const std::string& what) {
    return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), unit(z, what))
        .toRotationMatrix();
}

}  // namespace polymass_cli::audit
