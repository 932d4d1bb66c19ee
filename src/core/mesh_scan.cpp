#include "mesh_scan.hpp"

#include <algorithm>
#include <limits>

namespace polymass::core {

template <class Scalar, class Index>
MeshScan scan_mesh(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory) {
    MeshScan scan(memory);
    // No index can reach past this, however long the caller says the array is.
    const std::size_t addressable = std::min<std::size_t>(
        mesh.vertex_count, std::size_t(std::numeric_limits<Index>::max()) + 1);
    scan.used.assign((addressable + 63) / 64, 0);
    for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
        bool in_range = true;
        for (std::size_t i = first; i < first + size; ++i) {
            const std::size_t vertex = mesh.indices[i];
            if (vertex >= mesh.vertex_count) {
                if (scan.out_of_range_indices++ == 0)
                    scan.first_out_of_range_index = mesh.indices[i];
                in_range = false;
                continue;
            }
            scan.used[vertex / 64] |= std::uint64_t{1} << (vertex % 64);
        }
        if (!in_range) scan.out_of_range_faces.record(face);
    });
    for (std::size_t vertex = 0; vertex < addressable; ++vertex) {
        if (!scan.is_used(vertex)) continue;
        ++scan.used_vertex_count;
        const Eigen::Vector3d p = mesh.positions[vertex];
        if (!p.allFinite()) {
            scan.non_finite.record(vertex);
            continue;
        }
        scan.bounds.extend(p);
    }
    return scan;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                    \
    template MeshScan scan_mesh<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                               std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
