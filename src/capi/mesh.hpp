// The object behind polymass_mesh: a validated solid, kept as its integrals.
#pragma once

#include <polymass/polymass.h>

#include <Eigen/Core>
#include <cstdint>

#include "core/volume_integrals.hpp"

// A solid: its integrals, not the caller's arrays.
struct polymass_mesh {
    polymass_allocator allocator;               // to free it with; the context may be gone by then
    polymass::core::VolumeIntegrals integrals;  // about `reference`, outward-oriented
    polymass::core::IntegralBounds bounds;      // on their rounding errors
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    double surface_area = 0.0;
    uint32_t warnings = 0;
};

namespace polymass::capi {

// Validates (with the call's options) and integrates the caller's surface
// into `mesh`: the body of polymass_mesh_create. Returns the status, with the
// message in the context.
int32_t build_mesh(polymass_context* context, const polymass_mesh_desc* desc,
                   const polymass_options& options, polymass_mesh& mesh);

}  // namespace polymass::capi
