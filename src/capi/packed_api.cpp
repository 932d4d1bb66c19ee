// polymass_packed_compute: a dataset's many triangle meshes in shared arrays,
// each answered as polymass_mass_properties_compute answers it alone (the
// same reading of its surface, the same analysis, the same weighting), the
// results written in columns. The set's arguments are checked once; a mesh's
// own failure is its row's.
#include <polymass/polymass.h>

#include <atomic>
#include <cstring>
#include <limits>
#include <memory_resource>
#include <vector>

#include "api_guard.hpp"
#include "item_threads.hpp"
#include "mass_properties.hpp"
#include "mesh.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

// The set as checked: the caller's structs read, the stride resolved.
struct PackedSet {
    polymass_packed_meshes meshes;
    polymass_packed_results results;
    polymass_options options;
    uint64_t position_stride = 0;
    uint64_t index_bytes = 0;
};

// Each array of offsets: mesh_count + 1 of them, ascending from 0; the
// indices' in steps of whole triangles.
int32_t check_offsets(polymass_context* context, const uint64_t* offsets, uint64_t mesh_count,
                      const char* name, uint64_t step) {
    if (!offsets) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
    if (offsets[0] != 0)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s[0] is %llu; offsets start at 0",
                             name, u64(offsets[0]));
    for (uint64_t i = 0; i < mesh_count; ++i) {
        if (offsets[i + 1] < offsets[i])
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "%s[%llu] is %llu, less than %s[%llu] (%llu): offsets ascend",
                                 name, u64(i + 1), u64(offsets[i + 1]), name, u64(i),
                                 u64(offsets[i]));
        if ((offsets[i + 1] - offsets[i]) % step != 0)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "mesh %llu has %llu indices (%s[%llu] - %s[%llu]), not a "
                                 "multiple of 3: every face is a triangle",
                                 u64(i), u64(offsets[i + 1] - offsets[i]), name, u64(i + 1), name,
                                 u64(i));
    }
    return POLYMASS_OK;
}

// Everything about the set as a whole; `set` is written on success.
int32_t read_set(polymass_context* context, const polymass_packed_results* results,
                 const polymass_packed_meshes* meshes, const polymass_options* options,
                 PackedSet& set) {
    if (const int32_t status = check_struct(context, results, "results")) return status;
    if (const int32_t status = check_struct(context, meshes, "meshes")) return status;
    set.results = read_struct(*results, StructVersions<polymass_packed_results>::defaults());
    set.meshes = read_struct(*meshes, StructVersions<polymass_packed_meshes>::defaults());
    const polymass_packed_meshes& m = set.meshes;
    if (set.results.reserved != 0 || m.reserved != 0)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s->reserved is %u; it must be 0",
                             m.reserved ? "meshes" : "results",
                             unsigned(m.reserved ? m.reserved : set.results.reserved));
    if (m.index_base != POLYMASS_INDICES_LOCAL && m.index_base != POLYMASS_INDICES_GLOBAL)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "meshes->index_base %u is not POLYMASS_INDICES_LOCAL (0) or "
                             "POLYMASS_INDICES_GLOBAL (1)",
                             unsigned(m.index_base));
    if (m.mass_mode != POLYMASS_MASS_FROM_DENSITY && m.mass_mode != POLYMASS_MASS_FROM_TOTAL)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "meshes->mass_mode %u is not POLYMASS_MASS_FROM_DENSITY (0) or "
                             "POLYMASS_MASS_FROM_TOTAL (1)",
                             unsigned(m.mass_mode));
    if (m.index_type != POLYMASS_INDEX_UINT32 && m.index_type != POLYMASS_INDEX_UINT16 &&
        m.index_type != POLYMASS_INDEX_UINT64)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "meshes->index_type %u is not POLYMASS_INDEX_UINT32 (0), "
                             "POLYMASS_INDEX_UINT16 (1) or POLYMASS_INDEX_UINT64 (2)",
                             unsigned(m.index_type));
    if (const int32_t status = read_options(context, options, set.options)) return status;
    // The arrays of offsets (mesh_count + 1 each) must be addressable.
    if (m.mesh_count == UINT64_MAX || !span_fits(m.vertex_offsets, m.mesh_count + 1, 8, 8) ||
        !span_fits(m.index_offsets, m.mesh_count + 1, 8, 8))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "mesh_count %llu is larger than any array can be", u64(m.mesh_count));
    if (const int32_t status =
            check_offsets(context, m.vertex_offsets, m.mesh_count, "vertex_offsets", 1))
        return status;
    if (const int32_t status =
            check_offsets(context, m.index_offsets, m.mesh_count, "index_offsets", 3))
        return status;
    const uint64_t vertex_count = m.vertex_offsets[m.mesh_count];
    const uint64_t index_count = m.index_offsets[m.mesh_count];
    // The whole arrays, once: each mesh's are parts of them.
    MeshInput whole;
    if (const int32_t status = read_positions(context, m.positions, m.position_type, vertex_count,
                                              m.position_stride, whole))
        return status;
    set.position_stride = whole.position_stride;
    set.index_bytes = m.index_type == POLYMASS_INDEX_UINT16   ? 2
                      : m.index_type == POLYMASS_INDEX_UINT64 ? 8
                                                              : 4;
    if (index_count > 0 && !m.indices)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "indices is NULL but index_offsets[%llu] is %llu", u64(m.mesh_count),
                             u64(index_count));
    if (!span_fits(m.indices, index_count, set.index_bytes, set.index_bytes))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "index_offsets[%llu] %llu is larger than any array can be",
                             u64(m.mesh_count), u64(index_count));
    // A mesh's first vertex is subtracted from its global indices, and 64-bit
    // indices are narrowed, into 32 bits.
    if ((m.index_base == POLYMASS_INDICES_GLOBAL || m.index_type == POLYMASS_INDEX_UINT64) &&
        vertex_count > (uint64_t{1} << 32))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "%s over %llu vertices: 32-bit indices name at most 2^32",
                             m.index_base == POLYMASS_INDICES_GLOBAL ? "POLYMASS_INDICES_GLOBAL"
                                                                     : "POLYMASS_INDEX_UINT64",
                             u64(vertex_count));
    return POLYMASS_OK;
}

// A mesh's indices counted from `base` (its first vertex for global indices,
// 0 for local ones) as 32-bit indices, in `local`, which `desc` then reads:
// the mesh is read as a mesh of its own (nothing of the packed array outside
// its part), at the cost of one pass over its indices. 16- and 32-bit indices
// are rebased modulo 2^32: one below `base` wraps past every vertex of the
// mesh (read_set made base + vertex count at most 2^32), so the analysis
// finds it out of range, naming the lowest face, and adds `base` back
// modulo 2^32 as it was written. A 64-bit index below `base`, or of 2^32 or
// more (a negative int64 read as unsigned is), fails the mesh here, named as
// written, which the analysis's 32-bit arithmetic could not do; any other is
// the analysis's to judge, with the single call's message.
template <class Index>
int32_t rebase_as(polymass_context* context, polymass_mesh_desc& desc, uint64_t base,
                  std::pmr::vector<uint32_t>& local) {
    const auto* indices = static_cast<const unsigned char*>(desc.indices);
    local.resize(desc.index_count);
    // Rebased without a branch, so that the loop vectorises: a 64-bit index
    // of 2^32 or more has high bits, and so has its offset when it lies below
    // `base` (it wraps); only a mesh that has one is read again, for the first.
    uint64_t high_bits = 0;
    for (std::size_t i = 0; i < desc.index_count; ++i) {
        Index index;
        std::memcpy(&index, indices + i * sizeof index, sizeof index);
        const uint64_t offset = uint64_t(index) - base;
        high_bits |= (uint64_t(index) | offset) >> 32;
        local[i] = uint32_t(offset);
    }
    if constexpr (sizeof(Index) == sizeof(uint64_t))
        if (high_bits != 0)
            for (std::size_t i = 0;; ++i) {
                uint64_t index;
                std::memcpy(&index, indices + i * sizeof index, sizeof index);
                if (index < base || index > UINT32_MAX)
                    return context->fail(POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
                                         "face %llu refers to vertex %llu, beyond the mesh's %llu "
                                         "vertices, which start at %llu",
                                         u64(i / 3), u64(index), u64(desc.vertex_count), u64(base));
            }
    desc.index_type = POLYMASS_INDEX_UINT32;
    desc.indices = local.data();
    return POLYMASS_OK;
}

int32_t rebase(polymass_context* context, polymass_mesh_desc& desc, uint64_t base,
               std::pmr::vector<uint32_t>& local) {
    switch (desc.index_type) {
        case POLYMASS_INDEX_UINT16:
            return rebase_as<uint16_t>(context, desc, base, local);
        case POLYMASS_INDEX_UINT64:
            return rebase_as<uint64_t>(context, desc, base, local);
        default:
            return rebase_as<uint32_t>(context, desc, base, local);
    }
}

// Mesh i of the set, answered as polymass_mass_properties_compute answers a
// mesh given alone (its surface read from a polymass_mesh_desc of its part of
// the arrays); the status, with the message in the context.
int32_t compute_mesh(const PackedSet& set, uint64_t i, polymass_context* context,
                     polymass_mass_properties& out) {
    const polymass_packed_meshes& m = set.meshes;
    const uint64_t first_vertex = m.vertex_offsets[i], first_index = m.index_offsets[i];
    // Mesh i's part of an array (whose span read_set checked; a null array
    // has no part but the empty one at its start).
    auto part = [](const void* array, uint64_t first, uint64_t bytes) {
        return static_cast<const unsigned char*>(array) + first * bytes;
    };
    polymass_mesh_desc desc = StructVersions<polymass_mesh_desc>::defaults();
    desc.position_type = m.position_type;
    desc.positions = part(m.positions, first_vertex, set.position_stride);
    desc.vertex_count = m.vertex_offsets[i + 1] - first_vertex;
    desc.position_stride = set.position_stride;
    desc.index_type = m.index_type;
    desc.indices = part(m.indices, first_index, set.index_bytes);
    desc.index_count = m.index_offsets[i + 1] - first_index;
    // Global and 64-bit indices are read as 32-bit ones from the mesh's own
    // first vertex; the messages add `base` back to name them as written.
    std::pmr::vector<uint32_t> rebased(&context->memory);
    const uint64_t base = m.index_base == POLYMASS_INDICES_GLOBAL ? first_vertex : 0;
    if (m.index_base == POLYMASS_INDICES_GLOBAL || m.index_type == POLYMASS_INDEX_UINT64)
        if (const int32_t status = rebase(context, desc, base, rebased)) return status;
    MeshInput input;
    if (const int32_t status = read_mesh_desc(context, &desc, input)) return status;
    input.index_base = uint32_t(base);
    Answer answer;
    if (const int32_t status = analyse_surface(context, input, set.options, answer, nullptr))
        return status;
    if (!m.mass_values) return mass_properties(&out, context, answer.body, nullptr);
    polymass_mass_desc mass = StructVersions<polymass_mass_desc>::defaults();
    mass.mass_mode = m.mass_mode;
    (m.mass_mode == POLYMASS_MASS_FROM_TOTAL ? mass.mass : mass.density) = m.mass_values[i];
    return mass_properties(&out, context, answer.body, &mass);
}

// Row i of each wanted column: the properties, or the status and NaN.
void write_row(const polymass_packed_results& results, uint64_t i, int32_t status,
               const polymass_mass_properties& properties, const char* message) {
    const bool answered = status == POLYMASS_OK;
    auto put = [&](double* column, const double* values, std::size_t count) {
        if (!column) return;
        for (std::size_t k = 0; k < count; ++k)
            column[i * count + k] = answered ? values[k] : std::numeric_limits<double>::quiet_NaN();
    };
    if (results.status) results.status[i] = status;
    if (results.warnings) results.warnings[i] = answered ? properties.warnings : 0;
    put(results.volume, &properties.volume, 1);
    put(results.mass, &properties.mass, 1);
    put(results.surface_area, &properties.surface_area, 1);
    put(results.center_of_mass, properties.center_of_mass, 3);
    put(results.inertia, properties.inertia, 9);
    put(results.principal_moments, properties.principal_moments, 3);
    put(results.principal_axes, properties.principal_axes, 9);
    put(results.error_bound_volume, &properties.error_bound_volume, 1);
    put(results.error_bound_center_of_mass, &properties.error_bound_center_of_mass, 1);
    put(results.error_bound_inertia, &properties.error_bound_inertia, 1);
    if (results.messages) {
        char* row = results.messages + i * POLYMASS_BATCH_MESSAGE_SIZE;
        std::strncpy(row, answered ? "" : message, POLYMASS_BATCH_MESSAGE_SIZE - 1);
        row[POLYMASS_BATCH_MESSAGE_SIZE - 1] = '\0';
    }
}

}  // namespace
}  // namespace polymass::capi

using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_packed_compute(const polymass_packed_results* results,
                                             uint64_t* out_failed, polymass_context* context,
                                             const polymass_packed_meshes* meshes,
                                             const polymass_options* options) {
    return guarded(context, [&] {
        if (out_failed) *out_failed = 0;
        PackedSet set;
        if (const int32_t status = read_set(context, results, meshes, options, set)) return status;
        std::atomic<uint64_t> failed{0};
        for_each_item(context, set.meshes.mesh_count, [&](uint64_t i, polymass_context* own) {
            polymass_mass_properties properties =
                StructVersions<polymass_mass_properties>::defaults();
            // Each mesh guarded on its own: running out of memory on one
            // fails that mesh only.
            const int32_t status =
                guarded(own, [&] { return compute_mesh(set, i, own, properties); });
            write_row(set.results, i, status, properties, own->message);
            if (status != POLYMASS_OK) failed.fetch_add(1, std::memory_order_relaxed);
        });
        context->clear_message();
        if (out_failed) *out_failed = failed;
        return int32_t(POLYMASS_OK);
    });
}

}  // extern "C"
