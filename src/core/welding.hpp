// Welding: vertices at exactly the same position are one vertex.
//
// An STL file or any triangle soup repeats a vertex once per triangle; the
// surface is closed only once those copies are identified. Only exact equality
// counts (a tolerance would change the solid), and +0 equals −0.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mesh_scan.hpp"
#include "mesh_view.hpp"

namespace polymass::core {

// For every vertex the faces use, the smallest used vertex index at the same
// position (unused vertices map to themselves). scan must say the mesh is in
// range and finite.
template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> weld_vertices(const MeshView<Scalar, Index>& mesh,
                                              const MeshScan& scan,
                                              std::pmr::memory_resource* memory);

}  // namespace polymass::core
