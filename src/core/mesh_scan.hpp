// The first look at a mesh: are its indices in range and the coordinates its
// faces use finite, and where does it lie. Everything later relies on this.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <optional>
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

// How many of the used vertices among the first `count` (< 2^32) have
// `property`, a test of a vertex's index. In a block of 64 vertices all used
// (most of a mesh's blocks) it is read for each with no branch and no bit
// test: about half the instructions of testing each vertex's bit first.
template <class Property>
std::size_t count_used_with(const MeshScan& scan, std::size_t count, Property&& property) {
    std::size_t found = 0;
    for (std::size_t block = 0; 64 * block < count; ++block) {
        const std::size_t first = 64 * block, last = std::min(count, first + 64);
        if (scan.used[block] == ~std::uint64_t{0} && last == first + 64) {
            std::uint32_t in_block = 0;
            const auto base = std::uint32_t(first);
            for (std::uint32_t i = 0; i < 64; ++i) in_block += std::uint32_t(property(base + i));
            found += in_block;
            continue;
        }
        for (std::size_t vertex = first; vertex < last; ++vertex)
            found += scan.is_used(vertex) && property(std::uint32_t(vertex));
    }
    return found;
}

// A pass that reads the positions right after the scan (the exact weld),
// told of each stretch of vertices as soon as the scan has bounded them and
// set their bits of scan.used: it reads their positions while they are still
// in the L1 cache, rather than the whole array again from memory once it has
// outgrown the caches (docs/validity.md, "Closed and oriented").
class ScanFollower {
public:
    // Vertices [first, last), in ascending stretches from 0; scan.used holds
    // their bits and those of every vertex before them (nothing else of the
    // scan is final yet).
    virtual void follow(const MeshScan& scan, std::size_t first, std::size_t last) = 0;

protected:
    ~ScanFollower() = default;
};

// Runs in fixed parts on `tasks`: the same scan whatever runs them, and
// whichever instruction set's kernels read the arrays (`set` must be one this
// processor runs; tests compare them all). With a follower, the pass over the
// vertices runs on the calling thread, a stretch of them at a time, each
// handed to the follower when bounded: still the same scan.
template <class Scalar, class Index>
MeshScan scan_mesh(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory,
                   TaskRunner& tasks, InstructionSet set = widest_instruction_set(),
                   ScanFollower* follower = nullptr);

// The same scan in pieces, for a pass over the faces that reads the index
// array anyway (the integration when nothing else needs the scan first): it
// marks the used vertices as it goes, about the bounds of every vertex, and
// the scan is finished from its marks. When every vertex is used (most
// meshes), the bounds of every vertex are those of the used ones, and the
// scan's own pass over the index array is saved.

// How many vertices indices can reach: the length of the marks.
template <class Scalar, class Index>
std::size_t addressable_vertices(const MeshView<Scalar, Index>& mesh);

// The bounds of every vertex, used or not, in fixed parts on `tasks`, with
// a zero's sign taken as scan_mesh takes it: when every index can reach every
// vertex, the positions are packed and every coordinate is finite; nullopt
// otherwise (scan_mesh then says what is wrong).
template <class Scalar, class Index>
std::optional<Eigen::AlignedBox3d> bound_every_vertex(
    const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory, TaskRunner& tasks,
    InstructionSet set = widest_instruction_set());

// scan_mesh from the marks of the whole index array, every index in range
// (addressable_vertices bytes), and bound_every_vertex: the same scan. With
// every vertex used, no pass over the positions.
template <class Scalar, class Index>
MeshScan scan_from_marks(const MeshView<Scalar, Index>& mesh,
                         const std::pmr::vector<unsigned char>& seen,
                         const Eigen::AlignedBox3d& every_vertex, std::pmr::memory_resource* memory,
                         TaskRunner& tasks, InstructionSet set = widest_instruction_set());

}  // namespace polymass::core
