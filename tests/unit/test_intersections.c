/* Surfaces that bound a region twice: faces crossing each other, shells
 * nested in a solid of the same sense, shells inside out - and the surfaces
 * that only look alike (touching parts, cavities, parts in hollows), which
 * must stay valid. Every case also far from the origin and at tiny and huge
 * scales: the verdicts come from exact predicates, so they must not change. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "reference/exact_reference.h"
#include "test_support.h"

/* The default options check intersections; UNCHECKED skips it by name. */
#define CHECKED 0u
#define UNCHECKED (POLYMASS_OPTION_SKIP_INTERSECTION_CHECK)

/* Where each case is also tried. */
static const pm_placement placements[] = {
    {"as given", 1.0, {0, 0, 0}},
    {"at 1e6", 1.0, {1e6, -1e6, 1e6}},
    {"at 1e8", 1.0, {1e8, 1e8, -1e8}},
    {"scaled 1e-60", 1e-60, {0, 0, 0}},
    {"scaled 1e60", 1e60, {0, 0, 0}},
    {"scaled 2^-10 at 2^20", 0.0009765625, {1048576, 1048576, -1048576}},
};
#define PLACEMENTS (sizeof placements / sizeof placements[0])

static void box(pm_mesh* m, double x0, double y0, double z0, double x1, double y1, double z1,
                int triangulate, int inside_out) {
    const double lo[3] = {x0, y0, z0}, hi[3] = {x1, y1, z1};
    pm_mesh part;
    pm_mesh_init(&part);
    pm_mesh_add_box(&part, lo, hi, triangulate);
    if (inside_out) {
        pm_mesh_reverse_all(&part);
    }
    pm_mesh_append(m, &part);
    pm_mesh_free(&part);
}

/* An octahedron of the given centre and radius (a cavity when inside_out). */
static void octahedron(pm_mesh* m, const double c[3], double r, int inside_out) {
    static const uint32_t faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                         {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const uint32_t base = (uint32_t)m->vertex_count;
    int k;
    pm_mesh_add_vertex(m, c[0] + r, c[1], c[2]);
    pm_mesh_add_vertex(m, c[0] - r, c[1], c[2]);
    pm_mesh_add_vertex(m, c[0], c[1] + r, c[2]);
    pm_mesh_add_vertex(m, c[0], c[1] - r, c[2]);
    pm_mesh_add_vertex(m, c[0], c[1], c[2] + r);
    pm_mesh_add_vertex(m, c[0], c[1], c[2] - r);
    for (k = 0; k < 8; ++k) {
        if (inside_out) {
            pm_mesh_add_tri(m, base + faces[k][0], base + faces[k][2], base + faces[k][1]);
        } else {
            pm_mesh_add_tri(m, base + faces[k][0], base + faces[k][1], base + faces[k][2]);
        }
    }
}

/* Computes with and without the intersection check; returns the checked
   status. The unchecked status is `unchecked`. */
static int32_t verdicts(const pm_mesh* m, int32_t* unchecked, uint32_t* warnings, double* volume) {
    polymass_context* plain = pm_context_new(UNCHECKED);
    polymass_context* checked = pm_context_new(CHECKED);
    polymass_mass_properties p, q;
    int32_t status;
    pm_props_init(&p);
    pm_props_init(&q);
    *unchecked = pm_compute(&p, plain, m, NULL);
    status = pm_compute(&q, checked, m, NULL);
    if (status == POLYMASS_OK) {
        *warnings = q.warnings;
        *volume = q.volume;
        /* The check never changes a result it accepts. */
        assert_int_equal(*unchecked, POLYMASS_OK);
        PM_ASSERT_SAME("volume", p.volume, q.volume);
        PM_ASSERT_SAME("Ixx", p.inertia[0], q.inertia[0]);
        PM_ASSERT_SAME("Ixy", p.inertia[1], q.inertia[1]);
    }
    polymass_context_destroy(plain);
    polymass_context_destroy(checked);
    return status;
}

typedef struct expectation {
    int32_t checked;   /* status with the intersection check */
    int32_t unchecked; /* status without */
    uint32_t warnings; /* with the check, when it passes */
    double volume;     /* with the check, when it passes (before placement) */
} expectation;

static void expect_everywhere(const char* what, const pm_mesh* original, expectation e) {
    size_t k;
    for (k = 0; k < PLACEMENTS; ++k) {
        const pm_placement* at = &placements[k];
        pm_mesh m;
        int32_t unchecked = -1, status;
        uint32_t warnings = 0;
        double volume = 0;
        pm_mesh_placed(&m, original, at);
        status = verdicts(&m, &unchecked, &warnings, &volume);
        if (status != e.checked || unchecked != e.unchecked) {
            fail_msg("%s, %s: checked %s (expected %s), unchecked %s (expected %s)", what, at->name,
                     polymass_status_string(status), polymass_status_string(e.checked),
                     polymass_status_string(unchecked), polymass_status_string(e.unchecked));
        }
        if (status == POLYMASS_OK) {
            const double s3 = at->scale * at->scale * at->scale;
            if (warnings != e.warnings) {
                fail_msg("%s, %s: warnings %#x, expected %#x", what, at->name, warnings,
                         e.warnings);
            }
            PM_ASSERT_REL("volume", e.volume * s3, volume, 1e-12);
        }
        pm_mesh_free(&m);
    }
    printf("  %-58s %s / unchecked %s\n", what, polymass_status_string(e.checked),
           polymass_status_string(e.unchecked));
}

static const expectation overlap = {POLYMASS_ERROR_INTERSECTING, POLYMASS_OK, 0, 0};

static void test_overlapping_cubes(void** state) {
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    box(&m, 0.5, 0.5, 0.5, 1.5, 1.5, 1.5, 0, 0);
    expect_everywhere("two unit cubes overlapping by 1/8 (quads)", &m, overlap);
    pm_mesh_free(&m);
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    box(&m, 0.5, 0.5, 0.5, 1.5, 1.5, 1.5, 1, 0);
    expect_everywhere("the same, triangulated", &m, overlap);
    pm_mesh_free(&m);
}

static void test_cube_overlapping_a_rotated_cube(void** state) {
    pm_mesh m, turned;
    double rotation[9];
    const double centre[3] = {0.9, 0.9, 0.9};
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_init(&turned);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    box(&turned, -0.5, -0.5, -0.5, 0.5, 0.5, 0.5, 1, 0);
    pm_rotation_from_quaternion(rotation, 0.9, 0.3, -0.2, 0.25);
    pm_mesh_transform(&turned, rotation, 1.0, centre);
    pm_mesh_append(&m, &turned);
    expect_everywhere("a cube overlapping a rotated cube", &m, overlap);
    pm_mesh_free(&turned);
    pm_mesh_free(&m);
}

static void test_vertex_pushed_through_the_opposite_face(void** state) {
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_unit_cube(&m, 1);
    /* Vertex 7 = (1, 1, 1) through the bottom face z = 0. */
    m.positions[3 * 7 + 0] = 0.7;
    m.positions[3 * 7 + 1] = 0.7;
    m.positions[3 * 7 + 2] = -0.6;
    expect_everywhere("a cube whose corner is pushed through its bottom", &m, overlap);
    pm_mesh_free(&m);
}

static void test_torus_through_itself(void** state) {
    static const double origin[3] = {0, 0, 0};
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    /* Ring radius below the tube's: the tube passes through itself around
       the axis (0.6 is chosen so that no ring of vertices falls exactly on
       the axis: there the sheets would only touch, see docs/validity.md). */
    pm_mesh_add_torus(&m, 24, 24, 0.6, 1.0, origin);
    expect_everywhere("a spindle torus (tube through itself)", &m, overlap);
    pm_mesh_free(&m);
    /* An ordinary torus is valid: no false positive on a curved surface. */
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 24, 24, 2.0, 1.0, origin);
    {
        polymass_context* ctx = pm_context_new(CHECKED);
        polymass_mass_properties p;
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_int_equal(p.warnings, 0);
        polymass_context_destroy(ctx);
    }
    pm_mesh_free(&m);
}

static void test_shells_touching_along_a_face(void** state) {
    pm_mesh m;
    const expectation touching = {POLYMASS_OK, POLYMASS_OK, POLYMASS_WARNING_TOUCHING_FACES, 2.0};
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    box(&m, 1, 0, 0, 2, 1, 1, 0, 0);
    expect_everywhere("two cubes resting against each other", &m, touching);
    pm_mesh_free(&m);
    /* Offset on the shared plane, triangulated: still touching only. */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    box(&m, 0.25, 0.5, 1, 1.25, 1.5, 2, 1, 0);
    expect_everywhere("a cube resting half on another", &m, touching);
    pm_mesh_free(&m);
}

static void test_cavities_and_parts_in_hollows(void** state) {
    pm_mesh m;
    const double centre[3] = {2, 2, 1};
    const expectation cavity = {POLYMASS_OK, POLYMASS_OK, 0, 64.0 - 8.0};
    const expectation nested = {POLYMASS_OK, POLYMASS_OK, 0, 216.0 - 64.0 + 8.0};
    const expectation touching_cavity = {POLYMASS_OK, POLYMASS_OK, POLYMASS_WARNING_TOUCHING_FACES,
                                         64.0 - 4.0 / 3.0};
    const expectation filled = {POLYMASS_OK, POLYMASS_OK, POLYMASS_WARNING_TOUCHING_FACES, 64.0};
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 4, 4, 4, 0, 0);
    box(&m, 1, 1, 1, 3, 3, 3, 1, 1);
    expect_everywhere("a cube with a cavity", &m, cavity);
    pm_mesh_free(&m);

    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 6, 6, 6, 0, 0);
    box(&m, 1, 1, 1, 5, 5, 5, 0, 1);
    box(&m, 2, 2, 2, 4, 4, 4, 1, 0);
    expect_everywhere("a part inside a hollow part", &m, nested);
    pm_mesh_free(&m);

    /* The octahedron's lowest corner (2, 2, 0) lies on the outer bottom face. */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 4, 4, 4, 0, 0);
    octahedron(&m, centre, 1.0, 1);
    expect_everywhere("a cavity touching its outer wall in one point", &m, touching_cavity);
    pm_mesh_free(&m);

    /* A part filling its cavity exactly: every probe of both starts on the
       other, so their nesting stays unknown and the boxes classify them (a
       cavity, a solid), which is right: the whole cube. */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 4, 4, 4, 0, 0);
    box(&m, 1, 1, 1, 3, 3, 3, 1, 1);
    box(&m, 1, 1, 1, 3, 3, 3, 1, 0);
    expect_everywhere("a part filling its cavity exactly", &m, filled);
    pm_mesh_free(&m);
}

static void test_solid_inside_a_solid_counts_twice(void** state) {
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 4, 4, 4, 0, 0);
    box(&m, 1, 1, 1, 2, 2, 2, 1, 0);
    expect_everywhere("a solid cube inside a solid cube", &m, overlap);
    pm_mesh_free(&m);
}

static void test_inside_out_shells(void** state) {
    pm_mesh m;
    static const double l_shape[] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 4, 0, 4};
    const expectation apart = {POLYMASS_ERROR_INVERTED, POLYMASS_ERROR_INVERTED, 0, 0};
    const expectation in_the_notch = {POLYMASS_ERROR_INVERTED, POLYMASS_OK, 0, 0};
    (void)state;
    /* Apart from the solid: refused with or without the check (boxes tell). */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    box(&m, 3, 0, 0, 3.5, 0.5, 0.5, 0, 1);
    expect_everywhere("a cube and, apart, a cube inside out", &m, apart);
    pm_mesh_free(&m);
    /* In the notch of an L: within its box, outside the solid. Only the
       counted nesting can tell it from a cavity. */
    pm_mesh_init(&m);
    pm_mesh_add_prism(&m, l_shape, 6, 0, 1);
    box(&m, 2.5, 2.5, 0.25, 3, 3, 0.75, 1, 1);
    expect_everywhere("an inside-out cube in the notch of an L", &m, in_the_notch);
    pm_mesh_free(&m);
}

/* Overlapping cubes of subnormal size (2^-1050: every corner still exact) are
   still found to cross; the search's grid over them must not overflow (it
   once scaled by 1023 / width, infinite for a subnormal width). */
static void test_subnormal_surfaces(void** state) {
    const double scale = ldexp(1.0, -1050);
    pm_mesh m;
    polymass_context* ctx = pm_context_new(CHECKED);
    polymass_diagnostics d;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, scale, scale, scale, 1, 0);
    box(&m, 0.5 * scale, 0.5 * scale, 0.5 * scale, 1.5 * scale, 1.5 * scale, 1.5 * scale, 1, 0);
    pm_diagnostics_init(&d);
    pm_check(&d, ctx, &m);
    assert_true(d.intersecting_face_pairs >= 3);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_report_lists_pairs_and_shells(void** state) {
    pm_mesh m;
    polymass_context* ctx = pm_context_new(CHECKED);
    polymass_diagnostics d;
    polymass_shell shells[3];
    uint64_t count = 0, i;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    box(&m, 0.5, 0.5, 0.5, 1.5, 1.5, 1.5, 0, 0);
    pm_diagnostics_init(&d);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INTERSECTING, pm_check(&d, ctx, &m));
    assert_non_null(strstr(polymass_context_message(ctx), "cross each other"));
    assert_int_equal(d.status, POLYMASS_ERROR_INTERSECTING);
    assert_int_equal(d.shell_count, 2);
    /* Each cube has three faces through the other's interior, every one
       crossing three of the other's: 3 x 3 pairs... at least one per face. */
    assert_true(d.intersecting_face_pairs >= 3);
    for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
        if (i < d.intersecting_face_pairs) {
            assert_true(d.first_intersecting_face_pairs[i][0] < 6);  /* first cube */
            assert_true(d.first_intersecting_face_pairs[i][1] >= 6); /* second cube */
            assert_true(d.first_intersecting_face_pairs[i][1] < 12);
            if (i > 0) { /* ascending */
                assert_true(d.first_intersecting_face_pairs[i - 1][0] <
                                d.first_intersecting_face_pairs[i][0] ||
                            (d.first_intersecting_face_pairs[i - 1][0] ==
                                 d.first_intersecting_face_pairs[i][0] &&
                             d.first_intersecting_face_pairs[i - 1][1] <
                                 d.first_intersecting_face_pairs[i][1]));
            }
        } else {
            assert_true(d.first_intersecting_face_pairs[i][0] == POLYMASS_NONE);
        }
    }
    assert_int_equal(d.touching_face_pairs, 0);
    for (i = 0; i < 3; ++i) {
        memset(&shells[i], 0, sizeof shells[i]);
        shells[i].struct_size = sizeof shells[i];
    }
    {
        polymass_mesh_desc desc = pm_mesh_desc(&m);
        PM_ASSERT_OK(ctx, polymass_mesh_shell_list(shells, 3, &count, ctx, &desc));
    }
    assert_int_equal(count, 2);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_SOLID);
    assert_int_equal(shells[0].face_count, 6);
    assert_int_equal(shells[1].first_face, 6);
    PM_ASSERT_REL("shell volume", 1.0, shells[1].signed_volume, 1e-14);
    pm_mesh_free(&m);

    /* A cavity and an inside-out shell, described. */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 4, 4, 4, 0, 0);
    box(&m, 1, 1, 1, 3, 3, 3, 0, 1);
    box(&m, 6, 0, 0, 7, 1, 1, 0, 1);
    pm_diagnostics_init(&d);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED, pm_check(&d, ctx, &m));
    PM_ASSERT_MENTIONS(ctx, "shell", 2);
    assert_int_equal(d.shell_count, 3);
    assert_int_equal(d.inverted_shells, 1);
    assert_int_equal(d.first_inverted_shells[0], 2);
    assert_true(d.first_inverted_shells[1] == POLYMASS_NONE);
    {
        polymass_mesh_desc desc = pm_mesh_desc(&m);
        count = 0;
        PM_ASSERT_OK(ctx, polymass_mesh_shell_list(NULL, 0, &count, ctx, &desc));
        assert_int_equal(count, 3);
        PM_ASSERT_OK(ctx, polymass_mesh_shell_list(shells, 3, &count, ctx, &desc));
    }
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_SOLID);
    assert_int_equal(shells[1].kind, POLYMASS_SHELL_CAVITY);
    assert_int_equal(shells[2].kind, POLYMASS_SHELL_INVERTED);
    PM_ASSERT_REL("cavity volume", -8.0, shells[1].signed_volume, 1e-14);
    pm_mesh_free(&m);

    /* A flat pillow beside a cube (a triangle and its reverse: closed, with
       no volume): valid, and its shell described as having none. */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    {
        const uint32_t a = pm_mesh_add_vertex(&m, 5, 0, 0);
        const uint32_t b = pm_mesh_add_vertex(&m, 6, 0, 0);
        const uint32_t c = pm_mesh_add_vertex(&m, 5, 1, 0);
        pm_mesh_add_tri(&m, a, b, c);
        pm_mesh_add_tri(&m, a, c, b);
    }
    pm_diagnostics_init(&d);
    PM_ASSERT_OK(ctx, pm_check(&d, ctx, &m));
    assert_int_equal(d.shell_count, 2);
    {
        polymass_mesh_desc desc = pm_mesh_desc(&m);
        PM_ASSERT_OK(ctx, polymass_mesh_shell_list(shells, 3, &count, ctx, &desc));
    }
    assert_int_equal(count, 2);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_SOLID);
    assert_int_equal(shells[1].kind, POLYMASS_SHELL_NO_VOLUME);
    assert_int_equal(shells[1].first_face, 6);
    assert_int_equal(shells[1].face_count, 2);
    assert_true(shells[1].signed_volume == 0.0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* A pile of `copies` triangulated unit cubes, copy k moved by k * step
   along (1, 2, 3) (step 0: all coincident), checked. */
static int32_t check_pile(polymass_diagnostics* d, polymass_context* ctx, int copies, double step) {
    pm_mesh m;
    int32_t status;
    int k;
    pm_mesh_init(&m);
    for (k = 0; k < copies; ++k)
        box(&m, k * step, 2 * k * step, 3 * k * step, 1 + k * step, 1 + 2 * k * step,
            1 + 3 * k * step, 1, 0);
    pm_diagnostics_init(d);
    status = pm_check(d, ctx, &m);
    pm_mesh_free(&m);
    return status;
}

/* Piles of copies of a part meet in face pairs by the square of the copies
   (a fuzzed pile of 252 coincident cubes took minutes): counting stops at 2048
   pairs of a kind and says "at least 2048", and the pairs listed are still the
   lowest, those of a pile of four. Forty copies pass the limit for both kinds. */
static void test_piles_of_copies_stop_counting(void** state) {
    static const double steps[] = {1e-3, 0.0}; /* crossing, then touching */
    polymass_context* ctx = pm_context_new(CHECKED);
    polymass_diagnostics few, many;
    size_t s, i;
    (void)state;
    for (s = 0; s < 2; ++s) {
        const int32_t status = check_pile(&few, ctx, 4, steps[s]);
        const uint64_t few_count = s == 0 ? few.intersecting_face_pairs : few.touching_face_pairs;
        const uint64_t(*few_first)[2] =
            s == 0 ? few.first_intersecting_face_pairs : few.first_touching_face_pairs;
        const uint64_t(*many_first)[2] =
            s == 0 ? many.first_intersecting_face_pairs : many.first_touching_face_pairs;
        assert_true(few_count >= POLYMASS_DIAGNOSTIC_LOCATIONS && few_count < 2048);
        if (s == 0) assert_null(strstr(polymass_context_message(ctx), "at least"));
        PM_ASSERT_STATUS(ctx, status, check_pile(&many, ctx, 40, steps[s]));
        if (s == 0) {
            assert_int_equal(status, POLYMASS_ERROR_INTERSECTING);
            assert_non_null(strstr(polymass_context_message(ctx), "(at least 2048 "));
            assert_int_equal(many.intersecting_face_pairs, 2048);
        } else {
            assert_int_equal(many.touching_face_pairs, 2048);
        }
        for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
            assert_int_equal(many_first[i][0], few_first[i][0]);
            assert_int_equal(many_first[i][1], few_first[i][1]);
        }
    }
    polymass_context_destroy(ctx);
}

/* A triangulated cube [0, size]^3 turned by `rotation` (row-major, NULL:
   none) about its vertex 0, the origin, inside out with `inside_out`, whose
   first `reused` vertices are m's vertices reuse[0..reused) (at the same
   positions), and whose triangles list their corners from corner `first`. */
static void add_cube(pm_mesh* m, double size, const double* rotation, int inside_out,
                     const uint32_t* reuse, size_t reused, int first) {
    const double lo[3] = {0, 0, 0}, hi[3] = {size, size, size};
    pm_mesh cube;
    uint32_t ids[8];
    size_t v, f;
    pm_mesh_init(&cube);
    pm_mesh_add_box(&cube, lo, hi, 1);
    if (inside_out) pm_mesh_reverse_all(&cube);
    if (rotation) pm_mesh_transform(&cube, rotation, 1.0, lo);
    for (v = 0; v < 8; ++v) {
        const double* p = cube.positions + 3 * v;
        ids[v] = v < reused ? reuse[v] : pm_mesh_add_vertex(m, p[0], p[1], p[2]);
    }
    for (f = 0; f < cube.face_count; ++f) {
        const uint32_t* t = cube.indices + 3 * f;
        pm_mesh_add_tri(m, ids[t[first]], ids[t[(first + 1) % 3]], ids[t[(first + 2) % 3]]);
    }
    pm_mesh_free(&cube);
}

static void assert_same_pairs(const polymass_diagnostics* a, const polymass_diagnostics* b) {
    size_t i;
    assert_int_equal(a->intersecting_face_pairs, b->intersecting_face_pairs);
    assert_int_equal(a->touching_face_pairs, b->touching_face_pairs);
    for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
        assert_int_equal(a->first_intersecting_face_pairs[i][0],
                         b->first_intersecting_face_pairs[i][0]);
        assert_int_equal(a->first_intersecting_face_pairs[i][1],
                         b->first_intersecting_face_pairs[i][1]);
        assert_int_equal(a->first_touching_face_pairs[i][0], b->first_touching_face_pairs[i][0]);
        assert_int_equal(a->first_touching_face_pairs[i][1], b->first_touching_face_pairs[i][1]);
    }
}

/* Copies of a triangle (same positions in the same order) are found once,
   through the lowest of them, and paired with each other and with the
   triangles they meet without the box tree. The pairs, counts and message
   must be those of the same surface whose triangles are not copies (their
   corners listed from another corner), however the copies share corners and
   whichever of their corners is shared:
   three unit cubes at one place, copy c with copy 0's first c vertices
   (touching all over), and a fourth turned about their common corner,
   which it shares with copy 0, so that faces meeting there cross. */
static void test_copies_are_paired_as_triangles_are(void** state) {
    static const uint32_t first_vertices[] = {0, 1, 2};
    /* 0.4 radians about (1, 2, 3) / sqrt(14) */
    static const double turn[9] = {0.92669949,  -0.30095229, 0.22506836, 0.32350629, 0.94361500,
                                   -0.07024543, -0.19123736, 0.13790743, 0.97180750};
    polymass_context* ctx = pm_context_new(POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    int turned_cube;
    (void)state;
    for (turned_cube = 0; turned_cube < 2; ++turned_cube) {
        polymass_diagnostics d[2];
        char message[512];
        int32_t status = POLYMASS_OK;
        int turned;
        for (turned = 0; turned < 2; ++turned) {
            pm_mesh m;
            int c;
            pm_mesh_init(&m);
            for (c = 0; c < 3; ++c)
                add_cube(&m, 1.0, NULL, 0, first_vertices, (size_t)c, turned ? c : 1);
            if (turned_cube) add_cube(&m, 1.0, turn, 0, first_vertices, 1, 0);
            pm_diagnostics_init(&d[turned]);
            if (!turned) {
                status = pm_check(&d[0], ctx, &m);
                snprintf(message, sizeof message, "%s", polymass_context_message(ctx));
            } else {
                PM_ASSERT_STATUS(ctx, status, pm_check(&d[1], ctx, &m));
                assert_string_equal(message, polymass_context_message(ctx));
            }
            pm_mesh_free(&m);
        }
        assert_true(d[0].touching_face_pairs > 0);
        assert_true((d[0].intersecting_face_pairs > 0) == turned_cube);
        assert_same_pairs(&d[0], &d[1]);
    }
    polymass_context_destroy(ctx);
}

/* Faces of two shells lying in one plane, overlapping over an area and
   facing the same way bound the region behind them twice, as crossing faces
   do: a surface written twice, or parts overlapping flush with each other
   (none of whose faces pass through another's, and whose corners all lie on
   the other part or outside it, so that no probe sees the overlap). Facing
   opposite ways they only touch. */
static void test_coinciding_faces_of_two_shells(void** state) {
    pm_mesh m;
    int triangulate;
    (void)state;
    for (triangulate = 0; triangulate < 2; ++triangulate) {
        pm_mesh_init(&m);
        box(&m, 0, 0, 0, 1, 1, 1, triangulate, 0);
        box(&m, 0, 0, 0, 1, 1, 1, triangulate, 0);
        expect_everywhere(
            triangulate ? "a cube written twice, triangulated" : "a cube written twice (quads)", &m,
            overlap);
        pm_mesh_free(&m);
        pm_mesh_init(&m);
        box(&m, 0, 0, 0, 1, 1, 1, triangulate, 0);
        box(&m, 0.5, 0, 0, 1.5, 1, 1, triangulate, 0);
        expect_everywhere(triangulate ? "cubes overlapping by half, flush, triangulated"
                                      : "cubes overlapping by half, flush (quads)",
                          &m, overlap);
        pm_mesh_free(&m);
    }
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 2, 2, 2, 1, 0);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    expect_everywhere("a cube nested flush in a corner of another", &m, overlap);
    pm_mesh_free(&m);
    {
        const expectation nothing = {POLYMASS_ERROR_ZERO_VOLUME, POLYMASS_ERROR_ZERO_VOLUME, 0, 0};
        pm_mesh_init(&m);
        box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
        box(&m, 0, 0, 0, 1, 1, 1, 1, 1);
        expect_everywhere("a cube and its inside-out copy (touching)", &m, nothing);
        pm_mesh_free(&m);
    }
}

/* A surface welded to a copy of itself: every face listed twice on the same
   vertices, so every edge is used four times, balanced, and the surface is
   accepted as non-manifold. It bounds its solid twice: a face written twice
   in one turn is crossing, whatever the shells. A face beside its reverse
   (a sheet of no thickness) cancels instead, and so does a cube beside its
   inside-out copy on the same vertices. */
static void test_surface_welded_to_its_copy(void** state) {
    const int32_t flags = CHECKED | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
    polymass_context* checked = pm_context_new(flags);
    polymass_context* plain = pm_context_new(UNCHECKED | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
    int triangulate, reversed;
    (void)state;
    for (triangulate = 0; triangulate < 2; ++triangulate) {
        for (reversed = 0; reversed < 2; ++reversed) {
            pm_mesh m, copy;
            polymass_mass_properties p;
            polymass_diagnostics d;
            size_t f;
            pm_mesh_init(&m);
            box(&m, 0, 0, 0, 1, 1, 1, triangulate, 0);
            pm_mesh_copy(&copy, &m);
            if (reversed) pm_mesh_reverse_all(&copy);
            for (f = 0; f < copy.face_count; ++f) {
                pm_mesh_add_face(&m, copy.face_sizes[f],
                                 copy.indices + pm_mesh_face_offset(&copy, f));
            }
            pm_props_init(&p);
            pm_diagnostics_init(&d);
            if (reversed) {
                /* Nothing bounded: no face pair crosses. */
                PM_ASSERT_STATUS(checked, POLYMASS_ERROR_ZERO_VOLUME, pm_check(&d, checked, &m));
                assert_int_equal(d.intersecting_face_pairs, 0);
            } else {
                PM_ASSERT_STATUS(checked, POLYMASS_ERROR_INTERSECTING, pm_check(&d, checked, &m));
                /* each face with its copy (quads: with both halves' copies) */
                assert_true(d.intersecting_face_pairs >= copy.face_count);
                /* Without the check the solid counts twice, as documented. */
                PM_ASSERT_OK(plain, pm_compute(&p, plain, &m, NULL));
                PM_ASSERT_REL("volume counted twice", 2.0, p.volume, 1e-15);
            }
            pm_mesh_free(&copy);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(checked);
    polymass_context_destroy(plain);
}

/* A double pyramid whose square waist lies on a face of a cube: lower_apex_z
   below the waist's, its lower half lies in the cube, passing through the
   cube's face exactly along its own edges (no faces cross, none coincide),
   every vertex on the cube or outside it; above, it rests on the cube. */
static void double_pyramid(pm_mesh* m, double x, double y, double waist_z, double lower_apex_z) {
    const uint32_t top = pm_mesh_add_vertex(m, x + 0.5, y + 0.5, waist_z + 1);
    const uint32_t bottom = pm_mesh_add_vertex(m, x + 0.5, y + 0.5, lower_apex_z);
    uint32_t waist[4];
    int k;
    waist[0] = pm_mesh_add_vertex(m, x + 0.25, y + 0.25, waist_z);
    waist[1] = pm_mesh_add_vertex(m, x + 0.75, y + 0.25, waist_z);
    waist[2] = pm_mesh_add_vertex(m, x + 0.75, y + 0.75, waist_z);
    waist[3] = pm_mesh_add_vertex(m, x + 0.25, y + 0.75, waist_z);
    for (k = 0; k < 4; ++k) {
        pm_mesh_add_tri(m, top, waist[k], waist[(k + 1) % 4]);
        pm_mesh_add_tri(m, bottom, waist[(k + 1) % 4], waist[k]);
    }
}

#define STACK 4 /* cubes along each side of the stack */

/* A shell passing through another's face along its own edges lies partly
   inside it, though no probe from a vertex sees it: probes from inside the
   triangles that touch the other shell do. */
static void test_shell_passing_through_a_face_along_its_edges(void** state) {
    pm_mesh m;
    const expectation resting = {POLYMASS_OK, POLYMASS_OK, POLYMASS_WARNING_TOUCHING_FACES,
                                 1.0 + 0.25 / 3.0};
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    double_pyramid(&m, 0, 0, 1.0, 0.0);
    expect_everywhere("a double pyramid through a cube's face, apex on its floor", &m, overlap);
    pm_mesh_free(&m);
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    double_pyramid(&m, 0, 0, 1.0, 0.5);
    expect_everywhere("the same, triangulated, apex inside", &m, overlap);
    pm_mesh_free(&m);
    /* Its upper half alone, resting on the cube (its base on the cube's top
       face, facing down): its triangles touch the cube too, and all their
       probes agree. */
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    {
        const uint32_t top = pm_mesh_add_vertex(&m, 0.5, 0.5, 2);
        const uint32_t a = pm_mesh_add_vertex(&m, 0.25, 0.25, 1);
        const uint32_t b = pm_mesh_add_vertex(&m, 0.75, 0.25, 1);
        const uint32_t c = pm_mesh_add_vertex(&m, 0.75, 0.75, 1);
        const uint32_t d = pm_mesh_add_vertex(&m, 0.25, 0.75, 1);
        pm_mesh_add_tri(&m, top, a, b);
        pm_mesh_add_tri(&m, top, b, c);
        pm_mesh_add_tri(&m, top, c, d);
        pm_mesh_add_tri(&m, top, d, a);
        pm_mesh_add_tri(&m, a, c, b);
        pm_mesh_add_tri(&m, a, d, c);
    }
    expect_everywhere("a pyramid resting on a cube", &m, resting);
    pm_mesh_free(&m);
    /* The same pyramid through the top of a stack of cubes resting on each
       other, listed last: past the count's stop of touching pairs, its pairs
       are still tested and its triangles probed. */
    {
        polymass_context* ctx = pm_context_new(CHECKED);
        polymass_diagnostics d;
        int x, y, z;
        pm_mesh_init(&m);
        for (z = 0; z < STACK; ++z)
            for (y = 0; y < STACK; ++y)
                for (x = 0; x < STACK; ++x) box(&m, x, y, z, x + 1, y + 1, z + 1, 1, 0);
        double_pyramid(&m, STACK - 1, STACK - 1, STACK, STACK - 1);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INTERSECTING, pm_check(&d, ctx, &m));
        assert_int_equal(d.touching_face_pairs, 2048); /* stopped: "at least" */
        assert_int_equal(d.overlapping_shells, 1);
        assert_int_equal(d.first_overlapping_shells[0], STACK * STACK * STACK); /* the pyramid */
        pm_mesh_free(&m);
        polymass_context_destroy(ctx);
    }
}

/* The corners of the rectangle [x0, x1] x [y0, y1] at height z, counter-clockwise
   seen from above. */
static void rectangle(pm_mesh* m, uint32_t corner[4], double x0, double y0, double x1, double y1,
                      double z) {
    corner[0] = pm_mesh_add_vertex(m, x0, y0, z);
    corner[1] = pm_mesh_add_vertex(m, x1, y0, z);
    corner[2] = pm_mesh_add_vertex(m, x1, y1, z);
    corner[3] = pm_mesh_add_vertex(m, x0, y1, z);
}

/* A box [0,4]^2 x [0,1] whose top is split around the triangle t of corners
   (0.5,0.5), (3.5,0.5), (2,3.5); resting on it, a slab [0.25,3.75]^2 x [1,2]
   whose bottom lies flush on t around all three of t's corners and has a
   window [1.5,2.5] x [1,2] over t's middle, closed by a pyramid of apex
   (2, 1.5, apex_z): down into the box (apex_z < 1) or up into the slab, a
   pocket (apex_z > 1). */
static void slab_over_a_window(pm_mesh* m, double apex_z) {
    uint32_t c[4], k[3], d[4], o[4], w[4], u[4], apex;
    int i;
    rectangle(m, c, 0, 0, 4, 4, 1);
    rectangle(m, d, 0, 0, 4, 4, 0);
    k[0] = pm_mesh_add_vertex(m, 0.5, 0.5, 1);
    k[1] = pm_mesh_add_vertex(m, 3.5, 0.5, 1);
    k[2] = pm_mesh_add_vertex(m, 2, 3.5, 1);
    /* The box: its top (t and the ring around it), bottom and sides. */
    pm_mesh_add_tri(m, k[0], k[1], k[2]);
    pm_mesh_add_tri(m, c[0], c[1], k[1]);
    pm_mesh_add_tri(m, c[0], k[1], k[0]);
    pm_mesh_add_tri(m, c[1], c[2], k[1]);
    pm_mesh_add_tri(m, k[1], c[2], k[2]);
    pm_mesh_add_tri(m, c[2], c[3], k[2]);
    pm_mesh_add_tri(m, c[3], k[0], k[2]);
    pm_mesh_add_tri(m, c[3], c[0], k[0]);
    pm_mesh_add_tri(m, d[0], d[3], d[2]);
    pm_mesh_add_tri(m, d[0], d[2], d[1]);
    for (i = 0; i < 4; ++i) {
        pm_mesh_add_tri(m, d[i], d[(i + 1) % 4], c[(i + 1) % 4]);
        pm_mesh_add_tri(m, d[i], c[(i + 1) % 4], c[i]);
    }
    /* The slab: its bottom ring around the window, top, sides, and the pyramid. */
    rectangle(m, o, 0.25, 0.25, 3.75, 3.75, 1);
    rectangle(m, w, 1.5, 1, 2.5, 2, 1);
    rectangle(m, u, 0.25, 0.25, 3.75, 3.75, 2);
    apex = pm_mesh_add_vertex(m, 2, 1.5, apex_z);
    pm_mesh_add_tri(m, u[0], u[1], u[2]);
    pm_mesh_add_tri(m, u[0], u[2], u[3]);
    for (i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        pm_mesh_add_tri(m, o[i], o[j], u[j]);
        pm_mesh_add_tri(m, o[i], u[j], u[i]);
        pm_mesh_add_tri(m, o[i], w[j], o[j]);
        pm_mesh_add_tri(m, o[i], w[i], w[j]);
        pm_mesh_add_tri(m, w[i], apex, w[j]);
    }
}

/* Flush faces covering all three corners of a triangle with a piece between
   them (docs/validity.md): the triangle's own probes start on the other
   shell and are skipped, but the other shell's triangles that leave the
   plane along the piece's edges start theirs inside the box. */
static void test_flush_faces_around_a_window(void** state) {
    const expectation pocket = {POLYMASS_OK, POLYMASS_OK, POLYMASS_WARNING_TOUCHING_FACES,
                                16.0 + 3.5 * 3.5 - 0.5 / 3.0};
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    slab_over_a_window(&m, 0.0);
    expect_everywhere("a slab through a window, its apex on the box's floor", &m, overlap);
    pm_mesh_free(&m);
    pm_mesh_init(&m);
    slab_over_a_window(&m, 0.5);
    expect_everywhere("a slab through a window, its apex inside the box", &m, overlap);
    pm_mesh_free(&m);
    pm_mesh_init(&m);
    slab_over_a_window(&m, 1.5);
    expect_everywhere("a slab with a pocket over the window, resting", &m, pocket);
    pm_mesh_free(&m);
}

/* The shell list refuses what it cannot fill or judge, saying why. */
static void test_shell_list_refuses_bad_arguments(void** state) {
    polymass_context* ctx = pm_context_new(CHECKED);
    polymass_context* trusting = pm_context_new(POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    polymass_shell shells[2];
    uint64_t count = 0;
    pm_mesh m;
    polymass_mesh_desc desc;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    desc = pm_mesh_desc(&m);
    memset(shells, 0, sizeof shells);
    shells[0].struct_size = sizeof shells[0];
    shells[1].struct_size = sizeof shells[1] - 8;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_shell_list(shells, 1, NULL, ctx, &desc));
    assert_non_null(strstr(polymass_context_message(ctx), "out_shell_count"));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_shell_list(shells, 2, &count, ctx, &desc));
    assert_non_null(strstr(polymass_context_message(ctx), "out_shells[1].struct_size"));
    PM_ASSERT_STATUS(trusting, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_shell_list(shells, 1, &count, trusting, &desc));
    assert_non_null(strstr(polymass_context_message(trusting), "topology checks"));
    PM_ASSERT_OK(ctx, polymass_mesh_shell_list(shells, 1, &count, ctx, &desc));
    assert_int_equal(count, 1);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_SOLID);
    pm_mesh_free(&m);
    polymass_context_destroy(trusting);
    polymass_context_destroy(ctx);
}

/* No false positive: every exact-reference solid passes the check, far from
   the origin too, with bit-identical results. */
static void test_reference_solids_do_not_intersect(void** state) {
    size_t r, k;
    (void)state;
    for (r = 0; r < PM_REF_COUNT; ++r) {
        pm_mesh solid;
        pm_mesh_init(&solid);
        pm_mesh_from_reference(&solid, &pm_reference_solids[r]);
        for (k = 0; k < PLACEMENTS; ++k) {
            pm_mesh m;
            int32_t unchecked = -1, status;
            uint32_t warnings = 0;
            double volume = 0;
            pm_mesh_placed(&m, &solid, &placements[k]);
            status = verdicts(&m, &unchecked, &warnings, &volume);
            if (status != unchecked) {
                fail_msg("%s, %s: %s with the check, %s without", pm_reference_solids[r].name,
                         placements[k].name, polymass_status_string(status),
                         polymass_status_string(unchecked));
            }
            if (!(warnings & POLYMASS_WARNING_TOUCHING_FACES) !=
                !pm_reference_touches_itself(&pm_reference_solids[r])) {
                fail_msg("%s, %s: touching faces %s", pm_reference_solids[r].name,
                         placements[k].name,
                         warnings & POLYMASS_WARNING_TOUCHING_FACES ? "found" : "missed");
            }
            pm_mesh_free(&m);
        }
        pm_mesh_free(&solid);
    }
    printf("  %d reference solids x %d placements: no intersection\n", (int)PM_REF_COUNT,
           (int)PLACEMENTS);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_overlapping_cubes),
        cmocka_unit_test(test_cube_overlapping_a_rotated_cube),
        cmocka_unit_test(test_vertex_pushed_through_the_opposite_face),
        cmocka_unit_test(test_torus_through_itself),
        cmocka_unit_test(test_shells_touching_along_a_face),
        cmocka_unit_test(test_cavities_and_parts_in_hollows),
        cmocka_unit_test(test_solid_inside_a_solid_counts_twice),
        cmocka_unit_test(test_inside_out_shells),
        cmocka_unit_test(test_report_lists_pairs_and_shells),
        cmocka_unit_test(test_piles_of_copies_stop_counting),
        cmocka_unit_test(test_copies_are_paired_as_triangles_are),
        cmocka_unit_test(test_coinciding_faces_of_two_shells),
        cmocka_unit_test(test_surface_welded_to_its_copy),
        cmocka_unit_test(test_shell_passing_through_a_face_along_its_edges),
        cmocka_unit_test(test_flush_faces_around_a_window),
        cmocka_unit_test(test_shell_list_refuses_bad_arguments),
        cmocka_unit_test(test_subnormal_surfaces),
        cmocka_unit_test(test_reference_solids_do_not_intersect),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
