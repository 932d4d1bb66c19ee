// polymass_mesh_weld: the library's welding on its own, for a caller (a
// triangle-soup reader) that numbers vertices before it hands a mesh over.
#include <polymass/polymass.h>

#include <algorithm>
#include <cstdint>

#include "api_guard.hpp"
#include "core/welding.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"

using namespace polymass;
using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_mesh_weld(uint32_t* out_vertex_of, uint64_t* out_distinct_count,
                                        polymass_context* context, const polymass_mesh_desc* desc) {
    return guarded(context, [&] {
        if (!out_vertex_of || !out_distinct_count)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s is NULL",
                                 out_vertex_of ? "out_distinct_count" : "out_vertex_of");
        MeshInput input;
        if (const int32_t status = read_mesh_desc(context, desc, input)) return status;
        if (input.vertex_count > UINT32_MAX)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "the mesh has %llu vertices; welding numbers up to %u",
                                 static_cast<unsigned long long>(input.vertex_count), UINT32_MAX);
        const double tolerance = context->options.weld_tolerance;
        return visit_mesh(input, [&](const auto& view) {
            std::pmr::memory_resource* memory = &context->memory;
            core::MeshAnalysis scanned(
                core::scan_mesh(view, memory, context->tasks(context->options)));
            scanned.verdict = core::judge(scanned, {});
            // An exact weld compares bits, so only indices out of range stop
            // it; a weld within a tolerance measures distances, which need
            // finite coordinates.
            const core::Defect defect = scanned.verdict.defect;
            if (defect == core::Defect::index_out_of_range ||
                (tolerance > 0.0 && defect == core::Defect::non_finite)) {
                uint32_t warnings = 0;
                return report_verdict(context, input, context->options, scanned, warnings);
            }
            const std::pmr::vector<std::uint32_t> welded =
                core::weld_vertices(view, scanned.scan, tolerance, memory);
            // welded stops at the index type's reach (65,536 vertices for
            // 16-bit indices): the vertices past it are used by no face.
            std::copy(welded.begin(), welded.end(), out_vertex_of);
            for (std::size_t vertex = welded.size(); vertex < input.vertex_count; ++vertex)
                out_vertex_of[vertex] = std::uint32_t(vertex);
            *out_distinct_count = core::distinct_vertices(welded, scanned.scan);
            return int32_t(POLYMASS_OK);
        });
    });
}

}  // extern "C"
