// Little-endian numbers of the binary formats (binary STL, MuJoCo's .msh),
// read byte by byte, so that neither the host's byte order nor the
// alignment of the bytes matters.
#pragma once

#include <cstdint>
#include <cstring>

namespace polymass_cli {

inline uint32_t little_endian_u32(const unsigned char* bytes) {
    return static_cast<uint32_t>(bytes[0]) | static_cast<uint32_t>(bytes[1]) << 8 |
           static_cast<uint32_t>(bytes[2]) << 16 | static_cast<uint32_t>(bytes[3]) << 24;
}

inline int32_t little_endian_i32(const unsigned char* bytes) {
    const uint32_t bits = little_endian_u32(bytes);
    int32_t value = 0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

inline float little_endian_f32(const unsigned char* bytes) {
    const uint32_t bits = little_endian_u32(bytes);
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

}  // namespace polymass_cli
