#include "shells.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "face_blocks.hpp"
#include "mesh_scan.hpp"
#include "smallest_index_sets.hpp"

namespace polymass::core {
namespace {

// Joins each face's vertices (a triangle's loop unrolled: the root stays in a
// register).
template <class Scalar, class Index, class VertexId>
void join_faces(const MeshView<Scalar, Index>& mesh, const std::pmr::vector<std::size_t>& starts,
                VertexId&& id, const ConcurrentSmallestIndexSets& sets, TaskRunner& tasks) {
    tasks.run(starts.size(), [&](std::size_t block) {
        for_each_face_of_block(mesh, block, starts[block],
                               [&](std::size_t, std::size_t first, std::size_t size) {
                                   std::uint32_t root = id(first);
#pragma GCC unroll 4
                                   for (std::size_t i = 1; i < size; ++i)
                                       root = sets.join(root, id(first + i));
                               });
    });
}

// The roots among the identities the faces use: with welded positions
// numbered densely, every identity is used; without, the used vertices.
// scan.used ends with the vertices indices can reach.
std::size_t count_roots(const std::pmr::vector<std::uint32_t>& parent, const MeshScan& scan,
                        const VertexIdentities& identities) {
    if (identities.of_vertex) {
        std::size_t roots = 0;
        for (std::size_t identity = 0; identity < parent.size(); ++identity)
            roots += parent[identity] == identity;
        return roots;
    }
    const std::size_t reachable = std::min(parent.size(), 64 * scan.used.size());
    return count_used_with(scan, reachable,
                           [&](std::uint32_t vertex) { return parent[vertex] == vertex; });
}

}  // namespace

template <class Scalar, class Index>
Shells find_shells(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                   const VertexIdentities& identities, std::pmr::vector<std::uint32_t> vertex_sets,
                   TaskRunner& tasks, std::pmr::memory_resource* memory) {
    const std::uint32_t* const vertex_ids = identities.of_vertex;
    auto id = [&](std::size_t position) {
        const std::uint32_t vertex = mesh.indices[position];
        return vertex_ids ? vertex_ids[vertex] : vertex;
    };
    const std::pmr::vector<std::size_t> starts = face_block_starts(mesh, memory);
    std::pmr::vector<std::uint32_t> parent(std::move(vertex_sets), memory);
    const bool joined_by_topology = !parent.empty();
    if (!joined_by_topology) {
        parent.resize(identities.count_among(mesh.vertex_count));
        std::iota(parent.begin(), parent.end(), 0u);
    }
    const ConcurrentSmallestIndexSets sets(parent.data());
    if (!joined_by_topology) {
        // Without welding, no test per index for the identities.
        if (vertex_ids)
            join_faces(mesh, starts, id, sets, tasks);
        else
            join_faces(
                mesh, starts, [&](std::size_t position) { return mesh.indices[position]; }, sets,
                tasks);
    }
    Shells shells(memory);
    // Every set holds the identities of some faces' vertices, and its root is
    // one of them: the shells are as many as the roots among those
    // identities. One root (the common case) makes every face shell 0, with
    // no search per face.
    if (count_roots(parent, scan, identities) == 1) {
        shells.count = 1;
        shells.of_face.assign(mesh.face_count, 0u);
        return shells;
    }
    // Each face's root, then shells numbered as their first faces come.
    shells.of_face.resize(mesh.face_count);
    tasks.run(starts.size(), [&](std::size_t block) {
        for_each_face_of_block(mesh, block, starts[block],
                               [&](std::size_t face, std::size_t first, std::size_t) {
                                   shells.of_face[face] = sets.find(id(first));
                               });
    });
    constexpr std::uint32_t unnumbered = UINT32_MAX;
    std::pmr::vector<std::uint32_t> number_of_root(parent.size(), unnumbered, memory);
    for (std::uint32_t& shell : shells.of_face) {
        std::uint32_t& number = number_of_root[shell];
        if (number == unnumbered) number = std::uint32_t(shells.count++);
        shell = number;
    }
    return shells;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                       \
    template Shells find_shells<Scalar, Index>(                                   \
        const MeshView<Scalar, Index>&, const MeshScan&, const VertexIdentities&, \
        std::pmr::vector<std::uint32_t>, TaskRunner&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
