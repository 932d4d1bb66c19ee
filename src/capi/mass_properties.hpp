// From a solid's integrals and a polymass_mass_desc to polymass_mass_properties.
#pragma once

#include "context.hpp"
#include "mesh.hpp"

namespace polymass::capi {

// Checks `mass` (NULL: unit density, point = origin) and writes the body's
// properties to *out, or returns the status with the message in the context.
int32_t mass_properties(polymass_mass_properties* out, polymass_context* context,
                        const polymass_mesh& mesh, const polymass_mass_desc* mass);

}  // namespace polymass::capi
