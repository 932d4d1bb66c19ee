#include "vertex_welder.hpp"

#include <cstring>

#include "mesh_reader.hpp"

namespace polymass_cli {
namespace {

uint64_t bits_of(double value) {
    value += 0.0;  // -0 becomes +0: the same position
    uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

}  // namespace

size_t VertexWelder::PositionHash::operator()(const std::array<uint64_t, 3>& bits) const {
    // 64-bit mix of the three bit patterns (splitmix64's finaliser).
    uint64_t h = bits[0] * 0x9E3779B97F4A7C15ull ^ bits[1] * 0xC2B2AE3D27D4EB4Full ^
                 bits[2] * 0x165667B19E3779F9ull;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    return static_cast<size_t>(h);
}

uint32_t VertexWelder::index_of(double x, double y, double z) {
    const std::array<uint64_t, 3> key{bits_of(x), bits_of(y), bits_of(z)};
    const uint64_t next = positions_.size() / 3;
    if (next >= kIndexOutOfRange) throw ReadError("more than 4294967294 distinct vertices");
    const auto [where, inserted] = indices_.emplace(key, static_cast<uint32_t>(next));
    if (inserted) {
        positions_.push_back(x);
        positions_.push_back(y);
        positions_.push_back(z);
    }
    return where->second;
}

}  // namespace polymass_cli
