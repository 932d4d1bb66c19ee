// From a solid's integrals and a polymass_mass_desc to polymass_mass_properties.
#pragma once

#include <Eigen/Core>

#include "context.hpp"
#include "core/moments.hpp"
#include "mesh.hpp"

namespace polymass::capi {

// Checks `mass` (NULL: unit density) and writes the body's properties to
// *out, or returns the status with the message in the context.
int32_t mass_properties(polymass_mass_properties* out, polymass_context* context,
                        const core::Body& body, const polymass_mass_desc* mass);

// The moments with the density or mass of `mass` (NULL: as they are): the
// whole mass distribution rescaled to that mean density or total mass.
int32_t weight_moments(polymass_context* context, const core::Moments& moments,
                       const polymass_mass_desc* mass, core::Moments& out);

// The inertia about `point` of the body whose properties are `properties`
// (checked: a known struct_size, finite values), or the status.
int32_t inertia_about(double* out, const polymass_mass_properties& properties,
                      const Eigen::Vector3d& point);

// The mass properties of a body given by its moments, weighted as by
// weight_moments; the surface area is unknown (NaN), the warnings none.
int32_t moments_mass_properties(polymass_mass_properties* out, polymass_context* context,
                                const core::Moments& moments, const polymass_mass_desc* mass);

}  // namespace polymass::capi
