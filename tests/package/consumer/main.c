/* The packaging tests' consumer: the version, and the volume of a unit cube. */
#include <polymass/polymass.h>
#include <stdio.h>

int main(void) {
    /* The unit cube [0, 1]^3: 8 corners, 6 quads counter-clockwise from outside. */
    static const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    static const uint32_t quads[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                       1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    static const uint32_t sizes[6] = {4, 4, 4, 4, 4, 4};
    polymass_context* context = NULL;
    polymass_mesh_desc desc = POLYMASS_MESH_DESC_INIT;
    polymass_mass_properties properties = POLYMASS_MASS_PROPERTIES_INIT;
    int32_t status;

    if (polymass_version() / 10000 != POLYMASS_VERSION_MAJOR) {
        fprintf(stderr, "library %s, header %s\n", polymass_version_string(),
                POLYMASS_VERSION_STRING);
        return 1;
    }
    printf("polymass %s\n", polymass_version_string());

    status = polymass_context_create(&context, NULL);
    if (status != POLYMASS_OK) {
        fprintf(stderr, "context: %s\n", polymass_status_string(status));
        return 1;
    }
    desc.position_type = POLYMASS_POSITION_FLOAT64;
    desc.positions = corners;
    desc.vertex_count = 8;
    desc.index_type = POLYMASS_INDEX_UINT32;
    desc.indices = quads;
    desc.index_count = 24;
    desc.face_sizes = sizes;
    desc.face_count = 6;
    /* No provenance, default options (every check), unit density. */
    status = polymass_mass_properties_compute(&properties, NULL, context, &desc, NULL, NULL);
    if (status != POLYMASS_OK) {
        fprintf(stderr, "compute: %s: %s\n", polymass_status_string(status),
                polymass_context_message(context));
        polymass_context_destroy(context);
        return 1;
    }
    polymass_context_destroy(context);
    if (properties.volume - 1.0 > 1e-12 || properties.volume - 1.0 < -1e-12) {
        fprintf(stderr, "volume %.17g, expected 1\n", properties.volume);
        return 1;
    }
    printf("volume 1\n");
    return 0;
}
