#include "rigid_body.hpp"

namespace polymass::core {
namespace {

// |d|² 𝟙 − d dᵀ: the inertia of a unit point mass at d.
Eigen::Matrix3d point_inertia(const Eigen::Vector3d& d) {
    return d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose();
}

}  // namespace

RigidBody rigid_body(const VolumeIntegrals& integrals, const Eigen::Vector3d& reference,
                     double density) {
    RigidBody body;
    body.volume = integrals.volume;
    body.density = density;
    body.mass = density * integrals.volume;
    // Centroid relative to the reference point: small, so the shift below
    // cancels no large terms.
    const Eigen::Vector3d centroid = integrals.first / integrals.volume;
    body.center_of_mass = reference + centroid;

    // ∫ r rᵀ about the reference, then about the centroid.
    const Eigen::Vector3d& sq = integrals.second;
    const Eigen::Vector3d& pr = integrals.products;  // xy, yz, zx
    Eigen::Matrix3d moments;
    moments << sq.x(), pr.x(), pr.z(),  //
        pr.x(), sq.y(), pr.y(),         //
        pr.z(), pr.y(), sq.z();
    const Eigen::Matrix3d central = moments - integrals.volume * centroid * centroid.transpose();
    body.inertia = density * (central.trace() * Eigen::Matrix3d::Identity() - central);
    return body;
}

Eigen::Matrix3d inertia_about(const RigidBody& body, const Eigen::Vector3d& point) {
    return body.inertia + body.mass * point_inertia(body.center_of_mass - point);
}

}  // namespace polymass::core
