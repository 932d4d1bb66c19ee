#include "mass_properties.hpp"

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
    return with_bounds(body, moments, solid.approximation, mass.total);
}

Moments weighed(const Moments& moments, const GivenMass& mass) {
    const double factor = mass.total ? mass.value / moments.mass.volume
                                     : mass.value * (moments.volume / moments.mass.volume);
    Moments weighted = moments.weighted(factor);
    if (mass.total) weighted.mass.volume = mass.value;
    return weighted;
}

MassProperties mass_properties(const Moments& moments) {
    return with_bounds(moments.rigid_body(), moments, {}, false);
}

}  // namespace polymass::core
