// Does the surface bound any region twice? Faces that cross each other, faces
// that only touch (surface_contacts.hpp), and, when nothing crosses, how
// shells lie inside one another (shell_nesting.hpp), both over one index of
// the surface's triangles (indexed_surface.hpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "findings.hpp"
#include "mesh_view.hpp"
#include "shell_nesting.hpp"
#include "shells.hpp"
#include "task_runner.hpp"

namespace polymass::core {

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
// surface's shells, whose windings are then counted. may_have_copies: false
// when copies are ruled out (copies_ruled_out, topology.hpp). The search for
// meeting faces runs as tasks of `tasks`; the result is the same for every
// runner. Indices must be in range, coordinates finite, faces fewer than 2^32.
template <class Scalar, class Index>
SurfaceOverlaps find_overlaps(const MeshView<Scalar, Index>& mesh, const std::uint32_t* vertex_ids,
                              const Eigen::Vector3d& reference, double size, const Shells* shells,
                              bool may_have_copies, TaskRunner& tasks,
                              std::pmr::memory_resource* memory);

}  // namespace polymass::core
