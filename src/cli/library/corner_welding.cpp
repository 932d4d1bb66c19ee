#include "library/corner_welding.hpp"

#include <polymass/polymass.h>

#include <algorithm>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace polymass_cli {
namespace {

// A context with the default options (an exact weld, whatever the tool's
// --weld-tolerance: that one is applied when the library computes).
class DefaultContext {
public:
    DefaultContext() {
        const int32_t created = polymass_context_create(&context_, nullptr);
        if (created == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
        if (created != POLYMASS_OK)
            throw std::runtime_error(std::string("polymass_context_create: ") +
                                     polymass_status_string(created));
    }
    ~DefaultContext() { polymass_context_destroy(context_); }
    DefaultContext(const DefaultContext&) = delete;
    DefaultContext& operator=(const DefaultContext&) = delete;
    polymass_context* get() const { return context_; }

private:
    polymass_context* context_ = nullptr;
};

// For each corner, the first corner at its position; how many positions there
// are in distinct.
template <class Scalar>
std::vector<uint32_t> first_corner_at_each_position(const std::vector<Scalar>& corners,
                                                    uint64_t corner_count, uint64_t& distinct) {
    // The corners as one polygon face that uses each of them (a soup of 1 or
    // 2 corners repeats the last, since a face has at least 3).
    std::vector<uint32_t> face(std::max<uint64_t>(corner_count, 3));
    std::iota(face.begin(), face.begin() + corner_count, 0u);
    std::fill(face.begin() + corner_count, face.end(), uint32_t(corner_count - 1));
    const uint32_t face_size = uint32_t(face.size());
    polymass_mesh_desc desc{};
    desc.struct_size = sizeof desc;
    desc.position_type =
        std::is_same_v<Scalar, float> ? POLYMASS_POSITION_FLOAT32 : POLYMASS_POSITION_FLOAT64;
    desc.positions = corners.data();
    desc.vertex_count = corner_count;
    desc.index_type = POLYMASS_INDEX_UINT32;
    desc.indices = face.data();
    desc.index_count = face.size();
    desc.face_sizes = &face_size;
    desc.face_count = 1;
    const DefaultContext context;
    std::vector<uint32_t> first(corner_count);
    const int32_t status = polymass_mesh_weld(first.data(), &distinct, context.get(), &desc);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK)
        throw std::runtime_error(std::string("polymass_mesh_weld: ") +
                                 polymass_context_message(context.get()));
    return first;
}

}  // namespace

template <class Scalar>
std::vector<uint32_t> weld_corners(const std::vector<Scalar>& corners,
                                   std::vector<double>& positions) {
    const uint64_t corner_count = corners.size() / 3;
    if (corner_count == 0) return {};
    if (corner_count > UINT32_MAX)
        throw std::length_error("more than 4294967295 triangle corners to weld");
    uint64_t distinct = 0;
    std::vector<uint32_t> vertex_of =
        first_corner_at_each_position(corners, corner_count, distinct);
    positions.reserve(positions.size() + 3 * distinct);
    // In place: a corner's first corner comes no later, so it is renumbered
    // already when a later copy looks it up.
    const uint64_t first_new = positions.size() / 3;
    uint64_t next = first_new;
    for (uint64_t corner = 0; corner < corner_count; ++corner) {
        if (vertex_of[corner] != corner) {
            vertex_of[corner] = vertex_of[vertex_of[corner]];
            continue;
        }
        if (next >= UINT32_MAX) throw std::length_error("more than 4294967294 distinct vertices");
        vertex_of[corner] = uint32_t(next++);
        const Scalar* p = &corners[3 * corner];
        positions.insert(positions.end(), {double(p[0]), double(p[1]), double(p[2])});
    }
    return vertex_of;
}

template std::vector<uint32_t> weld_corners<float>(const std::vector<float>&, std::vector<double>&);
template std::vector<uint32_t> weld_corners<double>(const std::vector<double>&,
                                                    std::vector<double>&);

}  // namespace polymass_cli
