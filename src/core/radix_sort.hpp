// Sorting of 64-bit keys in linear time (least significant digit first).
//
// The box tree of the intersection check (box_tree.cpp) sorts one Morton key
// per triangle, and the search for copies of a triangle (indexed_surface.cpp)
// one hash; for meshes of millions of faces a comparison sort would
// dominate the whole check.
#pragma once

#include <cstdint>
#include <memory_resource>

namespace polymass::core {

// Sorts [first, last) ascending, with scratch memory from `memory`, for keys
// whose low 32 bits already ascend through [first, last) (a key above the
// index of its item, made in the items' order): they are sorted stably by
// their high 32 bits alone, which gives the order of a full sort in half the
// passes.
void radix_sort_high_half(std::uint64_t* first, std::uint64_t* last,
                          std::pmr::memory_resource* memory);

}  // namespace polymass::core
