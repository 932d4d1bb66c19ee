#include "moments.hpp"

#include <algorithm>
#include <cmath>

namespace polymass::core {
namespace {

constexpr double u = 0x1p-53;  // unit roundoff

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

// The largest magnitude of a VolumeIntegrals' second moments and products.
double largest_second(const VolumeIntegrals& m) {
    return std::max(m.second.cwiseAbs().maxCoeff(), m.products.cwiseAbs().maxCoeff());
}

}  // namespace

Moments Moments::of_solid(const VolumeIntegrals& integrals, const IntegralBounds& bounds,
                          const Eigen::Vector3d& reference, double density) {
    Moments moments;
    moments.reference = reference;
    moments.volume = integrals.volume;
    moments.mass = integrals;
    moments.volume_bound = bounds.volume;
    moments.mass_bounds = bounds;
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
    // The shift's terms and its roundings; an error r in where the reference
    // is counts as a shift by r (docs/error_bound.md).
    const double m = std::abs(mass.volume), first = f.cwiseAbs().maxCoeff();
    const double dd = d.cwiseAbs().maxCoeff(), r = reference_bound;
    const IntegralBounds& b = mass_bounds;
    moved.mass_bounds.first = b.first + b.volume * dd + m * r + 3.0 * u * (first + m * dd);
    moved.mass_bounds.second = b.second + 2.0 * b.first * dd + b.volume * dd * dd +
                               2.0 * (first + m * dd) * r +
                               8.0 * u * (largest_second(mass) + 2.0 * first * dd + m * dd * dd);
    moved.reference_bound = 0.0;
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
    const double largest = factors.cwiseAbs().maxCoeff();
    stretched.reference_bound =
        largest * reference_bound + u * stretched.reference.cwiseAbs().maxCoeff();
    stretched.volume_bound = jacobian * volume_bound + 2.0 * u * std::abs(stretched.volume);
    stretched.mass_bounds = {
        jacobian * mass_bounds.volume + 2.0 * u * std::abs(stretched.mass.volume),
        jacobian * largest * mass_bounds.first +
            3.0 * u * stretched.mass.first.cwiseAbs().maxCoeff(),
        jacobian * largest * largest * mass_bounds.second +
            4.0 * u * largest_second(stretched.mass)};
    return stretched;
}

Moments Moments::weighted(double factor) const {
    Moments weighted = *this;
    weighted.mass = {factor * mass.volume, factor * mass.first, factor * mass.second,
                     factor * mass.products};
    const double f = std::abs(factor);
    weighted.mass_bounds = {f * mass_bounds.volume + u * std::abs(weighted.mass.volume),
                            f * mass_bounds.first + u * weighted.mass.first.cwiseAbs().maxCoeff(),
                            f * mass_bounds.second + u * largest_second(weighted.mass)};
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

ResultBounds Moments::result_bounds(const RigidBody& body, const PrincipalAxes& principal) const {
    ResultBounds bounds =
        core::result_bounds(mass, mass_bounds, volume_bound, reference, body, principal);
    bounds.center_of_mass += reference_bound;  // the body is where its reference is
    return bounds;
}

Moments operator+(const Moments& a, const Moments& b) {
    // Both about a's reference, whose own error r counts as a shift of a by r.
    const Moments shifted = b.about(a.reference);
    const Moments anchored = a.about(a.reference);
    Moments sum = anchored;
    sum.volume += shifted.volume;
    sum.mass.volume += shifted.mass.volume;
    sum.mass.first += shifted.mass.first;
    sum.mass.second += shifted.mass.second;
    sum.mass.products += shifted.mass.products;
    sum.volume_bound = a.volume_bound + b.volume_bound + u * std::abs(sum.volume);
    sum.mass_bounds = {
        anchored.mass_bounds.volume + shifted.mass_bounds.volume + u * std::abs(sum.mass.volume),
        anchored.mass_bounds.first + shifted.mass_bounds.first +
            u * sum.mass.first.cwiseAbs().maxCoeff(),
        anchored.mass_bounds.second + shifted.mass_bounds.second + u * largest_second(sum.mass)};
    return sum;
}

Moments operator-(const Moments& a, const Moments& b) {
    Moments negated = b;  // the bounds stay: they are magnitudes
    negated.volume = -b.volume;
    negated.mass = b.mass.negated();
    return a + negated;
}

}  // namespace polymass::core
