// Everything the library learns about a mesh before it trusts it: the scan,
// welding, the topology check, the integration pass, the shells and (when
// asked) the intersection check, in that order, each run only when the ones
// before it leave the next one meaningful - and the verdict on all of it.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <optional>
#include <utility>

#include "mesh_integration.hpp"
#include "mesh_scan.hpp"
#include "mesh_view.hpp"
#include "shell_survey.hpp"
#include "surface_overlaps.hpp"
#include "task_runner.hpp"
#include "topology.hpp"
#include "verdict.hpp"

namespace polymass::core {

struct AnalysisSettings {
    bool check_topology = true;        // closed, manifold, oriented, planar, shells
    bool check_intersections = false;  // crossing faces, shells nested twice
    bool weld = false;                 // identify coincident vertices first
    double weld_tolerance = 0;         // relative to the mesh's extent; 0: exact
    bool stop_at_first_problem = true;
    // Lists the shells (welded as the topology is) even when they are not
    // judged: a surface that fails a check before them, or whose topology
    // is not checked. Faces that cannot be read have none.
    bool list_shells = false;
    double planarity_tolerance = 1e-6;
    Policy policy;
    // Runs the pieces of the passes over the faces; null: the calling thread.
    TaskRunner* tasks = nullptr;
};

struct MeshAnalysis {
    MeshScan scan;
    std::size_t used_vertex_count = 0;             // after welding
    std::optional<TopologyReport> topology;        // when checked
    std::optional<IntegrationResult> integration;  // about scan.reference_point()
    std::optional<ShellSurvey> shells;             // when checked and closed
    std::optional<Shells> unjudged_shells;         // when listed and not judged
    std::optional<SurfaceOverlaps> overlaps;       // when asked for
    Verdict verdict;

    explicit MeshAnalysis(MeshScan scanned) : scan(std::move(scanned)) {}
};

template <class Scalar, class Index>
MeshAnalysis analyse_mesh(const MeshView<Scalar, Index>& mesh, const AnalysisSettings& settings,
                          std::pmr::memory_resource* memory);

}  // namespace polymass::core
