// Gives vertices at exactly the same position one index, as a triangle soup
// (STL) needs before it has any topology. Only bit-identical coordinates are
// merged (-0 and +0 being the same), so the solid is unchanged; near-coincident
// vertices are the library's business (POLYMASS_OPTION_WELD_VERTICES with
// weld_tolerance).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace polymass_cli {

class VertexWelder {
public:
    explicit VertexWelder(std::vector<double>& positions);

    // The index of the vertex at (x, y, z) (the lowest, if positions already
    // held equal ones), appended to positions if new.
    uint32_t index_of(double x, double y, double z);

private:
    // Re-inserts every vertex into slot_count (a power of two) slots or more.
    void rebuild(size_t slot_count);

    std::vector<double>& positions_;
    // Open addressing with linear probing: each slot holds a vertex index + 1
    // (0 is empty). A million-triangle STL asks 3 million times; a node-based
    // map spent most of the reading time allocating.
    std::vector<uint32_t> slots_;
};

}  // namespace polymass_cli
