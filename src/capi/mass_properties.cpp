#include "mass_properties.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "core/approximation_bound.hpp"
#include "core/principal_axes.hpp"
#include "core/rigid_body.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

using RowMajor3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// A NULL mass description means unit density, inertia_point about the origin.
int32_t read_mass_desc(polymass_context* context, const polymass_mass_desc* mass,
                       polymass_mass_desc& out) {
    out = StructVersions<polymass_mass_desc>::defaults();
    if (!mass) return POLYMASS_OK;
    if (const int32_t status = check_struct(context, mass, "mass")) return status;
    const polymass_mass_desc read = read_struct(*mass, out);
    const bool from_density = read.mass_mode == POLYMASS_MASS_FROM_DENSITY;
    if (!from_density && read.mass_mode != POLYMASS_MASS_FROM_TOTAL)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "mass->mass_mode %u is not POLYMASS_MASS_FROM_DENSITY (0) or "
                             "POLYMASS_MASS_FROM_TOTAL (1)",
                             unsigned(read.mass_mode));
    const double value = from_density ? read.density : read.mass;
    if (!(value > 0.0 && std::isfinite(value)))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "mass->%s is %g; it must be positive and finite",
                             from_density ? "density" : "mass", value);
    for (int axis = 0; axis < 3; ++axis)
        if (!std::isfinite(read.point[axis]))
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "mass->point[%d] is %g; it must be finite", axis,
                                 read.point[axis]);
    out = read;
    return POLYMASS_OK;
}

void copy_matrix(const Eigen::Matrix3d& matrix, double (&out)[9]) { RowMajor3d::Map(out) = matrix; }

void copy_vector(const Eigen::Vector3d& vector, double (&out)[3]) {
    Eigen::Vector3d::Map(out) = vector;
}

// Every value finite (the surface area may be unknown: NaN), and mass and
// moments not underflowed to zero or to subnormal numbers (which keep too few
// digits).
bool result_in_range(const polymass_mass_properties& p) {
    const double scalars[] = {p.volume, p.mass, p.density};
    // By magnitude: an unchecked non-solid can have negative moments.
    const double largest_moment =
        Eigen::Map<const Eigen::Vector3d>(p.principal_moments).cwiseAbs().maxCoeff();
    return all_finite(scalars) && !std::isinf(p.surface_area) && p.mass >= DBL_MIN &&
           p.density >= DBL_MIN && largest_moment >= DBL_MIN && all_finite(p.center_of_mass) &&
           all_finite(p.inertia) && all_finite(p.inertia_origin) && all_finite(p.inertia_point) &&
           all_finite(p.principal_moments) && all_finite(p.principal_axes);
}

// The body's properties, with inertia_point about `point`, written to *out
// when they fit in doubles. `moments` are those the body was computed from,
// for the error bounds.
int32_t write_body(polymass_mass_properties* out, polymass_context* context,
                   const core::RigidBody& body, const core::Moments& moments,
                   const Eigen::Vector3d& point, double surface_area, uint32_t warnings,
                   const core::ApproximationBound& approximation = {}, bool mass_given = false) {
    const core::PrincipalAxes principal = core::principal_axes(body.inertia);
    const core::ResultBounds bounds = core::widen(moments.result_bounds(body, principal),
                                                  approximation, body, mass_given, principal);
    polymass_mass_properties result{};
    result.struct_size = sizeof result;
    result.warnings = warnings;
    result.volume = body.volume;
    result.mass = body.mass;
    result.density = body.density;
    result.surface_area = surface_area;
    copy_vector(body.center_of_mass, result.center_of_mass);
    copy_matrix(body.inertia, result.inertia);
    copy_matrix(core::inertia_about(body, Eigen::Vector3d::Zero()), result.inertia_origin);
    copy_matrix(core::inertia_about(body, point), result.inertia_point);
    copy_vector(principal.moments, result.principal_moments);
    copy_matrix(principal.axes, result.principal_axes);
    result.error_bound_volume = bounds.volume;
    result.error_bound_center_of_mass = bounds.center_of_mass;
    result.error_bound_inertia = bounds.inertia;
    result.error_bound_principal_moments = bounds.principal_moments;
    result.error_bound_principal_axes = bounds.principal_axes;
    if (!(result_in_range(result)))
        return context->fail(
            POLYMASS_ERROR_OVERFLOW,
            "the mass properties do not fit in a double (mass %g, density %g, "
            "largest coordinate of the centre of mass or point %g): scale the "
            "coordinates, the density or mass, or the point",
            result.mass, result.density,
            std::max(body.center_of_mass.cwiseAbs().maxCoeff(), point.cwiseAbs().maxCoeff()));
    write_struct(out, result);
    return POLYMASS_OK;
}

}  // namespace

int32_t mass_properties(polymass_mass_properties* out, polymass_context* context,
                        const polymass_mesh& mesh, const polymass_mass_desc* mass,
                        polymass_provenance* provenance) {
    polymass_mass_desc body_desc;
    if (const int32_t status = read_mass_desc(context, mass, body_desc)) return status;
    const double density = body_desc.mass_mode == POLYMASS_MASS_FROM_TOTAL
                               ? body_desc.mass / mesh.integrals.volume
                               : body_desc.density;
    const core::RigidBody body = core::rigid_body(mesh.integrals, mesh.reference, density);
    const core::Moments moments =
        core::Moments::of_solid(mesh.integrals, mesh.bounds, mesh.reference, density);
    const bool mass_given = body_desc.mass_mode == POLYMASS_MASS_FROM_TOTAL;
    if (provenance) {
        provenance->approximation_bound_volume = mesh.approximation.volume;
        provenance->approximation_bound_center_of_mass = mesh.approximation.center_of_mass;
        provenance->approximation_bound_inertia =
            core::approximation_inertia(mesh.approximation, body, mass_given);
    }
    return write_body(out, context, body, moments,
                      Eigen::Map<const Eigen::Vector3d>(body_desc.point), mesh.surface_area,
                      mesh.warnings, mesh.approximation, mass_given);
}

int32_t weight_moments(polymass_context* context, const core::Moments& moments,
                       const polymass_mass_desc* mass, core::Moments& out, Eigen::Vector3d* point) {
    if (!mass) {
        out = moments;
        if (point) point->setZero();
        return POLYMASS_OK;
    }
    polymass_mass_desc body_desc;
    if (const int32_t status = read_mass_desc(context, mass, body_desc)) return status;
    if (!(moments.volume > 0.0 && moments.mass.volume > 0.0))
        return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                             "the moments have volume %g and mass %g; a density or mass applies "
                             "to a body of positive volume and mass",
                             moments.volume, moments.mass.volume);
    // Both rescale the whole mass distribution: its mean density, or its total.
    const double factor = body_desc.mass_mode == POLYMASS_MASS_FROM_TOTAL
                              ? body_desc.mass / moments.mass.volume
                              : body_desc.density * (moments.volume / moments.mass.volume);
    out = moments.weighted(factor);
    if (point) *point = Eigen::Map<const Eigen::Vector3d>(body_desc.point);
    return POLYMASS_OK;
}

int32_t moments_mass_properties(polymass_mass_properties* out, polymass_context* context,
                                const core::Moments& moments, const polymass_mass_desc* mass) {
    core::Moments weighted;
    Eigen::Vector3d point;
    if (const int32_t status = weight_moments(context, moments, mass, weighted, &point))
        return status;
    if (!(weighted.volume > 0.0 && weighted.mass.volume > 0.0))
        return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                             "the moments have volume %g and mass %g; mass properties need a "
                             "body of positive volume and mass (a difference larger than what "
                             "it is taken from?)",
                             weighted.volume, weighted.mass.volume);
    return write_body(out, context, weighted.rigid_body(), weighted, point,
                      std::numeric_limits<double>::quiet_NaN(), 0);
}

}  // namespace polymass::capi
