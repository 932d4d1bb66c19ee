// polymass_polygon_compute: planar polygons.
#include <polymass/polymass.h>

#include <Eigen/Core>
#include <cstring>

#include "api_guard.hpp"
#include "core/planar_polygon.hpp"
#include "struct_io.hpp"

using namespace polymass;
using namespace polymass::capi;

namespace {

using u64 = unsigned long long;  // for printf

bool span_fits(const double* points, uint64_t count, uint64_t stride) {
    if (count == 0) return true;
    // The last point starts at (count - 1) * stride and is 16 bytes long.
    uint64_t last = 0;
    if (__builtin_mul_overflow(count - 1, stride, &last)) return false;
    return last <= uint64_t(PTRDIFF_MAX) - 16 &&
           last + 16 <= UINTPTR_MAX - reinterpret_cast<std::uintptr_t>(points);
}

}  // namespace

extern "C" {

POLYMASS_API int32_t polymass_polygon_compute(polymass_polygon_properties* out_properties,
                                              polymass_context* context, const double* points,
                                              uint64_t point_count, uint64_t stride) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        if (!points && point_count > 0)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "points is NULL but point_count is %llu", u64(point_count));
        const uint64_t step = stride ? stride : 2 * sizeof(double);
        if (step < 2 * sizeof(double))
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "stride %llu is smaller than a point (16 bytes)", u64(step));
        if (!span_fits(points, point_count, step))
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "point_count %llu at stride %llu is larger than any array can be",
                                 u64(point_count), u64(step));

        const auto* bytes = reinterpret_cast<const unsigned char*>(points);
        const auto point_at = [&](std::size_t i) {
            double xy[2];
            std::memcpy(xy, bytes + i * step, sizeof xy);
            return Eigen::Vector2d(xy[0], xy[1]);
        };
        const core::PolygonCheck check = core::check_polygon(std::size_t(point_count), point_at);
        switch (check.defect) {
            case core::PolygonDefect::too_few_points:
                return context->fail(POLYMASS_ERROR_FACE_TOO_SMALL,
                                     "the polygon has %llu points; a polygon needs at least 3",
                                     u64(point_count));
            case core::PolygonDefect::non_finite:
                return context->fail(POLYMASS_ERROR_NON_FINITE,
                                     "point %llu has a NaN or infinite coordinate",
                                     u64(check.point));
            case core::PolygonDefect::none:
                break;
        }

        const core::PlanarPolygon polygon =
            core::planar_polygon(std::size_t(point_count), point_at);
        if (polygon.zero_area)
            return context->fail(POLYMASS_ERROR_ZERO_AREA,
                                 "the polygon encloses no area: its signed area is at rounding "
                                 "level for its size and number of points (%llu)",
                                 u64(point_count));

        polymass_polygon_properties result{};
        result.struct_size = sizeof result;
        result.orientation =
            polygon.orientation > 0 ? POLYMASS_COUNTER_CLOCKWISE : POLYMASS_CLOCKWISE;
        result.area = polygon.area;
        Eigen::Vector2d::Map(result.centroid) = polygon.centroid;
        Eigen::Vector3d::Map(result.second_moments) = polygon.moments;
        Eigen::Vector3d::Map(result.second_moments_origin) = polygon.moments_origin;
        result.polar_moment = polygon.polar_moment;
        Eigen::Vector2d::Map(result.principal_moments) = polygon.principal_moments;
        result.principal_angle = polygon.principal_angle;
        if (!core::fits_in_doubles(polygon))
            return context->fail(POLYMASS_ERROR_OVERFLOW,
                                 "the polygon's area and second moments do not fit in a double "
                                 "(area %g): its coordinates are too large or too small; scale "
                                 "them",
                                 result.area);
        write_struct(out_properties, result);
        return POLYMASS_OK;
    });
}

}  // extern "C"
