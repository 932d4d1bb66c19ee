/* The public header must compile as strict C99 (-std=c99 -pedantic -Werror
 * -Wall -Wextra ...): no C11, no GNU extensions, no C++ in the C path. Every
 * function is taken through a pointer of the signature a 2.0 caller writes
 * (a changed parameter fails the compile), every struct is built with its
 * POLYMASS_*_INIT macro, every constant is used. This file is compiled, never
 * linked or run. */
#include <polymass/polymass.h>

/* C99 has no _Static_assert: a negative array size fails the compile. */
#define C99_STATIC_ASSERT(name, condition) typedef char name[(condition) ? 1 : -1]

C99_STATIC_ASSERT(version_number_matches,
                  POLYMASS_VERSION_NUMBER == POLYMASS_VERSION_MAJOR * 10000 +
                                                 POLYMASS_VERSION_MINOR * 100 +
                                                 POLYMASS_VERSION_PATCH);
C99_STATIC_ASSERT(version_is_2, POLYMASS_VERSION_MAJOR == 2);
C99_STATIC_ASSERT(allocator_starts_with_size, offsetof(polymass_allocator, struct_size) == 0);
C99_STATIC_ASSERT(options_starts_with_size, offsetof(polymass_options, struct_size) == 0);
C99_STATIC_ASSERT(mesh_desc_starts_with_size, offsetof(polymass_mesh_desc, struct_size) == 0);
C99_STATIC_ASSERT(mass_desc_starts_with_size, offsetof(polymass_mass_desc, struct_size) == 0);
C99_STATIC_ASSERT(mass_properties_starts_with_size,
                  offsetof(polymass_mass_properties, struct_size) == 0);
C99_STATIC_ASSERT(diagnostics_starts_with_size, offsetof(polymass_diagnostics, struct_size) == 0);
C99_STATIC_ASSERT(shell_starts_with_size, offsetof(polymass_shell, struct_size) == 0);
C99_STATIC_ASSERT(provenance_starts_with_size, offsetof(polymass_provenance, struct_size) == 0);
C99_STATIC_ASSERT(moments_starts_with_size, offsetof(polymass_moments, struct_size) == 0);
C99_STATIC_ASSERT(polygon_properties_starts_with_size,
                  offsetof(polymass_polygon_properties, struct_size) == 0);
C99_STATIC_ASSERT(batch_item_starts_with_size, offsetof(polymass_batch_item, struct_size) == 0);
C99_STATIC_ASSERT(packed_meshes_starts_with_size,
                  offsetof(polymass_packed_meshes, struct_size) == 0);
C99_STATIC_ASSERT(packed_results_starts_with_size,
                  offsetof(polymass_packed_results, struct_size) == 0);
C99_STATIC_ASSERT(modes_have_room,
                  sizeof(((polymass_options*)0)->modes) == POLYMASS_MAX_MODES * sizeof(uint32_t));
C99_STATIC_ASSERT(batch_message_size,
                  sizeof(((polymass_batch_item*)0)->message) == POLYMASS_BATCH_MESSAGE_SIZE);

/* Every function, with the signature a 2.0 caller compiles against. */
void polymass_header_c99_functions(void);
void polymass_header_c99_functions(void) {
    uint32_t (*version)(void) = polymass_version;
    const char* (*version_string)(void) = polymass_version_string;
    const char* (*status_string)(int32_t) = polymass_status_string;

    uint32_t (*sizes[])(void) = {
        polymass_sizeof_allocator,       polymass_sizeof_options,
        polymass_sizeof_mesh_desc,       polymass_sizeof_mass_desc,
        polymass_sizeof_mass_properties, polymass_sizeof_diagnostics,
        polymass_sizeof_shell,           polymass_sizeof_provenance,
        polymass_sizeof_moments,         polymass_sizeof_polygon_properties,
        polymass_sizeof_batch_item,      polymass_sizeof_packed_meshes,
        polymass_sizeof_packed_results,
    };
    int32_t (*allocator_init)(polymass_allocator*, uint32_t) = polymass_allocator_init;
    int32_t (*options_init)(polymass_options*, uint32_t) = polymass_options_init;
    int32_t (*mesh_desc_init)(polymass_mesh_desc*, uint32_t) = polymass_mesh_desc_init;
    int32_t (*mass_desc_init)(polymass_mass_desc*, uint32_t) = polymass_mass_desc_init;
    int32_t (*mass_properties_init)(polymass_mass_properties*, uint32_t) =
        polymass_mass_properties_init;
    int32_t (*diagnostics_init)(polymass_diagnostics*, uint32_t) = polymass_diagnostics_init;
    int32_t (*shell_init)(polymass_shell*, uint32_t) = polymass_shell_init;
    int32_t (*provenance_init)(polymass_provenance*, uint32_t) = polymass_provenance_init;
    int32_t (*moments_init)(polymass_moments*, uint32_t) = polymass_moments_init;
    int32_t (*polygon_properties_init)(polymass_polygon_properties*, uint32_t) =
        polymass_polygon_properties_init;
    int32_t (*batch_item_init)(polymass_batch_item*, uint32_t) = polymass_batch_item_init;
    int32_t (*packed_meshes_init)(polymass_packed_meshes*, uint32_t) = polymass_packed_meshes_init;
    int32_t (*packed_results_init)(polymass_packed_results*, uint32_t) =
        polymass_packed_results_init;

    int32_t (*context_create)(polymass_context**, const polymass_allocator*) =
        polymass_context_create;
    void (*context_destroy)(polymass_context*) = polymass_context_destroy;
    int32_t (*context_set_threads)(polymass_context*, uint32_t) = polymass_context_set_threads;
    int32_t (*context_set_scratch_limit)(polymass_context*, uint64_t) =
        polymass_context_set_scratch_limit;
    const char* (*context_message)(const polymass_context*) = polymass_context_message;

    int32_t (*mass_properties_compute)(polymass_mass_properties*, polymass_provenance*,
                                       polymass_context*, const polymass_mesh_desc*,
                                       const polymass_options*, const polymass_mass_desc*) =
        polymass_mass_properties_compute;

    int32_t (*mesh_create)(polymass_mesh**, polymass_context*, const polymass_mesh_desc*,
                           const polymass_options*) = polymass_mesh_create;
    void (*mesh_destroy)(polymass_mesh*) = polymass_mesh_destroy;
    int32_t (*mesh_status)(const polymass_mesh*) = polymass_mesh_status;
    const char* (*mesh_message)(const polymass_mesh*) = polymass_mesh_message;
    int32_t (*mesh_diagnostics)(polymass_diagnostics*, polymass_context*, const polymass_mesh*) =
        polymass_mesh_diagnostics;
    int32_t (*mesh_shells)(polymass_shell*, uint64_t, uint64_t*, polymass_context*,
                           const polymass_mesh*) = polymass_mesh_shells;
    int32_t (*mesh_shell_of_face)(uint32_t*, uint64_t, polymass_context*, const polymass_mesh*) =
        polymass_mesh_shell_of_face;
    int32_t (*mesh_provenance)(polymass_provenance*, polymass_context*, const polymass_mesh*) =
        polymass_mesh_provenance;
    int32_t (*mesh_moments)(polymass_moments*, polymass_context*, const polymass_mesh*) =
        polymass_mesh_moments;
    int32_t (*mesh_mass_properties)(polymass_mass_properties*, polymass_context*,
                                    const polymass_mesh*, const polymass_mass_desc*) =
        polymass_mesh_mass_properties;
    int32_t (*inertia_about)(double[9], const polymass_mass_properties*, const double[3]) =
        polymass_inertia_about;

    int32_t (*batch_compute)(polymass_batch_item*, uint64_t, uint64_t*, polymass_context*) =
        polymass_batch_compute;
    int32_t (*packed_compute)(const polymass_packed_results*, uint64_t*, polymass_context*,
                              const polymass_packed_meshes*, const polymass_options*) =
        polymass_packed_compute;

    int32_t (*moments_compute_faces)(polymass_moments*, polymass_context*,
                                     const polymass_mesh_desc*, uint64_t, uint64_t, const double[3],
                                     const polymass_options*) = polymass_moments_compute_faces;
    int32_t (*moments_add)(polymass_moments*, polymass_context*, const polymass_moments*,
                           const polymass_moments*) = polymass_moments_add;
    int32_t (*moments_subtract)(polymass_moments*, polymass_context*, const polymass_moments*,
                                const polymass_moments*) = polymass_moments_subtract;
    int32_t (*moments_transform)(polymass_moments*, polymass_context*, const polymass_moments*,
                                 const double[9], const double[3]) = polymass_moments_transform;
    int32_t (*moments_scale)(polymass_moments*, polymass_context*, const polymass_moments*,
                             const double[3]) = polymass_moments_scale;
    int32_t (*moments_weight)(polymass_moments*, polymass_context*, const polymass_moments*,
                              const polymass_mass_desc*) = polymass_moments_weight;
    int32_t (*moments_mass_properties)(polymass_mass_properties*, polymass_context*,
                                       const polymass_moments*, const polymass_mass_desc*) =
        polymass_moments_mass_properties;

    int32_t (*polygon_compute)(polymass_polygon_properties*, polymass_context*, const double*,
                               uint64_t, uint64_t) = polymass_polygon_compute;
    int32_t (*weld_positions)(uint32_t*, uint64_t*, polymass_context*, const void*, uint32_t,
                              uint64_t, uint64_t, double) = polymass_weld_positions;

    (void)version;
    (void)version_string;
    (void)status_string;
    (void)sizes;
    (void)allocator_init;
    (void)options_init;
    (void)mesh_desc_init;
    (void)mass_desc_init;
    (void)mass_properties_init;
    (void)diagnostics_init;
    (void)shell_init;
    (void)provenance_init;
    (void)moments_init;
    (void)polygon_properties_init;
    (void)batch_item_init;
    (void)packed_meshes_init;
    (void)packed_results_init;
    (void)context_create;
    (void)context_destroy;
    (void)context_set_threads;
    (void)context_set_scratch_limit;
    (void)context_message;
    (void)mass_properties_compute;
    (void)mesh_create;
    (void)mesh_destroy;
    (void)mesh_status;
    (void)mesh_message;
    (void)mesh_diagnostics;
    (void)mesh_shells;
    (void)mesh_shell_of_face;
    (void)mesh_provenance;
    (void)mesh_moments;
    (void)mesh_mass_properties;
    (void)inertia_about;
    (void)batch_compute;
    (void)packed_compute;
    (void)moments_compute_faces;
    (void)moments_add;
    (void)moments_subtract;
    (void)moments_transform;
    (void)moments_scale;
    (void)moments_weight;
    (void)moments_mass_properties;
    (void)polygon_compute;
    (void)weld_positions;
}

/* Every struct from its static initialiser, every constant a constant
   expression of a sensible type. */
void polymass_header_c99_values(void);
void polymass_header_c99_values(void) {
    polymass_allocator allocator = POLYMASS_ALLOCATOR_INIT;
    polymass_options options = POLYMASS_OPTIONS_INIT;
    polymass_mesh_desc desc = POLYMASS_MESH_DESC_INIT;
    polymass_mass_desc mass = POLYMASS_MASS_DESC_INIT;
    polymass_mass_properties properties = POLYMASS_MASS_PROPERTIES_INIT;
    polymass_diagnostics diagnostics = POLYMASS_DIAGNOSTICS_INIT;
    polymass_shell shell = POLYMASS_SHELL_INIT;
    polymass_provenance provenance = POLYMASS_PROVENANCE_INIT;
    polymass_moments moments = POLYMASS_MOMENTS_INIT;
    polymass_polygon_properties polygon = POLYMASS_POLYGON_PROPERTIES_INIT;
    polymass_batch_item item = POLYMASS_BATCH_ITEM_INIT;
    polymass_packed_meshes packed = POLYMASS_PACKED_MESHES_INIT;
    polymass_packed_results columns = POLYMASS_PACKED_RESULTS_INIT;
    polymass_context* context = 0;
    polymass_mesh* mesh = 0;

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
    static const uint32_t bits[] = {
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
        POLYMASS_WARNING_REPAIRED,
        POLYMASS_WARNING_SHELL,
        POLYMASS_WARNING_HULL,
        POLYMASS_WARNING_INTERSECTIONS_UNCHECKED,
        POLYMASS_CHECKED_TOPOLOGY,
        POLYMASS_CHECKED_SHELLS,
        POLYMASS_CHECKED_INTERSECTIONS,
        POLYMASS_MOMENTS_PARTIAL,
    };
    static const uint32_t enumerations[] = {
        POLYMASS_MODE_NONE,
        POLYMASS_MODE_SOLID,
        POLYMASS_MODE_REPAIR,
        POLYMASS_MODE_SHELL,
        POLYMASS_MODE_HULL,
        POLYMASS_POSITION_FLOAT64,
        POLYMASS_POSITION_FLOAT32,
        POLYMASS_INDEX_UINT32,
        POLYMASS_INDEX_UINT16,
        POLYMASS_MASS_FROM_DENSITY,
        POLYMASS_MASS_FROM_TOTAL,
        POLYMASS_INDICES_LOCAL,
        POLYMASS_INDICES_GLOBAL,
        POLYMASS_MAX_MODES,
        POLYMASS_MAX_THREADS,
        POLYMASS_DIAGNOSTIC_LOCATIONS,
        POLYMASS_MAX_COUNTED_FACE_PAIRS,
        POLYMASS_BATCH_MESSAGE_SIZE,
    };
    static const int32_t kinds[] = {
        POLYMASS_SHELL_UNJUDGED,    POLYMASS_SHELL_SOLID,       POLYMASS_SHELL_CAVITY,
        POLYMASS_SHELL_INVERTED,    POLYMASS_SHELL_OVERLAPPING, POLYMASS_SHELL_NO_VOLUME,
        POLYMASS_COUNTER_CLOCKWISE, POLYMASS_CLOCKWISE,
    };
    static const double tolerances[] = {POLYMASS_DEFAULT_PLANARITY_TOLERANCE,
                                        POLYMASS_MAX_WELD_TOLERANCE};
    static const uint64_t none = POLYMASS_NONE;
    static const char version_text[] = POLYMASS_VERSION_STRING;

    options.modes[0] = POLYMASS_MODE_SOLID;
    mass.density = 2700.0;
    item.desc = &desc;
    item.options = &options;
    item.mass = &mass;
    item.properties = &properties;
    item.provenance = &provenance;
    (void)allocator;
    (void)diagnostics;
    (void)shell;
    (void)moments;
    (void)polygon;
    (void)item;
    (void)packed;
    (void)columns;
    (void)context;
    (void)mesh;
    (void)statuses;
    (void)bits;
    (void)enumerations;
    (void)kinds;
    (void)tolerances;
    (void)none;
    (void)version_text;
}
