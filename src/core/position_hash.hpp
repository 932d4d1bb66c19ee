// A position's identity bit for bit, for welding and for finding copies of a
// triangle: two positions are one when their coordinates have the same bits,
// +0 and -0 counting as one (they compare equal).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace polymass::core {

// The bits of a coordinate in its own precision (float or double), +0 for
// -0: adding zero makes -0 +0 and quiets a NaN, as the widening of a float
// to a double does, so two floats have equal bits exactly when their
// doubles do.
template <class Scalar>
auto position_bits(Scalar value) {
    static_assert(std::is_same_v<Scalar, float> || std::is_same_v<Scalar, double>);
    value += Scalar(0);
    std::conditional_t<std::is_same_v<Scalar, float>, std::uint32_t, std::uint64_t> bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// MurmurHash3's 64-bit finaliser: every input bit reaches every output bit.
inline std::uint64_t avalanche(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ull;
    h ^= h >> 33;
    return h;
}

// A 64-bit hash of a position's three bit patterns, each coordinate folded
// into the mix of those before it. A sum of each coordinate's product with a
// constant, mixed once afterwards, was not enough: flipping a sign flips only
// the top bit of its product, so a position and its turn by half a circle
// about an axis, (x, y, z) and (-x, -y, z), hashed alike. On a UV sphere's
// half million float32 positions only a quarter of the hashes' high halves
// were distinct, and the weld's probes visited 4.3 slots each (7.2 on a grid
// of integer points about the origin); now 1.5, as for a random hash
// (docs/validity.md).
inline std::uint64_t position_hash(const std::array<std::uint64_t, 3>& bits) {
    return avalanche(avalanche(avalanche(bits[0] ^ 0x9E3779B97F4A7C15ull) ^ bits[1]) ^ bits[2]);
}

}  // namespace polymass::core
