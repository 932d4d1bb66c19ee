// Repair: the fixes that have one right answer, each recorded, and bounds on
// what the fixes that are not exact may have changed (docs/repair.md).
//
// The surface is welded (exact positions always, the caller's tolerance when
// given) and turned into triangles: faces of fewer than three distinct
// vertices are dropped, a face and its duplicates kept once (a face and its
// reverse cancel: both dropped), non-planar polygons triangulated (the
// volume between their possible triangulations bounded), non-manifold edges
// used as often each way split into manifold pairs, every shell's faces
// turned to agree across its edges, each hole capped by triangles over its
// boundary loop (the volume between cap and missing
// surface bounded under the assumption docs/repair.md states), and each shell turned to enclose
// positive volume unless it lies inside an odd number of other shells (a
// cavity). The result is a list of triangles over the caller's positions
// and the caps' centres: the same verdict and integration as any surface
// judge it.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "approximation_bound.hpp"
#include "findings.hpp"
#include "mesh_scan.hpp"
#include "mesh_view.hpp"
#include "topology.hpp"

namespace polymass::core {

struct RepairSettings {
    double weld_tolerance = 0.0;  // relative, as for welding; exact positions are always welded
    double planarity_tolerance = 1e-6;
};

// Why a surface has no repair (the first problem met).
enum class RepairFailure {
    none,
    nothing_left,             // every face was dropped
    unbalanced_non_manifold,  // an edge used by more than two faces, unevenly each way
    non_orientable,           // a shell whose faces cannot agree (a Möbius strip)
};

struct RepairReport {
    Finding reoriented_faces;    // input faces turned to agree with their shell
    Finding turned_shells;       // shells turned inside out, located by their first input face
    Finding duplicate_faces;     // input faces dropped as copies of another (or its reverse)
    Finding degenerate_faces;    // input faces of fewer than three distinct vertices, dropped
    Finding triangulated_faces;  // non-planar input polygons
    EdgeFinding split_edges;     // non-manifold edges split into manifold pairs
    Finding holes;               // boundary loops capped, each located by its lowest vertex
    std::size_t cap_triangles = 0;
    double cap_area = 0.0;

    // The caps' share of the answered surface (of area surface_area, caps
    // included): 0 for a surface without area, which has no caps to weigh.
    double cap_area_fraction(double surface_area) const {
        return surface_area > 0.0 ? cap_area / surface_area : 0.0;
    }

    RepairFailure failure = RepairFailure::none;
    std::array<std::uint32_t, 2> failed_edge{};  // unbalanced_non_manifold
    std::size_t failed_forward = 0, failed_backward = 0;
    std::size_t failed_face = 0;  // non_orientable: an input face of that shell
};

struct RepairedMesh {
    // x, y, z of each vertex: the caller's (as doubles), then the caps' centres.
    std::pmr::vector<double> positions;
    // Vertex indices into `positions`, three per triangle, outward-oriented.
    std::pmr::vector<std::uint32_t> triangles;
    // Where the repaired surface may differ from the true one (caps, bent
    // polygons); empty when every fix was exact.
    std::pmr::vector<UncertainRegion> uncertain;
    Eigen::AlignedBox3d bounds;  // of the repaired surface
    RepairReport report;

    explicit RepairedMesh(std::pmr::memory_resource* memory)
        : positions(memory), triangles(memory), uncertain(memory) {}
};

// scan must say the mesh is in range and finite. Faces of any size are
// accepted (those of fewer than three vertices are dropped).
template <class Scalar, class Index>
RepairedMesh repair_mesh(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                         const RepairSettings& settings, std::pmr::memory_resource* memory);

}  // namespace polymass::core
