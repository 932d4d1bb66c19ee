#include "mesh_analysis.hpp"

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

}  // namespace

template <class Scalar, class Index>
MeshAnalysis scan_surface(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory,
                          TaskRunner& tasks) {
    MeshAnalysis analysis(scan_mesh(mesh, memory, tasks));
    analysis.small_faces = faces_too_small(mesh.face_sizes, mesh.face_count);
    analysis.used_vertex_count = analysis.scan.used_vertex_count;
    analysis.verdict = judge(analysis, {});
    return analysis;
}

template <class Scalar, class Index>
MeshAnalysis analyse_mesh(const MeshView<Scalar, Index>& mesh, const AnalysisSettings& settings,
                          std::pmr::memory_resource* memory) {
    SerialTaskRunner serial;
    TaskRunner& tasks = settings.tasks ? *settings.tasks : serial;
    MeshAnalysis analysis = scan_surface(mesh, memory, tasks);
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

    std::pmr::vector<std::uint32_t> welded(memory);
    if (settings.weld && (settings.check_topology || settings.list_shells)) {
        welded = weld_vertices(mesh, scan, settings.weld_tolerance, memory);
        analysis.used_vertex_count = distinct_vertices(welded, scan);
    }
    const std::uint32_t* vertex_ids = welded.empty() ? nullptr : welded.data();
    // The vertices joined along the edges by the topology check: the shells' sets.
    std::pmr::vector<std::uint32_t> vertex_sets(memory);
    // The shells as connected pieces, when they were not judged.
    auto finish = [&] {
        if (settings.list_shells && !analysis.shells)
            analysis.unjudged_shells =
                find_shells(mesh, scan, vertex_ids, std::move(vertex_sets), tasks, memory);
        return std::move(analysis);
    };
    if (settings.check_topology) {
        analysis.topology = analyse_topology(mesh, vertex_ids, tasks, memory, vertex_sets);
        if (stop()) return finish();
    }

    IntegrationSettings integration;
    integration.reference = scan.reference_point();
    integration.size = scan.diagonal();
    integration.check_planarity = settings.check_topology;
    integration.planarity_tolerance = settings.planarity_tolerance;
    analysis.integration = integrate_mesh(mesh, integration, tasks);
    if (stop()) return finish();

    // Shells are judged on a closed, oriented surface of planar faces whose
    // integrals fit in doubles: a surface refused whole for its volume (none,
    // or inside out) still has its shells judged, signed as they are found.
    const Defect defect = analysis.verdict.defect;
    if (analysis.topology &&
        analysis.topology->closed_and_oriented(settings.policy.accept_balanced_non_manifold) &&
        (defect == Defect::none || defect == Defect::inverted || defect == Defect::zero_volume)) {
        analysis.shells =
            survey_shells(mesh, scan, vertex_ids, std::move(vertex_sets), integration.reference,
                          analysis.verdict.outward, analysis.integration->integrals.volume,
                          analysis.integration->encloses_no_volume, tasks, memory);
        if (stop()) return finish();
    }
    if (settings.check_topology && settings.check_intersections && std::isfinite(scan.diagonal())) {
        const Shells* shells = analysis.shells ? &analysis.shells->shells : nullptr;
        analysis.overlaps = find_overlaps(mesh, vertex_ids, integration.reference, integration.size,
                                          shells, tasks, memory);
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
