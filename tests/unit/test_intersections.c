/* Faces that cross each other or only touch: the search for meeting faces
 * (src/core/surface_contacts.cpp). Crossing surfaces must be refused, and the
 * surfaces that only look alike (touching parts, folds, copies on one shell)
 * must keep their verdicts. How shells nest is test_nesting.c's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "overlap_cases.h"
#include "reference/exact_reference.h"

/* Whether face pair a comes before b: by first face, then by second. */
static int pair_before(const uint64_t a[2], const uint64_t b[2]) {
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

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
        polymass_context* ctx = pm_context_new();
        polymass_mass_properties p;
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_int_equal(p.warnings, 0);
        polymass_context_destroy(ctx);
    }
    pm_mesh_free(&m);
}

/* An octahedron of radius 1 at the origin whose top corner (0, 0, 1) is
   moved to `apex`. */
static void octahedron_with_apex_at(pm_mesh* m, double x, double y, double z) {
    static const double origin[3] = {0, 0, 0};
    pm_mesh_init(m);
    octahedron(m, origin, 1.0, 0);
    m->positions[3 * 4 + 0] = x;
    m->positions[3 * 4 + 1] = y;
    m->positions[3 * 4 + 2] = z;
}

/* Neighbours that cross: pairs sharing an edge or a corner are decided from
   that, and folding a surface onto itself must still be told from a dent. */
static void test_neighbours_folded_through_each_other(void** state) {
    const expectation dented = {POLYMASS_OK, POLYMASS_OK, 0, 2.0 / 3.0 - 1.0 / 6.0};
    pm_mesh m;
    (void)state;
    /* The top corner pushed down inside the lower half: every upper face
       folds against its neighbours, none crosses; the volume is the lower
       pyramid less the dent (height 1/4 over the square of area 2). */
    octahedron_with_apex_at(&m, 0.125, 0.0625, -0.25);
    expect_everywhere("an octahedron dented to below its waist", &m, dented);
    pm_mesh_free(&m);
    /* Pushed out through a lower face: the upper faces beside that face's
       edge pass through it, sharing one corner with it. */
    octahedron_with_apex_at(&m, 0.375, 0.25, -0.625);
    expect_everywhere("an octahedron's corner poking through a face beside it", &m, overlap);
    pm_mesh_free(&m);
}

/* A pyramid flattened onto its base: each side face lies on the base face
   sharing its edge, facing the other way, a sheet of no thickness. It
   encloses nothing, and the check says no more than the topology does. The
   computation stops at the zero volume before the check, so the check's own
   verdict is read from the full report, which runs it whatever the volume. */
static void test_faces_folded_flat_onto_their_neighbours(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    size_t k;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_vertex(&m, 0, 0, 0);
    pm_mesh_add_vertex(&m, 1, 0, 0);
    pm_mesh_add_vertex(&m, 1, 1, 0);
    pm_mesh_add_vertex(&m, 0, 1, 0);
    pm_mesh_add_vertex(&m, 0.4, 0.3, 0); /* the apex, in the base's plane */
    pm_mesh_add_tri(&m, 0, 2, 1);
    pm_mesh_add_tri(&m, 0, 3, 2);
    pm_mesh_add_tri(&m, 0, 1, 4);
    pm_mesh_add_tri(&m, 1, 2, 4);
    pm_mesh_add_tri(&m, 2, 3, 4);
    pm_mesh_add_tri(&m, 3, 0, 4);
    for (k = 0; k < placement_count; ++k) {
        pm_mesh placed;
        int32_t unchecked = -1;
        uint32_t warnings = 0;
        double volume = 0;
        int32_t checked;
        pm_mesh_placed(&placed, &m, &placements[k]);
        checked = verdicts(&placed, &unchecked, &warnings, &volume);
        assert_int_equal(checked, unchecked);
        assert_int_not_equal(unchecked, POLYMASS_OK);
        {
            polymass_diagnostics report;
            pm_check(&report, ctx, &placed);
            if (report.intersecting_face_pairs != 0) {
                fail_msg("%s: %llu face pairs found crossing", placements[k].name,
                         (unsigned long long)report.intersecting_face_pairs);
            }
        }
        pm_mesh_free(&placed);
    }
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Overlapping cubes of subnormal size (2^-1050: every corner still exact) are
   still found to cross; the search's grid over them must not overflow (it
   once scaled by 1023 / width, infinite for a subnormal width). */
static void test_subnormal_surfaces(void** state) {
    const double scale = ldexp(1.0, -1050);
    pm_mesh m;
    polymass_context* ctx = pm_context_new();
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
    polymass_context* ctx = pm_context_new();
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
            if (i > 0) /* ascending */
                assert_true(pair_before(d.first_intersecting_face_pairs[i - 1],
                                        d.first_intersecting_face_pairs[i]));
        } else {
            assert_true(d.first_intersecting_face_pairs[i][0] == POLYMASS_NONE);
        }
    }
    assert_int_equal(d.touching_face_pairs, 0);
    for (i = 0; i < 3; ++i) {
        memset(&shells[i], 0, sizeof shells[i]);
        shells[i].struct_size = sizeof shells[i];
    }
    PM_ASSERT_OK(ctx, shell_list(shells, 3, &count, ctx, &m, CHECKED));
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
    count = 0;
    PM_ASSERT_OK(ctx, shell_list(NULL, 0, &count, ctx, &m, CHECKED));
    assert_int_equal(count, 3);
    PM_ASSERT_OK(ctx, shell_list(shells, 3, &count, ctx, &m, CHECKED));
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
    PM_ASSERT_OK(ctx, shell_list(shells, 3, &count, ctx, &m, CHECKED));
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

/* Whether d lists its first crossing pairs in ascending order, each of faces
   of two cubes of 12 triangles (a pile's cubes cross only each other). */
static int crossing_pairs_of_two_cubes(const polymass_diagnostics* d) {
    size_t i;
    for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
        const uint64_t* pair = d->first_intersecting_face_pairs[i];
        if (pair[0] >= pair[1] || pair[0] / 12 == pair[1] / 12) return 0;
        if (i > 0 && !pair_before(d->first_intersecting_face_pairs[i - 1], pair)) return 0;
    }
    return 1;
}

/* Piles of copies of a part meet in face pairs by the square of the copies
   (a fuzzed pile of 252 coincident cubes took minutes): counting stops at 2048
   pairs of a kind and says "at least 2048". Past the touching pairs' stop the
   pairs listed are still the lowest, those of a pile of four. Past the
   crossing pairs' stop the search ends (POLYMASS_MAX_COUNTED_FACE_PAIRS):
   the pairs listed are crossing ones, the same on one thread and on two.
   Forty copies pass the limit for both kinds. */
static void test_piles_of_copies_stop_counting(void** state) {
    static const double steps[] = {1e-3, 0.0}; /* crossing, then touching */
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics few, many, on_two_threads;
    size_t s, i;
    (void)state;
    for (s = 0; s < 2; ++s) {
        const int32_t status = check_pile(&few, ctx, 4, steps[s]);
        const uint64_t few_count = s == 0 ? few.intersecting_face_pairs : few.touching_face_pairs;
        assert_true(few_count >= POLYMASS_DIAGNOSTIC_LOCATIONS && few_count < 2048);
        if (s == 0) assert_null(strstr(polymass_context_message(ctx), "at least"));
        PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, 1));
        PM_ASSERT_STATUS(ctx, status, check_pile(&many, ctx, 40, steps[s]));
        PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, 2));
        PM_ASSERT_STATUS(ctx, status, check_pile(&on_two_threads, ctx, 40, steps[s]));
        assert_memory_equal(&many, &on_two_threads, sizeof many);
        if (s == 0) {
            assert_int_equal(status, POLYMASS_ERROR_INTERSECTING);
            assert_non_null(strstr(polymass_context_message(ctx), "(at least 2048 "));
            assert_int_equal(many.intersecting_face_pairs, 2048);
            assert_true(crossing_pairs_of_two_cubes(&many));
        } else {
            assert_int_equal(many.touching_face_pairs, 2048);
            for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
                assert_int_equal(many.first_touching_face_pairs[i][0],
                                 few.first_touching_face_pairs[i][0]);
                assert_int_equal(many.first_touching_face_pairs[i][1],
                                 few.first_touching_face_pairs[i][1]);
            }
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
    polymass_context* ctx = pm_context_new();
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

/* A surface of triangles given with aligned 32-bit indices is searched
   through the caller's indices; misaligned or 16-bit ones through a copy
   (IndexedSurface). Both must find the same pairs: two cubes crossing, a
   third resting on one of them (touching pairs). */
static void test_pairs_whatever_the_index_layout(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics d[3];
    char message[512];
    unsigned char* misaligned;
    uint16_t* narrow;
    pm_mesh m;
    size_t k;
    int layout;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 1, 0);
    box(&m, 0.5, 0.5, 0.5, 1.5, 1.5, 1.5, 1, 0);
    box(&m, 0, 0, 1, 1, 1, 2, 1, 0);
    misaligned = malloc(m.index_count * sizeof(uint32_t) + 1);
    narrow = malloc(m.index_count * sizeof *narrow);
    assert_non_null(misaligned);
    assert_non_null(narrow);
    memcpy(misaligned + 1, m.indices, m.index_count * sizeof(uint32_t));
    for (k = 0; k < m.index_count; ++k) narrow[k] = (uint16_t)m.indices[k];
    for (layout = 0; layout < 3; ++layout) {
        polymass_mesh_desc desc = pm_mesh_desc(&m);
        const polymass_options options = pm_options(0, 0.0);
        if (layout == 1) desc.indices = misaligned + 1;
        if (layout == 2) {
            desc.indices = narrow;
            desc.index_type = POLYMASS_INDEX_UINT16;
        }
        pm_diagnostics_init(&d[layout]);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INTERSECTING,
                         pm_diagnose(&d[layout], ctx, &desc, &options));
        if (layout == 0) {
            snprintf(message, sizeof message, "%s", polymass_context_message(ctx));
        } else {
            assert_string_equal(message, polymass_context_message(ctx));
            assert_same_pairs(&d[0], &d[layout]);
        }
    }
    assert_true(d[0].intersecting_face_pairs > 0);
    assert_true(d[0].touching_face_pairs > 0);
    free(misaligned);
    free(narrow);
    pm_mesh_free(&m);
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
    const uint32_t flags = CHECKED | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
    polymass_context* checked = pm_context_new();
    polymass_context* plain = pm_context_new();
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
                PM_ASSERT_STATUS(checked, POLYMASS_ERROR_ZERO_VOLUME,
                                 pm_check_flags(&d, checked, &m, flags));
                assert_int_equal(d.intersecting_face_pairs, 0);
            } else {
                PM_ASSERT_STATUS(checked, POLYMASS_ERROR_INTERSECTING,
                                 pm_check_flags(&d, checked, &m, flags));
                /* each face with its copy (quads: with both halves' copies) */
                assert_true(d.intersecting_face_pairs >= copy.face_count);
                /* Without the check the solid counts twice, as documented. */
                PM_ASSERT_OK(
                    plain, pm_compute_flags(&p, plain, &m,
                                            UNCHECKED | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD, NULL));
                PM_ASSERT_REL("volume counted twice", 2.0, p.volume, 1e-15);
            }
            pm_mesh_free(&copy);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(checked);
    polymass_context_destroy(plain);
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
        for (k = 0; k < placement_count; ++k) {
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
           (int)placement_count);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_overlapping_cubes),
        cmocka_unit_test(test_cube_overlapping_a_rotated_cube),
        cmocka_unit_test(test_vertex_pushed_through_the_opposite_face),
        cmocka_unit_test(test_torus_through_itself),
        cmocka_unit_test(test_neighbours_folded_through_each_other),
        cmocka_unit_test(test_faces_folded_flat_onto_their_neighbours),
        cmocka_unit_test(test_report_lists_pairs_and_shells),
        cmocka_unit_test(test_piles_of_copies_stop_counting),
        cmocka_unit_test(test_copies_are_paired_as_triangles_are),
        cmocka_unit_test(test_pairs_whatever_the_index_layout),
        cmocka_unit_test(test_coinciding_faces_of_two_shells),
        cmocka_unit_test(test_surface_welded_to_its_copy),
        cmocka_unit_test(test_subnormal_surfaces),
        cmocka_unit_test(test_reference_solids_do_not_intersect),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
