#include "welding.hpp"

#include <algorithm>
#include <tuple>

namespace polymass::core {

template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> weld_vertices(const MeshView<Scalar, Index>& mesh,
                                              const MeshScan& scan,
                                              std::pmr::memory_resource* memory) {
    const std::size_t addressable = scan.used.size() * 64;
    std::pmr::vector<std::uint32_t> representative(std::min(mesh.vertex_count, addressable),
                                                   memory);
    std::pmr::vector<std::uint32_t> used(memory);
    used.reserve(scan.used_vertex_count);
    for (std::size_t vertex = 0; vertex < representative.size(); ++vertex) {
        representative[vertex] = std::uint32_t(vertex);
        if (scan.is_used(vertex)) used.push_back(std::uint32_t(vertex));
    }
    auto key = [&](std::uint32_t vertex) {
        const Eigen::Vector3d p = mesh.positions[vertex];
        return std::make_tuple(p.x(), p.y(), p.z());
    };
    // Sorting by position, then index, puts each group's smallest index first.
    std::sort(used.begin(), used.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::make_pair(key(a), a) < std::make_pair(key(b), b);
    });
    for (std::size_t i = 1; i < used.size(); ++i) {
        if (key(used[i]) == key(used[i - 1])) representative[used[i]] = representative[used[i - 1]];
    }
    return representative;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                \
    template std::pmr::vector<std::uint32_t> weld_vertices<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const MeshScan&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
