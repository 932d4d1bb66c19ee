// Is the surface closed and consistently oriented?
//
// Every edge of a closed, consistently oriented surface is traversed once in
// each direction. Counting, for each undirected edge, how often it is
// traversed each way classifies it: once in all → open; twice the same way →
// misoriented; more than twice → non-manifold (balanced when both ways are
// equally frequent: two solids touching along an edge, whose integrals are
// still right).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "findings.hpp"
#include "instruction_sets.hpp"
#include "mesh_view.hpp"
#include "task_runner.hpp"
#include "vertex_identities.hpp"

namespace polymass::core {

// Edges are recorded in ascending order of their vertex pair, so the kept
// ones are the lowest.
struct EdgeFinding {
    std::size_t count = 0;
    // Vertex indices, each edge in its (most frequent) direction.
    std::array<std::array<std::uint32_t, 2>, kKeptLocations> lowest{};
    std::size_t first_traversals = 0;  // how many times faces traverse the first one

    std::size_t kept() const { return std::min(count, kKeptLocations); }
    const std::array<std::uint32_t, 2>& first() const { return lowest[0]; }  // when count > 0

    void record(std::uint32_t from, std::uint32_t to, std::size_t traversals) {
        if (count == 0) first_traversals = traversals;
        if (count < kKeptLocations) lowest[count] = {from, to};
        ++count;
    }
    // The findings of edges that all come after this one's.
    void append(const EdgeFinding& later) {
        if (count == 0) first_traversals = later.first_traversals;
        for (std::size_t i = 0; i < later.kept() && count + i < kKeptLocations; ++i)
            lowest[count + i] = later.lowest[i];
        count += later.count;
    }
};

struct TopologyReport {
    std::size_t edge_count = 0;  // distinct undirected edges
    EdgeFinding open;
    EdgeFinding misoriented;
    EdgeFinding non_manifold;
    bool non_manifold_balanced = true;  // every non-manifold edge as often each way

    bool closed_and_oriented(bool accept_balanced_non_manifold) const {
        const bool manifold_enough =
            non_manifold.count == 0 || (accept_balanced_non_manifold && non_manifold_balanced);
        return open.count == 0 && misoriented.count == 0 && manifold_enough;
    }
};

// Whether no two triangles of a surface can lie at the same three positions
// in the same order (copies, indexed_surface.hpp): every face a triangle,
// its vertices welded (equal positions one vertex), and every edge used
// exactly once each way. Two such triangles would be on the same three
// vertices and use each of their edges the same way.
inline bool copies_ruled_out(bool all_triangles, bool welded, const TopologyReport& topology) {
    return all_triangles && welded && topology.closed_and_oriented(false);
}

// identities: each vertex's for the check (vertex_identities.hpp: itself, or
// its welded position numbered densely); edges are named by the vertices
// identities.vertex gives. Indices must be in range. Edges whose two ends are
// the same identity (a repeated index) are no edges.
// The walk that classifies each edge also joins its two ends: vertex_sets
// gets one parent an identity (ConcurrentSmallestIndexSets,
// smallest_index_sets.hpp), every identity joined with those it shares an
// edge with - the sets of the shells (find_shells), with no second pass over
// the faces.
// The passes run in pieces on `tasks`; the report and the sets are the same
// for every runner.
template <class Scalar, class Index>
TopologyReport analyse_topology(const MeshView<Scalar, Index>& mesh,
                                const VertexIdentities& identities, TaskRunner& tasks,
                                std::pmr::memory_resource* memory,
                                std::pmr::vector<std::uint32_t>& vertex_sets,
                                InstructionSet set = widest_instruction_set());

}  // namespace polymass::core
