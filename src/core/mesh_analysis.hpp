// Everything the library learns about a mesh before it trusts it: the scan,
// welding, the topology check, the integration pass, the shells and (when
// asked) the intersection check, judged in that order, each kept only when
// the ones before it leave the next one meaningful - and the verdict on all of
// it. (A mesh of triangles not welded is integrated with its scan, which the
// integration's reads finish: mesh_analysis.cpp.)
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
    // Every check by default, as the C API's defaults: skipping one is asked for by name.
    bool check_topology = true;       // closed, manifold, oriented, planar, shells
    bool check_intersections = true;  // crossing faces, shells nested twice (with the topology)
    bool weld = false;                // identify coincident vertices first
    double weld_tolerance = 0;        // relative to the mesh's extent; 0: exact
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
    Finding small_faces;  // faces of fewer than 3 vertices: not a solid's, unreadable
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

// The first look at a surface: the faces' sizes and the scan, judged. What
// every later step (the checks, the modes, a piece's moments) starts from.
template <class Scalar, class Index>
MeshAnalysis scan_surface(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory,
                          TaskRunner& tasks);

// The whole analysis, from scan_surface on, as far as the settings ask.
template <class Scalar, class Index>
MeshAnalysis analyse_mesh(const MeshView<Scalar, Index>& mesh, const AnalysisSettings& settings,
                          std::pmr::memory_resource* memory);

// A range of a surface's faces (a piece, integrated on its own about the
// caller's `reference`: polymass_moments_compute_faces) judged on what a
// piece can be judged on (judge_piece), with its integrals when its faces
// can be read. settings: check_topology (planarity with it), the tolerance,
// the tasks.
template <class Scalar, class Index>
MeshAnalysis analyse_piece(const MeshView<Scalar, Index>& mesh, const Eigen::Vector3d& reference,
                           const AnalysisSettings& settings, std::pmr::memory_resource* memory);

}  // namespace polymass::core
