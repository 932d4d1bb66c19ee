#include "result_bounds.hpp"

#include <cmath>
#include <limits>

namespace polymass::core {
namespace {

constexpr double u = 0x1p-53;  // unit roundoff
constexpr double half_pi = 1.5707963267948966;
// As in principal_axes.cpp: moments this close, relative to the largest, are
// taken as equal and their axes chosen by convention, not by the data.
constexpr double coincidence = 1e-10;

}  // namespace

ResultBounds result_bounds(const VolumeIntegrals& mass, const IntegralBounds& mass_bounds,
                           double volume_bound, const Eigen::Vector3d& reference,
                           const RigidBody& body, const PrincipalAxes& principal) {
    ResultBounds bounds;
    bounds.volume = volume_bound + u * std::abs(body.volume);
    const double m = std::abs(mass.volume), dm = mass_bounds.volume;
    if (!(dm < 0.5 * m)) {  // the rounding could be the mass itself: no bound
        const double unknown = std::numeric_limits<double>::infinity();
        return {bounds.volume, unknown, unknown, unknown, half_pi};
    }

    // The centroid relative to the reference, c = F / m, then the centre.
    const Eigen::Vector3d c = mass.first / mass.volume;
    const Eigen::Vector3d dc = ((mass_bounds.first + c.cwiseAbs().array() * dm) / (m - dm) +
                                2.0 * u * c.cwiseAbs().array())
                                   .matrix();
    bounds.center_of_mass = (dc + u * (reference + c).cwiseAbs()).maxCoeff();

    // Central second moments S − m c cᵀ, entry by entry.
    const Eigen::Vector3d& sq = mass.second;
    const Eigen::Vector3d& pr = mass.products;  // xy, yz, zx
    Eigen::Matrix3d s;
    s << sq.x(), pr.x(), pr.z(),  //
        pr.x(), sq.y(), pr.y(),   //
        pr.z(), pr.y(), sq.z();
    const Eigen::Vector3d a = c.cwiseAbs();
    const Eigen::Matrix3d cc = a * a.transpose();
    const Eigen::Matrix3d central_error =
        (mass_bounds.second + dm * cc.array() +
         m * (dc * a.transpose() + a * dc.transpose() + dc * dc.transpose()).array() +
         4.0 * u * (s.cwiseAbs() + m * cc).array())
            .matrix();
    // A diagonal entry of the inertia sums two central moments, an
    // off-diagonal one negates one; then the density (already in `mass`).
    const double largest_inertia = body.inertia.cwiseAbs().maxCoeff();
    bounds.inertia = 2.0 * central_error.maxCoeff() + 3.0 * u * largest_inertia;

    bound_principal(bounds, principal);
    return bounds;
}

void bound_principal(ResultBounds& bounds, const PrincipalAxes& principal) {
    // Weyl: each eigenvalue moves by at most the perturbation's 2-norm, at
    // most 3 times its largest entry; plus the eigensolver's backward error.
    const double largest_moment = principal.moments.cwiseAbs().maxCoeff();
    const double perturbation = 3.0 * bounds.inertia + 32.0 * u * largest_moment;
    bounds.principal_moments = perturbation;

    // Davis–Kahan: an axis turns by at most perturbation / gap, the gap to the
    // nearest other moment less what both may have moved.
    const Eigen::Vector3d& l = principal.moments;
    const double tolerance = coincidence * largest_moment;
    double worst = 0.0;
    for (int i = 0; i < 3; ++i) {
        double gap = std::numeric_limits<double>::infinity();
        for (int j = 0; j < 3; ++j)
            if (j != i) gap = std::min(gap, std::abs(l[i] - l[j]));
        if (gap <= tolerance) continue;  // a conventional axis: not the data's
        const double usable = gap - 2.0 * bounds.principal_moments;
        worst = std::max(worst, usable > 0.0 ? std::min(half_pi, perturbation / usable) : half_pi);
    }
    bounds.principal_axes = worst;
}

}  // namespace polymass::core
