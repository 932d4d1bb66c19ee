// The public header must compile as strict C++17 (-std=c++17 -pedantic -Werror
// -Wall -Wextra -Wold-style-cast ...), with C linkage for every function. This
// file is compiled, never linked or run.
#include <polymass/polymass.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>

static_assert(POLYMASS_VERSION_NUMBER == POLYMASS_VERSION_MAJOR * 10000 +
                                             POLYMASS_VERSION_MINOR * 100 + POLYMASS_VERSION_PATCH);
static_assert(std::is_standard_layout_v<polymass_mesh_desc>);
static_assert(std::is_trivially_copyable_v<polymass_mass_properties>);
static_assert(offsetof(polymass_mass_properties, struct_size) == 0);
static_assert(std::is_same_v<decltype(polymass_version()), uint32_t>);

// C linkage: a redeclaration must agree with the header's.
extern "C" uint32_t polymass_version(void);

namespace {
[[maybe_unused]] constexpr std::uint64_t none = POLYMASS_NONE;
[[maybe_unused]] constexpr std::int32_t clockwise = POLYMASS_CLOCKWISE;
[[maybe_unused]] constexpr std::uint32_t flags =
    POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_ACCEPT_INVERTED |
    POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
}  // namespace

int polymass_header_cxx17_uses();
int polymass_header_cxx17_uses() {
    polymass_mass_properties properties{};
    properties.struct_size = sizeof properties;
    polymass_mesh_desc desc{};
    desc.struct_size = sizeof desc;
    return static_cast<int>(properties.struct_size + desc.struct_size);
}
