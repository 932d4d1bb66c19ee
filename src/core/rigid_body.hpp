// From volume integrals to a rigid body: mass, centre of mass, inertia tensors.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "volume_integrals.hpp"

namespace polymass::core {

struct RigidBody {
    double volume = 0.0;
    double mass = 0.0;
    double density = 0.0;
    Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass
};

// integrals are about `reference`; the body's frame is the caller's.
// I = ρ ∫(|r|² 𝟙 − r rᵀ) dV: off-diagonal terms are −ρ∫xy (negated products).
RigidBody rigid_body(const VolumeIntegrals& integrals, const Eigen::Vector3d& reference,
                     double density);

// Parallel-axis theorem: the inertia about `point` of a body whose inertia
// about its centre of mass is `body.inertia`.
Eigen::Matrix3d inertia_about(const RigidBody& body, const Eigen::Vector3d& point);

}  // namespace polymass::core
