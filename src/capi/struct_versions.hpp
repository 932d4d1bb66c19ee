// The versions of every size-prefixed public struct, defined once.
//
// A caller sets struct_size to sizeof(the struct) as its header declared it.
// Fields are only ever appended, so each version of a struct is a prefix of
// the current one and is known by where its last field ends. The 1.0.0
// layout (commit fae181b) is the first version of every struct; a struct that
// grows lists the end of each later version here when it grows again (the
// current layout, sizeof, is always accepted without being listed). Nothing
// else needs to change: struct_io.hpp reads and writes any listed prefix.
#pragma once

#include <polymass/polymass.h>

#include <cstddef>
#include <cstdint>

namespace polymass::capi {

// Where `field` of `Struct` ends: the size of the version whose last field it is.
#define POLYMASS_FIELD_END(Struct, field) \
    static_cast<uint32_t>(offsetof(Struct, field) + sizeof(Struct::field))

// A struct of zeros but for its struct_size: the defaults of most structs.
template <class Struct>
Struct zeroed() {
    Struct value{};
    value.struct_size = sizeof(Struct);
    return value;
}

// Specialised for each size-prefixed struct: `ends`, the sizes of its earlier
// versions, oldest first (the first is the 1.0.0 baseline), and `defaults()`,
// the value fields take when the caller's version does not have them (and
// what polymass_*_init writes).
template <class Struct>
struct StructVersions;

template <>
struct StructVersions<polymass_options> {
    static constexpr uint32_t ends[] = {
        POLYMASS_FIELD_END(polymass_options, weld_tolerance),    // 1.0
        POLYMASS_FIELD_END(polymass_options, shell_thickness)};  // 1.2
    static polymass_options defaults() {
        return zeroed<polymass_options>();
    }  // 0: default tolerances
};

template <>
struct StructVersions<polymass_mesh_desc> {
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_mesh_desc, face_count)};
    static polymass_mesh_desc defaults() { return zeroed<polymass_mesh_desc>(); }
};

template <>
struct StructVersions<polymass_mass_desc> {
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_mass_desc, point)};
    static polymass_mass_desc defaults() {  // unit density, point at the origin
        polymass_mass_desc value = zeroed<polymass_mass_desc>();
        value.mass_mode = POLYMASS_MASS_FROM_DENSITY;
        value.density = 1.0;
        return value;
    }
};

template <>
struct StructVersions<polymass_mass_properties> {
    static constexpr uint32_t ends[] = {
        POLYMASS_FIELD_END(polymass_mass_properties, principal_axes)};
    static polymass_mass_properties defaults() { return zeroed<polymass_mass_properties>(); }
};

template <>
struct StructVersions<polymass_diagnostics> {
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_diagnostics, signed_volume)};
    static polymass_diagnostics defaults() { return zeroed<polymass_diagnostics>(); }
};

template <>
struct StructVersions<polymass_polygon_properties> {
    static constexpr uint32_t ends[] = {
        POLYMASS_FIELD_END(polymass_polygon_properties, principal_angle)};
    static polymass_polygon_properties defaults() { return zeroed<polymass_polygon_properties>(); }
};

template <>
struct StructVersions<polymass_moments> {  // new in the release after 1.0.0
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_moments, second_error_bound)};
    static polymass_moments defaults() { return zeroed<polymass_moments>(); }
};

template <>
struct StructVersions<polymass_batch_item> {  // new in the release after 1.0.0
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_batch_item, message)};
    static polymass_batch_item defaults() { return zeroed<polymass_batch_item>(); }
};

template <>
struct StructVersions<polymass_shell> {  // new in 1.1.0
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_shell, signed_volume)};
    static polymass_shell defaults() { return zeroed<polymass_shell>(); }
};

template <>
struct StructVersions<polymass_provenance> {  // new in 1.2.0
    static constexpr uint32_t ends[] = {POLYMASS_FIELD_END(polymass_provenance, hull_volume)};
    static polymass_provenance defaults() { return zeroed<polymass_provenance>(); }
};

}  // namespace polymass::capi
