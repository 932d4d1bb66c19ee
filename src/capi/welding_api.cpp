// polymass_weld_positions: the library's welding on its own, over positions
// alone, for a caller (a triangle-soup reader) that numbers vertices before it
// hands a mesh over.
#include <polymass/polymass.h>

#include <algorithm>
#include <cstdint>

#include "api_guard.hpp"
#include "core/welding.hpp"
#include "mesh_input.hpp"

using namespace polymass;
using namespace polymass::capi;

namespace {

using u64 = unsigned long long;  // for printf

}  // namespace

extern "C" {

POLYMASS_API int32_t polymass_weld_positions(uint32_t* out_vertex_of, uint64_t* out_distinct_count,
                                             polymass_context* context, const void* positions,
                                             uint32_t position_type, uint64_t vertex_count,
                                             uint64_t position_stride, double weld_tolerance) {
    return guarded(context, [&] {
        if ((!out_vertex_of && vertex_count > 0) || !out_distinct_count)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s is NULL",
                                 out_distinct_count ? "out_vertex_of" : "out_distinct_count");
        if (!(weld_tolerance >= 0.0 && weld_tolerance <= POLYMASS_MAX_WELD_TOLERANCE))
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "weld_tolerance is %g; it must be in [0, %g]", weld_tolerance,
                                 POLYMASS_MAX_WELD_TOLERANCE);
        if (vertex_count > UINT32_MAX)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "there are %llu positions; welding numbers up to %u",
                                 u64(vertex_count), UINT32_MAX);
        MeshInput input;
        if (const int32_t status = read_positions(context, positions, position_type, vertex_count,
                                                  position_stride, input))
            return status;
        auto weld = [&](auto scalar) {
            using Scalar = decltype(scalar);
            const core::PositionArray<Scalar> array{input.positions, input.position_stride};
            return core::weld_positions(array, input.vertex_count, weld_tolerance, context->tasks(),
                                        &context->memory);
        };
        const core::WeldedPositions welded =
            input.position_type == POLYMASS_POSITION_FLOAT32 ? weld(float{}) : weld(double{});
        if (welded.vertex_of.size() != input.vertex_count)
            return context->fail(POLYMASS_ERROR_NON_FINITE,
                                 "position %llu has a NaN or infinite coordinate (%llu such "
                                 "positions): a weld within a tolerance needs finite ones",
                                 u64(welded.non_finite.first()), u64(welded.non_finite.count));
        std::copy(welded.vertex_of.begin(), welded.vertex_of.end(), out_vertex_of);
        *out_distinct_count = welded.distinct;
        return int32_t(POLYMASS_OK);
    });
}

}  // extern "C"
