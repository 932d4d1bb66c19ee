// A position's identity bit for bit, for welding and for finding copies of a
// triangle: two positions are one when their coordinates have the same bits,
// +0 and -0 counting as one (they compare equal).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>

namespace polymass::core {

// The bits of a coordinate, +0 for -0.
inline std::uint64_t position_bits(double value) {
    value += 0.0;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// A 64-bit mix of a position's three bit patterns (splitmix64's finaliser).
inline std::uint64_t position_hash(const std::array<std::uint64_t, 3>& bits) {
    std::uint64_t h = bits[0] * 0x9E3779B97F4A7C15ull ^ bits[1] * 0xC2B2AE3D27D4EB4Full ^
                      bits[2] * 0x165667B19E3779F9ull;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    return h;
}

}  // namespace polymass::core
