// The shells of a mesh: its connected pieces of surface. Faces sharing a
// vertex are in one shell - after welding, when the options weld, so a
// triangle soup or a CAD export with noisy coordinates splits as its solid
// does.
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

struct Shells {
    std::size_t count = 0;
    std::pmr::vector<std::uint32_t> of_face;  // 0 .. count - 1, in the order of first faces

    explicit Shells(std::pmr::memory_resource* memory) : of_face(memory) {}
};

// identities: each vertex's (vertex_identities.hpp: itself, or its welded
// position numbered densely); `scan` is the mesh's (its used vertices).
// Indices must be in range; faces fewer than 2^32. vertex_sets: the
// identities already joined along the faces' edges
// (ConcurrentSmallestIndexSets' parents, one an identity: analyse_topology's),
// taken over; or empty, and the faces are joined here, in blocks on `tasks`.
// The numbering is the same for every runner.
template <class Scalar, class Index>
Shells find_shells(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                   const VertexIdentities& identities, std::pmr::vector<std::uint32_t> vertex_sets,
                   TaskRunner& tasks, std::pmr::memory_resource* memory);

}  // namespace polymass::core
