/* The public header must compile as strict C99 (-std=c99 -pedantic -Werror
 * -Wall -Wextra ...): no C11, no GNU extensions, no C++ in the C path. This
 * file is compiled, never linked or run. */
#include <polymass/polymass.h>

/* C99 has no _Static_assert: a negative array size fails the compile. */
#define C99_STATIC_ASSERT(name, condition) typedef char name[(condition) ? 1 : -1]

C99_STATIC_ASSERT(version_number_matches,
                  POLYMASS_VERSION_NUMBER == POLYMASS_VERSION_MAJOR * 10000 +
                                                 POLYMASS_VERSION_MINOR * 100 +
                                                 POLYMASS_VERSION_PATCH);
C99_STATIC_ASSERT(options_starts_with_size, offsetof(polymass_options, struct_size) == 0);
C99_STATIC_ASSERT(mesh_desc_starts_with_size, offsetof(polymass_mesh_desc, struct_size) == 0);
C99_STATIC_ASSERT(mass_desc_starts_with_size, offsetof(polymass_mass_desc, struct_size) == 0);
C99_STATIC_ASSERT(mass_properties_starts_with_size,
                  offsetof(polymass_mass_properties, struct_size) == 0);
C99_STATIC_ASSERT(diagnostics_starts_with_size, offsetof(polymass_diagnostics, struct_size) == 0);
C99_STATIC_ASSERT(polygon_properties_starts_with_size,
                  offsetof(polymass_polygon_properties, struct_size) == 0);

/* Every function is declared (the exact signatures are the ABI gate's job). */
void polymass_header_c99_uses(void);
void polymass_header_c99_uses(void) {
    polymass_context* context = 0;
    polymass_mesh* mesh = 0;
    polymass_mesh_desc desc = {0};
    polymass_mass_properties properties = {0};

    (void)polymass_version;
    (void)polymass_version_string;
    (void)polymass_status_string;
    (void)polymass_sizeof_allocator;
    (void)polymass_sizeof_options;
    (void)polymass_sizeof_mesh_desc;
    (void)polymass_sizeof_mass_desc;
    (void)polymass_sizeof_mass_properties;
    (void)polymass_sizeof_diagnostics;
    (void)polymass_sizeof_polygon_properties;
    (void)polymass_sizeof_shell;
    (void)polymass_mesh_shell_list;
    (void)polymass_context_create;
    (void)polymass_context_destroy;
    (void)polymass_context_set_options;
    (void)polymass_context_get_options;
    (void)polymass_context_message;
    (void)polymass_mesh_create;
    (void)polymass_mesh_destroy;
    (void)polymass_mesh_mass_properties;
    (void)polymass_mass_properties_compute;
    (void)polymass_mesh_check;
    (void)polymass_polygon_compute;
    (void)context;
    (void)mesh;
    (void)desc;
    (void)properties;

    /* Every macro is a constant expression of a sensible type. */
    static const int32_t statuses[] = {
        POLYMASS_OK,
        POLYMASS_ERROR_INVALID_ARGUMENT,
        POLYMASS_ERROR_OUT_OF_MEMORY,
        POLYMASS_ERROR_INTERNAL,
        POLYMASS_ERROR_NON_FINITE,
        POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
        POLYMASS_ERROR_FACE_TOO_SMALL,
        POLYMASS_ERROR_OPEN,
        POLYMASS_ERROR_NON_MANIFOLD,
        POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
        POLYMASS_ERROR_NON_PLANAR_FACE,
        POLYMASS_ERROR_INTERSECTING,
        POLYMASS_ERROR_INVERTED,
        POLYMASS_ERROR_ZERO_VOLUME,
        POLYMASS_ERROR_ZERO_AREA,
        POLYMASS_ERROR_OVERFLOW,
    };
    static const uint32_t flags[] = {
        POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS,
        POLYMASS_OPTION_ACCEPT_INVERTED,
        POLYMASS_OPTION_WELD_VERTICES,
        POLYMASS_OPTION_ACCEPT_NON_MANIFOLD,
        POLYMASS_OPTION_SKIP_INTERSECTION_CHECK,
        POLYMASS_WARNING_INVERTED,
        POLYMASS_WARNING_DEGENERATE_FACES,
        POLYMASS_WARNING_UNCHECKED,
        POLYMASS_WARNING_NON_MANIFOLD,
        POLYMASS_WARNING_TOUCHING_FACES,
        POLYMASS_SHELL_SOLID,
        POLYMASS_SHELL_CAVITY,
        POLYMASS_SHELL_INVERTED,
        POLYMASS_SHELL_OVERLAPPING,
        POLYMASS_SHELL_NO_VOLUME,
        POLYMASS_POSITION_FLOAT64,
        POLYMASS_POSITION_FLOAT32,
        POLYMASS_INDEX_UINT32,
        POLYMASS_INDEX_UINT16,
        POLYMASS_MASS_FROM_DENSITY,
        POLYMASS_MASS_FROM_TOTAL,
    };
    static const int32_t orientations[] = {POLYMASS_COUNTER_CLOCKWISE, POLYMASS_CLOCKWISE};
    static const double tolerance = POLYMASS_DEFAULT_PLANARITY_TOLERANCE;
    static const uint64_t none = POLYMASS_NONE;
    static const char version_text[] = POLYMASS_VERSION_STRING;

    polymass_allocator allocator = {0};
    polymass_options options = {0};

    (void)statuses;
    (void)flags;
    (void)orientations;
    (void)tolerance;
    (void)none;
    (void)version_text;
    options.struct_size = sizeof options;
    (void)allocator;
    (void)options;
}
