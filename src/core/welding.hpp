// Welding: vertices at the same position are one vertex.
//
// An STL file or any triangle soup repeats a vertex once per triangle; the
// surface is closed only once those copies are identified. By default only
// exact equality counts (+0 equals −0). CAD exports whose coordinates carry
// rounding noise need a tolerance: two vertices whose coordinates each differ
// by at most tolerance (at least 2^-50) × the largest extent of the used
// vertices' bounding box are one, and so are chains of such vertices. Welding
// only serves the topology checks: the integrals use the positions as given.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mesh_scan.hpp"
#include "mesh_view.hpp"
#include "task_runner.hpp"
#include "vertex_identities.hpp"

namespace polymass::core {

// For every vertex the faces use, the smallest used vertex index welded to it
// (unused vertices map to themselves), over the vertices the index type can
// reach (scan.used's bits; fewer than the mesh's when 16-bit indices meet
// more than 65,536 vertices). scan must say the mesh is in range, and
// finite when tolerance > 0 (an exact weld compares bits: copies of one NaN
// are one vertex); tolerance is relative, >= 0. Exact welding deals the
// positions into buckets by hash and hashes the buckets on `tasks`; within a
// tolerance, a sort by grid cell. The answer is the same whatever runs the tasks.
template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> weld_vertices(const MeshView<Scalar, Index>& mesh,
                                              const MeshScan& scan, double tolerance,
                                              TaskRunner& tasks, std::pmr::memory_resource* memory);

// The same weld, numbered (vertex_identities.hpp): each used vertex's
// position numbered 0 .. n - 1 in the order of its lowest vertex, and each
// number's lowest vertex. The exact weld numbers as it hashes (a pass fewer
// than numbering weld_vertices' answer); the same numbers whatever runs the
// tasks.
template <class Scalar, class Index>
NumberedVertices weld_and_number(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                                 double tolerance, TaskRunner& tasks,
                                 std::pmr::memory_resource* memory);

// scan_mesh (mesh_scan.hpp) and, into `numbered`, weld_and_number's exact
// weld (tolerance 0) of the same mesh when the scan finds every index in range
// and every used coordinate finite (else `numbered` is left empty). On one
// thread the weld follows the scan (ScanFollower): it hashes each stretch of
// vertices just after the scan has bounded it, while the positions are in
// cache, so that a soup too large for the caches is read from memory once
// rather than twice. On more, the scan runs in its parts and the weld in its
// shares after it. The same scan and numbers either way.
template <class Scalar, class Index>
MeshScan scan_and_weld_exact(const MeshView<Scalar, Index>& mesh, NumberedVertices& numbered,
                             TaskRunner& tasks, std::pmr::memory_resource* memory);

// weld_vertices' answer from weld_and_number's (the mesh `scan` scanned).
std::pmr::vector<std::uint32_t> lowest_welded_vertices(const NumberedVertices& numbered,
                                                       const MeshScan& scan,
                                                       std::pmr::memory_resource* memory);

// Welding a caller's positions alone, with no faces (polymass_weld_positions):
// every position is a vertex.
struct WeldedPositions {
    // The lowest index welded to each position; empty when the weld did not run.
    std::pmr::vector<std::uint32_t> vertex_of;
    std::size_t distinct = 0;  // positions that are their own lowest
    // Positions with a NaN or infinite coordinate: a weld within a tolerance
    // measures distances, which they have none of, so it does not run.
    Finding non_finite;

    explicit WeldedPositions(std::pmr::memory_resource* memory) : vertex_of(memory) {}
};

// count < 2^32; tolerance as weld_vertices'. The extent is that of the
// finite positions.
template <class Scalar>
WeldedPositions weld_positions(const PositionArray<Scalar>& positions, std::size_t count,
                               double tolerance, TaskRunner& tasks,
                               std::pmr::memory_resource* memory);

}  // namespace polymass::core
