// The public header must compile as strict C++17 (-std=c++17 -pedantic -Werror
// -Wall -Wextra -Wold-style-cast ...), with C linkage for every function and
// structs a C++ caller can copy and zero-initialise. Every function's type is
// the one a 2.0 caller expects (a changed parameter fails the compile). This
// file is compiled, never linked or run.
#include <polymass/polymass.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>

static_assert(POLYMASS_VERSION_NUMBER == POLYMASS_VERSION_MAJOR * 10000 +
                                             POLYMASS_VERSION_MINOR * 100 + POLYMASS_VERSION_PATCH);
static_assert(POLYMASS_VERSION_MAJOR == 2);

namespace {

// A public struct: plain data that starts with its size.
template <typename Struct>
constexpr bool plain_and_size_prefixed() {
    return std::is_standard_layout_v<Struct> && std::is_trivially_copyable_v<Struct> &&
           std::is_same_v<decltype(Struct::struct_size), std::uint32_t> &&
           offsetof(Struct, struct_size) == 0;
}
static_assert(plain_and_size_prefixed<polymass_allocator>());
static_assert(plain_and_size_prefixed<polymass_options>());
static_assert(plain_and_size_prefixed<polymass_mesh_desc>());
static_assert(plain_and_size_prefixed<polymass_mass_desc>());
static_assert(plain_and_size_prefixed<polymass_mass_properties>());
static_assert(plain_and_size_prefixed<polymass_diagnostics>());
static_assert(plain_and_size_prefixed<polymass_shell>());
static_assert(plain_and_size_prefixed<polymass_provenance>());
static_assert(plain_and_size_prefixed<polymass_moments>());
static_assert(plain_and_size_prefixed<polymass_polygon_properties>());
static_assert(plain_and_size_prefixed<polymass_batch_item>());
static_assert(plain_and_size_prefixed<polymass_packed_meshes>());
static_assert(plain_and_size_prefixed<polymass_packed_results>());

template <typename Expected, typename Function>
constexpr bool has_type(Function*) {
    return std::is_same_v<Expected, Function>;
}
using std::int32_t;
using std::uint32_t;
using std::uint64_t;
using Context = polymass_context;
using Mesh = polymass_mesh;

static_assert(has_type<uint32_t()>(polymass_version));
static_assert(has_type<const char*()>(polymass_version_string));
static_assert(has_type<const char*(int32_t)>(polymass_status_string));
static_assert(has_type<uint32_t()>(polymass_sizeof_allocator));
static_assert(has_type<uint32_t()>(polymass_sizeof_options));
static_assert(has_type<uint32_t()>(polymass_sizeof_mesh_desc));
static_assert(has_type<uint32_t()>(polymass_sizeof_mass_desc));
static_assert(has_type<uint32_t()>(polymass_sizeof_mass_properties));
static_assert(has_type<uint32_t()>(polymass_sizeof_diagnostics));
static_assert(has_type<uint32_t()>(polymass_sizeof_shell));
static_assert(has_type<uint32_t()>(polymass_sizeof_provenance));
static_assert(has_type<uint32_t()>(polymass_sizeof_moments));
static_assert(has_type<uint32_t()>(polymass_sizeof_polygon_properties));
static_assert(has_type<uint32_t()>(polymass_sizeof_batch_item));
static_assert(has_type<uint32_t()>(polymass_sizeof_packed_meshes));
static_assert(has_type<uint32_t()>(polymass_sizeof_packed_results));
static_assert(has_type<int32_t(polymass_allocator*, uint32_t)>(polymass_allocator_init));
static_assert(has_type<int32_t(polymass_options*, uint32_t)>(polymass_options_init));
static_assert(has_type<int32_t(polymass_mesh_desc*, uint32_t)>(polymass_mesh_desc_init));
static_assert(has_type<int32_t(polymass_mass_desc*, uint32_t)>(polymass_mass_desc_init));
static_assert(
    has_type<int32_t(polymass_mass_properties*, uint32_t)>(polymass_mass_properties_init));
static_assert(has_type<int32_t(polymass_diagnostics*, uint32_t)>(polymass_diagnostics_init));
static_assert(has_type<int32_t(polymass_shell*, uint32_t)>(polymass_shell_init));
static_assert(has_type<int32_t(polymass_provenance*, uint32_t)>(polymass_provenance_init));
static_assert(has_type<int32_t(polymass_moments*, uint32_t)>(polymass_moments_init));
static_assert(
    has_type<int32_t(polymass_polygon_properties*, uint32_t)>(polymass_polygon_properties_init));
static_assert(has_type<int32_t(polymass_batch_item*, uint32_t)>(polymass_batch_item_init));
static_assert(has_type<int32_t(polymass_packed_meshes*, uint32_t)>(polymass_packed_meshes_init));
static_assert(has_type<int32_t(polymass_packed_results*, uint32_t)>(polymass_packed_results_init));
static_assert(has_type<int32_t(Context**, const polymass_allocator*)>(polymass_context_create));
static_assert(has_type<void(Context*)>(polymass_context_destroy));
static_assert(has_type<int32_t(Context*, uint32_t)>(polymass_context_set_threads));
static_assert(has_type<int32_t(Context*, uint64_t)>(polymass_context_set_scratch_limit));
static_assert(has_type<const char*(const Context*)>(polymass_context_message));
static_assert(has_type<int32_t(polymass_mass_properties*, polymass_provenance*, Context*,
                               const polymass_mesh_desc*, const polymass_options*,
                               const polymass_mass_desc*)>(polymass_mass_properties_compute));
static_assert(has_type<int32_t(Mesh**, Context*, const polymass_mesh_desc*,
                               const polymass_options*)>(polymass_mesh_create));
static_assert(has_type<void(Mesh*)>(polymass_mesh_destroy));
static_assert(has_type<int32_t(const Mesh*)>(polymass_mesh_status));
static_assert(has_type<const char*(const Mesh*)>(polymass_mesh_message));
static_assert(
    has_type<int32_t(polymass_diagnostics*, Context*, const Mesh*)>(polymass_mesh_diagnostics));
static_assert(has_type<int32_t(polymass_shell*, uint64_t, uint64_t*, Context*, const Mesh*)>(
    polymass_mesh_shells));
static_assert(
    has_type<int32_t(uint32_t*, uint64_t, Context*, const Mesh*)>(polymass_mesh_shell_of_face));
static_assert(
    has_type<int32_t(polymass_provenance*, Context*, const Mesh*)>(polymass_mesh_provenance));
static_assert(has_type<int32_t(polymass_moments*, Context*, const Mesh*)>(polymass_mesh_moments));
static_assert(has_type<int32_t(polymass_mass_properties*, Context*, const Mesh*,
                               const polymass_mass_desc*)>(polymass_mesh_mass_properties));
static_assert(has_type<int32_t(double*, const polymass_mass_properties*, const double*)>(
    polymass_inertia_about));
static_assert(
    has_type<int32_t(polymass_batch_item*, uint64_t, uint64_t*, Context*)>(polymass_batch_compute));
static_assert(has_type<int32_t(const polymass_packed_results*, uint64_t*, Context*,
                               const polymass_packed_meshes*, const polymass_options*)>(
    polymass_packed_compute));
static_assert(
    has_type<int32_t(polymass_moments*, Context*, const polymass_mesh_desc*, uint64_t, uint64_t,
                     const double*, const polymass_options*)>(polymass_moments_compute_faces));
static_assert(has_type<int32_t(polymass_moments*, Context*, const polymass_moments*,
                               const polymass_moments*)>(polymass_moments_add));
static_assert(has_type<int32_t(polymass_moments*, Context*, const polymass_moments*,
                               const polymass_moments*)>(polymass_moments_subtract));
static_assert(has_type<int32_t(polymass_moments*, Context*, const polymass_moments*, const double*,
                               const double*)>(polymass_moments_transform));
static_assert(has_type<int32_t(polymass_moments*, Context*, const polymass_moments*,
                               const double*)>(polymass_moments_scale));
static_assert(has_type<int32_t(polymass_moments*, Context*, const polymass_moments*,
                               const polymass_mass_desc*)>(polymass_moments_weight));
static_assert(has_type<int32_t(polymass_mass_properties*, Context*, const polymass_moments*,
                               const polymass_mass_desc*)>(polymass_moments_mass_properties));
static_assert(has_type<int32_t(polymass_polygon_properties*, Context*, const double*, uint64_t,
                               uint64_t)>(polymass_polygon_compute));
static_assert(has_type<int32_t(uint32_t*, uint64_t*, Context*, const void*, uint32_t, uint64_t,
                               uint64_t, double)>(polymass_weld_positions));

[[maybe_unused]] constexpr std::uint64_t none = POLYMASS_NONE;
[[maybe_unused]] constexpr std::int32_t clockwise = POLYMASS_CLOCKWISE;
[[maybe_unused]] constexpr std::uint32_t flags =
    POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_ACCEPT_INVERTED |
    POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD |
    POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
[[maybe_unused]] constexpr std::uint32_t warnings = POLYMASS_WARNING_INTERSECTIONS_UNCHECKED;
[[maybe_unused]] constexpr std::uint32_t counted_pairs = POLYMASS_MAX_COUNTED_FACE_PAIRS;
}  // namespace

// C linkage: a redeclaration must agree with the header's.
extern "C" uint32_t polymass_version(void);

// C++ before C++20 has no POLYMASS_*_INIT: value-initialised structs, sized.
int polymass_header_cxx17_uses();
int polymass_header_cxx17_uses() {
    polymass_mass_properties properties{};
    properties.struct_size = sizeof properties;
    polymass_options options{};
    options.struct_size = sizeof options;
    options.modes[0] = POLYMASS_MODE_SOLID;
    return static_cast<int>(properties.struct_size + options.struct_size);
}
