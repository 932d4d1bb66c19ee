/* How shells lie inside one another, once no face crosses another: the
 * count of winding numbers (src/core/shell_nesting.cpp). Cavities, parts in
 * hollows and parts resting on each other stay valid; a solid inside a solid,
 * a shell inside out and a shell passing through another where they touch
 * are refused. */
#include <stdio.h>
#include <string.h>

#include "overlap_cases.h"

#include <math.h>

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
        polymass_context* ctx = pm_context_new();
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

/* The shell list refuses what it cannot fill, saying why; shells it could
   not judge (the topology checks skipped) are listed unjudged. */
static void test_shell_list_refuses_bad_arguments(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_shell shells[2];
    uint64_t count = 0;
    pm_mesh m;
    polymass_mesh_desc desc;
    polymass_mesh* mesh = NULL;
    (void)state;
    pm_mesh_init(&m);
    box(&m, 0, 0, 0, 1, 1, 1, 0, 0);
    desc = pm_mesh_desc(&m);
    memset(shells, 0, sizeof shells);
    shells[0].struct_size = sizeof shells[0];
    shells[1].struct_size = sizeof shells[1] - 8;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_shells(shells, 1, NULL, ctx, mesh));
    assert_non_null(strstr(polymass_context_message(ctx), "out_shell_count"));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_shells(shells, 2, &count, ctx, mesh));
    assert_non_null(strstr(polymass_context_message(ctx), "out_shells[1].struct_size"));
    PM_ASSERT_OK(ctx, polymass_mesh_shells(shells, 1, &count, ctx, mesh));
    assert_int_equal(count, 1);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_SOLID);
    polymass_mesh_destroy(mesh);
    PM_ASSERT_OK(ctx, shell_list(shells, 1, &count, ctx, &m, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS));
    assert_int_equal(count, 1);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_UNJUDGED);
    assert_int_equal(shells[0].face_count, 6);
    assert_int_equal(shells[0].first_face, 0);
    assert_true(isnan(shells[0].signed_volume));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* A surface inside out as a whole passes the checks before the shells
   (closed, manifold, oriented, planar): its shells are judged, signed as
   found - inside out, refused - or, accepted inside out, counted turned. */
static void test_surface_inside_out_as_a_whole(void** state) {
    const pm_reference_solid* tetra = &pm_reference_solids[PM_REF_TETRA_CORNER];
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics d;
    polymass_shell shells[2];
    uint64_t count = 0;
    pm_mesh m;
    (void)state;
    pm_mesh_from_reference(&m, tetra);
    pm_mesh_reverse_all(&m);
    memset(shells, 0, sizeof shells);
    shells[0].struct_size = shells[1].struct_size = sizeof shells[0];
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED, pm_check(&d, ctx, &m));
    assert_true(d.checks & POLYMASS_CHECKED_SHELLS);
    assert_int_equal(d.inverted_shells, 1);
    assert_int_equal(d.first_inverted_shells[0], 0);
    PM_ASSERT_OK(ctx, shell_list(shells, 2, &count, ctx, &m, CHECKED));
    assert_int_equal(count, 1);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_INVERTED);
    PM_ASSERT_REL("signed as found", -tetra->volume, shells[0].signed_volume, PM_TOL);
    PM_ASSERT_OK(ctx, shell_list(shells, 2, &count, ctx, &m, POLYMASS_OPTION_ACCEPT_INVERTED));
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_SOLID);
    PM_ASSERT_REL("counted turned", tetra->volume, shells[0].signed_volume, PM_TOL);
    /* two shells, both inside out: each judged, inside out */
    box(&m, 5, 0, 0, 6, 1, 1, 1, 1);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED, pm_check(&d, ctx, &m));
    assert_int_equal(d.inverted_shells, 2);
    PM_ASSERT_OK(ctx, shell_list(shells, 2, &count, ctx, &m, CHECKED));
    assert_int_equal(count, 2);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_INVERTED);
    assert_int_equal(shells[1].kind, POLYMASS_SHELL_INVERTED);
    PM_ASSERT_REL("the box, signed as found", -1.0, shells[1].signed_volume, PM_TOL);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shells_touching_along_a_face),
        cmocka_unit_test(test_cavities_and_parts_in_hollows),
        cmocka_unit_test(test_solid_inside_a_solid_counts_twice),
        cmocka_unit_test(test_inside_out_shells),
        cmocka_unit_test(test_shell_passing_through_a_face_along_its_edges),
        cmocka_unit_test(test_flush_faces_around_a_window),
        cmocka_unit_test(test_shell_list_refuses_bad_arguments),
        cmocka_unit_test(test_surface_inside_out_as_a_whole),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
