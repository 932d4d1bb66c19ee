#include "library/corner_welding.hpp"

#include <polymass/polymass.h>

#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "library/huge_page_memory.hpp"

namespace polymass_cli {
namespace {

// A context for the weld, freed on destruction.
class WeldContext {
public:
    WeldContext() {
        const int32_t created = polymass_context_create(&context_, huge_page_allocator());
        if (created == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
        if (created != POLYMASS_OK)
            throw std::runtime_error(std::string("polymass_context_create: ") +
                                     polymass_status_string(created));
    }
    ~WeldContext() { polymass_context_destroy(context_); }
    WeldContext(const WeldContext&) = delete;
    WeldContext& operator=(const WeldContext&) = delete;
    polymass_context* get() const { return context_; }

private:
    polymass_context* context_ = nullptr;
};

// For each corner, the first corner at its position; how many positions there
// are in distinct. An exact weld (tolerance 0), whatever the tool's
// --weld-tolerance: that one is applied when the library computes.
template <class Scalar>
std::vector<uint32_t> first_corner_at_each_position(const Scalar* corners, uint64_t corner_count,
                                                    uint64_t& distinct) {
    const uint32_t position_type =
        std::is_same_v<Scalar, float> ? POLYMASS_POSITION_FLOAT32 : POLYMASS_POSITION_FLOAT64;
    const WeldContext context;
    std::vector<uint32_t> first(corner_count);
    const int32_t status = polymass_weld_positions(first.data(), &distinct, context.get(), corners,
                                                   position_type, corner_count, 0, 0.0);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK)
        throw std::runtime_error(std::string("polymass_weld_positions: ") +
                                 polymass_context_message(context.get()));
    return first;
}

}  // namespace

template <class Scalar>
std::vector<uint32_t> weld_corners(const Scalar* corners, uint64_t corner_count,
                                   std::vector<Scalar>& positions) {
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
        positions.insert(positions.end(), p, p + 3);
    }
    return vertex_of;
}

template std::vector<uint32_t> weld_corners<float>(const float*, uint64_t, std::vector<float>&);
template std::vector<uint32_t> weld_corners<double>(const double*, uint64_t, std::vector<double>&);

}  // namespace polymass_cli
