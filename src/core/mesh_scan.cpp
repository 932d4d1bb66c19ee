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
    // A byte per vertex, packed into scan.used afterwards: setting bits in
    // place would chain each face's read-modify-write of a word to the last
    // one's (neighbouring faces share vertices), a byte store waits for nothing.
    std::pmr::vector<unsigned char> seen(addressable, 0, memory);
    // The index array in one run, faces aside: they matter only to report an
    // index out of range, which is rare enough to look for again.
    // (Copies in locals: a byte store may alias anything, so what it could
    // overwrite would be read again after each.)
    const auto indices = mesh.indices;
    const std::size_t index_count = mesh.index_count, vertex_count = mesh.vertex_count;
    unsigned char* const seen_vertex = seen.data();
    bool all_in_range = true;
    for (std::size_t i = 0; i < index_count; ++i) {
        const std::size_t vertex = indices[i];
        if (vertex < vertex_count)
            seen_vertex[vertex] = 1;
        else
            all_in_range = false;
    }
    if (!all_in_range) {
        for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
            bool in_range = true;
            for (std::size_t i = first; i < first + size; ++i) {
                if (mesh.indices[i] < mesh.vertex_count) continue;
                if (scan.out_of_range_indices++ == 0)
                    scan.first_out_of_range_index = mesh.indices[i];
                in_range = false;
            }
            if (!in_range) scan.out_of_range_faces.record(face);
        });
    }

    scan.used.assign((addressable + 63) / 64, 0);
    // Locals rather than scan's members, which the stores into scan.used might alias.
    Eigen::Vector3d low = scan.bounds.min(), high = scan.bounds.max();
    std::size_t used_vertex_count = 0;
    for (std::size_t block = 0; block < scan.used.size(); ++block) {
        const std::size_t end = std::min(addressable, 64 * block + 64);
        std::uint64_t used = 0;
        for (std::size_t vertex = 64 * block; vertex < end; ++vertex) {
            if (!seen[vertex]) continue;
            used |= std::uint64_t{1} << (vertex % 64);
            ++used_vertex_count;
            const Eigen::Vector3d p = mesh.positions[vertex];
            // x − x is 0 for a finite x and NaN otherwise: one test for three coordinates.
            const double finite_if_zero = (p.x() - p.x()) + (p.y() - p.y()) + (p.z() - p.z());
            if (finite_if_zero != 0.0) {
                scan.non_finite.record(vertex);
                continue;
            }
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
        scan.used[block] = used;
    }
    scan.used_vertex_count = used_vertex_count;
    scan.bounds = Eigen::AlignedBox3d(low, high);
    return scan;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                    \
    template MeshScan scan_mesh<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                               std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
