// Sorting of 64-bit keys in linear time (least significant digit first).
//
// The topology check sorts three keys per triangle; for meshes of millions of
// faces a comparison sort dominates the whole computation.
#pragma once

#include <cstdint>
#include <memory_resource>

namespace polymass::core {

// Sorts [first, last) ascending, with scratch memory from `memory`.
void radix_sort(std::uint64_t* first, std::uint64_t* last, std::pmr::memory_resource* memory);

}  // namespace polymass::core
