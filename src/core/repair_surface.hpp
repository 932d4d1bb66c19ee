// The surface repair works on (src/core/mesh_repair.*): triangles over welded
// vertex ids, each knowing the input face it came from, and the steps that
// share it - turning shells (repair_orientation.*) and capping holes
// (hole_caps.*).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "approximation_bound.hpp"
#include "mesh_repair.hpp"

namespace polymass::core {

// The face of a triangle that closes a hole: no input face.
inline constexpr std::uint32_t kCapFace = UINT32_MAX;

struct RepairTriangle {
    std::array<std::uint32_t, 3> corners;  // welded vertex ids
    std::uint32_t face;                    // the input face, or kCapFace
    bool turned = false;                   // reversed relative to the input face

    void turn() {
        std::swap(corners[1], corners[2]);
        turned = !turned;
    }
};

struct RepairSurface {
    // By vertex id (the ids the triangles use): the caller's, then caps' centres.
    std::pmr::vector<Eigen::Vector3d> points;
    std::pmr::vector<RepairTriangle> triangles;
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();  // near the surface, for volumes

    explicit RepairSurface(std::pmr::memory_resource* memory) : points(memory), triangles(memory) {}

    const Eigen::Vector3d& point(std::uint32_t id) const { return points[id]; }
};

// Two triangles sharing an edge of the surface (a manifold edge, or a pair
// split off a non-manifold one); same_direction: both traverse it the same
// way, so one of them must turn.
struct EdgeLink {
    std::uint32_t first, second;
    bool same_direction;
};

// A triangle edge no other triangle shares: part of a hole's rim.
struct RimEdge {
    std::uint32_t triangle;
    std::uint32_t a, b;  // its ends, in no particular order
};

// Records each face of `faces` once, in ascending order (faces is sorted).
inline void record_faces(std::pmr::vector<std::uint32_t>& faces, Finding& finding) {
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    for (std::uint32_t face : faces) finding.record(face);
}

// Turns triangles so that linked ones agree, and numbers the connected
// pieces in component (one entry per triangle). False, with report.failure
// set, when some piece cannot agree (a Möbius strip).
bool orient_pieces(RepairSurface& surface, const std::pmr::vector<EdgeLink>& links,
                   std::pmr::vector<std::uint32_t>& component, std::size_t& component_count,
                   RepairReport& report, std::pmr::memory_resource* memory);

// Closes each loop of rim edges with triangles (ears clipped from the loop,
// or from its centre, a point appended to the surface's points), appended to
// the surface, their component that of the rim, pieces a cap joins merged,
// recording the holes and the uncertain region each cap leaves.
void cap_holes(RepairSurface& surface, const std::pmr::vector<RimEdge>& rim,
               std::pmr::vector<std::uint32_t>& component, std::size_t& component_count,
               RepairReport& report, std::pmr::vector<UncertainRegion>& uncertain,
               std::pmr::memory_resource* memory);

// Turns each closed piece to enclose positive volume, or negative when it
// lies inside an odd number of other pieces (a cavity), and records which
// faces and pieces were turned relative to the input.
void turn_shells(RepairSurface& surface, const std::pmr::vector<std::uint32_t>& component,
                 std::size_t component_count, RepairReport& report,
                 std::pmr::memory_resource* memory);

}  // namespace polymass::core
