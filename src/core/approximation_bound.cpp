#include "approximation_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polymass::core {

ApproximationBound bound_of_changed_volume(double changed_volume, double answer_volume,
                                           double span) {
    // docs/approximations.md, "A changed region": with a the answer's volume
    // and D the changed volume, the true volume is at least a − D; both
    // centroids lie within the span of each other.
    const double d = changed_volume, a = answer_volume;
    ApproximationBound bound;
    bound.volume = d;
    if (!(a > d)) {
        bound.center_of_mass = span;
        bound.inertia = std::numeric_limits<double>::infinity();
        return bound;
    }
    const double rest = a - d;
    bound.center_of_mass = std::min(span, d * span / rest);
    bound.inertia = 2.0 * d * span * span * (1.0 + a * d / (rest * rest));
    return bound;
}

ApproximationBound approximation_bound(const std::pmr::vector<UncertainRegion>& regions,
                                       const RigidBody& solid, const Eigen::AlignedBox3d& box) {
    // The true solid is the answer plus a signed measure δ inside the
    // regions, |δ| ≤ ΔV; with s = r − c its points relative to the centroid:
    //   c' − c = ∫δ s / V',   each coordinate at most Σ vᵢ rᵢ / (V − ΔV),
    //   J'(c) − J(c) = ∫δ (|s|² 𝟙 − s sᵀ), each entry at most Σ vᵢ rᵢ²,
    // and the move from c to c' takes V' (|d|² 𝟙 − d dᵀ), |d|² ≤ 3 Δc².
    // Whatever the regions' volume, both solids lie in the box reached by the
    // answer and the regions, and so do their centroids: each coordinate is
    // off by at most the box's extent, and with L its diagonal each inertia
    // entry is at most V L² in the answer and (V + ΔV) L² in the truth.
    ApproximationBound bound;
    Eigen::AlignedBox3d reach = box;
    for (const UncertainRegion& region : regions) {
        reach.extend(region.centre - Eigen::Vector3d::Constant(region.radius));
        reach.extend(region.centre + Eigen::Vector3d::Constant(region.radius));
    }
    double first = 0.0, second = 0.0;
    for (const UncertainRegion& region : regions) {
        const double distance = (region.centre - solid.center_of_mass).norm() + region.radius;
        bound.volume += region.volume;
        first += region.volume * distance;
        second += region.volume * distance * distance;
    }
    const double volume = std::abs(solid.volume);
    const double extent = reach.sizes().maxCoeff(), diagonal = reach.diagonal().norm();
    bound.center_of_mass = extent;
    bound.inertia = (2.0 * volume + bound.volume) * diagonal * diagonal;
    if (bound.volume < volume) {
        const double shift = first / (volume - bound.volume);
        bound.center_of_mass = std::min(bound.center_of_mass, shift);
        bound.inertia =
            std::min(bound.inertia, second + 3.0 * (volume + bound.volume) * shift * shift);
    }
    return bound;
}

double approximation_inertia(const ApproximationBound& approximation, const RigidBody& body,
                             bool mass_given) {
    if (!mass_given) return body.density * approximation.inertia;
    // I = (M / V) J: the density M / V' of the true solid moves too.
    const double volume = std::abs(body.volume), dv = approximation.volume;
    if (!(dv < volume)) return std::numeric_limits<double>::infinity();
    const double largest = body.inertia.cwiseAbs().maxCoeff();
    return body.density * volume / (volume - dv) *
           (approximation.inertia + largest / body.density * dv / volume);
}

ResultBounds widen(const ResultBounds& rounding, const ApproximationBound& approximation,
                   const RigidBody& body, bool mass_given, const PrincipalAxes& principal) {
    if (approximation.volume == 0.0 && approximation.center_of_mass == 0.0 &&
        approximation.inertia == 0.0)
        return rounding;  // exact: nothing to add
    ResultBounds bounds = rounding;
    bounds.volume += approximation.volume;
    bounds.center_of_mass += approximation.center_of_mass;
    bounds.inertia += approximation_inertia(approximation, body, mass_given);
    bound_principal(bounds, principal);
    return bounds;
}

}  // namespace polymass::core
