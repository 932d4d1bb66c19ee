// Does the surface bound any region twice? Faces that cross each other, faces
// that only touch, and how shells lie inside one another.
//
// Candidate pairs come from a box tree over the surface's triangles, so a
// closed surface costs about as many triangle tests as each triangle has
// neighbours. Each candidate is decided with exact predicates
// (triangle_contact.hpp). Faces that share an edge meet there by
// construction and are not compared; faces that share one vertex are compared
// for crossing only.
//
// Nesting: when nothing crosses, the shells' surfaces are disjoint or touch,
// and each shell lies inside a whole number of the others. The winding number
// of the rest of the surface at a vertex of a shell says how many (counted
// with their orientation): it is counted exactly, as the signed crossings of a
// segment from that vertex to a point outside everything, with exact
// predicates; a segment that grazes an edge or a vertex, or starts on another
// shell, is replaced by another. Where shells touch, a shell may pass through
// another along its own edges, so each triangle touching another shell is
// also probed from a point inside it (symbolically perturbed), and a shell
// whose probes disagree is marked mixed. docs/validity.md has the reasoning.
#pragma once

#include <Eigen/Core>
#include <climits>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "findings.hpp"
#include "mesh_view.hpp"
#include "shells.hpp"
#include "task_runner.hpp"

namespace polymass::core {

// A winding number that could not be counted (every probe was degenerate).
inline constexpr int kUnknownWinding = INT_MIN;
// Windings that differ between pieces of one shell: the shell passes
// through another's surface (where the two touch) and bounds some region
// twice, or less than once.
inline constexpr int kMixedWinding = INT_MAX;

struct SurfaceOverlaps {
    PairFinding crossing;  // face pairs (low, high) that cross
    PairFinding touching;  // face pairs that meet without crossing (and share no vertex)
    // With shells and nothing crossing: for each shell, the winding number of
    // every other shell at a point of it (kUnknownWinding where it could not
    // be counted, kMixedWinding where it differs between points). Empty
    // otherwise.
    std::pmr::vector<int> winding_of_shell;

    explicit SurfaceOverlaps(std::pmr::memory_resource* memory) : winding_of_shell(memory) {}
};

// vertex_ids: welding (see weld_vertices), null meaning the index itself.
// reference, size: a point near the surface and its size (the scan's bounding
// box centre and diagonal). shells: null, or the
// surface's shells, whose windings are then counted. The search for meeting
// faces runs as tasks of `tasks`; the result is the same for every runner.
// Indices must be in range, coordinates finite, faces fewer than 2^32.
template <class Scalar, class Index>
SurfaceOverlaps find_overlaps(const MeshView<Scalar, Index>& mesh, const std::uint32_t* vertex_ids,
                              const Eigen::Vector3d& reference, double size, const Shells* shells,
                              TaskRunner& tasks, std::pmr::memory_resource* memory);

}  // namespace polymass::core
