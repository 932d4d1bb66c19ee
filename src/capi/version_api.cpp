// Version queries and struct sizes, for callers and bindings to check what
// they loaded against what they were built with.
#include <polymass/polymass.h>

extern "C" {

POLYMASS_API uint32_t polymass_version(void) { return POLYMASS_VERSION_NUMBER; }
POLYMASS_API const char* polymass_version_string(void) { return POLYMASS_VERSION_STRING; }

POLYMASS_API uint32_t polymass_sizeof_allocator(void) { return sizeof(polymass_allocator); }
POLYMASS_API uint32_t polymass_sizeof_options(void) { return sizeof(polymass_options); }
POLYMASS_API uint32_t polymass_sizeof_mesh_desc(void) { return sizeof(polymass_mesh_desc); }
POLYMASS_API uint32_t polymass_sizeof_mass_desc(void) { return sizeof(polymass_mass_desc); }
POLYMASS_API uint32_t polymass_sizeof_mass_properties(void) {
    return sizeof(polymass_mass_properties);
}
POLYMASS_API uint32_t polymass_sizeof_diagnostics(void) { return sizeof(polymass_diagnostics); }
POLYMASS_API uint32_t polymass_sizeof_shell(void) { return sizeof(polymass_shell); }
POLYMASS_API uint32_t polymass_sizeof_provenance(void) { return sizeof(polymass_provenance); }
POLYMASS_API uint32_t polymass_sizeof_moments(void) { return sizeof(polymass_moments); }
POLYMASS_API uint32_t polymass_sizeof_polygon_properties(void) {
    return sizeof(polymass_polygon_properties);
}
POLYMASS_API uint32_t polymass_sizeof_batch_item(void) { return sizeof(polymass_batch_item); }

}  // extern "C"
