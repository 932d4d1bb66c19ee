// The versions of every size-prefixed public struct, defined once.
//
// A caller sets struct_size to sizeof(the struct) as its header declared it.
// Fields are only ever appended, so each version of a struct is a prefix of
// the current one and is known by where its last field ends. The 2.0.0
// layout is the first version of every struct; a struct that grows lists
// the end of each earlier version in `earlier` when it grows (the current
// layout, sizeof, is always accepted without being listed). Nothing else
// needs to change: struct_io.hpp reads and writes any listed prefix.
#pragma once

#include <polymass/polymass.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace polymass::capi {

// A struct of zeros but for its struct_size: the defaults of most structs.
template <class Struct>
Struct zeroed() {
    Struct value{};
    value.struct_size = sizeof(Struct);
    return value;
}

// No version before the current one (the 2.0.0 layout).
using FirstVersion = std::array<uint32_t, 0>;

// Specialised for each size-prefixed struct: `earlier`, the sizes of its
// earlier versions, oldest first (none before 2.0.0), and `defaults()`, the
// value fields take when the caller's version does not have them (and what
// polymass_*_init writes).
template <class Struct>
struct StructVersions {
    static constexpr FirstVersion earlier{};
    static Struct defaults() { return zeroed<Struct>(); }
};

template <>
struct StructVersions<polymass_mass_desc> {
    static constexpr FirstVersion earlier{};
    static polymass_mass_desc defaults() {  // unit density
        polymass_mass_desc value = zeroed<polymass_mass_desc>();
        value.mass_mode = POLYMASS_MASS_FROM_DENSITY;
        value.density = 1.0;
        return value;
    }
};

// Output structs with locations: every location POLYMASS_NONE until a
// finding fills it.
template <>
struct StructVersions<polymass_diagnostics> {
    static constexpr FirstVersion earlier{};
    static polymass_diagnostics defaults();
};

template <>
struct StructVersions<polymass_provenance> {
    static constexpr FirstVersion earlier{};
    static polymass_provenance defaults();
};

}  // namespace polymass::capi
