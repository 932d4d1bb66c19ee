#include "mesh_findings.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

int32_t fail_on_edge(polymass_context* context, int32_t status, const core::EdgeFinding& edges,
                     const char* what) {
    return context->fail(status, "edge (%u, %u) is %s (%llu such edges)", edges.first()[0],
                         edges.first()[1], what, u64(edges.count));
}

}  // namespace

core::MeshAnalysis analyse(polymass_context* context, const MeshInput& input,
                           const polymass_options& options, bool full_report) {
    core::AnalysisSettings settings;
    settings.check_topology =
        full_report || !(options.flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    settings.weld = options.flags & POLYMASS_OPTION_WELD_VERTICES;
    settings.weld_tolerance = options.weld_tolerance;
    settings.stop_at_first_problem = !full_report;
    settings.planarity_tolerance = options.planarity_tolerance;
    const bool accept_non_manifold = options.flags & POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
    return visit_mesh(input, [&](const auto& view) {
        return core::analyse_mesh(view, settings, accept_non_manifold, &context->memory);
    });
}

int32_t judge_scan(polymass_context* context, const MeshInput& input, const core::MeshScan& scan) {
    if (scan.out_of_range_indices > 0)
        return context->fail(POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
                             "face %llu refers to vertex %u, but there are only %llu vertices "
                             "(%llu indices out of range, in %llu faces)",
                             u64(scan.out_of_range_faces.first()), scan.first_out_of_range_index,
                             u64(input.vertex_count), u64(scan.out_of_range_indices),
                             u64(scan.out_of_range_faces.count));
    if (scan.non_finite.count > 0)
        return context->fail(POLYMASS_ERROR_NON_FINITE,
                             "vertex %llu, used by a face, has a NaN or infinite coordinate "
                             "(%llu such vertices)",
                             u64(scan.non_finite.first()), u64(scan.non_finite.count));
    if (!std::isfinite(scan.diagonal()))
        return context->fail(POLYMASS_ERROR_OVERFLOW,
                             "the mesh spans more than a double can hold (its bounding box "
                             "reaches from %g to %g)",
                             scan.bounds.min().minCoeff(), scan.bounds.max().maxCoeff());
    return POLYMASS_OK;
}

int32_t judge_planarity(polymass_context* context, const core::IntegrationResult& integration,
                        const polymass_options& options) {
    if (integration.non_planar_faces.count == 0) return POLYMASS_OK;
    return context->fail(POLYMASS_ERROR_NON_PLANAR_FACE,
                         "face %llu is not planar: a vertex is off its plane by %.3g of "
                         "the face's diameter, more than the tolerance %.3g (%llu such faces)",
                         u64(integration.non_planar_faces.first()), integration.max_non_planarity,
                         options.planarity_tolerance, u64(integration.non_planar_faces.count));
}

int32_t judge(polymass_context* context, const MeshInput& input, const polymass_options& options,
              const core::MeshAnalysis& analysis, uint32_t& warnings) {
    const uint32_t flags = options.flags;
    const core::MeshScan& scan = analysis.scan;
    if (const int32_t status = judge_scan(context, input, scan)) return status;
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
                    topology->non_manifold.first()[0], topology->non_manifold.first()[1],
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
    if (const int32_t status = judge_planarity(context, integration, options)) return status;
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
    // A solid too small for a double: its volume (size^3) underflowed. The
    // inertia (size^5 x density) can underflow too, but that depends on the
    // density: polymass_mesh_mass_properties says so.
    if (!(std::abs(integrals.volume) >= DBL_MIN))
        return context->fail(POLYMASS_ERROR_OVERFLOW,
                             "the volume %g is too small for a double (below %g): the mesh is "
                             "too small (size %.3g); scale its coordinates up",
                             integrals.volume, DBL_MIN, scan.diagonal());
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

namespace {

static_assert(core::kKeptLocations == POLYMASS_DIAGNOSTIC_LOCATIONS,
              "the core keeps as many locations as the report lists");

void copy_locations(const core::Finding& found, uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS]) {
    for (std::size_t i = 0; i < found.kept(); ++i) first[i] = found.lowest[i];
}

void copy_finding(const core::Finding& found, uint64_t& count,
                  uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS]) {
    count = found.count;
    copy_locations(found, first);
}

void copy_finding(const core::EdgeFinding& found, uint64_t& count,
                  uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS][2]) {
    count = found.count;
    for (std::size_t i = 0; i < found.kept(); ++i) {
        first[i][0] = found.lowest[i][0];
        first[i][1] = found.lowest[i][1];
    }
}

}  // namespace

void fill_report(polymass_diagnostics& report, const MeshInput& input,
                 const core::MeshAnalysis* analysis) {
    report = polymass_diagnostics{};
    report.struct_size = sizeof report;
    // Every location POLYMASS_NONE until a finding fills it: the struct is
    // nothing but counts, locations and the two doubles set below.
    for (uint64_t* location :
         {&report.first_non_finite_vertices[0], &report.first_out_of_range_faces[0],
          &report.first_small_faces[0], &report.first_degenerate_faces[0],
          &report.first_non_planar_faces[0]})
        std::fill_n(location, POLYMASS_DIAGNOSTIC_LOCATIONS, POLYMASS_NONE);
    for (uint64_t* edge : {&report.first_open_edges[0][0], &report.first_non_manifold_edges[0][0],
                           &report.first_misoriented_edges[0][0]})
        std::fill_n(edge, 2 * POLYMASS_DIAGNOSTIC_LOCATIONS, POLYMASS_NONE);
    report.face_count = input.face_count;
    report.signed_volume = std::numeric_limits<double>::quiet_NaN();
    copy_finding(input.small_faces, report.small_faces, report.first_small_faces);
    if (!analysis) return;

    const core::MeshScan& scan = analysis->scan;
    report.used_vertex_count = analysis->used_vertex_count;
    copy_finding(scan.non_finite, report.non_finite_vertices, report.first_non_finite_vertices);
    // Counted per index, located per face.
    report.out_of_range_indices = scan.out_of_range_indices;
    copy_locations(scan.out_of_range_faces, report.first_out_of_range_faces);
    if (const auto& topology = analysis->topology) {
        report.edge_count = topology->edge_count;
        copy_finding(topology->open, report.open_edges, report.first_open_edges);
        copy_finding(topology->non_manifold, report.non_manifold_edges,
                     report.first_non_manifold_edges);
        copy_finding(topology->misoriented, report.misoriented_edges,
                     report.first_misoriented_edges);
    }
    if (const auto& integration = analysis->integration) {
        copy_finding(integration->degenerate_faces, report.degenerate_faces,
                     report.first_degenerate_faces);
        copy_finding(integration->non_planar_faces, report.non_planar_faces,
                     report.first_non_planar_faces);
        report.max_non_planarity = integration->max_non_planarity;
        report.signed_volume = integration->integrals.volume;
    }
}

}  // namespace polymass::capi
