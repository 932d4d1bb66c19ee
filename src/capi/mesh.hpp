// The object behind polymass_mesh: one analysis of a surface, kept as what
// its questions need (the verdict, the diagnostics, the shells, the
// provenance and the body that answered), not as the caller's arrays.
#pragma once

#include <polymass/polymass.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "context.hpp"
#include "core/surface_answer.hpp"

namespace polymass::capi {

// What the chain of modes answered: the body, and which mode gave it, how.
struct Answer {
    core::Body body;
    polymass_provenance provenance{};
};

}  // namespace polymass::capi

struct polymass_mesh {
    explicit polymass_mesh(const polymass_allocator& hook)
        : allocator(hook), memory(hook), shells(&memory), shell_of_face(&memory) {}

    polymass_allocator allocator;               // to free it with; the context may be gone by then
    polymass::capi::HookMemoryResource memory;  // the mesh's own arrays below
    int32_t status = POLYMASS_OK;               // POLYMASS_OK when a mode answered
    // What is wrong with the surface (polymass_mesh_message).
    char message[sizeof(polymass_context::message)] = "";
    polymass_diagnostics diagnostics{};
    std::pmr::vector<polymass_shell> shells;
    std::pmr::vector<uint32_t> shell_of_face;  // empty when the faces are unreadable
    polymass::capi::Answer answer;             // when status is POLYMASS_OK
};

namespace polymass::capi {

struct MeshInput;

// The one analysis of a surface read into `input`, shared by
// polymass_mesh_create and polymass_mass_properties_compute
// (core::answer_surface). With `findings` (a mesh being made), every check
// runs to its end and the diagnostics and shells are written to it; without,
// the analysis stops at the first problem. Returns the status with the
// message in the context (when no mode answers: each mode's reason) and, on
// success, the answer.
int32_t analyse_surface(polymass_context* context, const MeshInput& input,
                        const polymass_options& options, Answer& answer, polymass_mesh* findings);

// POLYMASS_OK when a mode answered, else the mesh's status with its message
// in the context: what the getters of the answer return.
inline int32_t unanswered(polymass_context* context, const polymass_mesh& mesh) {
    if (mesh.status == POLYMASS_OK) return POLYMASS_OK;
    return context->fail(mesh.status, "%s", mesh.message);
}

}  // namespace polymass::capi
