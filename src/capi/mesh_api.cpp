// polymass_mesh_* and polymass_mass_properties_compute: one analysis of the
// caller's surface (core::answer_surface), kept in a mesh or answered at once.
#include <polymass/polymass.h>

#include <algorithm>
#include <memory>

#include "answer_report.hpp"
#include "api_guard.hpp"
#include "mass_properties.hpp"
#include "mesh.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

struct MeshDeleter {
    void operator()(polymass_mesh* mesh) const { destroy_object(mesh); }
};

// Reads the call's options and surface; the status of the arguments.
int32_t read_call(polymass_context* context, const polymass_mesh_desc* desc,
                  const polymass_options* options, polymass_options& call, MeshInput& input) {
    if (const int32_t status = read_options(context, options, call)) return status;
    return read_mesh_desc(context, desc, input);
}

}  // namespace

int32_t analyse_surface(polymass_context* context, const MeshInput& input,
                        const polymass_options& options, Answer& answer, polymass_mesh* findings) {
    const core::AnswerSettings settings = answer_settings(context, options, findings != nullptr);
    const core::SurfaceAnswer result = visit_mesh(input, [&](const auto& view) {
        return core::answer_surface(view, settings, &context->memory);
    });
    if (findings) {
        fill_report(findings->diagnostics, input, result.surface);
        findings->diagnostics.status = status_of(result.surface.verdict.defect);
        list_shells(result.surface, findings->shells, findings->shell_of_face);
        mesh_message(context, input, options, result, findings->message);
    }
    if (const int32_t status = report_answer(context, input, options, result)) {
        // A mesh's failure says what its message says.
        if (findings) context->fail(status, "%s", findings->message);
        return status;
    }
    context->clear_message();
    answer.body = result.body;
    answer.provenance = provenance_of(result, options);
    return POLYMASS_OK;
}

}  // namespace polymass::capi

using namespace polymass;
using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_mass_properties_compute(polymass_mass_properties* out_properties,
                                                      polymass_provenance* out_provenance,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_options* options,
                                                      const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        if (out_provenance)
            if (const int32_t status = check_struct(context, out_provenance, "out_provenance"))
                return status;
        polymass_options call;
        MeshInput input;
        if (const int32_t status = read_call(context, desc, options, call, input)) return status;
        Answer answer;
        if (const int32_t status = analyse_surface(context, input, call, answer, nullptr))
            return status;
        if (const int32_t status = mass_properties(out_properties, context, answer.body, mass))
            return status;
        if (out_provenance) write_struct(out_provenance, answer.provenance);
        return POLYMASS_OK;
    });
}

POLYMASS_API int32_t polymass_mesh_create(polymass_mesh** out_mesh, polymass_context* context,
                                          const polymass_mesh_desc* desc,
                                          const polymass_options* options) {
    if (out_mesh) *out_mesh = nullptr;  // on every failure, even without a context
    return guarded(context, [&] {
        if (!out_mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "out_mesh is NULL");
        polymass_options call;
        MeshInput input;
        if (const int32_t status = read_call(context, desc, options, call, input)) return status;
        if (input.face_count > UINT32_MAX)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "the mesh has %llu faces; a mesh numbers its shells for up to %u",
                                 u64(input.face_count), UINT32_MAX);
        std::unique_ptr<polymass_mesh, MeshDeleter> mesh(
            create_object<polymass_mesh>(context->allocator, context->allocator));
        if (!mesh)
            return context->fail(POLYMASS_ERROR_OUT_OF_MEMORY,
                                 "out of memory: the allocator could not provide the mesh");
        mesh->status = analyse_surface(context, input, call, mesh->answer, mesh.get());
        *out_mesh = mesh.release();
        return (*out_mesh)->status;
    });
}

POLYMASS_API void polymass_mesh_destroy(polymass_mesh* mesh) { destroy_object(mesh); }

POLYMASS_API int32_t polymass_mesh_status(const polymass_mesh* mesh) {
    return mesh ? mesh->status : POLYMASS_ERROR_INVALID_ARGUMENT;
}

POLYMASS_API const char* polymass_mesh_message(const polymass_mesh* mesh) {
    return mesh ? mesh->message : "mesh is NULL";
}

POLYMASS_API int32_t polymass_mesh_diagnostics(polymass_diagnostics* out_diagnostics,
                                               polymass_context* context,
                                               const polymass_mesh* mesh) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_diagnostics, "out_diagnostics"))
            return status;
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        write_struct(out_diagnostics, mesh->diagnostics);
        return int32_t(POLYMASS_OK);
    });
}

POLYMASS_API int32_t polymass_mesh_shells(polymass_shell* out_shells, uint64_t capacity,
                                          uint64_t* out_shell_count, polymass_context* context,
                                          const polymass_mesh* mesh) {
    return guarded(context, [&] {
        if (!out_shell_count)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "out_shell_count is NULL");
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
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
                                         u64(i), unsigned(element(i)->struct_size),
                                         unsigned(out_shells[0].struct_size));
        }
        const uint64_t written = std::min<uint64_t>(capacity, mesh->shells.size());
        for (uint64_t i = 0; i < written; ++i) write_struct(element(i), mesh->shells[i]);
        *out_shell_count = mesh->shells.size();
        return int32_t(POLYMASS_OK);
    });
}

POLYMASS_API int32_t polymass_mesh_shell_of_face(uint32_t* out_shell_of_face, uint64_t capacity,
                                                 polymass_context* context,
                                                 const polymass_mesh* mesh) {
    return guarded(context, [&] {
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        if (!out_shell_of_face && capacity > 0)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "out_shell_of_face is NULL but capacity is %llu", u64(capacity));
        // Faces that could not be read have no shells.
        if (mesh->shell_of_face.empty()) return unanswered(context, *mesh);
        const uint64_t written = std::min<uint64_t>(capacity, mesh->shell_of_face.size());
        std::copy_n(mesh->shell_of_face.begin(), written, out_shell_of_face);
        return int32_t(POLYMASS_OK);
    });
}

POLYMASS_API int32_t polymass_mesh_provenance(polymass_provenance* out_provenance,
                                              polymass_context* context,
                                              const polymass_mesh* mesh) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_provenance, "out_provenance"))
            return status;
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        if (const int32_t status = unanswered(context, *mesh)) return status;
        write_struct(out_provenance, mesh->answer.provenance);
        return int32_t(POLYMASS_OK);
    });
}

POLYMASS_API int32_t polymass_mesh_mass_properties(polymass_mass_properties* out_properties,
                                                   polymass_context* context,
                                                   const polymass_mesh* mesh,
                                                   const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        if (const int32_t status = unanswered(context, *mesh)) return status;
        return mass_properties(out_properties, context, mesh->answer.body, mass);
    });
}

POLYMASS_API int32_t polymass_inertia_about(double out_inertia[9],
                                            const polymass_mass_properties* properties,
                                            const double point[3]) {
    if (!out_inertia || !properties || !point) return POLYMASS_ERROR_INVALID_ARGUMENT;
    return inertia_about(out_inertia, *properties, Eigen::Map<const Eigen::Vector3d>(point));
}

}  // extern "C"
