/* Version, status strings, struct sizes and initialisers, the context, and
   the checks of the options a call is given. */
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void test_version_number_matches_header(void** state) {
    (void)state;
    assert_int_equal(polymass_version(), POLYMASS_VERSION_NUMBER);
    assert_int_equal(
        POLYMASS_VERSION_NUMBER,
        POLYMASS_VERSION_MAJOR * 10000 + POLYMASS_VERSION_MINOR * 100 + POLYMASS_VERSION_PATCH);
    assert_int_equal(polymass_version() / 10000, POLYMASS_VERSION_MAJOR);
}

static void test_version_string_matches_header(void** state) {
    char expected[64];
    (void)state;
    assert_non_null(polymass_version_string());
    assert_string_equal(polymass_version_string(), POLYMASS_VERSION_STRING);
    snprintf(expected, sizeof expected, "%d.%d.%d", POLYMASS_VERSION_MAJOR, POLYMASS_VERSION_MINOR,
             POLYMASS_VERSION_PATCH);
    assert_string_equal(polymass_version_string(), expected);
}

static void test_struct_sizes_match_c(void** state) {
    (void)state;
    assert_int_equal(polymass_sizeof_allocator(), sizeof(polymass_allocator));
    assert_int_equal(polymass_sizeof_options(), sizeof(polymass_options));
    assert_int_equal(polymass_sizeof_mesh_desc(), sizeof(polymass_mesh_desc));
    assert_int_equal(polymass_sizeof_mass_desc(), sizeof(polymass_mass_desc));
    assert_int_equal(polymass_sizeof_mass_properties(), sizeof(polymass_mass_properties));
    assert_int_equal(polymass_sizeof_diagnostics(), sizeof(polymass_diagnostics));
    assert_int_equal(polymass_sizeof_polygon_properties(), sizeof(polymass_polygon_properties));
    assert_int_equal(polymass_sizeof_batch_item(), sizeof(polymass_batch_item));
    assert_int_equal(polymass_sizeof_moments(), sizeof(polymass_moments));
    assert_int_equal(polymass_sizeof_shell(), sizeof(polymass_shell));
    assert_int_equal(polymass_sizeof_provenance(), sizeof(polymass_provenance));
}

/* Every location of an output struct is POLYMASS_NONE once initialised. */
static void check_locations_none(const uint64_t* locations, size_t count) {
    size_t i;
    for (i = 0; i < count; ++i) {
        assert_true(locations[i] == POLYMASS_NONE);
    }
}

/* Each initialiser writes its struct's defaults up to the size given, accepts
   only sizes of known versions, and agrees with its C macro. */
static void test_initialisers(void** state) {
    unsigned char buffer[4096];
    polymass_allocator allocator = POLYMASS_ALLOCATOR_INIT;
    polymass_options options = POLYMASS_OPTIONS_INIT;
    polymass_mesh_desc desc = POLYMASS_MESH_DESC_INIT;
    polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
    polymass_mass_properties properties = POLYMASS_MASS_PROPERTIES_INIT;
    polymass_diagnostics report = POLYMASS_DIAGNOSTICS_INIT;
    polymass_polygon_properties polygon = POLYMASS_POLYGON_PROPERTIES_INIT;
    polymass_shell shell = POLYMASS_SHELL_INIT;
    polymass_provenance provenance = POLYMASS_PROVENANCE_INIT;
    polymass_moments moments = POLYMASS_MOMENTS_INIT;
    polymass_batch_item item = POLYMASS_BATCH_ITEM_INIT;
    (void)state;
#define CHECK_INIT(init, value)                                                                    \
    do {                                                                                           \
        memset(buffer, 0xA5, sizeof buffer);                                                       \
        assert_int_equal(init((void*)buffer, sizeof(value)), POLYMASS_OK);                         \
        assert_memory_equal(buffer, &(value), sizeof(value));                                      \
        assert_int_equal(buffer[sizeof(value)], 0xA5); /* nothing written past the size */         \
        assert_int_equal(init((void*)buffer, sizeof(value) + 8), POLYMASS_ERROR_INVALID_ARGUMENT); \
        assert_int_equal(init((void*)buffer, 4), POLYMASS_ERROR_INVALID_ARGUMENT);                 \
        assert_int_equal(init(NULL, sizeof(value)), POLYMASS_ERROR_INVALID_ARGUMENT);              \
    } while (0)
    CHECK_INIT(polymass_allocator_init, allocator);
    CHECK_INIT(polymass_options_init, options);
    CHECK_INIT(polymass_mesh_desc_init, desc);
    CHECK_INIT(polymass_mass_desc_init, body);
    CHECK_INIT(polymass_mass_properties_init, properties);
    CHECK_INIT(polymass_polygon_properties_init, polygon);
    CHECK_INIT(polymass_shell_init, shell);
    CHECK_INIT(polymass_moments_init, moments);
    CHECK_INIT(polymass_batch_item_init, item);
#undef CHECK_INIT
    /* The locations of the reports are POLYMASS_NONE, the rest zero (the
       macros set only struct_size: the library writes the locations). */
    memset(&report, 0xA5, sizeof report);
    assert_int_equal(polymass_diagnostics_init(&report, sizeof report), POLYMASS_OK);
    assert_int_equal(report.struct_size, sizeof report);
    assert_int_equal(report.status, POLYMASS_OK);
    assert_int_equal(report.checks, 0);
    assert_int_equal(report.face_count, 0);
    assert_int_equal(report.open_edges, 0);
    check_locations_none(report.first_non_finite_vertices, POLYMASS_DIAGNOSTIC_LOCATIONS);
    check_locations_none(&report.first_open_edges[0][0], 2 * POLYMASS_DIAGNOSTIC_LOCATIONS);
    check_locations_none(&report.first_touching_face_pairs[0][0],
                         2 * POLYMASS_DIAGNOSTIC_LOCATIONS);
    assert_int_equal(polymass_diagnostics_init(&report, sizeof report + 8),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    memset(&provenance, 0xA5, sizeof provenance);
    assert_int_equal(polymass_provenance_init(&provenance, sizeof provenance), POLYMASS_OK);
    assert_int_equal(provenance.mode, POLYMASS_MODE_NONE);
    assert_int_equal(provenance.holes, 0);
    assert_true(provenance.hull_volume == 0.0);
    check_locations_none(provenance.first_reoriented_faces, POLYMASS_DIAGNOSTIC_LOCATIONS);
    check_locations_none(provenance.first_holes, POLYMASS_DIAGNOSTIC_LOCATIONS);
    check_locations_none(&provenance.first_split_edges[0][0], 2 * POLYMASS_DIAGNOSTIC_LOCATIONS);
    assert_int_equal(polymass_provenance_init(NULL, sizeof provenance),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_int_equal(body.struct_size, sizeof body);
    assert_int_equal(body.mass_mode, POLYMASS_MASS_FROM_DENSITY);
    assert_true(body.density == 1.0);
}

static void test_status_values_are_the_documented_ones(void** state) {
    (void)state;
    /* The ABI: explicit values, never reused. */
    assert_int_equal(POLYMASS_OK, 0);
    assert_int_equal(POLYMASS_ERROR_INVALID_ARGUMENT, 1);
    assert_int_equal(POLYMASS_ERROR_OUT_OF_MEMORY, 2);
    assert_int_equal(POLYMASS_ERROR_INTERNAL, 3);
    assert_int_equal(POLYMASS_ERROR_NON_FINITE, 10);
    assert_int_equal(POLYMASS_ERROR_INDEX_OUT_OF_RANGE, 11);
    assert_int_equal(POLYMASS_ERROR_FACE_TOO_SMALL, 12);
    assert_int_equal(POLYMASS_ERROR_OPEN, 20);
    assert_int_equal(POLYMASS_ERROR_NON_MANIFOLD, 21);
    assert_int_equal(POLYMASS_ERROR_INCONSISTENT_ORIENTATION, 22);
    assert_int_equal(POLYMASS_ERROR_NON_PLANAR_FACE, 23);
    assert_int_equal(POLYMASS_ERROR_INTERSECTING, 24);
    assert_int_equal(POLYMASS_ERROR_INVERTED, 30);
    assert_int_equal(POLYMASS_ERROR_ZERO_VOLUME, 31);
    assert_int_equal(POLYMASS_ERROR_ZERO_AREA, 32);
    assert_int_equal(POLYMASS_ERROR_OVERFLOW, 40);
}

/* Every status has its own name; an unknown code has the "unknown" one. */
static void test_status_strings_distinct_and_non_empty(void** state) {
    size_t i, j;
    const char* unknown = polymass_status_string(9999);
    (void)state;
    assert_non_null(unknown);
    assert_string_equal(unknown, "unknown status");
    assert_string_equal(polymass_status_string(-1), "unknown status");
    assert_string_equal(polymass_status_string(4), "unknown status");
    assert_string_equal(polymass_status_string(INT32_MIN), "unknown status");
    for (i = 0; i < pm_status_count; ++i) {
        const char* s = polymass_status_string(pm_all_statuses[i]);
        assert_non_null(s);
        assert_true(strlen(s) > 0);
        assert_string_not_equal(s, unknown);
        for (j = 0; j < i; ++j) {
            assert_string_not_equal(s, polymass_status_string(pm_all_statuses[j]));
        }
    }
}

/* A call's options are checked where they are given; NULL (or all zeros) is
   every check, SOLID alone. */
static void test_call_options_invalid(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh cube;
    polymass_mesh_desc desc;
    polymass_mass_properties p;
    polymass_options o = pm_options(0, 0.0);
    (void)state;
    pm_mesh_unit_cube(&cube, 1);
    desc = pm_mesh_desc(&cube);
    pm_props_init(&p);
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &desc, NULL, NULL));
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));

    o.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    o.struct_size = 0x7FFF0000u;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));
    o.struct_size = sizeof o;

    o.flags = 1u << 31; /* unknown flag */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));
    o.flags = 0;
    o.planarity_tolerance = -1e-3;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));
    o.planarity_tolerance = NAN;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

/* The context keeps the caller's threads (in [1, POLYMASS_MAX_THREADS]) and
   its last message; nothing else. */
static void test_context_threads(void** state) {
    polymass_context* ctx = pm_context_new();
    (void)state;
    assert_string_equal(polymass_context_message(ctx), "");
    PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, 1));
    PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, POLYMASS_MAX_THREADS));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_threads(ctx, 0));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_context_set_threads(ctx, POLYMASS_MAX_THREADS + 1));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_threads(NULL, 2));
    PM_ASSERT_OK(ctx, polymass_context_set_scratch_limit(ctx, 0));
    assert_string_equal(polymass_context_message(ctx), "");
    polymass_context_destroy(ctx);
}

static void test_context_create_and_destroy(void** state) {
    polymass_context* ctx = (polymass_context*)&ctx; /* garbage: must be overwritten */
    (void)state;
    assert_int_equal(polymass_context_create(NULL, NULL), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_int_equal(polymass_context_create(&ctx, NULL), POLYMASS_OK);
    assert_non_null(ctx);
    assert_ptr_not_equal(ctx, (polymass_context*)&ctx);
    polymass_context_destroy(ctx);
    polymass_context_destroy(NULL);
    polymass_mesh_destroy(NULL);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_number_matches_header),
        cmocka_unit_test(test_version_string_matches_header),
        cmocka_unit_test(test_struct_sizes_match_c),
        cmocka_unit_test(test_initialisers),
        cmocka_unit_test(test_status_values_are_the_documented_ones),
        cmocka_unit_test(test_status_strings_distinct_and_non_empty),
        cmocka_unit_test(test_call_options_invalid),
        cmocka_unit_test(test_context_threads),
        cmocka_unit_test(test_context_create_and_destroy),
    };
    return cmocka_run_group_tests_name("version", tests, NULL, NULL);
}
