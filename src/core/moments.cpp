#include "moments.hpp"

namespace polymass::core {
namespace {

// ∫ρ r rᵀ as a symmetric matrix, and back.
Eigen::Matrix3d second_moment_matrix(const VolumeIntegrals& m) {
    const Eigen::Vector3d& sq = m.second;
    const Eigen::Vector3d& pr = m.products;  // xy, yz, zx
    Eigen::Matrix3d s;
    s << sq.x(), pr.x(), pr.z(),  //
        pr.x(), sq.y(), pr.y(),   //
        pr.z(), pr.y(), sq.z();
    return s;
}

void set_second_moments(VolumeIntegrals& m, const Eigen::Matrix3d& s) {
    m.second = s.diagonal();
    m.products = {s(0, 1), s(1, 2), s(2, 0)};
}

}  // namespace

Moments Moments::of_solid(const VolumeIntegrals& integrals, const Eigen::Vector3d& reference,
                          double density) {
    Moments moments;
    moments.reference = reference;
    moments.volume = integrals.volume;
    moments.mass = integrals;
    return density == 1.0 ? moments : moments.weighted(density);
}

Moments Moments::about(const Eigen::Vector3d& point) const {
    // r_point = r_reference + d: the first moments gain m d, the second
    // F dᵀ + d Fᵀ + m d dᵀ (docs/moments.md).
    const Eigen::Vector3d d = reference - point;
    Moments moved = *this;
    moved.reference = point;
    const Eigen::Vector3d& f = mass.first;
    moved.mass.first = f + mass.volume * d;
    const Eigen::Matrix3d shift =
        f * d.transpose() + d * f.transpose() + mass.volume * d * d.transpose();
    set_second_moments(moved.mass, second_moment_matrix(mass) + shift);
    return moved;
}

Moments Moments::transformed(const Eigen::Matrix3d& rotation,
                             const Eigen::Vector3d& translation) const {
    // Integrals about the reference are rotated in place; the reference moves
    // with the body. A mirror maps the solid to its mirror image, whose
    // volume and mass are the same positive numbers.
    Moments moved = *this;
    moved.reference = rotation * reference + translation;
    moved.mass.first = rotation * mass.first;
    set_second_moments(moved.mass, rotation * second_moment_matrix(mass) * rotation.transpose());
    return moved;
}

Moments Moments::scaled(const Eigen::Vector3d& factors) const {
    // r -> D r with D = diag(factors): dV -> |det D| dV.
    const double jacobian = std::abs(factors.prod());
    Moments stretched;
    stretched.reference = factors.cwiseProduct(reference);
    stretched.volume = jacobian * volume;
    stretched.mass.volume = jacobian * mass.volume;
    stretched.mass.first = jacobian * factors.cwiseProduct(mass.first);
    const Eigen::Matrix3d d = factors.asDiagonal();
    set_second_moments(stretched.mass, jacobian * (d * second_moment_matrix(mass) * d));
    return stretched;
}

Moments Moments::weighted(double factor) const {
    Moments weighted = *this;
    weighted.mass = {factor * mass.volume, factor * mass.first, factor * mass.second,
                     factor * mass.products};
    return weighted;
}

RigidBody Moments::rigid_body() const {
    // The mass integrals are those of a unit-density solid whose "volume" is
    // the mass: core::rigid_body does the rest about the reference point.
    RigidBody body = core::rigid_body(mass, reference, 1.0);
    body.volume = volume;
    body.density = mass.volume / volume;
    return body;
}

Moments operator+(const Moments& a, const Moments& b) {
    const Moments shifted = b.about(a.reference);
    Moments sum = a;
    sum.volume += shifted.volume;
    sum.mass.volume += shifted.mass.volume;
    sum.mass.first += shifted.mass.first;
    sum.mass.second += shifted.mass.second;
    sum.mass.products += shifted.mass.products;
    return sum;
}

Moments operator-(const Moments& a, const Moments& b) {
    Moments negated = b;
    negated.volume = -b.volume;
    negated.mass = b.mass.negated();
    return a + negated;
}

}  // namespace polymass::core
