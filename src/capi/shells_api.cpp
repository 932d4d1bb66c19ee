// polymass_mesh_shells and polymass_mesh_shell_list: the connected pieces of
// a surface, and what each one is.
#include <polymass/polymass.h>

#include <algorithm>
#include <cstdint>

#include "api_guard.hpp"
#include "core/shells.hpp"
#include "core/welding.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

using namespace polymass;
using namespace polymass::capi;

namespace {

int32_t check_face_count(polymass_context* context, const MeshInput& input) {
    if (input.face_count > UINT32_MAX)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "the mesh has %llu faces; shells are numbered for up to %u",
                             static_cast<unsigned long long>(input.face_count), UINT32_MAX);
    return POLYMASS_OK;
}

int32_t shell_kind(core::ShellKind kind) {
    switch (kind) {
        case core::ShellKind::solid:
            return POLYMASS_SHELL_SOLID;
        case core::ShellKind::cavity:
            return POLYMASS_SHELL_CAVITY;
        case core::ShellKind::inverted:
            return POLYMASS_SHELL_INVERTED;
        case core::ShellKind::overlapping:
            return POLYMASS_SHELL_OVERLAPPING;
        case core::ShellKind::no_volume:
            return POLYMASS_SHELL_NO_VOLUME;
    }
    return POLYMASS_SHELL_NO_VOLUME;
}

}  // namespace

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
        if (const int32_t status = check_face_count(context, input)) return status;
        return visit_mesh(input, [&](const auto& view) {
            std::pmr::memory_resource* memory = &context->memory;
            core::MeshAnalysis scanned(core::scan_mesh(view, memory, context->tasks(call)));
            scanned.verdict = core::judge(scanned, {});
            uint32_t warnings = 0;
            if (const int32_t status = report_verdict(context, input, call, scanned, warnings))
                return status;
            std::pmr::vector<std::uint32_t> welded(memory);
            if (call.flags & POLYMASS_OPTION_WELD_VERTICES)
                welded = core::weld_vertices(view, scanned.scan, call.weld_tolerance, memory);
            const core::Shells shells =
                core::find_shells(view, scanned.scan, welded.empty() ? nullptr : welded.data(),
                                  context->tasks(call), memory);
            std::copy(shells.of_face.begin(), shells.of_face.end(), out_shell_of_face);
            *out_shell_count = shells.count;
            return int32_t(POLYMASS_OK);
        });
    });
}

POLYMASS_API int32_t polymass_mesh_shell_list(polymass_shell* out_shells, uint64_t capacity,
                                              uint64_t* out_shell_count, polymass_context* context,
                                              const polymass_mesh_desc* desc) {
    return guarded(context, [&] {
        if (!out_shell_count)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "out_shell_count is NULL");
        // The caller's elements lie its sizeof(polymass_shell) apart, which
        // is the struct_size it set in each.
        auto element = [&](uint64_t i) {
            return reinterpret_cast<polymass_shell*>(reinterpret_cast<unsigned char*>(out_shells) +
                                                     i * out_shells[0].struct_size);
        };
        if (capacity > 0) {
            if (const int32_t status = check_struct(context, out_shells, "out_shells"))
                return status;
            for (uint64_t i = 1; i < capacity; ++i)
                if (element(i)->struct_size != out_shells[0].struct_size)
                    return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                         "out_shells[%llu].struct_size is %u, not %u as in "
                                         "out_shells[0]",
                                         static_cast<unsigned long long>(i),
                                         unsigned(element(i)->struct_size),
                                         unsigned(out_shells[0].struct_size));
        }
        MeshInput input;
        if (const int32_t status = read_mesh_desc(context, desc, input)) return status;
        if (const int32_t status = check_face_count(context, input)) return status;
        // The full analysis, stopping at the first defect before the shells:
        // they are described whether or not they pass.
        core::MeshAnalysis analysis = analyse(context, input, context->options, false);
        if (!analysis.shells) {
            uint32_t warnings = 0;
            const int32_t status =
                report_verdict(context, input, context->options, analysis, warnings);
            if (status != POLYMASS_OK) return status;
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "the shells are judged with the topology checks on: clear "
                                 "POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS");
        }
        const core::ShellSurvey& survey = *analysis.shells;
        *out_shell_count = survey.summary.size();
        const uint64_t written = std::min<uint64_t>(capacity, survey.summary.size());
        for (uint64_t i = 0; i < written; ++i) {
            const core::ShellSummary& summary = survey.summary[i];
            polymass_shell shell = StructVersions<polymass_shell>::defaults();
            shell.kind = shell_kind(summary.kind);
            shell.face_count = summary.face_count;
            shell.first_face = summary.first_face;
            shell.signed_volume = summary.signed_volume;
            write_struct(element(i), shell);
        }
        return int32_t(POLYMASS_OK);
    });
}

}  // extern "C"
