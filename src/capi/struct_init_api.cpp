// polymass_*_init: each struct's defaults (struct_versions.hpp), written up to
// the caller's struct_size.
#include <polymass/polymass.h>

#include "struct_io.hpp"

using namespace polymass::capi;

namespace {

template <class Struct>
int32_t init(Struct* output, uint32_t struct_size) {
    return init_struct(output, struct_size, StructVersions<Struct>::defaults());
}

}  // namespace

extern "C" {

POLYMASS_API int32_t polymass_allocator_init(polymass_allocator* allocator, uint32_t struct_size) {
    return init(allocator, struct_size);
}
POLYMASS_API int32_t polymass_options_init(polymass_options* options, uint32_t struct_size) {
    return init(options, struct_size);
}
POLYMASS_API int32_t polymass_mesh_desc_init(polymass_mesh_desc* desc, uint32_t struct_size) {
    return init(desc, struct_size);
}
POLYMASS_API int32_t polymass_mass_desc_init(polymass_mass_desc* mass, uint32_t struct_size) {
    return init(mass, struct_size);
}
POLYMASS_API int32_t polymass_mass_properties_init(polymass_mass_properties* properties,
                                                   uint32_t struct_size) {
    return init(properties, struct_size);
}
POLYMASS_API int32_t polymass_diagnostics_init(polymass_diagnostics* diagnostics,
                                               uint32_t struct_size) {
    return init(diagnostics, struct_size);
}
POLYMASS_API int32_t polymass_shell_init(polymass_shell* shell, uint32_t struct_size) {
    return init(shell, struct_size);
}
POLYMASS_API int32_t polymass_provenance_init(polymass_provenance* provenance,
                                              uint32_t struct_size) {
    return init(provenance, struct_size);
}
POLYMASS_API int32_t polymass_moments_init(polymass_moments* moments, uint32_t struct_size) {
    return init(moments, struct_size);
}
POLYMASS_API int32_t polymass_polygon_properties_init(polymass_polygon_properties* properties,
                                                      uint32_t struct_size) {
    return init(properties, struct_size);
}
POLYMASS_API int32_t polymass_batch_item_init(polymass_batch_item* item, uint32_t struct_size) {
    return init(item, struct_size);
}

}  // extern "C"
