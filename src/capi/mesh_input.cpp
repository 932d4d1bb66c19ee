#include "mesh_input.hpp"

#include <limits>

#include "struct_io.hpp"

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

// True when [pointer, pointer + count * stride) — the last element `element`
// bytes long — is addressable: no arithmetic on it can overflow.
bool span_fits(const void* pointer, uint64_t count, uint64_t stride, uint64_t element) {
    if (count == 0) return true;
    uint64_t last = 0, end = 0;
    if (__builtin_mul_overflow(count - 1, stride, &last)) return false;
    if (__builtin_add_overflow(last, element, &end)) return false;
    const uint64_t room = uint64_t(std::numeric_limits<std::uintptr_t>::max()) -
                          uint64_t(reinterpret_cast<std::uintptr_t>(pointer));
    return end <= room && end <= uint64_t(std::numeric_limits<std::ptrdiff_t>::max());
}

int32_t read_face_sizes(polymass_context* context, const polymass_mesh_desc& desc,
                        MeshInput& input) {
    if (!desc.face_sizes) {
        if (desc.face_count != 0)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "face_count is %llu but face_sizes is NULL (NULL face_sizes "
                                 "means triangles, counted from index_count)",
                                 u64(desc.face_count));
        if (desc.index_count % 3 != 0)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "index_count %llu is not a multiple of 3 (face_sizes is NULL, "
                                 "so every face is a triangle)",
                                 u64(desc.index_count));
        input.face_count = std::size_t(desc.index_count / 3);
        return POLYMASS_OK;
    }
    if (!span_fits(desc.face_sizes, desc.face_count, sizeof(uint32_t), sizeof(uint32_t)))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "face_count %llu is larger than any array can be",
                             u64(desc.face_count));
    uint64_t total = 0;
    for (uint64_t face = 0; face < desc.face_count; ++face) {
        const uint32_t size = desc.face_sizes[face];
        // Saturating: an absurd total must still compare unequal to index_count.
        total = size > std::numeric_limits<uint64_t>::max() - total
                    ? std::numeric_limits<uint64_t>::max()
                    : total + size;
    }
    input.face_sizes = desc.face_sizes;
    input.face_count = std::size_t(desc.face_count);
    if (total != desc.index_count)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "face_sizes add up to %llu indices but index_count is %llu",
                             u64(total), u64(desc.index_count));
    return POLYMASS_OK;
}

}  // namespace

int32_t read_positions(polymass_context* context, const void* positions, uint32_t position_type,
                       uint64_t vertex_count, uint64_t position_stride, MeshInput& input) {
    if (position_type != POLYMASS_POSITION_FLOAT64 && position_type != POLYMASS_POSITION_FLOAT32)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "position_type %u is not POLYMASS_POSITION_FLOAT64 (0) or "
                             "POLYMASS_POSITION_FLOAT32 (1)",
                             unsigned(position_type));
    const uint64_t vertex_bytes = position_type == POLYMASS_POSITION_FLOAT32 ? 12 : 24;
    const uint64_t stride = position_stride ? position_stride : vertex_bytes;
    if (stride < vertex_bytes)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "position_stride %llu is smaller than a vertex (%llu bytes)",
                             u64(stride), u64(vertex_bytes));
    if (vertex_count > 0 && !positions)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "positions is NULL but vertex_count is %llu", u64(vertex_count));
    if (!span_fits(positions, vertex_count, stride, vertex_bytes))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "vertex_count %llu at stride %llu is larger than any array can be",
                             u64(vertex_count), u64(stride));
    input.position_type = position_type;
    input.positions = static_cast<const unsigned char*>(positions);
    input.vertex_count = std::size_t(vertex_count);
    input.position_stride = std::size_t(stride);
    return POLYMASS_OK;
}

int32_t read_mesh_desc(polymass_context* context, const polymass_mesh_desc* caller_desc,
                       MeshInput& input) {
    if (const int32_t status = check_struct(context, caller_desc, "desc")) return status;
    const polymass_mesh_desc desc =
        read_struct(*caller_desc, StructVersions<polymass_mesh_desc>::defaults());
    if (const int32_t status = read_positions(context, desc.positions, desc.position_type,
                                              desc.vertex_count, desc.position_stride, input))
        return status;
    if (desc.index_type != POLYMASS_INDEX_UINT32 && desc.index_type != POLYMASS_INDEX_UINT16)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "index_type %u is not POLYMASS_INDEX_UINT32 (0) or "
                             "POLYMASS_INDEX_UINT16 (1)",
                             unsigned(desc.index_type));
    if (desc.reserved != 0)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "reserved is %u; it must be 0",
                             unsigned(desc.reserved));

    const uint64_t index_bytes = desc.index_type == POLYMASS_INDEX_UINT16 ? 2 : 4;
    // Faces listed without indices are faces too small (core/ says so); no
    // faces at all is not a mesh.
    const bool faces_listed = desc.face_sizes && desc.face_count > 0;
    if (desc.index_count == 0 && !faces_listed)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "the mesh has no faces (index_count is 0)");
    if (!desc.indices && desc.index_count > 0)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "indices is NULL but index_count is %llu", u64(desc.index_count));
    if (!span_fits(desc.indices, desc.index_count, index_bytes, index_bytes))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "index_count %llu is larger than any array can be",
                             u64(desc.index_count));

    input.index_type = desc.index_type;
    input.indices = static_cast<const unsigned char*>(desc.indices);
    input.index_count = std::size_t(desc.index_count);
    return read_face_sizes(context, desc, input);
}

int32_t select_faces(polymass_context* context, MeshInput& input, uint64_t first_face,
                     uint64_t face_count) {
    if (first_face > input.face_count || face_count > input.face_count - first_face)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "faces [%llu, %llu + %llu) are not all in the mesh, which has %llu",
                             u64(first_face), u64(first_face), u64(face_count),
                             u64(input.face_count));
    if (face_count == 0)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "face_count is 0: no faces");
    std::size_t first_index = 3 * std::size_t(first_face), index_count = 3 * face_count;
    if (input.face_sizes) {
        first_index = 0;
        for (std::size_t face = 0; face < first_face; ++face) first_index += input.face_sizes[face];
        index_count = 0;
        for (std::size_t face = first_face; face < first_face + face_count; ++face)
            index_count += input.face_sizes[face];
        input.face_sizes += first_face;
    }
    const std::size_t index_bytes = input.index_type == POLYMASS_INDEX_UINT16 ? 2 : 4;
    input.indices += first_index * index_bytes;
    input.index_count = index_count;
    input.face_count = std::size_t(face_count);
    return POLYMASS_OK;
}

}  // namespace polymass::capi
