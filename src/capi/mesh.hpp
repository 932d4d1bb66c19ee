// The object behind polymass_mesh: a validated solid, kept as its integrals.
#pragma once

#include <polymass/polymass.h>

#include <Eigen/Core>
#include <cstdint>

#include "core/approximation_bound.hpp"
#include "core/volume_integrals.hpp"

// A solid: its integrals, not the caller's arrays.
struct polymass_mesh {
    polymass_allocator allocator;               // to free it with; the context may be gone by then
    polymass::core::VolumeIntegrals integrals;  // about `reference`, outward-oriented
    polymass::core::IntegralBounds bounds;      // on their rounding errors
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    double surface_area = 0.0;
    uint32_t warnings = 0;
    // How far the body can be from the caller's solid when a mode other than
    // SOLID answered (zero otherwise), at unit density.
    polymass::core::ApproximationBound approximation;
};

namespace polymass::capi {

// Validates (with the call's options) and integrates the caller's surface
// into `mesh`: the body of polymass_mesh_create. Returns the status, with the
// message in the context.
int32_t build_mesh(polymass_context* context, const polymass_mesh_desc* desc,
                   const polymass_options& options, polymass_mesh& mesh);

struct MeshInput;

// build_mesh on an input already read: the SOLID mode.
int32_t build_solid(polymass_context* context, const MeshInput& input,
                    const polymass_options& options, polymass_mesh& mesh);

// The mesh as the first mode of the options' chain that answers gives it
// (docs/repair.md), and what that mode did. Returns the status, with the
// message in the context (when no mode answers: each mode's reason).
int32_t build_answer(polymass_context* context, const polymass_mesh_desc* desc,
                     const polymass_options& options, polymass_mesh& mesh,
                     polymass_provenance& provenance);

}  // namespace polymass::capi
