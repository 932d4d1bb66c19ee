/* Moments that compose (polymass_moments_*) and options given per call.
 *   - two disjoint parts added equal the mesh holding both, to 1e-15 relative;
 *   - moved (rotated, mirrored, translated to 1e6 and 1e8) moments equal the
 *     moved mesh's and the exact values moved the same way;
 *   - per-axis scale, a bore subtracted from a block, densities and masses of
 *     an assembly, face ranges added up, against exact values. */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Agreement of two computations of the same quantity by different paths. */
#define SUM_TOL 1e-15

static polymass_moments moments_of(polymass_context* ctx, const pm_mesh* m) {
    polymass_moments out;
    polymass_mesh_desc desc = pm_mesh_desc(m);
    assert_int_equal(polymass_moments_init(&out, sizeof out), POLYMASS_OK);
    PM_ASSERT_OK(ctx, pm_moments(&out, ctx, &desc, NULL));
    return out;
}

/* A mirrored mesh is inverted; accepted, it is turned the right way. */
static const uint32_t accept_inverted = POLYMASS_OPTION_ACCEPT_INVERTED;

static polymass_mass_properties properties_of(polymass_context* ctx, const polymass_moments* m,
                                              const polymass_mass_desc* mass) {
    polymass_mass_properties p;
    pm_props_init(&p);
    PM_ASSERT_OK(ctx, polymass_moments_mass_properties(&p, ctx, m, mass));
    assert_true(isnan(p.surface_area));
    return p;
}

/* The same properties by two paths: volume, mass, centre (to the size),
   inertia (off-diagonal to the largest entry), all to tol. */
static void assert_same_body(const char* what, const polymass_mass_properties* expected,
                             const polymass_mass_properties* got, double size, double tol) {
    int i;
    PM_ASSERT_REL(what, expected->volume, got->volume, tol);
    PM_ASSERT_REL(what, expected->mass, got->mass, tol);
    for (i = 0; i < 3; ++i)
        PM_ASSERT_ABS(what, expected->center_of_mass[i], got->center_of_mass[i],
                      tol * size + 2 * DBL_EPSILON * fabs(expected->center_of_mass[i]));
    PM_ASSERT_TENSOR(what, expected->inertia, got->inertia, tol);
}

static void without_area(pm_expected* e) { e->surface_area = NAN; }

/* Each reference solid beside a second copy moved clear of it. */
static void test_disjoint_parts_add_up(void** state) {
    polymass_context* ctx = pm_context_new();
    static const double offsets[][3] = {{8, 0.5, -0.25}, {1e6, 0, 0}, {1e8, -1e8, 0}};
    int k;
    size_t o;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        const pm_reference_solid* ref = &pm_reference_solids[k];
        for (o = 0; o < sizeof offsets / sizeof offsets[0]; ++o) {
            pm_mesh a, b, both;
            polymass_moments ma, mb, sum = POLYMASS_MOMENTS_INIT;
            polymass_mass_properties from_sum, from_mesh;
            char label[200];
            pm_mesh_from_reference(&a, ref);
            pm_mesh_copy(&b, &a);
            pm_mesh_transform(&b, NULL, 1.0, offsets[o]);
            pm_mesh_copy(&both, &a);
            pm_mesh_append(&both, &b);
            ma = moments_of(ctx, &a);
            mb = moments_of(ctx, &b);
            PM_ASSERT_OK(ctx, polymass_moments_add(&sum, ctx, &ma, &mb));
            from_sum = properties_of(ctx, &sum, NULL);
            PM_ASSERT_OK(ctx, pm_compute(&from_mesh, ctx, &both, NULL));
            snprintf(label, sizeof label, "%s + copy at (%g, %g, %g)", ref->name, offsets[o][0],
                     offsets[o][1], offsets[o][2]);
            {
                const pm_expected e0 = pm_expected_from_reference(ref);
                const pm_expected e1 = pm_expected_transform(&e0, NULL, 1.0, offsets[o]);
                pm_expected e = pm_expected_sum(&e0, &e1);
                e.size = pm_mesh_size(&both);
                without_area(&e);
                PM_ASSERT_PROPERTIES(label, &e, &from_sum, SUM_TOL);
            }
            /* The sum is within 1e-15 of the exact moments of the mesh
               holding both; integrating that mesh directly, about one point
               between the parts, is not as close (5e-15 here, 7e-10 relative
               for parts 1e8 apart, whose faces' terms cancel): it is checked
               at the library's usual tolerance, near the origin. */
            if (o == 0) assert_same_body(label, &from_mesh, &from_sum, pm_mesh_size(&both), PM_TOL);
            pm_mesh_free(&a);
            pm_mesh_free(&b);
            pm_mesh_free(&both);
        }
    }
    polymass_context_destroy(ctx);
}

/* Same result whatever the grouping (to rounding), and the same bits for the
   same grouping and order. */
static void test_sum_associative_and_deterministic(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_moments parts[3], left = POLYMASS_MOMENTS_INIT, right = POLYMASS_MOMENTS_INIT,
                               again = POLYMASS_MOMENTS_INIT;
    polymass_mass_properties p_left, p_right;
    static const double at[3][3] = {{0, 0, 0}, {5, 1, 0}, {1e6, 2, -3}};
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        pm_mesh m;
        pm_mesh_from_reference(&m, &pm_reference_solids[i + 2]);
        pm_mesh_transform(&m, NULL, 1.0, at[i]);
        parts[i] = moments_of(ctx, &m);
        pm_mesh_free(&m);
    }
    PM_ASSERT_OK(ctx, polymass_moments_add(&left, ctx, &parts[0], &parts[1]));
    PM_ASSERT_OK(ctx, polymass_moments_add(&left, ctx, &left, &parts[2])); /* out == a */
    PM_ASSERT_OK(ctx, polymass_moments_add(&right, ctx, &parts[1], &parts[2]));
    PM_ASSERT_OK(ctx, polymass_moments_add(&right, ctx, &parts[0], &right)); /* out == b */
    p_left = properties_of(ctx, &left, NULL);
    p_right = properties_of(ctx, &right, NULL);
    assert_same_body("(a + b) + c against a + (b + c)", &p_left, &p_right, 1e6, SUM_TOL);
    PM_ASSERT_OK(ctx, polymass_moments_add(&again, ctx, &parts[0], &parts[1]));
    PM_ASSERT_OK(ctx, polymass_moments_add(&again, ctx, &again, &parts[2]));
    assert_memory_equal(&again, &left, sizeof left);
    polymass_context_destroy(ctx);
}

typedef struct motion {
    const char* name;
    double rotation[9];
    double translation[3];
} motion;

/* Rotations and mirrors with entries 0 and +-1 move dyadic coordinates
   exactly, so the moved mesh is exactly the moved solid. */
static const motion motions[] = {
    {"translate (1e6, -1e6, 1e6)", {1, 0, 0, 0, 1, 0, 0, 0, 1}, {1e6, -1e6, 1e6}},
    {"translate (1e8, 1e8, -1e8)", {1, 0, 0, 0, 1, 0, 0, 0, 1}, {1e8, 1e8, -1e8}},
    {"90 degrees about z, to 1e8", {0, -1, 0, 1, 0, 0, 0, 0, 1}, {1e8, 0, 0}},
    {"cyclic permutation, to 1e6", {0, 1, 0, 0, 0, 1, 1, 0, 0}, {1e6, 1e6, 1e6}},
    {"mirror x", {-1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}},
    {"mirror through the origin, to 1e8", {-1, 0, 0, 0, -1, 0, 0, 0, -1}, {0, 1e8, 1e8}},
};

static void test_moved_moments_equal_moved_mesh(void** state) {
    polymass_context* ctx = pm_context_new();
    size_t t;
    int k;
    (void)state;
    for (t = 0; t < sizeof motions / sizeof motions[0]; ++t) {
        const motion* mo = &motions[t];
        for (k = 0; k < PM_REF_COUNT; ++k) {
            const pm_reference_solid* ref = &pm_reference_solids[k];
            const pm_expected e0 = pm_expected_from_reference(ref);
            pm_expected e = pm_expected_transform(&e0, mo->rotation, 1.0, mo->translation);
            pm_mesh m;
            polymass_moments moments;
            polymass_mass_properties moved, mesh_moved;
            char label[200];
            pm_mesh_from_reference(&m, ref);
            moments = moments_of(ctx, &m);
            PM_ASSERT_OK(ctx, polymass_moments_transform(&moments, ctx, &moments, mo->rotation,
                                                         mo->translation));
            moved = properties_of(ctx, &moments, NULL);
            /* A mirrored mesh is inverted; accepted, it is turned the right way. */
            pm_mesh_transform(&m, mo->rotation, 1.0, mo->translation);
            PM_ASSERT_OK(ctx, pm_compute_flags(&mesh_moved, ctx, &m, accept_inverted, NULL));
            snprintf(label, sizeof label, "%s, %s", ref->name, mo->name);
            e.size = pm_mesh_size(&m);
            without_area(&e);
            PM_ASSERT_PROPERTIES(label, &e, &moved, PM_TOL);
            assert_same_body(label, &mesh_moved, &moved, e.size, PM_TOL);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(ctx);
}

/* Per-axis scale by powers of two (exact on the mesh), with a mirror. */
static void test_scaled_moments_equal_scaled_mesh(void** state) {
    polymass_context* ctx = pm_context_new();
    static const double factors[][3] = {{2, 0.5, 4}, {1024, 1024, 1024}, {-0.25, 1, 8}};
    size_t f;
    int k;
    (void)state;
    for (f = 0; f < sizeof factors / sizeof factors[0]; ++f) {
        const double* s = factors[f];
        const double diagonal[9] = {s[0], 0, 0, 0, s[1], 0, 0, 0, s[2]};
        for (k = 0; k < PM_REF_COUNT; ++k) {
            pm_mesh m;
            polymass_moments moments;
            polymass_mass_properties scaled, mesh_scaled;
            char label[200];
            pm_mesh_from_reference(&m, &pm_reference_solids[k]);
            moments = moments_of(ctx, &m);
            PM_ASSERT_OK(ctx, polymass_moments_scale(&moments, ctx, &moments, s));
            scaled = properties_of(ctx, &moments, NULL);
            pm_mesh_transform(&m, diagonal, 1.0, NULL);
            PM_ASSERT_OK(ctx, pm_compute_flags(&mesh_scaled, ctx, &m, accept_inverted, NULL));
            snprintf(label, sizeof label, "%s scaled by (%g, %g, %g)", pm_reference_solids[k].name,
                     s[0], s[1], s[2]);
            assert_same_body(label, &mesh_scaled, &scaled, pm_mesh_size(&m), PM_TOL);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(ctx);
}

/* cube_cavity is a cube with a box cavity: the block minus the bore. */
static void test_difference_is_block_minus_bore(void** state) {
    polymass_context* ctx = pm_context_new();
    static const double lo[3] = {-0.75, -0.5, -1.125}, hi[3] = {1.25, 1.5, 0.875};
    static const double bore_lo[3] = {-0.25, 0.25, -0.125}, bore_hi[3] = {0.5, 1.0, 0.625};
    const pm_reference_solid* ref = NULL;
    pm_mesh block, bore;
    polymass_moments mb, mh, diff = POLYMASS_MOMENTS_INIT;
    polymass_mass_properties p;
    pm_expected e;
    int k;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k)
        if (strcmp(pm_reference_solids[k].name, "cube_cavity") == 0) ref = &pm_reference_solids[k];
    assert_non_null(ref);
    pm_mesh_box(&block, lo, hi, 0);
    pm_mesh_box(&bore, bore_lo, bore_hi, 1);
    mb = moments_of(ctx, &block);
    mh = moments_of(ctx, &bore);
    PM_ASSERT_OK(ctx, polymass_moments_subtract(&diff, ctx, &mb, &mh));
    p = properties_of(ctx, &diff, NULL);
    e = pm_expected_from_reference(ref);
    without_area(&e);
    PM_ASSERT_PROPERTIES("block minus bore", &e, &p, PM_TOL);
    /* The bore minus the block has a negative volume: no mass properties. */
    PM_ASSERT_OK(ctx, polymass_moments_subtract(&diff, ctx, &mh, &mb));
    assert_true(diff.volume < 0);
    pm_props_init(&p);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_VOLUME,
                     polymass_moments_mass_properties(&p, ctx, &diff, NULL));
    pm_mesh_free(&block);
    pm_mesh_free(&bore);
    polymass_context_destroy(ctx);
}

/* Three boxes of densities 1, 2 and a given mass, far from the origin: the
   exact composite from the closed forms of boxes and the parallel-axis theorem. */
static void test_assembly_of_weighted_parts(void** state) {
    polymass_context* ctx = pm_context_new();
    static const double lo[3][3] = {{1e6, 1e6, 0}, {1e6 + 2, 1e6, 0}, {1e6, 1e6 + 3, 0.5}};
    static const double hi[3][3] = {
        {1e6 + 2, 1e6 + 1, 1}, {1e6 + 3, 1e6 + 2, 0.5}, {1e6 + 0.5, 1e6 + 4, 2}};
    const double density[3] = {1.0, 2.0, 0.0}, given_mass = 3.0; /* part 2: by its mass */
    polymass_moments total = POLYMASS_MOMENTS_INIT;
    polymass_mass_properties p;
    long double mass = 0, com[3] = {0, 0, 0};
    double part_mass[3], part_com[3][3], part_inertia[3][9], center[3], expected[9] = {0};
    int i, j;
    (void)state;
    for (i = 0; i < 3; ++i) {
        pm_mesh m;
        polymass_moments part;
        polymass_mass_desc weight = i < 2 ? pm_mass_density(density[i]) : pm_mass_total(given_mass);
        const pm_expected e = pm_expected_box(lo[i], hi[i]);
        const double rho = i < 2 ? density[i] : given_mass / e.volume;
        pm_mesh_box(&m, lo[i], hi[i], i == 1);
        part = moments_of(ctx, &m);
        PM_ASSERT_OK(ctx, polymass_moments_weight(&part, ctx, &part, &weight));
        if (i == 0)
            total = part;
        else
            PM_ASSERT_OK(ctx, polymass_moments_add(&total, ctx, &total, &part));
        part_mass[i] = rho * e.volume;
        for (j = 0; j < 3; ++j) part_com[i][j] = e.center_of_mass[j];
        for (j = 0; j < 9; ++j) part_inertia[i][j] = rho * e.inertia[j];
        mass += part_mass[i];
        for (j = 0; j < 3; ++j) com[j] += (long double)part_mass[i] * e.center_of_mass[j];
        pm_mesh_free(&m);
    }
    for (j = 0; j < 3; ++j) center[j] = (double)(com[j] / mass);
    for (i = 0; i < 3; ++i) {
        double about[9];
        pm_parallel_axis(about, part_inertia[i], part_mass[i], part_com[i], center);
        for (j = 0; j < 9; ++j) expected[j] += about[j];
    }
    p = properties_of(ctx, &total, NULL);
    PM_ASSERT_REL("assembly mass", (double)mass, p.mass, PM_TOL);
    PM_ASSERT_VEC("assembly centre of mass", center, p.center_of_mass, 3, PM_TOL, 10.0);
    PM_ASSERT_TENSOR("assembly inertia", expected, p.inertia, PM_TOL);
    PM_ASSERT_REL("assembly mean density", (double)mass / 3.75, p.density, PM_TOL);
    polymass_context_destroy(ctx);
}

/* Ranges of faces about one point, added in order, are the whole surface. */
static void test_face_ranges_add_up(void** state) {
    polymass_context* ctx = pm_context_new();
    static const double far[3] = {1e8, -1e6, 3};
    int k;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        pm_mesh m;
        polymass_mesh_desc desc;
        polymass_moments whole, sum = POLYMASS_MOMENTS_INIT, range = POLYMASS_MOMENTS_INIT;
        polymass_mass_properties a, b;
        double reference[3];
        size_t first = 0, step;
        pm_mesh_from_reference(&m, &pm_reference_solids[k]);
        pm_mesh_transform(&m, NULL, 1.0, far);
        desc = pm_mesh_desc(&m);
        whole = moments_of(ctx, &m);
        memcpy(reference, whole.reference, sizeof reference);
        step = (m.face_count ? m.face_count : m.index_count / 3) / 3 + 1;
        while (first < (m.face_count ? m.face_count : m.index_count / 3)) {
            const size_t faces = m.face_count ? m.face_count : m.index_count / 3;
            const size_t count = first + step < faces ? step : faces - first;
            PM_ASSERT_OK(ctx, polymass_moments_compute_faces(&range, ctx, &desc, first, count,
                                                             reference, NULL));
            assert_true(range.flags & POLYMASS_MOMENTS_PARTIAL);
            if (first == 0)
                sum = range;
            else
                PM_ASSERT_OK(ctx, polymass_moments_add(&sum, ctx, &sum, &range));
            first += count;
        }
        /* Partial moments are not a body until the caller says they are. */
        pm_props_init(&b);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_moments_mass_properties(&b, ctx, &sum, NULL));
        sum.flags &= ~POLYMASS_MOMENTS_PARTIAL;
        a = properties_of(ctx, &whole, NULL);
        b = properties_of(ctx, &sum, NULL);
        assert_same_body(pm_reference_solids[k].name, &a, &b, pm_mesh_size(&m), SUM_TOL);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

static void test_moments_refuse_bad_arguments(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    polymass_moments moments, partial = POLYMASS_MOMENTS_INIT;
    polymass_mesh_desc desc;
    static const double not_rotation[9] = {1, 0, 0, 0, 2, 0, 0, 0, 1};
    static const double zero_factor[3] = {1, 0, 1};
    static const double origin[3] = {0, 0, 0};
    static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    polymass_mass_desc negative = pm_mass_density(-1.0);
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    desc = pm_mesh_desc(&m);
    moments = moments_of(ctx, &m);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_transform(&moments, ctx, &moments, not_rotation, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_scale(&moments, ctx, &moments, zero_factor));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_weight(&moments, ctx, &moments, &negative));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_compute_faces(&partial, ctx, &desc, 4, 3, origin, NULL));
    PM_ASSERT_OK(ctx, polymass_moments_compute_faces(&partial, ctx, &desc, 0, 2, origin, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_add(&partial, ctx, &partial, &moments));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_transform(&partial, ctx, &partial, identity, NULL));
    moments.flags = 0x80;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_moments_scale(&moments, ctx, &moments, origin));
    moments.flags = 0;
    {
        const double nowhere[3] = {0, NAN, 0}, far_away[3] = {0, 0, INFINITY};
        double turned[9];
        memcpy(turned, identity, sizeof turned);
        turned[4] = NAN;
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_moments_compute_faces(&partial, ctx, &desc, 0, 2, nowhere, NULL));
        assert_non_null(strstr(polymass_context_message(ctx), "is not finite"));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_moments_transform(&moments, ctx, &moments, turned, NULL));
        assert_non_null(strstr(polymass_context_message(ctx), "NaN or infinite"));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_moments_transform(&moments, ctx, &moments, identity, far_away));
        moments.mass_error_bound = -1e-9;
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_moments_add(&moments, ctx, &moments, &moments));
        assert_non_null(strstr(polymass_context_message(ctx), "negative or NaN error bound"));
        moments.mass_error_bound = 0;
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_moments_compute_faces(&partial, ctx, &desc, 2, 0, origin, NULL));
        assert_non_null(strstr(polymass_context_message(ctx), "no faces"));
    }
    moments.second[2] = NAN;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE,
                     polymass_moments_add(&moments, ctx, &moments, &moments));
    /* A bent quad in a range: its planarity is checked as the solid's is. */
    m.positions[3 * 7 + 2] = 1.25;
    desc = pm_mesh_desc(&m);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_PLANAR_FACE,
                     polymass_moments_compute_faces(&partial, ctx, &desc, 0, 6, origin, NULL));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Options given for one call apply to it alone; NULL is the defaults. */
static void test_options_per_call(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_options accept = pm_options(POLYMASS_OPTION_ACCEPT_INVERTED, 0.0), bad = accept;
    polymass_mass_properties p;
    polymass_diagnostics report;
    polymass_moments moments;
    polymass_mesh* mesh = NULL;
    polymass_mesh_desc desc;
    pm_mesh m;
    (void)state;
    pm_mesh_unit_cube(&m, 1);
    pm_mesh_reverse_all(&m);
    desc = pm_mesh_desc(&m);
    pm_props_init(&p);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, NULL, NULL));
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &desc, &accept, NULL));
    assert_true(p.warnings & POLYMASS_WARNING_INVERTED);
    PM_ASSERT_REL("turned volume", 1.0, p.volume, PM_TOL);
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc, &accept));
    polymass_mesh_destroy(mesh);
    pm_diagnostics_init(&report);
    PM_ASSERT_OK(ctx, pm_diagnose(&report, ctx, &desc, &accept));
    assert_int_equal(report.status, POLYMASS_OK);
    assert_int_equal(polymass_moments_init(&moments, sizeof moments), POLYMASS_OK);
    PM_ASSERT_OK(ctx, pm_moments(&moments, ctx, &desc, &accept));
    PM_ASSERT_REL("turned moments", 1.0, moments.volume, PM_TOL);
    bad.weld_tolerance = 1.0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &desc, &bad, NULL));
    /* Options last for their call only. */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED, pm_compute(&p, ctx, &m, NULL));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disjoint_parts_add_up),
        cmocka_unit_test(test_sum_associative_and_deterministic),
        cmocka_unit_test(test_moved_moments_equal_moved_mesh),
        cmocka_unit_test(test_scaled_moments_equal_scaled_mesh),
        cmocka_unit_test(test_difference_is_block_minus_bore),
        cmocka_unit_test(test_assembly_of_weighted_parts),
        cmocka_unit_test(test_face_ranges_add_up),
        cmocka_unit_test(test_moments_refuse_bad_arguments),
        cmocka_unit_test(test_options_per_call),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
