/* Solids against exact values: closed forms written here, and the exact
 * rational reference of reference/exact_reference.h for the general shapes. */
#include "test_support.h"

#include <math.h>
#include <string.h>

/* Runs check on every reference solid, all through one context. */
static void for_each_reference_solid(void (*check)(polymass_context*, const pm_reference_solid*)) {
    polymass_context* ctx = pm_context_new();
    int k;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        check(ctx, &pm_reference_solids[k]);
    }
    polymass_context_destroy(ctx);
}

/* Straight from the committed arrays, through
   polymass_mass_properties_compute: the exact values, no warning but of faces
   touching by construction. */
static void check_reference_solid_exact(polymass_context* ctx, const pm_reference_solid* ref) {
    polymass_mass_properties p;
    PM_ASSERT_REFERENCE_COMPUTE(ctx, ref, &p);
    assert_int_equal(p.warnings,
                     pm_reference_touches_itself(ref) ? POLYMASS_WARNING_TOUCHING_FACES : 0);
    assert_string_equal(polymass_context_message(ctx), "");
}

static void test_reference_solids_exact(void** state) {
    (void)state;
    for_each_reference_solid(check_reference_solid_exact);
}

/* polymass_mesh_create + polymass_mesh_mass_properties give the very same
   numbers as polymass_mass_properties_compute, and the diagnostics of a valid
   solid are clean with signed_volume = volume. */
static void check_reference_solid_via_mesh_object(polymass_context* ctx,
                                                  const pm_reference_solid* ref) {
    const polymass_mesh_desc desc = pm_reference_desc(ref);
    polymass_mesh* mesh = NULL;
    polymass_mass_properties a, b;
    polymass_diagnostics d;
    pm_props_init(&b);
    PM_ASSERT_OK(ctx, pm_compute_reference(&a, ctx, ref));
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc, NULL));
    assert_non_null(mesh);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&b, ctx, mesh, NULL));
    PM_ASSERT_SAME_PROPERTIES(ref->name, &a, &b);
    polymass_mesh_destroy(mesh);

    pm_diagnostics_init(&d);
    PM_ASSERT_OK(ctx, pm_diagnose(&d, ctx, &desc, NULL));
    assert_int_equal(d.status, POLYMASS_OK);
    assert_int_equal(d.face_count, ref->face_count);
    assert_int_equal(d.used_vertex_count, ref->vertex_count);
    assert_int_equal(d.edge_count, ref->index_count / 2); /* closed, 2-manifold */
    assert_int_equal(d.open_edges, 0);
    assert_int_equal(d.non_manifold_edges, 0);
    assert_int_equal(d.misoriented_edges, 0);
    assert_int_equal(d.non_planar_faces, 0);
    assert_int_equal(d.degenerate_faces, 0);
    assert_true(d.first_open_edges[0][0] == POLYMASS_NONE);
    assert_true(d.first_non_planar_faces[0] == POLYMASS_NONE);
    PM_ASSERT_REL(ref->name, ref->volume, d.signed_volume, PM_TOL);
}

static void test_reference_solids_via_mesh_object(void** state) {
    (void)state;
    for_each_reference_solid(check_reference_solid_via_mesh_object);
}

/* Closed-form boxes, as quads and as triangles, at and away from the origin. */
static void test_boxes_closed_form(void** state) {
    static const double boxes[][2][3] = {
        {{0, 0, 0}, {1, 1, 1}},
        {{0, 0, 0}, {4, 2, 1}},
        {{-1, 0.5, 2}, {2, 2, 2.625}},
        {{-3.5, -2.25, -1.125}, {-3, 1.75, 0.5}},
        {{10, 20, 30}, {10.0625, 20.5, 38}}, /* thin plate, far from the origin */
    };
    polymass_context* ctx = pm_context_new();
    size_t k;
    int triangulate;
    (void)state;
    for (k = 0; k < sizeof boxes / sizeof boxes[0]; ++k) {
        const pm_expected e = pm_expected_box(boxes[k][0], boxes[k][1]);
        for (triangulate = 0; triangulate < 2; ++triangulate) {
            pm_mesh m;
            polymass_mass_properties p;
            pm_mesh_box(&m, boxes[k][0], boxes[k][1], triangulate);
            PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
            PM_ASSERT_PROPERTIES(triangulate ? "box (triangles)" : "box (quads)", &e, &p, PM_TOL);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(ctx);
}

/* The unit cube at the origin corner: simple numbers, products of inertia
   about the origin negative (I = integral (|r|^2 Id - r r^T)). */
static void test_unit_cube_sign_convention(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    pm_mesh m;
    int i;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_REL("volume", 1.0, p.volume, PM_TOL);
    PM_ASSERT_REL("surface_area", 6.0, p.surface_area, PM_TOL);
    for (i = 0; i < 3; ++i) {
        PM_ASSERT_REL("center_of_mass", 0.5, p.center_of_mass[i], PM_TOL);
        PM_ASSERT_REL("Ic diagonal = 1/6", 1.0 / 6.0, p.inertia[4 * i], PM_TOL);
        PM_ASSERT_REL("Io diagonal = 2/3", 2.0 / 3.0, p.inertia_origin[4 * i], PM_TOL);
    }
    /* -integral x y dV = -1/4 */
    PM_ASSERT_REL("Io xy", -0.25, p.inertia_origin[1], PM_TOL);
    PM_ASSERT_REL("Io xz", -0.25, p.inertia_origin[2], PM_TOL);
    PM_ASSERT_REL("Io yz", -0.25, p.inertia_origin[5], PM_TOL);
    PM_ASSERT_REL("Io yx", -0.25, p.inertia_origin[3], PM_TOL);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Corner tetrahedron with legs a, b, c from a corner p:
   V = abc/6, C = p + (a, b, c)/4, about C: Ixx = 3V (b^2 + c^2)/80,
   Ixy = +V ab/80 (the product integral is -V ab/80, negated). */
static pm_expected corner_tetra_expected(const double p[3], double a, double b, double c) {
    static const double origin[3] = {0, 0, 0};
    pm_expected e;
    memset(&e, 0, sizeof e);
    e.volume = a * b * c / 6;
    e.center_of_mass[0] = p[0] + a / 4;
    e.center_of_mass[1] = p[1] + b / 4;
    e.center_of_mass[2] = p[2] + c / 4;
    e.inertia[0] = 3 * e.volume * (b * b + c * c) / 80;
    e.inertia[4] = 3 * e.volume * (a * a + c * c) / 80;
    e.inertia[8] = 3 * e.volume * (a * a + b * b) / 80;
    e.inertia[1] = e.inertia[3] = e.volume * a * b / 80;
    e.inertia[2] = e.inertia[6] = e.volume * a * c / 80;
    e.inertia[5] = e.inertia[7] = e.volume * b * c / 80;
    pm_parallel_axis(e.inertia_origin, e.inertia, e.volume, e.center_of_mass, origin);
    e.surface_area =
        0.5 * (a * b + b * c + c * a) + 0.5 * sqrt(a * a * b * b + b * b * c * c + c * c * a * a);
    e.size = sqrt(a * a + b * b + c * c);
    return e;
}

static void test_corner_tetrahedron_closed_form(void** state) {
    static const double corners[][3] = {{0, 0, 0}, {0.5, 0.25, -0.125}, {-7, 3, 11}};
    static const double legs[][3] = {{1, 1, 1}, {2, 1.5, 0.75}, {0.25, 4, 1}};
    polymass_context* ctx = pm_context_new();
    size_t k;
    (void)state;
    for (k = 0; k < 3; ++k) {
        const double* p = corners[k];
        const double a = legs[k][0], b = legs[k][1], c = legs[k][2];
        const pm_expected e = corner_tetra_expected(p, a, b, c);
        polymass_mass_properties r;
        pm_mesh m;
        pm_mesh_init(&m);
        pm_mesh_add_vertex(&m, p[0], p[1], p[2]);
        pm_mesh_add_vertex(&m, p[0] + a, p[1], p[2]);
        pm_mesh_add_vertex(&m, p[0], p[1] + b, p[2]);
        pm_mesh_add_vertex(&m, p[0], p[1], p[2] + c);
        pm_mesh_add_tri(&m, 0, 2, 1);
        pm_mesh_add_tri(&m, 0, 1, 3);
        pm_mesh_add_tri(&m, 0, 3, 2);
        pm_mesh_add_tri(&m, 1, 2, 3);
        PM_ASSERT_OK(ctx, pm_compute(&r, ctx, &m, NULL));
        PM_ASSERT_PROPERTIES("corner tetrahedron", &e, &r, PM_TOL);
        pm_mesh_free(&m);
    }
    /* The generator's corner tetrahedron agrees with the closed form. */
    {
        static const double p[3] = {0.5, 0.25, -0.125};
        const pm_expected closed = corner_tetra_expected(p, 2, 1.5, 0.75);
        polymass_mass_properties r;
        PM_ASSERT_OK(ctx, pm_compute_reference(&r, ctx, &pm_reference_solids[PM_REF_TETRA_CORNER]));
        PM_ASSERT_PROPERTIES("reference corner tetrahedron vs closed form", &closed, &r, PM_TOL);
    }
    polymass_context_destroy(ctx);
}

/* Regular tetrahedron of edge e: V = e^3 / (6 sqrt 2), I = m e^2 / 20 Id. */
static void test_regular_tetrahedron_closed_form(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TETRA_REGULAR];
    const double edge = 1.5 * sqrt(2.0);
    const double volume = edge * edge * edge / (6 * sqrt(2.0));
    const double moment = volume * edge * edge / 20;
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    int i;
    (void)state;
    PM_ASSERT_OK(ctx, pm_compute_reference(&p, ctx, ref));
    PM_ASSERT_REL("volume", volume, p.volume, PM_TOL);
    PM_ASSERT_REL("surface area = sqrt(3) e^2", sqrt(3.0) * edge * edge, p.surface_area, PM_TOL);
    PM_ASSERT_ABS("com x", 0.5, p.center_of_mass[0], PM_TOL);
    PM_ASSERT_ABS("com y", -0.25, p.center_of_mass[1], PM_TOL);
    PM_ASSERT_ABS("com z", 0.125, p.center_of_mass[2], PM_TOL);
    for (i = 0; i < 9; ++i) {
        PM_ASSERT_ABS("inertia = m e^2 / 20 Id", i % 4 == 0 ? moment : 0.0, p.inertia[i],
                      PM_TOL * moment);
    }
    for (i = 0; i < 3; ++i) {
        PM_ASSERT_REL("principal moments all m e^2 / 20", moment, p.principal_moments[i], PM_TOL);
    }
    polymass_context_destroy(ctx);
}

/* Prism of a regular-ish n-gon built here (C-side) equals the reference. */
static void test_prisms_built_in_c_match_reference(void** state) {
    /* The reference's L prism, rebuilt from its outline. */
    static const double ell[] = {-0.75, 0.125, 1.25,  0.125, 1.25,  0.625,
                                 -0.25, 0.625, -0.25, 1.625, -0.75, 1.625};
    const pm_expected e = pm_expected_from_reference(&pm_reference_solids[PM_REF_PRISM_L]);
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_prism(&m, ell, 6, 0.25, 1.0);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_PROPERTIES("L prism", &e, &p, PM_TOL);
    /* Closed form of the L: a 2 x 0.5 bar plus a 0.5 x 1 upright, height 0.75. */
    {
        static const double lo1[3] = {-0.75, 0.125, 0.25}, hi1[3] = {1.25, 0.625, 1.0};
        static const double lo2[3] = {-0.75, 0.625, 0.25}, hi2[3] = {-0.25, 1.625, 1.0};
        const pm_expected a = pm_expected_box(lo1, hi1), b = pm_expected_box(lo2, hi2);
        pm_expected sum = pm_expected_sum(&a, &b);
        sum.surface_area -= 2 * 0.5 * 0.75; /* the shared internal face */
        sum.size = e.size;
        PM_ASSERT_PROPERTIES("L prism as two boxes", &sum, &p, PM_TOL);
    }
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Cube with a cavity = outer box minus inner box (closed forms). */
static void test_cube_with_cavity_closed_form(void** state) {
    static const double olo[3] = {-0.75, -0.5, -1.125}, ohi[3] = {1.25, 1.5, 0.875};
    static const double ilo[3] = {-0.25, 0.25, -0.125}, ihi[3] = {0.5, 1.0, 0.625};
    const pm_expected outer = pm_expected_box(olo, ohi);
    pm_expected inner = pm_expected_box(ilo, ihi), e;
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    pm_mesh m, cavity;
    int i;
    (void)state;
    inner.volume = -inner.volume;
    for (i = 0; i < 9; ++i) {
        inner.inertia[i] = -inner.inertia[i];
        inner.inertia_origin[i] = -inner.inertia_origin[i];
    }
    e = pm_expected_sum(&outer, &inner); /* the cavity's area adds */
    e.size = outer.size;
    pm_mesh_box(&m, olo, ohi, 0);
    pm_mesh_box(&cavity, ilo, ihi, 1);
    pm_mesh_reverse_all(&cavity);
    pm_mesh_append(&m, &cavity);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_PROPERTIES("cube with cavity", &e, &p, PM_TOL);
    /* the reference cube with cavity is the same solid */
    {
        const pm_expected r = pm_expected_from_reference(&pm_reference_solids[PM_REF_CUBE_CAVITY]);
        PM_ASSERT_PROPERTIES("reference cube_cavity vs closed form", &r, &p, PM_TOL);
    }
    pm_mesh_free(&cavity);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* A square ring of four boxes (four shells touching face to face) is the sum
   of the four boxes. */
static void test_ring_of_boxes_closed_form(void** state) {
    static const double lo[4][3] = {
        {-1.5, -1.5, 0}, {-1.5, 0.75, 0}, {-1.5, -0.75, 0}, {0.75, -0.75, 0}};
    static const double hi[4][3] = {
        {1.5, -0.75, 0.5}, {1.5, 1.5, 0.5}, {-0.75, 0.75, 0.5}, {1.5, 0.75, 0.5}};
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_RING_OF_BOXES];
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    pm_expected e = pm_expected_box(lo[0], hi[0]);
    int k;
    (void)state;
    for (k = 1; k < 4; ++k) {
        const pm_expected b = pm_expected_box(lo[k], hi[k]);
        e = pm_expected_sum(&e, &b);
    }
    e.size = pm_expected_from_reference(ref).size;
    PM_ASSERT_OK(ctx, pm_compute_reference(&p, ctx, ref));
    PM_ASSERT_PROPERTIES("ring of four boxes", &e, &p, PM_TOL);
    /* centred ring: centre of mass on the z axis */
    PM_ASSERT_ABS("com x", 0.0, p.center_of_mass[0], PM_TOL);
    PM_ASSERT_ABS("com y", 0.0, p.center_of_mass[1], PM_TOL);
    polymass_context_destroy(ctx);
}

/* A quad cube and the same cube in triangles are the same solid. */
static void test_cube_quads_equals_triangles(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties q, t;
    const double lo[3] = {0.25, -0.5, 0.75}, hi[3] = {1.75, 1.0, 2.25};
    const pm_expected e = pm_expected_box(lo, hi);
    (void)state;
    PM_ASSERT_OK(ctx, pm_compute_reference(&q, ctx, &pm_reference_solids[PM_REF_CUBE_QUADS]));
    PM_ASSERT_OK(ctx, pm_compute_reference(&t, ctx, &pm_reference_solids[PM_REF_CUBE_TRIS]));
    PM_ASSERT_PROPERTIES("cube quads vs closed form", &e, &q, PM_TOL);
    PM_ASSERT_PROPERTIES("cube triangles vs closed form", &e, &t, PM_TOL);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reference_solids_exact),
        cmocka_unit_test(test_reference_solids_via_mesh_object),
        cmocka_unit_test(test_boxes_closed_form),
        cmocka_unit_test(test_unit_cube_sign_convention),
        cmocka_unit_test(test_corner_tetrahedron_closed_form),
        cmocka_unit_test(test_regular_tetrahedron_closed_form),
        cmocka_unit_test(test_prisms_built_in_c_match_reference),
        cmocka_unit_test(test_cube_with_cavity_closed_form),
        cmocka_unit_test(test_ring_of_boxes_closed_form),
        cmocka_unit_test(test_cube_quads_equals_triangles),
    };
    return cmocka_run_group_tests_name("analytic_solids", tests, NULL, NULL);
}
