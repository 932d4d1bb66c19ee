#include "mesh_analysis.hpp"

#include <cstring>

#include "shells.hpp"
#include "welding.hpp"

namespace polymass::core {

namespace {

// The rule for a face: at least 3 vertices (docs/validity.md).
Finding faces_too_small(const std::uint32_t* face_sizes, std::size_t face_count) {
    Finding small;
    if (!face_sizes) return small;  // triangles
    for (std::size_t face = 0; face < face_count; ++face)
        if (face_sizes[face] < 3) small.record(face);
    return small;
}

// scan_surface from the mesh's scan.
template <class Scalar, class Index>
MeshAnalysis judge_scan(const MeshView<Scalar, Index>& mesh, MeshScan scan) {
    MeshAnalysis analysis(std::move(scan));
    analysis.small_faces = faces_too_small(mesh.face_sizes, mesh.face_count);
    analysis.used_vertex_count = analysis.scan.used_vertex_count;
    analysis.verdict = judge(analysis, {});
    return analysis;
}

}  // namespace

template <class Scalar, class Index>
MeshAnalysis scan_surface(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory,
                          TaskRunner& tasks) {
    return judge_scan(mesh, scan_mesh(mesh, memory, tasks));
}

namespace {

// Whether the topology and the shells take welded positions.
bool welds(const AnalysisSettings& settings) {
    return settings.weld && (settings.check_topology || settings.list_shells);
}

IntegrationSettings integration_settings(const MeshScan& scan, const AnalysisSettings& settings) {
    IntegrationSettings integration;
    integration.reference = scan.reference_point();
    integration.size = scan.diagonal();
    integration.check_planarity = settings.check_topology;
    integration.planarity_tolerance = settings.planarity_tolerance;
    return integration;
}

// The same reference point and unit, to the bit (a zero's sign included).
bool same_frame(const IntegrationSettings& a, const IntegrationSettings& b) {
    return std::memcmp(a.reference.data(), b.reference.data(), sizeof(double) * 3) == 0 &&
           std::memcmp(&a.size, &b.size, sizeof a.size) == 0;
}

// When the faces are triangles and no weld renumbers their vertices, the
// integration marks the used vertices itself, about the centre of the bounds
// of every vertex, and the scan is finished from its marks: one pass over the
// index array fewer (the scan's own marking pass read all of it, a tenth of
// the checked path's time at 1e6 triangles: docs/validity.md). With a vertex
// unused, if the scan's bounds move the reference point or the unit, the
// faces are integrated again about the scan's: the results are the usual
// ones, to the bit. nullopt when the positions cannot be bounded this way
// (the usual analysis then says why) or an index is out of range.
template <class Scalar, class Index>
std::optional<MeshAnalysis> integrate_while_scanning(const MeshView<Scalar, Index>& mesh,
                                                     const AnalysisSettings& settings,
                                                     TaskRunner& tasks,
                                                     std::pmr::memory_resource* memory) {
    if (welds(settings) || !mesh.all_triangles()) return std::nullopt;
    const std::optional<Eigen::AlignedBox3d> every_vertex = bound_every_vertex(mesh, memory, tasks);
    if (!every_vertex) return std::nullopt;
    MeshScan provisional(memory);
    provisional.bounds = *every_vertex;
    IntegrationSettings integration = integration_settings(provisional, settings);
    std::pmr::vector<unsigned char> seen(addressable_vertices(mesh), 0, memory);
    integration.used_marks = &seen;
    IntegrationResult integrated = integrate_mesh(mesh, integration, tasks);
    if (!integrated.indices_in_range) return std::nullopt;
    MeshAnalysis analysis(scan_from_marks(mesh, seen, *every_vertex, memory, tasks));
    analysis.used_vertex_count = analysis.scan.used_vertex_count;
    // (Every coordinate is finite: the scan finds nothing to refuse.)
    const IntegrationSettings scanned = integration_settings(analysis.scan, settings);
    analysis.integration =
        same_frame(scanned, integration) ? integrated : integrate_mesh(mesh, scanned, tasks);
    return analysis;
}

}  // namespace

template <class Scalar, class Index>
MeshAnalysis analyse_mesh(const MeshView<Scalar, Index>& mesh, const AnalysisSettings& settings,
                          std::pmr::memory_resource* memory) {
    SerialTaskRunner serial;
    TaskRunner& tasks = settings.tasks ? *settings.tasks : serial;
    std::optional<MeshAnalysis> integrated =
        integrate_while_scanning(mesh, settings, tasks, memory);
    if (integrated && !settings.check_topology && !settings.list_shells) {
        integrated->verdict = judge(*integrated, settings.policy);
        return std::move(*integrated);
    }
    // The topology and the shells take the welded positions numbered densely.
    // An exact weld follows the scan (scan_and_weld_exact): a soup's positions
    // are read from memory once for both.
    const bool weld = welds(settings);
    const bool weld_exact = weld && !(settings.weld_tolerance > 0.0);
    NumberedVertices numbered(memory);
    MeshAnalysis analysis =
        integrated   ? std::move(*integrated)
        : weld_exact ? judge_scan(mesh, scan_and_weld_exact(mesh, numbered, tasks, memory))
                     : scan_surface(mesh, memory, tasks);
    // An integration done with the scan is the analysis's only once the
    // topology lets the analysis go on: judged before it, as it always is.
    std::optional<IntegrationResult> integrated_with_scan =
        std::exchange(analysis.integration, std::nullopt);
    const MeshScan& scan = analysis.scan;
    // Judges what is known; true when the analysis should end here.
    auto stop = [&] {
        analysis.verdict = judge(analysis, settings.policy);
        return settings.stop_at_first_problem && !analysis.verdict.valid();
    };
    // Faces too small and out-of-range indices cannot be read, and non-finite
    // coordinates poison every sum: nothing after this is meaningful.
    if (analysis.small_faces.count > 0 || scan.out_of_range_indices > 0 ||
        scan.non_finite.count > 0) {
        stop();
        return analysis;
    }

    if (weld) {
        if (!weld_exact)
            numbered = weld_and_number(mesh, scan, settings.weld_tolerance, tasks, memory);
        analysis.used_vertex_count = numbered.lowest_vertex.size();
        // Every vertex used and no two at one position (an indexed mesh, as
        // most are): each vertex is its own identity, and no numbering is kept.
        if (analysis.used_vertex_count == mesh.vertex_count) numbered = NumberedVertices(memory);
    }
    const bool welded = !numbered.lowest_vertex.empty();
    const VertexIdentities identities = welded ? numbered.identities() : VertexIdentities{};
    // The vertices joined along the edges by the topology check: the shells' sets.
    std::pmr::vector<std::uint32_t> vertex_sets(memory);
    // The shells as connected pieces, when they were not judged.
    auto finish = [&] {
        if (settings.list_shells && !analysis.shells)
            analysis.unjudged_shells =
                find_shells(mesh, scan, identities, std::move(vertex_sets), tasks, memory);
        return std::move(analysis);
    };
    if (settings.check_topology) {
        analysis.topology = analyse_topology(mesh, identities, tasks, memory, vertex_sets);
        if (stop()) return finish();
    }

    const IntegrationSettings integration = integration_settings(scan, settings);
    analysis.integration = integrated_with_scan ? std::move(integrated_with_scan)
                                                : integrate_mesh(mesh, integration, tasks);
    if (stop()) return finish();

    // Shells are judged on a closed, oriented surface of planar faces whose
    // integrals fit in doubles: a surface refused whole for its volume (none,
    // or inside out) still has its shells judged, signed as they are found.
    const Defect defect = analysis.verdict.defect;
    // The intersection check below also counts the windings of the shells.
    const bool intersection_check_runs =
        settings.check_topology && settings.check_intersections && std::isfinite(scan.diagonal());
    if (analysis.topology &&
        analysis.topology->closed_and_oriented(settings.policy.accept_balanced_non_manifold) &&
        (defect == Defect::none || defect == Defect::inverted || defect == Defect::zero_volume)) {
        analysis.shells =
            survey_shells(mesh, scan, identities, std::move(vertex_sets), integration.reference,
                          analysis.verdict.outward, analysis.integration->integrals.volume,
                          analysis.integration->encloses_no_volume, tasks, memory);
        // A shell inside out by the boxes alone is not yet a verdict when the
        // windings are counted next: they may find it a cavity across two
        // solids that touch, or passing through a surface. An analysis that
        // stops at the first problem goes on to them, so that every caller
        // gets the verdict of the full analysis.
        if (stop() && !intersection_check_runs) return finish();
    }
    if (intersection_check_runs) {
        const Shells* shells = analysis.shells ? &analysis.shells->shells : nullptr;
        // The check takes each vertex's lowest welded vertex.
        const std::pmr::vector<std::uint32_t> lowest =
            welded ? lowest_welded_vertices(numbered, scan, memory)
                   : std::pmr::vector<std::uint32_t>(memory);
        // Copies need no search where the topology rules them out (a closed,
        // oriented surface of welded triangles, most meshes).
        const bool may_have_copies =
            !copies_ruled_out(mesh.all_triangles(), weld, *analysis.topology);
        analysis.overlaps =
            find_overlaps(mesh, welded ? lowest.data() : nullptr, integration.reference,
                          integration.size, shells, may_have_copies, tasks, memory);
        if (!analysis.overlaps->winding_of_shell.empty())
            classify_by_winding(*analysis.shells, analysis.overlaps->winding_of_shell,
                                analysis.verdict.outward);
    }
    stop();
    return finish();
}

template <class Scalar, class Index>
MeshAnalysis analyse_piece(const MeshView<Scalar, Index>& mesh, const Eigen::Vector3d& reference,
                           const AnalysisSettings& settings, std::pmr::memory_resource* memory) {
    SerialTaskRunner serial;
    TaskRunner& tasks = settings.tasks ? *settings.tasks : serial;
    MeshAnalysis piece = scan_surface(mesh, memory, tasks);
    piece.verdict = judge_piece(piece);
    if (!piece.verdict.valid()) return piece;
    // About the caller's point, in a unit set by how far the faces reach
    // from it: twice the largest distance to a corner of the box.
    const MeshScan& scan = piece.scan;
    const Eigen::Vector3d farthest = (scan.bounds.min() - reference)
                                         .cwiseAbs()
                                         .cwiseMax((scan.bounds.max() - reference).cwiseAbs());
    IntegrationSettings integration;
    integration.reference = reference;
    integration.size = 2.0 * farthest.stableNorm();
    integration.check_planarity = settings.check_topology;
    integration.planarity_tolerance = settings.planarity_tolerance;
    piece.integration = integrate_mesh(mesh, integration, tasks);
    piece.verdict = judge_piece(piece);
    return piece;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                     \
    template MeshAnalysis scan_surface<Scalar, Index>(const MeshView<Scalar, Index>&,           \
                                                      std::pmr::memory_resource*, TaskRunner&); \
    template MeshAnalysis analyse_mesh<Scalar, Index>(                                          \
        const MeshView<Scalar, Index>&, const AnalysisSettings&, std::pmr::memory_resource*);   \
    template MeshAnalysis analyse_piece<Scalar, Index>(                                         \
        const MeshView<Scalar, Index>&, const Eigen::Vector3d&, const AnalysisSettings&,        \
        std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
