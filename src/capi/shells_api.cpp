// polymass_mesh_shells: which connected piece of the surface each face is in.
#include <polymass/polymass.h>

#include <algorithm>
#include <cstdint>

#include "api_guard.hpp"
#include "core/shells.hpp"
#include "core/welding.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"

using namespace polymass;
using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_mesh_shells(uint32_t* out_shell_of_face, uint64_t* out_shell_count,
                                          polymass_context* context,
                                          const polymass_mesh_desc* desc) {
    return polymass_mesh_shells_with_options(out_shell_of_face, out_shell_count, context, desc,
                                             nullptr);
}

POLYMASS_API int32_t polymass_mesh_shells_with_options(uint32_t* out_shell_of_face,
                                                       uint64_t* out_shell_count,
                                                       polymass_context* context,
                                                       const polymass_mesh_desc* desc,
                                                       const polymass_options* options) {
    return guarded(context, [&] {
        if (!out_shell_of_face || !out_shell_count)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s is NULL",
                                 out_shell_of_face ? "out_shell_count" : "out_shell_of_face");
        polymass_options call;
        if (const int32_t status = call_options(context, options, call)) return status;
        MeshInput input;
        if (const int32_t status = read_mesh_desc(context, desc, input)) return status;
        if (input.face_count > UINT32_MAX)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "the mesh has %llu faces; shells are numbered for up to %u",
                                 static_cast<unsigned long long>(input.face_count), UINT32_MAX);
        return visit_mesh(input, [&](const auto& view) {
            std::pmr::memory_resource* memory = &context->memory;
            const core::MeshScan scan = core::scan_mesh(view, memory);
            if (const int32_t status = judge_scan(context, input, scan)) return status;
            std::pmr::vector<std::uint32_t> welded(memory);
            if (call.flags & POLYMASS_OPTION_WELD_VERTICES)
                welded = core::weld_vertices(view, scan, call.weld_tolerance, memory);
            const core::Shells shells =
                core::find_shells(view, welded.empty() ? nullptr : welded.data(), memory);
            std::copy(shells.of_face.begin(), shells.of_face.end(), out_shell_of_face);
            *out_shell_count = shells.count;
            return int32_t(POLYMASS_OK);
        });
    });
}

}  // extern "C"
