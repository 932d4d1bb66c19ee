// Size-prefixed structs: every public struct starts with struct_size, set by
// the caller to sizeof(the struct) as its header declared it. Any version the
// library knows (struct_versions.hpp) is accepted: inputs are read up to the
// caller's size, later fields keeping their defaults; outputs are written up
// to the caller's size and no further.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <type_traits>

#include "context.hpp"
#include "struct_versions.hpp"

namespace polymass::capi {

// True when `size` is the size of a version of Struct: where its last field
// ends, or that rounded up to the struct's alignment (what sizeof gives a
// caller when the version ends in padding), or the current sizeof.
template <class Struct>
constexpr bool is_known_size(uint32_t size) {
    static_assert(std::is_trivially_copyable_v<Struct>, "public structs are plain data");
    if (size == sizeof(Struct)) return true;
    for (const uint32_t end : StructVersions<Struct>::earlier) {
        const uint32_t padded = (end + alignof(Struct) - 1) / alignof(Struct) * alignof(Struct);
        if (size == end || size == padded) return true;
    }
    return false;
}

template <class Struct>
int32_t check_struct(polymass_context* context, const Struct* value, const char* name) {
    if (!value) return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
    if (!is_known_size<Struct>(value->struct_size))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "%s->struct_size is %u; this library (version %s) expects %u, or "
                             "the size of an earlier %d.x version of the struct",
                             name, unsigned(value->struct_size), POLYMASS_VERSION_STRING,
                             unsigned(sizeof(Struct)), POLYMASS_VERSION_MAJOR);
    return POLYMASS_OK;
}

// The caller's input struct (checked with check_struct) over `defaults`: the
// fields its version has come from it, the later ones keep their defaults.
// The result has the current struct_size.
template <class Struct>
Struct read_struct(const Struct& input, Struct defaults) {
    const uint32_t size = std::min<uint32_t>(input.struct_size, sizeof(Struct));
    std::memcpy(&defaults, &input, size);
    defaults.struct_size = sizeof(Struct);
    return defaults;
}

// Writes `value` to the caller's output struct (checked with check_struct),
// up to its struct_size, which stays as the caller set it.
template <class Struct>
void write_struct(Struct* output, const Struct& value) {
    const uint32_t size = std::min<uint32_t>(output->struct_size, sizeof(Struct));
    std::memcpy(reinterpret_cast<unsigned char*>(output) + sizeof(uint32_t),
                reinterpret_cast<const unsigned char*>(&value) + sizeof(uint32_t),
                size - sizeof(uint32_t));
}

// polymass_*_init: `defaults` written up to struct_size, which must be the
// size of a known version.
template <class Struct>
int32_t init_struct(Struct* output, uint32_t struct_size, Struct defaults) {
    if (!output || !is_known_size<Struct>(struct_size)) return POLYMASS_ERROR_INVALID_ARGUMENT;
    output->struct_size = struct_size;
    write_struct(output, defaults);
    return POLYMASS_OK;
}

// Output structs are only written when every value in them is a number.
template <class Values>
bool all_finite(const Values& values) {
    return std::all_of(std::begin(values), std::end(values),
                       [](double value) { return std::isfinite(value); });
}

}  // namespace polymass::capi
