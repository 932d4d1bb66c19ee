/* Version, status strings, struct sizes and the context's options. */
#include "test_support.h"

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
}

/* Each initialiser writes its struct's defaults up to the size given, accepts
   only sizes of known versions, and agrees with its C macro. */
static void test_initialisers(void** state) {
    unsigned char buffer[4096];
    polymass_options options = POLYMASS_OPTIONS_INIT;
    polymass_mesh_desc desc = POLYMASS_MESH_DESC_INIT;
    polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
    polymass_mass_properties properties = POLYMASS_MASS_PROPERTIES_INIT;
    polymass_diagnostics report = POLYMASS_DIAGNOSTICS_INIT;
    polymass_polygon_properties polygon = POLYMASS_POLYGON_PROPERTIES_INIT;
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
    CHECK_INIT(polymass_options_init, options);
    CHECK_INIT(polymass_mesh_desc_init, desc);
    CHECK_INIT(polymass_mass_desc_init, body);
    CHECK_INIT(polymass_mass_properties_init, properties);
    CHECK_INIT(polymass_diagnostics_init, report);
    CHECK_INIT(polymass_polygon_properties_init, polygon);
#undef CHECK_INIT
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

static void test_context_default_options(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_options o;
    (void)state;
    memset(&o, 0xAB, sizeof o);
    o.struct_size = sizeof o;
    PM_ASSERT_OK(ctx, polymass_context_get_options(&o, ctx));
    assert_int_equal(o.struct_size, sizeof o);
    assert_int_equal(o.flags, 0);
    assert_true(o.planarity_tolerance == POLYMASS_DEFAULT_PLANARITY_TOLERANCE);
    assert_true(o.weld_tolerance == 0.0);
    assert_string_equal(polymass_context_message(ctx), "");
    polymass_context_destroy(ctx);
}

static void test_context_options_round_trip(void** state) {
    polymass_context* ctx = pm_context_new(0);
    const polymass_options in =
        pm_options(POLYMASS_OPTION_ACCEPT_INVERTED | POLYMASS_OPTION_WELD_VERTICES, 1e-4);
    polymass_options out = pm_options(0, 0.0);
    (void)state;
    PM_ASSERT_OK(ctx, polymass_context_set_options(ctx, &in));
    PM_ASSERT_OK(ctx, polymass_context_get_options(&out, ctx));
    assert_int_equal(out.flags, in.flags);
    assert_true(out.planarity_tolerance == 1e-4);
    polymass_context_destroy(ctx);
}

static void test_context_options_invalid(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_options o = pm_options(0, 0.0), out;
    (void)state;

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(NULL, &o));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(ctx, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_get_options(NULL, ctx));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_get_options(&o, NULL));

    o.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(ctx, &o));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    o.struct_size = 0x7FFF0000u;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(ctx, &o));
    o.struct_size = sizeof o;

    o.flags = 1u << 31; /* unknown flag */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(ctx, &o));
    o.flags = 0;
    o.planarity_tolerance = -1e-3;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(ctx, &o));
    o.planarity_tolerance = NAN;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_set_options(ctx, &o));

    /* A rejected call leaves the options as they were. */
    out = pm_options(0, 0.0);
    PM_ASSERT_OK(ctx, polymass_context_get_options(&out, ctx));
    assert_int_equal(out.flags, 0);
    assert_true(out.planarity_tolerance == POLYMASS_DEFAULT_PLANARITY_TOLERANCE);

    out.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_context_get_options(&out, ctx));
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
        cmocka_unit_test(test_context_default_options),
        cmocka_unit_test(test_context_options_round_trip),
        cmocka_unit_test(test_context_options_invalid),
        cmocka_unit_test(test_context_create_and_destroy),
    };
    return cmocka_run_group_tests_name("version", tests, NULL, NULL);
}
