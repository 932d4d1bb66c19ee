#include "shells.hpp"

#include <numeric>

#include "smallest_index_sets.hpp"

namespace polymass::core {

template <class Scalar, class Index>
Shells find_shells(const MeshView<Scalar, Index>& mesh, const std::uint32_t* vertex_ids,
                   std::pmr::memory_resource* memory) {
    auto id = [&](std::size_t position) {
        const std::uint32_t vertex = mesh.indices[position];
        return vertex_ids ? vertex_ids[vertex] : vertex;
    };
    std::pmr::vector<std::uint32_t> parent(mesh.vertex_count, memory);
    std::iota(parent.begin(), parent.end(), 0u);
    SmallestIndexSets sets(parent);
    for_each_face(mesh, [&](std::size_t, std::size_t first, std::size_t size) {
        for (std::size_t i = 1; i < size; ++i) sets.join(id(first), id(first + i));
    });
    // Shells numbered as their first faces come: a root's number, once met.
    constexpr std::uint32_t unnumbered = UINT32_MAX;
    std::pmr::vector<std::uint32_t> number_of_root(mesh.vertex_count, unnumbered, memory);
    Shells shells(memory);
    shells.of_face.reserve(mesh.face_count);
    for_each_face(mesh, [&](std::size_t, std::size_t first, std::size_t) {
        std::uint32_t& number = number_of_root[sets.find(id(first))];
        if (number == unnumbered) number = std::uint32_t(shells.count++);
        shells.of_face.push_back(number);
    });
    return shells;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                    \
    template Shells find_shells<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                               const std::uint32_t*, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
