// The identities the topology checks and the shells count vertices by. Without
// welding, a vertex index is its own identity. After welding (weld_and_number,
// welding.hpp), each position is numbered densely, 0 .. count - 1 in the
// order of its lowest vertex: the checks' per-identity arrays are then sized by the distinct
// positions, not by a soup's copies of them (a welded STL has six copies of
// each), and stay in cache as the soup grows. The numbering keeps the order
// of the lowest vertices, so ordered findings ("lowest first") and
// smallest-index sets are the same as with the lowest vertices themselves;
// reports name a position by its lowest vertex (lowest_vertex).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mesh_scan.hpp"

namespace polymass::core {

struct VertexIdentities {
    const std::uint32_t* of_vertex = nullptr;      // null: each vertex is its own identity
    const std::uint32_t* lowest_vertex = nullptr;  // of each identity, with of_vertex
    std::size_t count = 0;                         // identities, with of_vertex

    // How many identities a mesh of `vertex_count` vertices has: every index
    // below it may be one when there is no weld.
    std::size_t count_among(std::size_t vertex_count) const {
        return of_vertex ? count : vertex_count;
    }
    // The vertex a report names for an identity.
    std::uint32_t vertex(std::uint32_t identity) const {
        return of_vertex ? lowest_vertex[identity] : identity;
    }
};

// Welded vertices numbered densely, with the storage the identities point into.
struct NumberedVertices {
    std::pmr::vector<std::uint32_t> of_vertex;      // unused vertices: none read
    std::pmr::vector<std::uint32_t> lowest_vertex;  // one a distinct used position

    explicit NumberedVertices(std::pmr::memory_resource* memory)
        : of_vertex(memory), lowest_vertex(memory) {}
    VertexIdentities identities() const {
        return {of_vertex.data(), lowest_vertex.data(), lowest_vertex.size()};
    }
};

// The numbering of a weld given as each vertex's lowest welded vertex (the
// weld within a tolerance; the exact weld numbers as it hashes). welded:
// weld_vertices' answer for the mesh `scan` scanned; distinct: how many
// positions it leaves (the one block of identities is taken at its size, not
// grown - a context keeps a handful of freed blocks for its next call,
// capi/scratch_memory.hpp). One pass in vertex order: a vertex's lowest welded
// vertex is never above it, so it is numbered first.
inline NumberedVertices number_welded_vertices(const std::pmr::vector<std::uint32_t>& welded,
                                               const MeshScan& scan, std::size_t distinct,
                                               std::pmr::memory_resource* memory) {
    NumberedVertices numbered(memory);
    numbered.of_vertex.resize(welded.size());
    numbered.lowest_vertex.resize(distinct);
    std::uint32_t count = 0;
    for (std::size_t vertex = 0; vertex < welded.size(); ++vertex) {
        if (!scan.is_used(vertex)) continue;
        const std::uint32_t lowest = welded[vertex];
        if (lowest == vertex) {
            numbered.lowest_vertex[count] = lowest;
            numbered.of_vertex[vertex] = count++;
        } else {
            numbered.of_vertex[vertex] = numbered.of_vertex[lowest];
        }
    }
    return numbered;
}

}  // namespace polymass::core
