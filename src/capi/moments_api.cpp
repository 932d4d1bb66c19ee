// polymass_moments_*: mass integrals that compose (core::Moments), checked and
// translated at the boundary.
#include <polymass/polymass.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <iterator>

#include "api_guard.hpp"
#include "core/mesh_analysis.hpp"
#include "core/moments.hpp"
#include "mass_properties.hpp"
#include "mesh.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

constexpr uint32_t known_moment_flags = POLYMASS_MOMENTS_PARTIAL;

// What a polymass_moments holds, checked.
struct MomentsValue {
    core::Moments moments;
    bool partial = false;
};

int32_t read_moments(polymass_context* context, const polymass_moments* caller, const char* name,
                     MomentsValue& out) {
    if (const int32_t status = check_struct(context, caller, name)) return status;
    const polymass_moments in = read_struct(*caller, StructVersions<polymass_moments>::defaults());
    if (in.flags & ~known_moment_flags)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s->flags has unknown bits 0x%x",
                             name, unsigned(in.flags & ~known_moment_flags));
    const double scalars[] = {in.volume, in.mass};
    if (!(all_finite(in.reference) && all_finite(scalars) && all_finite(in.first) &&
          all_finite(in.second)))
        return context->fail(POLYMASS_ERROR_NON_FINITE, "%s holds a NaN or infinite value", name);
    const double bounds[] = {in.reference_error_bound, in.volume_error_bound, in.mass_error_bound,
                             in.first_error_bound, in.second_error_bound};
    if (!std::all_of(std::begin(bounds), std::end(bounds),
                     [](double bound) { return bound >= 0.0; }))  // also rejects NaN
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "%s has a negative or NaN error bound", name);
    core::Moments& m = out.moments;
    m.reference = Eigen::Map<const Eigen::Vector3d>(in.reference);
    m.volume = in.volume;
    m.mass.volume = in.mass;
    m.mass.first = Eigen::Map<const Eigen::Vector3d>(in.first);
    m.mass.second = Eigen::Map<const Eigen::Vector3d>(in.second);
    m.mass.products = Eigen::Map<const Eigen::Vector3d>(in.second + 3);
    m.reference_bound = in.reference_error_bound;
    m.volume_bound = in.volume_error_bound;
    m.mass_bounds = {in.mass_error_bound, in.first_error_bound, in.second_error_bound};
    out.partial = in.flags & POLYMASS_MOMENTS_PARTIAL;
    return POLYMASS_OK;
}

int32_t write_moments(polymass_context* context, polymass_moments* out, const MomentsValue& value) {
    polymass_moments result = StructVersions<polymass_moments>::defaults();
    const core::Moments& m = value.moments;
    result.flags = value.partial ? POLYMASS_MOMENTS_PARTIAL : 0u;
    Eigen::Vector3d::Map(result.reference) = m.reference;
    result.volume = m.volume;
    result.mass = m.mass.volume;
    Eigen::Vector3d::Map(result.first) = m.mass.first;
    Eigen::Vector3d::Map(result.second) = m.mass.second;
    Eigen::Vector3d::Map(result.second + 3) = m.mass.products;
    result.reference_error_bound = m.reference_bound;
    result.volume_error_bound = m.volume_bound;
    result.mass_error_bound = m.mass_bounds.volume;
    result.first_error_bound = m.mass_bounds.first;
    result.second_error_bound = m.mass_bounds.second;
    const double scalars[] = {result.volume, result.mass};
    if (!(all_finite(result.reference) && all_finite(scalars) && all_finite(result.first) &&
          all_finite(result.second)))
        return context->fail(POLYMASS_ERROR_OVERFLOW,
                             "the moments do not fit in a double (volume %g, mass %g)",
                             result.volume, result.mass);
    write_struct(out, result);
    return POLYMASS_OK;
}

int32_t refuse_partial(polymass_context* context, const MomentsValue& value, const char* name,
                       const char* what) {
    if (!value.partial) return POLYMASS_OK;
    return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                         "%s is POLYMASS_MOMENTS_PARTIAL (a range of faces): it cannot be %s; "
                         "add the ranges of the whole surface, then clear the flag",
                         name, what);
}

// Reads the output (checked), then the operand, runs `operation` on it and
// writes the result: the output may be the operand.
template <class Operation>
int32_t unary(polymass_moments* out, polymass_context* context, const polymass_moments* moments,
              const char* what, Operation&& operation) {
    if (const int32_t status = check_struct(context, out, "out_moments")) return status;
    MomentsValue value;
    if (const int32_t status = read_moments(context, moments, "moments", value)) return status;
    if (const int32_t status = refuse_partial(context, value, "moments", what)) return status;
    if (const int32_t status = operation(value.moments)) return status;
    return write_moments(context, out, value);
}

int32_t combine(polymass_moments* out, polymass_context* context, const polymass_moments* a,
                const polymass_moments* b, bool subtract) {
    if (const int32_t status = check_struct(context, out, "out_moments")) return status;
    MomentsValue left, right;
    if (const int32_t status = read_moments(context, a, "a", left)) return status;
    if (const int32_t status = read_moments(context, b, "b", right)) return status;
    // Ranges of faces are not solids: their integrals hold only about the
    // point they were taken about, so they add to nothing else.
    if ((left.partial || right.partial) && left.moments.reference != right.moments.reference)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "partial moments (ranges of faces) add only to moments about the "
                             "same reference point; a is about (%g, %g, %g), b about (%g, %g, %g)",
                             left.moments.reference.x(), left.moments.reference.y(),
                             left.moments.reference.z(), right.moments.reference.x(),
                             right.moments.reference.y(), right.moments.reference.z());
    MomentsValue result;
    result.moments = subtract ? left.moments - right.moments : left.moments + right.moments;
    result.partial = left.partial || right.partial;
    return write_moments(context, out, result);
}

int32_t face_range_moments(polymass_context* context, const polymass_mesh_desc* desc,
                           uint64_t first_face, uint64_t face_count, const double* reference,
                           const polymass_options& options, MomentsValue& out) {
    if (!reference) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "reference is NULL");
    const Eigen::Vector3d point = Eigen::Map<const Eigen::Vector3d>(reference);
    if (!point.allFinite())
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "reference (%g, %g, %g) is not finite", point.x(), point.y(),
                             point.z());
    MeshInput input;
    if (const int32_t status = read_mesh_desc(context, desc, input)) return status;
    if (const int32_t status = select_faces(context, input, first_face, face_count)) return status;
    core::AnalysisSettings settings;
    settings.check_topology = !(options.flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    settings.planarity_tolerance = options.planarity_tolerance;
    settings.tasks = &context->tasks();
    return visit_mesh(input, [&](const auto& view) {
        const core::MeshAnalysis piece =
            core::analyse_piece(view, point, settings, &context->memory);
        if (const int32_t status =
                report_verdict(context, input, options, piece, piece.verdict.defect))
            return status;
        const core::IntegrationResult& integration = *piece.integration;
        out.moments = core::Moments::of_solid(integration.integrals, integration.bounds, point);
        out.partial = true;
        return int32_t(POLYMASS_OK);
    });
}

int32_t check_rotation(polymass_context* context, const double* rotation, const double* translation,
                       Eigen::Matrix3d& r, Eigen::Vector3d& t) {
    if (!rotation) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "rotation is NULL");
    r = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rotation);
    t = translation ? Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(translation))
                    : Eigen::Vector3d::Zero();
    if (!r.allFinite() || !t.allFinite())
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "the rotation or translation has a NaN or infinite element");
    const double off = (r * r.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(off <= 1e-12))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "rotation is not orthonormal: R R^T differs from the identity by "
                             "%g (at most 1e-12 is accepted)",
                             off);
    return POLYMASS_OK;
}

}  // namespace
}  // namespace polymass::capi

using namespace polymass;
using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_moments_compute_faces(polymass_moments* out_moments,
                                                    polymass_context* context,
                                                    const polymass_mesh_desc* desc,
                                                    uint64_t first_face, uint64_t face_count,
                                                    const double reference[3],
                                                    const polymass_options* options) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_moments, "out_moments")) return status;
        polymass_options call;
        if (const int32_t status = read_options(context, options, call)) return status;
        MomentsValue value;
        if (const int32_t status =
                face_range_moments(context, desc, first_face, face_count, reference, call, value))
            return status;
        return write_moments(context, out_moments, value);
    });
}

POLYMASS_API int32_t polymass_mesh_moments(polymass_moments* out_moments, polymass_context* context,
                                           const polymass_mesh* mesh) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_moments, "out_moments")) return status;
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        if (const int32_t status = unanswered(context, *mesh)) return status;
        const core::Body& body = mesh->answer.body;
        MomentsValue value;
        value.moments = core::Moments::of_solid(body.integrals, body.bounds, body.reference);
        return write_moments(context, out_moments, value);
    });
}

POLYMASS_API int32_t polymass_moments_add(polymass_moments* out_moments, polymass_context* context,
                                          const polymass_moments* a, const polymass_moments* b) {
    return guarded(context, [&] { return combine(out_moments, context, a, b, false); });
}

POLYMASS_API int32_t polymass_moments_subtract(polymass_moments* out_moments,
                                               polymass_context* context, const polymass_moments* a,
                                               const polymass_moments* b) {
    return guarded(context, [&] { return combine(out_moments, context, a, b, true); });
}

POLYMASS_API int32_t polymass_moments_transform(polymass_moments* out_moments,
                                                polymass_context* context,
                                                const polymass_moments* moments,
                                                const double rotation[9],
                                                const double translation[3]) {
    return guarded(context, [&] {
        return unary(out_moments, context, moments, "moved", [&](core::Moments& m) {
            Eigen::Matrix3d r;
            Eigen::Vector3d t;
            if (const int32_t status = check_rotation(context, rotation, translation, r, t))
                return status;
            m = m.transformed(r, t);
            return int32_t(POLYMASS_OK);
        });
    });
}

POLYMASS_API int32_t polymass_moments_scale(polymass_moments* out_moments,
                                            polymass_context* context,
                                            const polymass_moments* moments,
                                            const double factors[3]) {
    return guarded(context, [&] {
        return unary(out_moments, context, moments, "scaled", [&](core::Moments& m) {
            if (!factors) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "factors is NULL");
            const Eigen::Vector3d f = Eigen::Map<const Eigen::Vector3d>(factors);
            if (!f.allFinite() || (f.array() == 0.0).any())
                return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                     "factors (%g, %g, %g) must be finite and non-zero", f.x(),
                                     f.y(), f.z());
            m = m.scaled(f);
            return int32_t(POLYMASS_OK);
        });
    });
}

POLYMASS_API int32_t polymass_moments_weight(polymass_moments* out_moments,
                                             polymass_context* context,
                                             const polymass_moments* moments,
                                             const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        return unary(out_moments, context, moments, "weighted", [&](core::Moments& m) {
            if (!mass) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mass is NULL");
            return weight_moments(context, m, mass, m);
        });
    });
}

POLYMASS_API int32_t polymass_moments_mass_properties(polymass_mass_properties* out_properties,
                                                      polymass_context* context,
                                                      const polymass_moments* moments,
                                                      const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        MomentsValue value;
        if (const int32_t status = read_moments(context, moments, "moments", value)) return status;
        if (const int32_t status =
                refuse_partial(context, value, "moments", "turned into mass properties"))
            return status;
        return moments_mass_properties(out_properties, context, value.moments, mass);
    });
}

}  // extern "C"
