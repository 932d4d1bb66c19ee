// The first look at a mesh: are its indices in range and the coordinates its
// faces use finite, and where does it lie. Everything later relies on this.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "findings.hpp"
#include "instruction_sets.hpp"
#include "mesh_view.hpp"
#include "task_runner.hpp"

namespace polymass::core {

struct MeshScan {
    std::size_t out_of_range_indices = 0;
    Finding out_of_range_faces;                  // faces with an index past the vertex array
    std::uint32_t first_out_of_range_index = 0;  // its value, in out_of_range_faces.first
    Finding non_finite;                          // used vertices with a NaN or infinite coordinate
    std::size_t used_vertex_count = 0;
    Eigen::AlignedBox3d bounds;            // of the used, finite vertices
    std::pmr::vector<std::uint64_t> used;  // bit v: vertex v is used by a face

    explicit MeshScan(std::pmr::memory_resource* memory) : used(memory) {}

    bool is_used(std::size_t vertex) const { return (used[vertex / 64] >> (vertex % 64)) & 1u; }
    // A point near every face: integrating about it keeps the digits of a mesh
    // far from the origin. Only vertices the faces use count.
    Eigen::Vector3d reference_point() const {
        return bounds.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                : Eigen::Vector3d(bounds.center());
    }
    // stableNorm: the square of a diagonal of 1e155 would overflow.
    double diagonal() const { return bounds.isEmpty() ? 0.0 : bounds.diagonal().stableNorm(); }
};

// Runs in fixed parts on `tasks`: the same scan whatever runs them, and
// whichever instruction set's kernels read the arrays (`set` must be one this
// processor runs; tests compare them all).
template <class Scalar, class Index>
MeshScan scan_mesh(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory,
                   TaskRunner& tasks, InstructionSet set = widest_instruction_set());

}  // namespace polymass::core
