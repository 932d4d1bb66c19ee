#include "mass_properties.hpp"

#include <Eigen/Core>
#include <cmath>

#include "core/mass_properties.hpp"
#include "core/rigid_body.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

using RowMajor3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// The mass `mass` gives (NULL: unit density), checked.
int32_t read_mass_desc(polymass_context* context, const polymass_mass_desc* mass,
                       core::GivenMass& out) {
    out = core::GivenMass{};
    if (!mass) return POLYMASS_OK;
    if (const int32_t status = check_struct(context, mass, "mass")) return status;
    const polymass_mass_desc read =
        read_struct(*mass, StructVersions<polymass_mass_desc>::defaults());
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
    out = core::GivenMass{!from_density, value};
    return POLYMASS_OK;
}

void copy_matrix(const Eigen::Matrix3d& matrix, double (&out)[9]) { RowMajor3d::Map(out) = matrix; }

void copy_vector(const Eigen::Vector3d& vector, double (&out)[3]) {
    Eigen::Vector3d::Map(out) = vector;
}

// The properties, written to *out when they fit in doubles.
int32_t write_body(polymass_mass_properties* out, polymass_context* context,
                   const core::MassProperties& properties, uint32_t warnings) {
    const core::RigidBody& body = properties.body;
    const core::ResultBounds& bounds = properties.bounds;
    polymass_mass_properties result{};
    result.struct_size = sizeof result;
    result.warnings = warnings;
    result.volume = body.volume;
    result.mass = body.mass;
    result.density = body.density;
    result.surface_area = properties.surface_area;
    copy_vector(body.center_of_mass, result.center_of_mass);
    copy_matrix(body.inertia, result.inertia);
    copy_matrix(properties.inertia_about_origin, result.inertia_origin);
    copy_vector(properties.principal.moments, result.principal_moments);
    copy_matrix(properties.principal.axes, result.principal_axes);
    result.error_bound_volume = bounds.volume;
    result.error_bound_center_of_mass = bounds.center_of_mass;
    result.error_bound_inertia = bounds.inertia;
    result.error_bound_principal_moments = bounds.principal_moments;
    result.error_bound_principal_axes = bounds.principal_axes;
    if (!core::fits_in_doubles(properties))
        return context->fail(
            POLYMASS_ERROR_OVERFLOW,
            "the mass properties do not fit in a double (mass %g, density %g, "
            "largest coordinate of the centre of mass %g): scale the coordinates, or the "
            "density or mass",
            result.mass, result.density, body.center_of_mass.cwiseAbs().maxCoeff());
    write_struct(out, result);
    return POLYMASS_OK;
}

}  // namespace

int32_t mass_properties(polymass_mass_properties* out, polymass_context* context,
                        const core::Body& answered, const polymass_mass_desc* mass) {
    core::GivenMass given;
    if (const int32_t status = read_mass_desc(context, mass, given)) return status;
    return write_body(out, context, core::mass_properties(answered, given), answered.warnings);
}

int32_t weight_moments(polymass_context* context, const core::Moments& moments,
                       const polymass_mass_desc* mass, core::Moments& out) {
    if (!mass) {
        out = moments;
        return POLYMASS_OK;
    }
    core::GivenMass given;
    if (const int32_t status = read_mass_desc(context, mass, given)) return status;
    if (!(moments.volume > 0.0 && moments.mass.volume > 0.0))
        return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                             "the moments have volume %g and mass %g; a density or mass applies "
                             "to a body of positive volume and mass",
                             moments.volume, moments.mass.volume);
    out = core::weighed(moments, given);
    return POLYMASS_OK;
}

int32_t moments_mass_properties(polymass_mass_properties* out, polymass_context* context,
                                const core::Moments& moments, const polymass_mass_desc* mass) {
    core::Moments weighted;
    if (const int32_t status = weight_moments(context, moments, mass, weighted)) return status;
    if (!(weighted.volume > 0.0 && weighted.mass.volume > 0.0))
        return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                             "the moments have volume %g and mass %g; mass properties need a "
                             "body of positive volume and mass (a difference larger than what "
                             "it is taken from?)",
                             weighted.volume, weighted.mass.volume);
    return write_body(out, context, core::mass_properties(weighted), 0);
}

int32_t inertia_about(double* out, const polymass_mass_properties& properties,
                      const Eigen::Vector3d& point) {
    if (!is_known_size<polymass_mass_properties>(properties.struct_size) || !point.allFinite())
        return POLYMASS_ERROR_INVALID_ARGUMENT;
    // The body as the properties give it: the parallel-axis step is the one
    // the properties' inertia_origin came from.
    core::RigidBody body;
    body.mass = properties.mass;
    body.center_of_mass = Eigen::Map<const Eigen::Vector3d>(properties.center_of_mass);
    body.inertia = RowMajor3d::Map(properties.inertia);
    if (!(std::isfinite(body.mass) && body.center_of_mass.allFinite() && body.inertia.allFinite()))
        return POLYMASS_ERROR_INVALID_ARGUMENT;
    const Eigen::Matrix3d inertia = core::inertia_about(body, point);
    if (!inertia.allFinite()) return POLYMASS_ERROR_OVERFLOW;
    RowMajor3d::Map(out) = inertia;
    return POLYMASS_OK;
}

}  // namespace polymass::capi
