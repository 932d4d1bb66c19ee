// A triangle soup's corners (STL repeats a vertex once per triangle) given
// one index per position through the library's exact welding of positions
// (polymass_weld_positions): only bit-identical coordinates are one vertex
// (-0 and +0 being the same), so the solid is unchanged; near-coincident
// vertices are the library's business when it computes
// (POLYMASS_OPTION_WELD_VERTICES with weld_tolerance).
#pragma once

#include <cstdint>
#include <vector>

namespace polymass_cli {

// corners holds x, y, z of each of corner_count corners, one corner after
// another (float for a binary STL, double for text). Appends the distinct positions to positions
// (in the corners' precision) in the order they first appear and returns each
// corner's vertex index, a
// position's first corner naming it. Throws std::length_error past 2^32 - 1
// corners, std::bad_alloc when memory runs out.
template <class Scalar>
std::vector<uint32_t> weld_corners(const Scalar* corners, uint64_t corner_count,
                                   std::vector<Scalar>& positions);

}  // namespace polymass_cli
