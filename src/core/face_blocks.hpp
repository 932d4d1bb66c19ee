// A mesh's faces cut into blocks of a fixed number of faces, the pieces that
// passes over the faces hand to a TaskRunner (task_runner.hpp). The cut
// depends on the mesh alone, never on the number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory_resource>
#include <vector>

#include "mesh_view.hpp"
#include "task_runner.hpp"

namespace polymass::core {

inline constexpr std::size_t kFacesPerBlock = kItemsPerBlock;

// Where each block's first face starts in the index array.
template <class Scalar, class Index>
std::pmr::vector<std::size_t> face_block_starts(const MeshView<Scalar, Index>& mesh,
                                                std::pmr::memory_resource* memory) {
    const std::size_t blocks = block_count(mesh.face_count, kFacesPerBlock);
    std::pmr::vector<std::size_t> starts(blocks, memory);
    if (mesh.all_triangles()) {
        for (std::size_t block = 0; block < blocks; ++block)
            starts[block] = 3 * block * kFacesPerBlock;
        return starts;
    }
    std::size_t first = 0;
    for (std::size_t face = 0; face < mesh.face_count; ++face) {
        if (face % kFacesPerBlock == 0) starts[face / kFacesPerBlock] = first;
        first += mesh.face_sizes[face];
    }
    return starts;
}

// for_each_face (mesh_view.hpp) over one block, whose first face starts at
// position `first` of the index array.
template <class View, class Visit>
void for_each_face_of_block(const View& mesh, std::size_t block, std::size_t first, Visit&& visit) {
    const std::size_t first_face = block * kFacesPerBlock;
    const std::size_t last_face = std::min(mesh.face_count, first_face + kFacesPerBlock);
    if (mesh.all_triangles()) {
        // A separate loop, so that visit() is compiled for a constant size of 3.
        for (std::size_t face = first_face; face < last_face; ++face) visit(face, 3 * face, 3);
        return;
    }
    for (std::size_t face = first_face; face < last_face; ++face) {
        visit(face, first, std::size_t(mesh.face_sizes[face]));
        first += mesh.face_sizes[face];
    }
}

}  // namespace polymass::core
