#include "mass_properties.hpp"

#include <cfloat>
#include <cmath>
#include <limits>

#include "approximation_bound.hpp"

namespace polymass::core {
namespace {

// `body` with its principal axes and the bounds of `moments` (those it was
// computed from), widened by `approximation`.
MassProperties with_bounds(const RigidBody& body, const Moments& moments,
                           const ApproximationBound& approximation, bool mass_given) {
    MassProperties properties;
    properties.body = body;
    properties.inertia_about_origin = inertia_about(body, Eigen::Vector3d::Zero());
    properties.principal = principal_axes(body.inertia);
    properties.bounds = widen(moments.result_bounds(body, properties.principal), approximation,
                              body, mass_given, properties.principal);
    return properties;
}

}  // namespace

MassProperties mass_properties(const Body& solid, const GivenMass& mass) {
    const double density = mass.total ? mass.value / solid.integrals.volume : mass.value;
    RigidBody body = rigid_body(solid.integrals, solid.reference, density);
    if (mass.total) body.mass = mass.value;
    const Moments moments =
        Moments::of_solid(solid.integrals, solid.bounds, solid.reference, density);
    MassProperties properties = with_bounds(body, moments, solid.approximation, mass.total);
    properties.surface_area = solid.surface_area;
    return properties;
}

Moments weighed(const Moments& moments, const GivenMass& mass) {
    const double factor = mass.total ? mass.value / moments.mass.volume
                                     : mass.value * (moments.volume / moments.mass.volume);
    Moments weighted = moments.weighted(factor);
    if (mass.total) weighted.mass.volume = mass.value;
    return weighted;
}

MassProperties mass_properties(const Moments& moments) {
    MassProperties properties = with_bounds(moments.rigid_body(), moments, {}, false);
    properties.surface_area = std::numeric_limits<double>::quiet_NaN();
    return properties;
}

bool fits_in_doubles(const MassProperties& properties) {
    const RigidBody& body = properties.body;
    const PrincipalAxes& principal = properties.principal;
    return std::isfinite(body.volume) && std::isfinite(body.mass) && std::isfinite(body.density) &&
           !std::isinf(properties.surface_area) && body.mass >= DBL_MIN &&
           body.density >= DBL_MIN && principal.moments.cwiseAbs().maxCoeff() >= DBL_MIN &&
           body.center_of_mass.allFinite() && body.inertia.allFinite() &&
           properties.inertia_about_origin.allFinite() && principal.moments.allFinite() &&
           principal.axes.allFinite();
}

}  // namespace polymass::core
