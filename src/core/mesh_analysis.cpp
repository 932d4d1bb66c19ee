#include "mesh_analysis.hpp"

#include "shells.hpp"
#include "welding.hpp"

namespace polymass::core {

template <class Scalar, class Index>
MeshAnalysis analyse_mesh(const MeshView<Scalar, Index>& mesh, const AnalysisSettings& settings,
                          std::pmr::memory_resource* memory) {
    SerialTaskRunner serial;
    TaskRunner& tasks = settings.tasks ? *settings.tasks : serial;
    MeshAnalysis analysis(scan_mesh(mesh, memory, tasks));
    const MeshScan& scan = analysis.scan;
    analysis.used_vertex_count = scan.used_vertex_count;
    // Judges what is known; true when the analysis should end here.
    auto stop = [&] {
        analysis.verdict = judge(analysis, settings.policy);
        return settings.stop_at_first_problem && !analysis.verdict.valid();
    };
    // Out-of-range indices cannot be read and non-finite coordinates poison
    // every sum: nothing after this is meaningful.
    if (scan.out_of_range_indices > 0 || scan.non_finite.count > 0) {
        stop();
        return analysis;
    }

    std::pmr::vector<std::uint32_t> welded(memory);
    if (settings.weld && (settings.check_topology || settings.list_shells)) {
        welded = weld_vertices(mesh, scan, settings.weld_tolerance, memory);
        analysis.used_vertex_count = distinct_vertices(welded, scan);
    }
    const std::uint32_t* vertex_ids = welded.empty() ? nullptr : welded.data();
    // The shells as connected pieces, when they were not judged.
    auto finish = [&] {
        if (settings.list_shells && !analysis.shells)
            analysis.unjudged_shells = find_shells(mesh, scan, vertex_ids, tasks, memory);
        return std::move(analysis);
    };
    if (settings.check_topology) {
        analysis.topology = analyse_topology(mesh, vertex_ids, tasks, memory);
        if (stop()) return finish();
    }

    IntegrationSettings integration;
    integration.reference = scan.reference_point();
    integration.size = scan.diagonal();
    integration.check_planarity = settings.check_topology;
    integration.planarity_tolerance = settings.planarity_tolerance;
    analysis.integration = integrate_mesh(mesh, integration, tasks);
    if (stop()) return finish();

    // Shells are judged on a closed, oriented surface with a volume.
    if (analysis.topology &&
        analysis.topology->closed_and_oriented(settings.policy.accept_balanced_non_manifold) &&
        analysis.verdict.valid()) {
        analysis.shells =
            survey_shells(mesh, scan, vertex_ids, integration.reference, analysis.verdict.outward,
                          analysis.integration->integrals.volume, tasks, memory);
        if (stop()) return finish();
    }
    if (settings.check_intersections && std::isfinite(scan.diagonal())) {
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

#define POLYMASS_INSTANTIATE(Scalar, Index)            \
    template MeshAnalysis analyse_mesh<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const AnalysisSettings&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
