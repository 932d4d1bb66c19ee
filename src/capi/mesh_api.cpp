// polymass_mesh_*: from the caller's arrays to a validated, integrated solid.
#include <polymass/polymass.h>

#include "api_guard.hpp"
#include "mass_properties.hpp"
#include "mesh.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

namespace polymass::capi {

int32_t build_mesh(polymass_context* context, const polymass_mesh_desc* desc,
                   const polymass_options& options, polymass_mesh& mesh) {
    MeshInput input;
    if (const int32_t status = read_mesh_desc(context, desc, input)) return status;
    return build_solid(context, input, options, mesh);
}

int32_t build_solid(polymass_context* context, const MeshInput& input,
                    const polymass_options& options, polymass_mesh& mesh) {
    const core::MeshAnalysis analysis = analyse(context, input, options, false);
    uint32_t warnings = 0;
    if (const int32_t status = report_verdict(context, input, options, analysis, warnings))
        return status;
    const core::IntegrationResult& integration = *analysis.integration;
    mesh.integrals = (warnings & POLYMASS_WARNING_INVERTED) ? integration.integrals.negated()
                                                            : integration.integrals;
    mesh.bounds = integration.bounds;
    mesh.reference = analysis.scan.reference_point();
    mesh.surface_area = integration.surface_area;
    mesh.warnings = warnings;
    return POLYMASS_OK;
}

}  // namespace polymass::capi

using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_mesh_create(polymass_mesh** out_mesh, polymass_context* context,
                                          const polymass_mesh_desc* desc) {
    return polymass_mesh_create_with_options(out_mesh, context, desc, nullptr);
}

POLYMASS_API int32_t polymass_mesh_create_with_options(polymass_mesh** out_mesh,
                                                       polymass_context* context,
                                                       const polymass_mesh_desc* desc,
                                                       const polymass_options* options) {
    if (out_mesh) *out_mesh = nullptr;  // on every failure, even without a context
    return guarded(context, [&] {
        if (!out_mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "out_mesh is NULL");
        polymass_options call;
        if (const int32_t status = call_options(context, options, call)) return status;
        polymass_mesh mesh{context->allocator, {}, {}, Eigen::Vector3d::Zero(), 0.0, 0, {}};
        polymass_provenance provenance{};
        if (const int32_t status = build_answer(context, desc, call, mesh, provenance))
            return status;
        *out_mesh = create_object<polymass_mesh>(context->allocator, mesh);
        if (!*out_mesh)
            return context->fail(POLYMASS_ERROR_OUT_OF_MEMORY,
                                 "out of memory: the allocator could not provide the mesh");
        return POLYMASS_OK;
    });
}

POLYMASS_API void polymass_mesh_destroy(polymass_mesh* mesh) { destroy_object(mesh); }

POLYMASS_API int32_t polymass_mesh_mass_properties(polymass_mass_properties* out_properties,
                                                   polymass_context* context,
                                                   const polymass_mesh* mesh,
                                                   const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        return mass_properties(out_properties, context, *mesh, mass);
    });
}

POLYMASS_API int32_t polymass_mass_properties_compute(polymass_mass_properties* out_properties,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_mass_desc* mass) {
    return polymass_mass_properties_compute_with_options(out_properties, context, desc, mass,
                                                         nullptr);
}

POLYMASS_API int32_t polymass_mass_properties_compute_with_options(
    polymass_mass_properties* out_properties, polymass_context* context,
    const polymass_mesh_desc* desc, const polymass_mass_desc* mass,
    const polymass_options* options) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        polymass_options call;
        if (const int32_t status = call_options(context, options, call)) return status;
        polymass_mesh mesh{context->allocator, {}, {}, Eigen::Vector3d::Zero(), 0.0, 0, {}};
        polymass_provenance provenance{};
        if (const int32_t status = build_answer(context, desc, call, mesh, provenance))
            return status;
        return mass_properties(out_properties, context, mesh, mass);
    });
}

POLYMASS_API int32_t polymass_mesh_check(polymass_diagnostics* out_report,
                                         polymass_context* context,
                                         const polymass_mesh_desc* desc) {
    return polymass_mesh_check_with_options(out_report, context, desc, nullptr);
}

POLYMASS_API int32_t polymass_mesh_check_with_options(polymass_diagnostics* out_report,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_options* options) {
    const bool report_valid =
        out_report && is_known_size<polymass_diagnostics>(out_report->struct_size);
    const int32_t status = guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_report, "out_report")) return status;
        polymass_options call;
        if (const int32_t status = call_options(context, options, call)) return status;
        MeshInput input;
        polymass_diagnostics report;
        int32_t found = read_mesh_desc(context, desc, input);
        fill_report(report, input, nullptr);  // what the arguments tell, if anything
        if (found == POLYMASS_OK) {
            const polymass::core::MeshAnalysis analysis = analyse(context, input, call, true);
            uint32_t warnings = 0;
            found = report_verdict(context, input, call, analysis, warnings);
            fill_report(report, input, &analysis);
        }
        write_struct(out_report, report);
        return found;
    });
    // Also when the checks could not finish (out of memory) or there is no context.
    if (report_valid) out_report->status = status;
    return status;
}

}  // extern "C"
