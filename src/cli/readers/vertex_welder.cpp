#include "readers/vertex_welder.hpp"

#include <cstring>

#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

uint64_t bits_of(double value) {
    value += 0.0;  // -0 becomes +0: the same position
    uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// A 64-bit mix of the three bit patterns (splitmix64's finaliser).
uint64_t hash_of(uint64_t x, uint64_t y, uint64_t z) {
    uint64_t h = x * 0x9E3779B97F4A7C15ull ^ y * 0xC2B2AE3D27D4EB4Full ^ z * 0x165667B19E3779F9ull;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    return h;
}

}  // namespace

VertexWelder::VertexWelder(std::vector<double>& positions) : positions_(positions) {
    rebuild(1024);
}

uint32_t VertexWelder::index_of(double x, double y, double z) {
    const uint64_t bx = bits_of(x), by = bits_of(y), bz = bits_of(z);
    const size_t mask = slots_.size() - 1;
    for (size_t slot = hash_of(bx, by, bz) & mask;; slot = (slot + 1) & mask) {
        const uint32_t held = slots_[slot];
        if (held == 0) break;
        const double* p = &positions_[3 * size_t(held - 1)];
        if (bits_of(p[0]) == bx && bits_of(p[1]) == by && bits_of(p[2]) == bz) return held - 1;
    }
    const uint64_t next = positions_.size() / 3;
    if (next >= kIndexOutOfRange - 1) throw ReadError("more than 4294967293 distinct vertices");
    positions_.insert(positions_.end(), {x, y, z});
    // At most half full, so probes stay short.
    if (2 * (next + 1) > slots_.size()) {
        rebuild(2 * slots_.size());
    } else {
        size_t slot = hash_of(bx, by, bz) & mask;
        while (slots_[slot] != 0) slot = (slot + 1) & mask;
        slots_[slot] = static_cast<uint32_t>(next + 1);
    }
    return static_cast<uint32_t>(next);
}

void VertexWelder::rebuild(size_t slot_count) {
    while (2 * (positions_.size() / 3) > slot_count) slot_count *= 2;
    slots_.assign(slot_count, 0);
    const size_t mask = slots_.size() - 1;
    for (size_t vertex = 0; vertex < positions_.size() / 3; ++vertex) {
        const double* p = &positions_[3 * vertex];
        size_t slot = hash_of(bits_of(p[0]), bits_of(p[1]), bits_of(p[2])) & mask;
        while (slots_[slot] != 0) slot = (slot + 1) & mask;
        slots_[slot] = static_cast<uint32_t>(vertex + 1);
    }
}

}  // namespace polymass_cli
