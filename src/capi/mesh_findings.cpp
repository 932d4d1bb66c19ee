#include "mesh_findings.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "struct_versions.hpp"

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

static_assert(core::kWarningInverted == POLYMASS_WARNING_INVERTED &&
                  core::kWarningDegenerate == POLYMASS_WARNING_DEGENERATE_FACES &&
                  core::kWarningUnchecked == POLYMASS_WARNING_UNCHECKED &&
                  core::kWarningNonManifold == POLYMASS_WARNING_NON_MANIFOLD &&
                  core::kWarningTouching == POLYMASS_WARNING_TOUCHING_FACES &&
                  core::kWarningIntersectionsUnchecked == POLYMASS_WARNING_INTERSECTIONS_UNCHECKED,
              "the core's warning bits are the API's");

int32_t fail_on_edge(polymass_context* context, int32_t status, const core::EdgeFinding& edges,
                     const char* what) {
    return context->fail(status, "edge (%u, %u) is %s (%llu such edges)", edges.first()[0],
                         edges.first()[1], what, u64(edges.count));
}

int32_t fail_on_shell(polymass_context* context, int32_t status, const core::ShellSurvey& survey,
                      const core::Finding& shells, const char* what) {
    const core::ShellSummary& shell = survey.summary[shells.first()];
    return context->fail(status,
                         "shell %llu (%llu faces, the first face %llu, signed volume %.17g) %s "
                         "(%llu such shells)",
                         u64(shells.first()), u64(shell.face_count), u64(shell.first_face),
                         shell.signed_volume, what, u64(shells.count));
}

}  // namespace

int32_t status_of(core::Defect defect) {
    using core::Defect;
    switch (defect) {
        case Defect::none:
            return POLYMASS_OK;
        case Defect::face_too_small:
            return POLYMASS_ERROR_FACE_TOO_SMALL;
        case Defect::index_out_of_range:
            return POLYMASS_ERROR_INDEX_OUT_OF_RANGE;
        case Defect::non_finite:
            return POLYMASS_ERROR_NON_FINITE;
        case Defect::open:
            return POLYMASS_ERROR_OPEN;
        case Defect::non_manifold:
            return POLYMASS_ERROR_NON_MANIFOLD;
        case Defect::misoriented:
            return POLYMASS_ERROR_INCONSISTENT_ORIENTATION;
        case Defect::non_planar:
            return POLYMASS_ERROR_NON_PLANAR_FACE;
        case Defect::zero_volume:
            return POLYMASS_ERROR_ZERO_VOLUME;
        case Defect::inverted:
        case Defect::inverted_shell:
            return POLYMASS_ERROR_INVERTED;
        case Defect::crossing:
        case Defect::overlapping_shells:
            return POLYMASS_ERROR_INTERSECTING;
        case Defect::extent_overflow:
        case Defect::integrals_overflow:
        case Defect::volume_underflow:
            return POLYMASS_ERROR_OVERFLOW;
    }
    return POLYMASS_ERROR_INTERNAL;
}

int32_t report_verdict(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, const core::MeshAnalysis& analysis,
                       core::Defect defect) {
    using core::Defect;
    const core::MeshScan& scan = analysis.scan;
    switch (defect) {
        case Defect::none:
            return POLYMASS_OK;
        case Defect::face_too_small: {
            const std::size_t face = analysis.small_faces.first();
            return context->fail(POLYMASS_ERROR_FACE_TOO_SMALL,
                                 "face %llu has %u vertices; a face needs at least 3 (%llu such "
                                 "faces)",
                                 u64(face), input.face_sizes[face],
                                 u64(analysis.small_faces.count));
        }
        case Defect::index_out_of_range:
            return context->fail(POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
                                 "face %llu refers to vertex %u, but there are only %llu vertices "
                                 "(%llu indices out of range, in %llu faces)",
                                 u64(scan.out_of_range_faces.first()),
                                 scan.first_out_of_range_index, u64(input.vertex_count),
                                 u64(scan.out_of_range_indices),
                                 u64(scan.out_of_range_faces.count));
        case Defect::non_finite:
            return context->fail(POLYMASS_ERROR_NON_FINITE,
                                 "vertex %llu, used by a face, has a NaN or infinite coordinate "
                                 "(%llu such vertices)",
                                 u64(scan.non_finite.first()), u64(scan.non_finite.count));
        case Defect::extent_overflow:
            return context->fail(POLYMASS_ERROR_OVERFLOW,
                                 "the mesh spans more than a double can hold (its bounding box "
                                 "reaches from %g to %g)",
                                 scan.bounds.min().minCoeff(), scan.bounds.max().maxCoeff());
        case Defect::open:
            return fail_on_edge(context, POLYMASS_ERROR_OPEN, analysis.topology->open,
                                "used by one face only: the surface is open");
        case Defect::non_manifold: {
            const core::EdgeFinding& edges = analysis.topology->non_manifold;
            return context->fail(POLYMASS_ERROR_NON_MANIFOLD,
                                 "edge (%u, %u) is used by %llu faces; an edge of a solid's "
                                 "surface has two (%llu such edges)",
                                 edges.first()[0], edges.first()[1], u64(edges.first_traversals),
                                 u64(edges.count));
        }
        case Defect::misoriented:
            return fail_on_edge(context, POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                                analysis.topology->misoriented,
                                "traversed in the same direction by both its faces: one of "
                                "them is reversed");
        case Defect::non_planar: {
            const core::IntegrationResult& integration = *analysis.integration;
            return context->fail(POLYMASS_ERROR_NON_PLANAR_FACE,
                                 "face %llu is not planar: a vertex is off its plane by %.3g of "
                                 "the face's diameter, more than the tolerance %.3g (%llu such "
                                 "faces)",
                                 u64(integration.non_planar_faces.first()),
                                 integration.max_non_planarity, options.planarity_tolerance,
                                 u64(integration.non_planar_faces.count));
        }
        case Defect::zero_volume:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the surface encloses no volume: its signed volume is at "
                                 "rounding level for its area and its size %.3g (a flat or "
                                 "double-sided surface)",
                                 scan.diagonal());
        case Defect::integrals_overflow:
            return context->fail(POLYMASS_ERROR_OVERFLOW,
                                 "the volume integrals overflow double precision: the mesh is "
                                 "too large (size %.3g); scale its coordinates down",
                                 scan.diagonal());
        case Defect::volume_underflow:
            return context->fail(POLYMASS_ERROR_OVERFLOW,
                                 "the volume %g is too small for a double (below %g): the mesh "
                                 "is too small (size %.3g); scale its coordinates up",
                                 // its magnitude: an underflow to -0 reads as "-0"
                                 std::fabs(analysis.integration->integrals.volume), DBL_MIN,
                                 scan.diagonal());
        case Defect::inverted:
            return context->fail(POLYMASS_ERROR_INVERTED,
                                 "the signed volume is %.17g: every face is reversed (faces "
                                 "must be counter-clockwise seen from outside); "
                                 "POLYMASS_OPTION_ACCEPT_INVERTED accepts it turned",
                                 analysis.integration->integrals.volume);
        case Defect::crossing: {
            const core::PairFinding& pairs = analysis.overlaps->crossing;
            const auto [low, high] = pairs.first();
            const char* at_least = pairs.complete ? "" : "at least ";
            if (analysis.shells) {
                const auto& of_face = analysis.shells->shells.of_face;
                return context->fail(POLYMASS_ERROR_INTERSECTING,
                                     "faces %llu (shell %u) and %llu (shell %u) cross each "
                                     "other: the region inside both would be counted twice "
                                     "(%s%llu such face pairs)",
                                     u64(low), of_face[low], u64(high), of_face[high], at_least,
                                     u64(pairs.count));
            }
            return context->fail(POLYMASS_ERROR_INTERSECTING,
                                 "faces %llu and %llu cross each other: the region inside both "
                                 "would be counted twice (%s%llu such face pairs)",
                                 u64(low), u64(high), at_least, u64(pairs.count));
        }
        case Defect::inverted_shell:
            return fail_on_shell(context, POLYMASS_ERROR_INVERTED, *analysis.shells,
                                 analysis.shells->inverted,
                                 "is inside out: its volume is negative and it lies inside no "
                                 "solid shell, so it would be subtracted from nothing");
        case Defect::overlapping_shells:
            return fail_on_shell(context, POLYMASS_ERROR_INTERSECTING, *analysis.shells,
                                 analysis.shells->overlapping,
                                 "lies inside another shell that already bounds the same "
                                 "side, or passes through its surface: its region would be "
                                 "counted twice");
    }
    return context->fail(POLYMASS_ERROR_INTERNAL, "unknown defect");
}

static_assert(core::kKeptLocations == POLYMASS_DIAGNOSTIC_LOCATIONS,
              "the core keeps as many locations as the report lists");
static_assert(core::kMostCountedPairs == POLYMASS_MAX_COUNTED_FACE_PAIRS,
              "the core counts as many face pairs as the header says");

void copy_locations(const core::Finding& found, uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS]) {
    for (std::size_t i = 0; i < found.kept(); ++i) first[i] = found.lowest[i];
}

void copy_finding(const core::Finding& found, uint64_t& count,
                  uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS]) {
    count = found.count;
    copy_locations(found, first);
}

void fill_report(polymass_diagnostics& report, const MeshInput& input,
                 const core::MeshAnalysis& analysis) {
    // Every location POLYMASS_NONE until a finding fills it.
    report = StructVersions<polymass_diagnostics>::defaults();
    report.face_count = input.face_count;
    report.signed_volume = std::numeric_limits<double>::quiet_NaN();
    const core::MeshScan& scan = analysis.scan;
    copy_finding(analysis.small_faces, report.small_faces, report.first_small_faces);
    report.used_vertex_count = analysis.used_vertex_count;
    copy_finding(scan.non_finite, report.non_finite_vertices, report.first_non_finite_vertices);
    // Counted per index, located per face.
    report.out_of_range_indices = scan.out_of_range_indices;
    copy_locations(scan.out_of_range_faces, report.first_out_of_range_faces);
    if (analysis.topology && analysis.integration) report.checks |= POLYMASS_CHECKED_TOPOLOGY;
    if (analysis.shells) report.checks |= POLYMASS_CHECKED_SHELLS;
    if (analysis.overlaps) report.checks |= POLYMASS_CHECKED_INTERSECTIONS;
    if (const auto& topology = analysis.topology) {
        report.edge_count = topology->edge_count;
        copy_finding(topology->open, report.open_edges, report.first_open_edges);
        copy_finding(topology->non_manifold, report.non_manifold_edges,
                     report.first_non_manifold_edges);
        copy_finding(topology->misoriented, report.misoriented_edges,
                     report.first_misoriented_edges);
    }
    if (const auto& integration = analysis.integration) {
        copy_finding(integration->degenerate_faces, report.degenerate_faces,
                     report.first_degenerate_faces);
        copy_finding(integration->non_planar_faces, report.non_planar_faces,
                     report.first_non_planar_faces);
        report.max_non_planarity = integration->max_non_planarity;
        report.signed_volume = integration->integrals.volume;
    }
    if (const auto& shells = analysis.shells) {
        report.shell_count = shells->shells.count;
        copy_finding(shells->inverted, report.inverted_shells, report.first_inverted_shells);
        copy_finding(shells->overlapping, report.overlapping_shells,
                     report.first_overlapping_shells);
    } else if (analysis.unjudged_shells) {
        report.shell_count = analysis.unjudged_shells->count;
    }
    if (const auto& overlaps = analysis.overlaps) {
        copy_finding(overlaps->crossing, report.intersecting_face_pairs,
                     report.first_intersecting_face_pairs);
        copy_finding(overlaps->touching, report.touching_face_pairs,
                     report.first_touching_face_pairs);
    }
}

namespace {

int32_t shell_kind(core::ShellKind kind) {
    switch (kind) {
        case core::ShellKind::solid:
            return POLYMASS_SHELL_SOLID;
        case core::ShellKind::cavity:
            return POLYMASS_SHELL_CAVITY;
        case core::ShellKind::inverted:
            return POLYMASS_SHELL_INVERTED;
        case core::ShellKind::overlapping:
            return POLYMASS_SHELL_OVERLAPPING;
        case core::ShellKind::no_volume:
            return POLYMASS_SHELL_NO_VOLUME;
    }
    return POLYMASS_SHELL_UNJUDGED;
}

}  // namespace

void list_shells(const core::MeshAnalysis& analysis, std::pmr::vector<polymass_shell>& shells,
                 std::pmr::vector<uint32_t>& shell_of_face) {
    polymass_shell shell = StructVersions<polymass_shell>::defaults();
    if (const auto& survey = analysis.shells) {
        shells.reserve(survey->summary.size());
        for (const core::ShellSummary& summary : survey->summary) {
            shell.kind = shell_kind(summary.kind);
            shell.face_count = summary.face_count;
            shell.first_face = summary.first_face;
            shell.signed_volume = summary.signed_volume;
            shells.push_back(shell);
        }
        shell_of_face.assign(survey->shells.of_face.begin(), survey->shells.of_face.end());
        return;
    }
    if (!analysis.unjudged_shells) return;
    // Connected pieces only: their sizes and first faces from the numbering.
    const core::Shells& pieces = *analysis.unjudged_shells;
    shell.kind = POLYMASS_SHELL_UNJUDGED;
    shell.signed_volume = std::numeric_limits<double>::quiet_NaN();
    shells.assign(pieces.count, shell);
    for (std::size_t face = pieces.of_face.size(); face-- > 0;) {
        polymass_shell& piece = shells[pieces.of_face[face]];
        ++piece.face_count;
        piece.first_face = face;
    }
    shell_of_face.assign(pieces.of_face.begin(), pieces.of_face.end());
}

}  // namespace polymass::capi
