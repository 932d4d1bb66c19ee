// Gives vertices at exactly the same position one index, as a triangle soup
// (STL) needs before it has any topology. Only bit-identical coordinates are
// merged (-0 and +0 being the same), so the solid is unchanged; near-coincident
// vertices are the library's business (POLYMASS_OPTION_WELD_VERTICES with
// weld_tolerance).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace polymass_cli {

class VertexWelder {
public:
    explicit VertexWelder(std::vector<double>& positions) : positions_(positions) {}

    // The index of the vertex at (x, y, z), appended to positions if new.
    uint32_t index_of(double x, double y, double z);

private:
    struct PositionHash {
        size_t operator()(const std::array<uint64_t, 3>& bits) const;
    };
    std::vector<double>& positions_;
    std::unordered_map<std::array<uint64_t, 3>, uint32_t, PositionHash> indices_;
};

}  // namespace polymass_cli
