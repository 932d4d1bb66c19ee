#include "approximation_bound.hpp"

#include <algorithm>
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

}  // namespace polymass::core
