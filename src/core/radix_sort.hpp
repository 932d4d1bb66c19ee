// Sorting of 64-bit keys in linear time (least significant digit first).
//
// The box tree of the intersection check (box_tree.cpp) sorts one Morton key
// per triangle; for meshes of millions of faces a comparison sort would
// dominate the whole check.
#pragma once

#include <cstdint>
#include <memory_resource>

namespace polymass::core {

// Sorts [first, last) ascending, with scratch memory from `memory`.
void radix_sort(std::uint64_t* first, std::uint64_t* last, std::pmr::memory_resource* memory);

}  // namespace polymass::core
