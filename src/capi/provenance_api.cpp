// polymass_mass_properties_with_provenance: the mass properties of the mode
// that answered, and what it did.
#include <polymass/polymass.h>

#include "api_guard.hpp"
#include "mass_properties.hpp"
#include "mesh.hpp"
#include "struct_io.hpp"

using namespace polymass::capi;

extern "C" {

POLYMASS_API uint32_t polymass_sizeof_provenance(void) { return sizeof(polymass_provenance); }

POLYMASS_API int32_t polymass_provenance_init(polymass_provenance* provenance,
                                              uint32_t struct_size) {
    return init_struct(provenance, struct_size, StructVersions<polymass_provenance>::defaults());
}

POLYMASS_API int32_t polymass_mass_properties_with_provenance(
    polymass_mass_properties* out_properties, polymass_provenance* out_provenance,
    polymass_context* context, const polymass_mesh_desc* desc, const polymass_mass_desc* mass,
    const polymass_options* options) {
    return guarded(context, [&] {
        if (const int32_t status = check_struct(context, out_properties, "out_properties"))
            return status;
        if (const int32_t status = check_struct(context, out_provenance, "out_provenance"))
            return status;
        polymass_options call;
        if (const int32_t status = call_options(context, options, call)) return status;
        polymass_mesh mesh{context->allocator, {}, {}, Eigen::Vector3d::Zero(), 0.0, 0, {}};
        polymass_provenance provenance;
        if (const int32_t status = build_answer(context, desc, call, mesh, provenance))
            return status;
        if (const int32_t status =
                mass_properties(out_properties, context, mesh, mass, &provenance))
            return status;
        write_struct(out_provenance, provenance);
        return POLYMASS_OK;
    });
}

}  // extern "C"
