#include "rigid_body.hpp"

namespace polymass::core {
namespace {

// tr(S) 𝟙 − S for a symmetric S, with each diagonal term summed from the two
// others (Iyy + Izz, not tr − Ixx): a body long in one direction would
// otherwise lose its small moments to cancellation.
Eigen::Matrix3d inertia_from_second_moments(const Eigen::Matrix3d& s) {
    Eigen::Matrix3d inertia = -s;
    inertia(0, 0) = s(1, 1) + s(2, 2);
    inertia(1, 1) = s(2, 2) + s(0, 0);
    inertia(2, 2) = s(0, 0) + s(1, 1);
    return inertia;
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
    body.inertia = density * inertia_from_second_moments(central);
    return body;
}

Eigen::Matrix3d inertia_about(const RigidBody& body, const Eigen::Vector3d& point) {
    // A unit point mass at d has second moments d dᵀ.
    const Eigen::Vector3d d = body.center_of_mass - point;
    return body.inertia + body.mass * inertia_from_second_moments(d * d.transpose());
}

}  // namespace polymass::core
