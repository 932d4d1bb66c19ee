// polymass_mesh_*: from the caller's arrays to a validated, integrated solid.
#include <polymass/polymass.h>

#include <Eigen/Core>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "api_guard.hpp"
#include "core/mesh_analysis.hpp"
#include "core/principal_axes.hpp"
#include "core/rigid_body.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

// A solid: its integrals, not the caller's arrays.
struct polymass_mesh {
    polymass_allocator allocator;               // to free it with; the context may be gone by then
    polymass::core::VolumeIntegrals integrals;  // about `reference`, outward-oriented
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    double surface_area = 0.0;
    uint32_t warnings = 0;
};

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf
using RowMajor3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

core::MeshAnalysis analyse(polymass_context* context, const MeshInput& input, bool full_report) {
    const polymass_options& options = context->options;
    core::AnalysisSettings settings;
    settings.check_topology =
        full_report || !(options.flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    settings.weld = options.flags & POLYMASS_OPTION_WELD_VERTICES;
    settings.stop_at_first_problem = !full_report;
    settings.planarity_tolerance = options.planarity_tolerance;
    const bool accept_non_manifold = options.flags & POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
    return visit_mesh(input, [&](const auto& view) {
        return core::analyse_mesh(view, settings, accept_non_manifold, &context->memory);
    });
}

int32_t fail_on_edge(polymass_context* context, int32_t status, const core::EdgeFinding& edges,
                     const char* what) {
    return context->fail(status, "edge (%u, %u) is %s (%llu such edges)", edges.first[0],
                         edges.first[1], what, u64(edges.count));
}

// The first problem, in the order the checks run, as a status and message;
// what the options accept instead becomes a warning.
int32_t judge(polymass_context* context, const MeshInput& input, const core::MeshAnalysis& analysis,
              uint32_t& warnings) {
    const uint32_t flags = context->options.flags;
    const core::MeshScan& scan = analysis.scan;
    if (scan.out_of_range_indices > 0)
        return context->fail(POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
                             "face %llu refers to vertex %u, but there are only %llu vertices "
                             "(%llu indices out of range, in %llu faces)",
                             u64(scan.out_of_range_faces.first), scan.first_out_of_range_index,
                             u64(input.vertex_count), u64(scan.out_of_range_indices),
                             u64(scan.out_of_range_faces.count));
    if (scan.non_finite.count > 0)
        return context->fail(POLYMASS_ERROR_NON_FINITE,
                             "vertex %llu, used by a face, has a NaN or infinite coordinate "
                             "(%llu such vertices)",
                             u64(scan.non_finite.first), u64(scan.non_finite.count));
    if (!std::isfinite(scan.diagonal()))
        return context->fail(POLYMASS_ERROR_OVERFLOW,
                             "the mesh spans more than a double can hold (its bounding box "
                             "reaches from %g to %g)",
                             scan.bounds.min().minCoeff(), scan.bounds.max().maxCoeff());

    if (const auto& topology = analysis.topology) {
        if (topology->open.count > 0)
            return fail_on_edge(context, POLYMASS_ERROR_OPEN, topology->open,
                                "used by one face only: the surface is open");
        if (topology->non_manifold.count > 0) {
            const bool accepted =
                (flags & POLYMASS_OPTION_ACCEPT_NON_MANIFOLD) && topology->non_manifold_balanced;
            if (!accepted)
                return context->fail(
                    POLYMASS_ERROR_NON_MANIFOLD,
                    "edge (%u, %u) is used by %llu faces; an edge of a solid's surface "
                    "has two (%llu such edges)",
                    topology->non_manifold.first[0], topology->non_manifold.first[1],
                    u64(topology->non_manifold.first_traversals),
                    u64(topology->non_manifold.count));
            warnings |= POLYMASS_WARNING_NON_MANIFOLD;
        }
        if (topology->misoriented.count > 0)
            return fail_on_edge(context, POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                                topology->misoriented,
                                "traversed in the same direction by both its faces: one of "
                                "them is reversed");
    } else {
        warnings |= POLYMASS_WARNING_UNCHECKED;
    }

    const core::IntegrationResult& integration = *analysis.integration;
    if (integration.non_planar_faces.count > 0)
        return context->fail(POLYMASS_ERROR_NON_PLANAR_FACE,
                             "face %llu is not planar: a vertex is off its plane by %.3g of "
                             "the face's diameter, more than the tolerance %.3g (%llu such faces)",
                             u64(integration.non_planar_faces.first), integration.max_non_planarity,
                             context->options.planarity_tolerance,
                             u64(integration.non_planar_faces.count));
    if (integration.degenerate_faces.count > 0) warnings |= POLYMASS_WARNING_DEGENERATE_FACES;

    if (integration.encloses_no_volume)
        return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                             "the surface encloses no volume: its signed volume is at rounding "
                             "level for its area and its size %.3g (a flat or double-sided "
                             "surface)",
                             scan.diagonal());
    const core::VolumeIntegrals& integrals = integration.integrals;
    if (!(std::isfinite(integration.surface_area) && std::isfinite(integrals.volume) &&
          integrals.first.allFinite() && integrals.second.allFinite() &&
          integrals.products.allFinite()))
        return context->fail(POLYMASS_ERROR_OVERFLOW,
                             "the volume integrals overflow double precision: the mesh is too "
                             "large (size %.3g); scale its coordinates down",
                             scan.diagonal());
    const double volume = integrals.volume;
    if (volume < 0) {
        if (!(flags & POLYMASS_OPTION_ACCEPT_INVERTED))
            return context->fail(POLYMASS_ERROR_INVERTED,
                                 "the signed volume is %.17g: every face is reversed (faces "
                                 "must be counter-clockwise seen from outside); "
                                 "POLYMASS_OPTION_ACCEPT_INVERTED accepts it turned",
                                 volume);
        warnings |= POLYMASS_WARNING_INVERTED;
    }
    return POLYMASS_OK;
}

// Validates and integrates: the body of polymass_mesh_create, with the result
// in a caller-owned polymass_mesh.
int32_t build_mesh(polymass_context* context, const polymass_mesh_desc* desc, polymass_mesh& mesh) {
    MeshInput input;
    if (const int32_t status = read_mesh_desc(context, desc, input)) return status;
    const core::MeshAnalysis analysis = analyse(context, input, false);
    uint32_t warnings = 0;
    if (const int32_t status = judge(context, input, analysis, warnings)) return status;
    const core::IntegrationResult& integration = *analysis.integration;
    mesh.integrals = (warnings & POLYMASS_WARNING_INVERTED) ? integration.integrals.negated()
                                                            : integration.integrals;
    mesh.reference = analysis.reference;
    mesh.surface_area = integration.surface_area;
    mesh.warnings = warnings;
    return POLYMASS_OK;
}

// A NULL mass description means unit density, inertia_point about the origin.
int32_t read_mass_desc(polymass_context* context, const polymass_mass_desc* mass,
                       polymass_mass_desc& out) {
    out = {sizeof(polymass_mass_desc), POLYMASS_MASS_FROM_DENSITY, 1.0, 0.0, {0.0, 0.0, 0.0}};
    if (!mass) return POLYMASS_OK;
    if (const int32_t status = check_struct(context, mass, "mass")) return status;
    const bool from_density = mass->mass_mode == POLYMASS_MASS_FROM_DENSITY;
    if (!from_density && mass->mass_mode != POLYMASS_MASS_FROM_TOTAL)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "mass->mass_mode %u is not POLYMASS_MASS_FROM_DENSITY (0) or "
                             "POLYMASS_MASS_FROM_TOTAL (1)",
                             unsigned(mass->mass_mode));
    const double value = from_density ? mass->density : mass->mass;
    if (!(value > 0.0 && std::isfinite(value)))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "mass->%s is %g; it must be positive and finite",
                             from_density ? "density" : "mass", value);
    for (int axis = 0; axis < 3; ++axis)
        if (!std::isfinite(mass->point[axis]))
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "mass->point[%d] is %g; it must be finite", axis,
                                 mass->point[axis]);
    out = *mass;
    return POLYMASS_OK;
}

void copy_matrix(const Eigen::Matrix3d& matrix, double (&out)[9]) { RowMajor3d::Map(out) = matrix; }

void copy_vector(const Eigen::Vector3d& vector, double (&out)[3]) {
    Eigen::Vector3d::Map(out) = vector;
}

// Every value finite, and mass and moments not underflowed to zero or to
// subnormal numbers (which keep too few digits).
bool result_in_range(const polymass_mass_properties& p) {
    const double scalars[] = {p.volume, p.mass, p.density, p.surface_area};
    // By magnitude: an unchecked non-solid can have negative moments.
    const double largest_moment =
        Eigen::Map<const Eigen::Vector3d>(p.principal_moments).cwiseAbs().maxCoeff();
    return all_finite(scalars) && p.mass >= DBL_MIN && p.density >= DBL_MIN &&
           largest_moment >= DBL_MIN && all_finite(p.center_of_mass) && all_finite(p.inertia) &&
           all_finite(p.inertia_origin) && all_finite(p.inertia_point) &&
           all_finite(p.principal_moments) && all_finite(p.principal_axes);
}

int32_t mass_properties(polymass_mass_properties* out, polymass_context* context,
                        const polymass_mesh& mesh, const polymass_mass_desc* mass) {
    polymass_mass_desc body_desc;
    if (const int32_t status = read_mass_desc(context, mass, body_desc)) return status;
    const double density = body_desc.mass_mode == POLYMASS_MASS_FROM_TOTAL
                               ? body_desc.mass / mesh.integrals.volume
                               : body_desc.density;
    const core::RigidBody body = core::rigid_body(mesh.integrals, mesh.reference, density);
    const core::PrincipalAxes principal = core::principal_axes(body.inertia);

    polymass_mass_properties result{};
    result.struct_size = sizeof result;
    result.warnings = mesh.warnings;
    result.volume = body.volume;
    result.mass = body.mass;
    result.density = body.density;
    result.surface_area = mesh.surface_area;
    copy_vector(body.center_of_mass, result.center_of_mass);
    copy_matrix(body.inertia, result.inertia);
    copy_matrix(core::inertia_about(body, Eigen::Vector3d::Zero()), result.inertia_origin);
    copy_matrix(core::inertia_about(body, Eigen::Map<const Eigen::Vector3d>(body_desc.point)),
                result.inertia_point);
    copy_vector(principal.moments, result.principal_moments);
    copy_matrix(principal.axes, result.principal_axes);
    if (!(result_in_range(result)))
        return context->fail(
            POLYMASS_ERROR_OVERFLOW,
            "the mass properties do not fit in a double (mass %g, density %g, "
            "largest coordinate of the centre of mass or point %g): scale the "
            "coordinates, the density or mass, or the point",
            result.mass, result.density,
            std::max(body.center_of_mass.cwiseAbs().maxCoeff(),
                     Eigen::Map<const Eigen::Vector3d>(body_desc.point).cwiseAbs().maxCoeff()));
    *out = result;
    return POLYMASS_OK;
}

void fill_report(polymass_diagnostics& report, const MeshInput& input,
                 const core::MeshAnalysis* analysis) {
    constexpr uint64_t none = POLYMASS_NONE;
    report = polymass_diagnostics{};
    report.struct_size = sizeof report;
    report.face_count = input.face_count;
    report.first_non_finite_vertex = report.first_out_of_range_face = none;
    report.first_small_face = report.first_degenerate_face = report.first_non_planar_face = none;
    for (uint64_t* edge :
         {report.first_open_edge, report.first_non_manifold_edge, report.first_misoriented_edge})
        edge[0] = edge[1] = none;
    report.signed_volume = std::numeric_limits<double>::quiet_NaN();
    report.small_faces = input.small_faces;
    if (input.small_faces > 0) report.first_small_face = input.first_small_face;
    if (!analysis) return;

    const core::MeshScan& scan = analysis->scan;
    report.used_vertex_count = analysis->used_vertex_count;
    report.non_finite_vertices = scan.non_finite.count;
    if (scan.non_finite.count) report.first_non_finite_vertex = scan.non_finite.first;
    report.out_of_range_indices = scan.out_of_range_indices;
    if (scan.out_of_range_indices) report.first_out_of_range_face = scan.out_of_range_faces.first;
    if (const auto& topology = analysis->topology) {
        report.edge_count = topology->edge_count;
        const auto copy_edges = [](const core::EdgeFinding& found, uint64_t& count,
                                   uint64_t(&first)[2]) {
            count = found.count;
            if (found.count) first[0] = found.first[0], first[1] = found.first[1];
        };
        copy_edges(topology->open, report.open_edges, report.first_open_edge);
        copy_edges(topology->non_manifold, report.non_manifold_edges,
                   report.first_non_manifold_edge);
        copy_edges(topology->misoriented, report.misoriented_edges, report.first_misoriented_edge);
    }
    if (const auto& integration = analysis->integration) {
        report.degenerate_faces = integration->degenerate_faces.count;
        if (integration->degenerate_faces.count)
            report.first_degenerate_face = integration->degenerate_faces.first;
        report.non_planar_faces = integration->non_planar_faces.count;
        if (integration->non_planar_faces.count)
            report.first_non_planar_face = integration->non_planar_faces.first;
        report.max_non_planarity = integration->max_non_planarity;
        report.signed_volume = integration->integrals.volume;
    }
}

}  // namespace
}  // namespace polymass::capi

using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_mesh_create(polymass_mesh** out_mesh, polymass_context* context,
                                          const polymass_mesh_desc* desc) {
    if (out_mesh) *out_mesh = nullptr;  // on every failure, even without a context
    return guarded(context, [&] {
        if (!out_mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "out_mesh is NULL");
        polymass_mesh mesh{context->allocator, {}, Eigen::Vector3d::Zero(), 0.0, 0};
        if (const int32_t status = build_mesh(context, desc, mesh)) return status;
        *out_mesh = create_object<polymass_mesh>(context->allocator, mesh);
        if (!*out_mesh)
            return context->fail(POLYMASS_ERROR_OUT_OF_MEMORY,
                                 "out of memory: the allocator could not provide the mesh");
        return POLYMASS_OK;
    });
}

POLYMASS_API void polymass_mesh_destroy(polymass_mesh* mesh) { destroy_object(mesh); }

POLYMASS_API int32_t polymass_mesh_mass_properties(polymass_mass_properties* out_properties,
                                                   polymass_context* context,
                                                   const polymass_mesh* mesh,
                                                   const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        if (!mesh) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "mesh is NULL");
        return mass_properties(out_properties, context, *mesh, mass);
    });
}

POLYMASS_API int32_t polymass_mass_properties_compute(polymass_mass_properties* out_properties,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_mass_desc* mass) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        polymass_mesh mesh{context->allocator, {}, Eigen::Vector3d::Zero(), 0.0, 0};
        if (const int32_t status = build_mesh(context, desc, mesh)) return status;
        return mass_properties(out_properties, context, mesh, mass);
    });
}

POLYMASS_API int32_t polymass_mesh_check(polymass_diagnostics* out_report,
                                         polymass_context* context,
                                         const polymass_mesh_desc* desc) {
    const bool report_valid = out_report && out_report->struct_size == sizeof *out_report;
    const int32_t status = guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_report, "out_report")) return status;
        MeshInput input;
        int32_t found = read_mesh_desc(context, desc, input);
        fill_report(*out_report, input, nullptr);  // what the arguments tell, if anything
        if (found == POLYMASS_OK) {
            const polymass::core::MeshAnalysis analysis = analyse(context, input, true);
            uint32_t warnings = 0;
            found = judge(context, input, analysis, warnings);
            fill_report(*out_report, input, &analysis);
        }
        return found;
    });
    // Also when the checks could not finish (out of memory) or there is no context.
    if (report_valid) out_report->status = status;
    return status;
}

}  // extern "C"
