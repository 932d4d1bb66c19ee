/* The modes (POLYMASS_MODE_REPAIR, SHELL, HULL) and their provenance.
 *
 * Repair: meshes with known answers (exact-reference solids, a polyhedral
 * sphere) are damaged - faces removed (holes of one to many triangles), faces
 * flipped, shells inverted, quads bent out of plane, faces duplicated, faces
 * of two vertices added - and the repaired answer must lie within its error
 * bound of the intact mesh's answer (volume, each coordinate of the centre of
 * mass, each inertia entry), near the origin and far from it. The test prints
 * the median ratio of the bound to the largest error it covers (over the
 * repairs whose error is more than rounding).
 * Valid solids give bit-identical results in every chain that starts with the
 * solid or repair; surfaces repair must give up on fail with a clear message.
 */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const pm_placement placements[] = {
    {"as given", 1.0, {0, 0, 0}},
    {"at (1e6, -1e6, 1e6)", 1.0, {1e6, -1e6, 1e6}},
    {"scaled 1e3, at -1e4", 1e3, {-1e4, 0, 0}},
};
#define PLACEMENT_COUNT (sizeof placements / sizeof placements[0])

/* ------------------------------------------------------------------------ */
/* Helpers                                                                  */
/* ------------------------------------------------------------------------ */

static polymass_options chain(uint32_t flags, uint32_t first, uint32_t second, uint32_t third) {
    polymass_options options = pm_options(flags, 0.0);
    options.modes[0] = first;
    options.modes[1] = second;
    options.modes[2] = third;
    return options;
}

/* Every reason of the one call's message ("solid: X; repair: Y") is in the
   mesh's ("X; repair: Y": the surface's own defect unnamed). */
static void expect_reasons_in(const char* one_call, const char* mesh_message) {
    char copy[512];
    char* part;
    snprintf(copy, sizeof copy, "%s", one_call);
    for (part = strtok(copy, ";"); part; part = strtok(NULL, ";")) {
        while (*part == ' ') ++part;
        if (strncmp(part, "solid: ", 7) == 0) part += 7;
        if (!strstr(mesh_message, part)) fail_msg("\"%s\" is not in \"%s\"", part, mesh_message);
    }
}

/* The one-call answer, which a mesh made with the same options gives too:
   the same status and reasons, the same bits, the same provenance. */
static int32_t compute_with(polymass_mass_properties* out, polymass_provenance* provenance,
                            polymass_context* ctx, const pm_mesh* m,
                            const polymass_options* options) {
    const polymass_mesh_desc desc = pm_mesh_desc(m);
    polymass_mass_properties from_mesh;
    polymass_provenance mesh_provenance;
    polymass_mesh* mesh = NULL;
    char message[512];
    int32_t status;
    pm_props_init(out);
    assert_int_equal(polymass_provenance_init(provenance, sizeof *provenance), POLYMASS_OK);
    status = polymass_mass_properties_compute(out, provenance, ctx, &desc, options, NULL);
    snprintf(message, sizeof message, "%s", polymass_context_message(ctx));
    assert_int_equal(polymass_mesh_create(&mesh, ctx, &desc, options), status);
    if (mesh == NULL) { /* the arguments: no analysis ran */
        assert_int_equal(status, POLYMASS_ERROR_INVALID_ARGUMENT);
        return status;
    }
    expect_reasons_in(message, polymass_mesh_message(mesh));
    pm_props_init(&from_mesh);
    assert_int_equal(polymass_provenance_init(&mesh_provenance, sizeof mesh_provenance),
                     POLYMASS_OK);
    assert_int_equal(polymass_mesh_mass_properties(&from_mesh, ctx, mesh, NULL), status);
    assert_int_equal(polymass_mesh_provenance(&mesh_provenance, ctx, mesh), status);
    if (status == POLYMASS_OK) {
        PM_ASSERT_SAME_PROPERTIES("one call and mesh", out, &from_mesh);
        assert_memory_equal(provenance, &mesh_provenance, sizeof mesh_provenance);
    }
    polymass_mesh_destroy(mesh);
    /* The one call's message back in the context. */
    assert_int_equal(polymass_mass_properties_compute(&from_mesh, NULL, ctx, &desc, options, NULL),
                     status);
    return status;
}

/* An icosphere of radius 1: an icosahedron whose triangles are split in four
   `levels` times, the new vertices pushed onto the sphere. */
static uint32_t midpoint(pm_mesh* m, uint32_t a, uint32_t b) {
    const double* p = m->positions;
    double x = p[3 * a] + p[3 * b], y = p[3 * a + 1] + p[3 * b + 1],
           z = p[3 * a + 2] + p[3 * b + 2];
    const double r = sqrt(x * x + y * y + z * z);
    /* Shared edges are split twice: reuse the vertex made the first time. */
    for (uint32_t v = 0; v < m->vertex_count; ++v)
        if (p[3 * v] == x / r && p[3 * v + 1] == y / r && p[3 * v + 2] == z / r) return v;
    return pm_mesh_add_vertex(m, x / r, y / r, z / r);
}

static void icosphere(pm_mesh* m, int levels) {
    const double t = (1.0 + sqrt(5.0)) / 2.0, s = sqrt(1.0 + t * t);
    /* The corners of three golden rectangles, (±1, ±t, 0) and their cyclic shifts. */
    const double corners[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                   {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                   {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    static const uint32_t faces[20][3] = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    pm_mesh_init(m);
    for (int v = 0; v < 12; ++v)
        pm_mesh_add_vertex(m, corners[v][0] / s, corners[v][1] / s, corners[v][2] / s);
    for (int f = 0; f < 20; ++f) pm_mesh_add_tri(m, faces[f][0], faces[f][1], faces[f][2]);
    for (int level = 0; level < levels; ++level) {
        pm_mesh next;
        pm_mesh_init(&next);
        for (size_t v = 0; v < m->vertex_count; ++v)
            pm_mesh_add_vertex(&next, m->positions[3 * v], m->positions[3 * v + 1],
                               m->positions[3 * v + 2]);
        for (size_t f = 0; f < m->face_count; ++f) {
            const uint32_t* c = m->indices + 3 * f;
            const uint32_t ab = midpoint(&next, c[0], c[1]), bc = midpoint(&next, c[1], c[2]),
                           ca = midpoint(&next, c[2], c[0]);
            pm_mesh_add_tri(&next, c[0], ab, ca);
            pm_mesh_add_tri(&next, c[1], bc, ab);
            pm_mesh_add_tri(&next, c[2], ca, bc);
            pm_mesh_add_tri(&next, ab, bc, ca);
        }
        pm_mesh_free(m);
        *m = next;
    }
}

/* Removes the faces whose centroids lie within `radius` of `point`. */
static size_t cut_hole(pm_mesh* m, const double point[3], double radius) {
    size_t removed = 0;
    for (size_t f = m->face_count; f-- > 0;) {
        const size_t first = pm_mesh_face_offset(m, f);
        const uint32_t n = m->face_sizes[f];
        double c[3] = {0, 0, 0};
        for (uint32_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) c[k] += m->positions[3 * m->indices[first + i] + k] / n;
        const double d =
            sqrt((c[0] - point[0]) * (c[0] - point[0]) + (c[1] - point[1]) * (c[1] - point[1]) +
                 (c[2] - point[2]) * (c[2] - point[2]));
        if (d < radius) {
            pm_mesh_remove_face(m, f);
            ++removed;
        }
    }
    return removed;
}

static void duplicate_face(pm_mesh* m, size_t face, int reversed) {
    const size_t first = pm_mesh_face_offset(m, face);
    const uint32_t n = m->face_sizes[face];
    uint32_t corners[16];
    for (uint32_t i = 0; i < n; ++i) corners[i] = m->indices[first + (reversed ? n - 1 - i : i)];
    pm_mesh_add_face(m, n, corners);
}

/* Ratios bound / actual error of the results with a nonzero error. */
typedef struct ratios {
    double values[8192];
    size_t count;
} ratios;

/* Of the volume, the centre of mass, the inertia. */
static ratios all_ratios[3];

/* Fails unless |got - truth| <= bound (up to rounding of the truth: a few
   ulps of the quantity's scale); returns the error. */
static double within(const char* what, const char* quantity, double bound, double truth, double got,
                     double scale) {
    const double error = fabs(got - truth);
    const double slack = 8.0 * DBL_EPSILON * scale;
    if (!(error <= bound + slack)) {
        print_error("%s: %s: error %.3g is outside the bound %.3g (value %.17g, truth %.17g)\n",
                    what, quantity, error, bound, got, truth);
        fail();
    }
    return error;
}

/* The looseness of a bound where the repair changed something (not where a
   planar cap or an exact fix left rounding only): the bound over the largest
   error it covers. */
static void record(ratios* r, double bound, double largest_error, double scale) {
    if (largest_error > 1e-9 * scale && r->count < sizeof r->values / sizeof r->values[0])
        r->values[r->count++] = bound / largest_error;
}

/* The answer lies within its bound of the truth. */
static void check_within_bound(const char* what, const polymass_mass_properties* truth,
                               const polymass_mass_properties* got, double size) {
    double largest = 0, worst_center = 0, worst_inertia = 0;
    for (int i = 0; i < 9; ++i) largest = fmax(largest, fabs(truth->inertia[i]));
    record(
        &all_ratios[0], got->error_bound_volume,
        within(what, "volume", got->error_bound_volume, truth->volume, got->volume, truth->volume),
        truth->volume);
    for (int k = 0; k < 3; ++k)
        worst_center =
            fmax(worst_center, within(what, "centre of mass", got->error_bound_center_of_mass,
                                      truth->center_of_mass[k], got->center_of_mass[k],
                                      size + fabs(truth->center_of_mass[k])));
    record(&all_ratios[1], got->error_bound_center_of_mass, worst_center, size);
    for (int i = 0; i < 9; ++i)
        worst_inertia = fmax(worst_inertia, within(what, "inertia", got->error_bound_inertia,
                                                   truth->inertia[i], got->inertia[i], largest));
    record(&all_ratios[2], got->error_bound_inertia, worst_inertia, largest);
}

static void message_says(const polymass_context* ctx, const char* text) {
    if (!strstr(polymass_context_message(ctx), text)) {
        print_error("the message \"%s\" does not say \"%s\"\n", polymass_context_message(ctx),
                    text);
        fail();
    }
}

static int compare(const void* a, const void* b) {
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

/* Repairs the damaged mesh in every placement and checks it against the
   intact one's answer; returns the provenance of the last placement. */
static polymass_provenance repair_and_check(const char* what, const pm_mesh* intact,
                                            const pm_mesh* damaged) {
    polymass_context* ctx = pm_context_new();
    polymass_provenance provenance;
    for (size_t p = 0; p < PLACEMENT_COUNT; ++p) {
        pm_mesh whole, broken;
        pm_mesh_placed(&whole, intact, &placements[p]);
        pm_mesh_placed(&broken, damaged, &placements[p]);
        char label[256];
        snprintf(label, sizeof label, "%s, %s", what, placements[p].name);
        polymass_mass_properties truth, got;
        const polymass_options solid =
            pm_options(POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD, 0.0);
        assert_int_equal(compute_with(&truth, &provenance, ctx, &whole, &solid), POLYMASS_OK);
        const polymass_options repair = chain(0, POLYMASS_MODE_REPAIR, 0, 0);
        const int32_t status = compute_with(&got, &provenance, ctx, &broken, &repair);
        if (status != POLYMASS_OK) {
            print_error("%s: repair failed: %s\n", label, polymass_context_message(ctx));
            fail();
        }
        assert_int_equal(provenance.mode, POLYMASS_MODE_REPAIR);
        assert_true(got.warnings & POLYMASS_WARNING_REPAIRED);
        check_within_bound(label, &truth, &got, pm_mesh_size(&whole));
        pm_mesh_free(&whole);
        pm_mesh_free(&broken);
    }
    polymass_context_destroy(ctx);
    return provenance;
}

static void reference_mesh(pm_mesh* m, int which) {
    pm_mesh_from_reference(m, &pm_reference_solids[which]);
}

/* ------------------------------------------------------------------------ */
/* Repair within its bound                                                  */
/* ------------------------------------------------------------------------ */

static void test_holes_in_a_sphere(void** state) {
    (void)state;
    pm_mesh sphere;
    icosphere(&sphere, 2); /* 320 triangles */
    static const double radii[] = {0.1, 0.3, 0.6, 1.0};
    for (size_t r = 0; r < sizeof radii / sizeof radii[0]; ++r) {
        pm_mesh broken;
        pm_mesh_copy(&broken, &sphere);
        const double point[3] = {0.6, 0.48, 0.64};
        const size_t removed = cut_hole(&broken, point, radii[r]);
        assert_true(removed > 0);
        char what[128];
        snprintf(what, sizeof what, "sphere, %zu faces removed", removed);
        const polymass_provenance provenance = repair_and_check(what, &sphere, &broken);
        assert_int_equal(provenance.holes, 1);
        assert_true(provenance.cap_area > 0 && provenance.cap_area_fraction < 1);
        assert_true(provenance.approximation_bound_volume > 0);
        pm_mesh_free(&broken);
    }
    /* Two holes at once. */
    pm_mesh broken;
    pm_mesh_copy(&broken, &sphere);
    const double a[3] = {1, 0, 0}, b[3] = {-1, 0, 0};
    cut_hole(&broken, a, 0.3);
    cut_hole(&broken, b, 0.5);
    assert_int_equal(repair_and_check("sphere, two holes", &sphere, &broken).holes, 2);
    pm_mesh_free(&broken);
    pm_mesh_free(&sphere);
}

static void test_holes_in_reference_solids(void** state) {
    (void)state;
    static const int solids[] = {PM_REF_CUBE_TRIS, PM_REF_CUBE_QUADS, PM_REF_PRISM_L,
                                 PM_REF_PRISM_STAR_TRIS, PM_REF_OCTAHEDRON_IRREGULAR};
    for (size_t s = 0; s < sizeof solids / sizeof solids[0]; ++s) {
        pm_mesh solid;
        reference_mesh(&solid, solids[s]);
        for (size_t face = 0; face < solid.face_count; face += 3) {
            pm_mesh broken;
            pm_mesh_copy(&broken, &solid);
            pm_mesh_remove_face(&broken, face);
            char what[128];
            snprintf(what, sizeof what, "%s without face %zu", pm_reference_solids[solids[s]].name,
                     face);
            const polymass_provenance provenance = repair_and_check(what, &solid, &broken);
            assert_int_equal(provenance.holes, 1);
            pm_mesh_free(&broken);
        }
        pm_mesh_free(&solid);
    }
}

static void test_flipped_faces_and_shells(void** state) {
    (void)state;
    pm_mesh sphere;
    icosphere(&sphere, 1);
    pm_mesh broken;
    pm_mesh_copy(&broken, &sphere);
    for (size_t f = 0; f < broken.face_count; f += 7) pm_mesh_reverse_face(&broken, f);
    polymass_provenance provenance = repair_and_check("sphere, faces flipped", &sphere, &broken);
    assert_int_equal(provenance.reoriented_faces, (broken.face_count + 6) / 7);
    assert_int_equal(provenance.first_reoriented_faces[1], 7);
    assert_int_equal(provenance.turned_shells, 0);
    assert_true(provenance.approximation_bound_volume == 0);
    pm_mesh_free(&broken);

    /* The whole surface inside out, with one face left as it was. */
    pm_mesh_copy(&broken, &sphere);
    pm_mesh_reverse_all(&broken);
    pm_mesh_reverse_face(&broken, 3);
    provenance = repair_and_check("sphere, inverted", &sphere, &broken);
    assert_int_equal(provenance.turned_shells, 1);
    assert_int_equal(provenance.reoriented_faces, 1);
    assert_int_equal(provenance.first_reoriented_faces[0], 3);
    pm_mesh_free(&broken);
    pm_mesh_free(&sphere);

    /* A cube with a cavity: the cavity turned into a solid must become a
       cavity again; the outer shell inverted must turn back. */
    pm_mesh hollow;
    reference_mesh(&hollow, PM_REF_CUBE_CAVITY);
    pm_mesh_copy(&broken, &hollow);
    const size_t half = broken.face_count / 2;
    for (size_t f = half; f < broken.face_count; ++f) pm_mesh_reverse_face(&broken, f);
    provenance = repair_and_check("hollow cube, cavity inverted", &hollow, &broken);
    assert_int_equal(provenance.turned_shells, 1);
    pm_mesh_free(&broken);
    pm_mesh_copy(&broken, &hollow);
    for (size_t f = 0; f < half; ++f) pm_mesh_reverse_face(&broken, f);
    repair_and_check("hollow cube, outer shell inverted", &hollow, &broken);
    pm_mesh_free(&broken);
    pm_mesh_free(&hollow);
}

static void test_duplicates_and_small_faces(void** state) {
    (void)state;
    pm_mesh cube;
    reference_mesh(&cube, PM_REF_CUBE_QUADS);
    pm_mesh broken;
    pm_mesh_copy(&broken, &cube);
    duplicate_face(&broken, 0, 0);
    duplicate_face(&broken, 2, 0);
    duplicate_face(&broken, 2, 0);
    /* A face and its reverse, glued onto the surface: they cancel. */
    duplicate_face(&broken, 4, 1);
    duplicate_face(&broken, 4, 0);
    const uint32_t pair[2] = {0, 1};
    pm_mesh_add_face(&broken, 2, pair);
    const uint32_t repeated[4] = {2, 2, 3, 3};
    pm_mesh_add_face(&broken, 4, repeated);
    const polymass_provenance provenance = repair_and_check("cube, duplicates", &cube, &broken);
    assert_int_equal(provenance.duplicate_faces, 5);
    assert_int_equal(provenance.degenerate_faces, 2);
    assert_int_equal(provenance.first_degenerate_faces[0], cube.face_count + 5);
    assert_true(provenance.approximation_bound_volume == 0);
    pm_mesh_free(&broken);
    pm_mesh_free(&cube);
}

/* The reference cube of quads whose corner (1.75, 1, 2.25) is moved out by
   `lift` along (1, 1, 1): the three quads around it are bent. The truth is one of their
   triangulations: the answer must be within its bound of both extremes. */
static void test_bent_quads(void** state) {
    (void)state;
    static const double lifts[] = {1e-3, 0.05, 0.3};
    for (size_t l = 0; l < sizeof lifts / sizeof lifts[0]; ++l) {
        pm_mesh bent;
        reference_mesh(&bent, PM_REF_CUBE_QUADS);
        uint32_t corner = 0;
        for (uint32_t v = 0; v < bent.vertex_count; ++v)
            if (bent.positions[3 * v] == 1.75 && bent.positions[3 * v + 1] == 1.0 &&
                bent.positions[3 * v + 2] == 2.25)
                corner = v;
        for (int k = 0; k < 3; ++k) bent.positions[3 * corner + k] += lifts[l];
        /* The two triangulations of every quad: fans from each face's first
           and its second corner. */
        pm_mesh first, second;
        pm_mesh_copy(&first, &bent);
        pm_mesh_triangulate_fan(&first);
        pm_mesh_init(&second);
        for (size_t v = 0; v < bent.vertex_count; ++v)
            pm_mesh_add_vertex(&second, bent.positions[3 * v], bent.positions[3 * v + 1],
                               bent.positions[3 * v + 2]);
        for (size_t f = 0; f < bent.face_count; ++f) {
            const uint32_t* c = bent.indices + pm_mesh_face_offset(&bent, f);
            pm_mesh_add_tri(&second, c[1], c[2], c[3]);
            pm_mesh_add_tri(&second, c[1], c[3], c[0]);
        }
        char what[128];
        snprintf(what, sizeof what, "cube, corner moved by %g, against one split", lifts[l]);
        polymass_provenance provenance = repair_and_check(what, &first, &bent);
        assert_int_equal(provenance.triangulated_faces, 3);
        snprintf(what, sizeof what, "cube, corner moved by %g, against the other", lifts[l]);
        repair_and_check(what, &second, &bent);
        pm_mesh_free(&first);
        pm_mesh_free(&second);
        pm_mesh_free(&bent);
    }
}

static void test_everything_at_once(void** state) {
    (void)state;
    pm_mesh sphere;
    icosphere(&sphere, 2);
    pm_mesh broken;
    pm_mesh_copy(&broken, &sphere);
    const double point[3] = {0, 0, 1};
    cut_hole(&broken, point, 0.4);
    for (size_t f = 1; f < broken.face_count; f += 11) pm_mesh_reverse_face(&broken, f);
    duplicate_face(&broken, 5, 0);
    pm_mesh_reverse_all(&broken);
    pm_mesh_to_soup(&broken); /* an STL: every triangle its own vertices */
    const polymass_provenance provenance = repair_and_check(
        "sphere, holed, flipped, inverted, duplicated, as a soup", &sphere, &broken);
    assert_int_equal(provenance.holes, 1);
    assert_int_equal(provenance.turned_shells, 1);
    assert_int_equal(provenance.duplicate_faces, 1);
    pm_mesh_free(&broken);
    pm_mesh_free(&sphere);
}

/* Two cubes sharing an edge, each closed: the edge is used by four faces,
   two each way, and splits into two manifold pairs. */
static void test_split_non_manifold_edge(void** state) {
    (void)state;
    pm_mesh cubes;
    pm_mesh_init(&cubes);
    const double lo1[3] = {0, 0, 0}, hi1[3] = {1, 1, 1}, lo2[3] = {1, 1, 0}, hi2[3] = {2, 2, 1};
    pm_mesh_add_box(&cubes, lo1, hi1, 1);
    pm_mesh_add_box(&cubes, lo2, hi2, 1);
    pm_mesh_to_soup(&cubes);
    pm_mesh broken;
    pm_mesh_copy(&broken, &cubes);
    pm_mesh_reverse_face(&broken, 0);
    const polymass_provenance provenance =
        repair_and_check("two cubes on an edge", &cubes, &broken);
    assert_int_equal(provenance.split_edges, 1);
    assert_int_equal(provenance.reoriented_faces, 1);
    pm_mesh_free(&broken);
    pm_mesh_free(&cubes);
}

static void test_median_ratio(void** state) {
    static const char* const names[3] = {"volume", "centre of mass", "inertia"};
    (void)state;
    for (int q = 0; q < 3; ++q) {
        ratios* r = &all_ratios[q];
        assert_true(r->count > 0);
        qsort(r->values, r->count, sizeof r->values[0], compare);
        printf(
            "repair: %s: median ratio of the bound to the largest error it covers %.3g, over "
            "%zu repairs whose error exceeds 1e-9 of its scale (smallest %.3g)\n",
            names[q], r->values[r->count / 2], r->count, r->values[0]);
    }
}

/* ------------------------------------------------------------------------ */
/* Valid solids: bit-identical in every chain                               */
/* ------------------------------------------------------------------------ */

static void test_valid_solids_bit_identical(void** state) {
    (void)state;
    polymass_context* ctx = pm_context_new();
    const polymass_options chains[] = {
        chain(0, POLYMASS_MODE_REPAIR, 0, 0),
        chain(0, POLYMASS_MODE_SOLID, POLYMASS_MODE_REPAIR, POLYMASS_MODE_HULL),
        chain(0, POLYMASS_MODE_REPAIR, POLYMASS_MODE_HULL, 0),
    };
    for (int s = 0; s < PM_REF_COUNT; ++s) {
        const polymass_mesh_desc desc = pm_reference_desc(&pm_reference_solids[s]);
        polymass_mass_properties solid, moded;
        pm_props_init(&solid);
        if (polymass_mass_properties_compute(&solid, NULL, ctx, &desc, NULL, NULL) != POLYMASS_OK)
            continue;
        for (size_t c = 0; c < sizeof chains / sizeof chains[0]; ++c) {
            polymass_provenance provenance = POLYMASS_PROVENANCE_INIT;
            pm_props_init(&moded);
            assert_int_equal(
                polymass_mass_properties_compute(&moded, &provenance, ctx, &desc, &chains[c], NULL),
                POLYMASS_OK);
            assert_int_equal(provenance.mode, POLYMASS_MODE_SOLID);
            assert_int_equal(provenance.holes, 0);
            assert_int_equal(provenance.first_holes[0], POLYMASS_NONE);
            assert_memory_equal(&solid, &moded, sizeof solid);
            /* The options' chain is followed by the older entry points too. */
            pm_props_init(&moded);
            assert_int_equal(
                polymass_mass_properties_compute(&moded, NULL, ctx, &desc, &chains[c], NULL),
                POLYMASS_OK);
            assert_memory_equal(&solid, &moded, sizeof solid);
        }
    }
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Hull and shell                                                           */
/* ------------------------------------------------------------------------ */

static void test_hull(void** state) {
    (void)state;
    polymass_context* ctx = pm_context_new();
    const polymass_options hull = chain(0, POLYMASS_MODE_HULL, 0, 0);
    /* A convex solid: the hull is the solid. */
    pm_mesh cube;
    reference_mesh(&cube, PM_REF_BOX);
    polymass_mass_properties solid, got;
    polymass_provenance provenance;
    assert_int_equal(pm_compute(&solid, ctx, &cube, NULL), POLYMASS_OK);
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &hull), POLYMASS_OK);
    assert_int_equal(provenance.mode, POLYMASS_MODE_HULL);
    assert_true(got.warnings & POLYMASS_WARNING_HULL);
    assert_int_equal(provenance.hull_triangle_count, 12);
    PM_ASSERT_REL("hull volume", solid.volume, got.volume, PM_TOL);
    PM_ASSERT_TENSOR("hull inertia", solid.inertia, got.inertia, PM_TOL);
    /* The true solid is inside: the bound holds for a non-convex one too. */
    pm_mesh l_prism;
    reference_mesh(&l_prism, PM_REF_PRISM_L);
    assert_int_equal(pm_compute(&solid, ctx, &l_prism, NULL), POLYMASS_OK);
    pm_mesh_remove_face(&l_prism, 0); /* open: only the hull answers */
    assert_int_equal(compute_with(&got, &provenance, ctx, &l_prism, &hull), POLYMASS_OK);
    assert_true(got.volume > solid.volume);
    check_within_bound("L prism's hull", &solid, &got, pm_mesh_size(&l_prism));
    /* A fuzzed cloud of subnormal and unit coordinates, beyond the exact
       tests' range: their signs disagree and the hull is refused, saying
       so (it indexed past its faces before: tests/fuzz/regressions/). */
    {
        static const double cloud[8][3] = {
            {0x0p+0, 0x0.03ffp-1022, 0x0.03ffp-1022},
            {-0x1.00000001ep-31, 0x0.0000000000004p-1022, 0x0p+0},
            {0x0.03ffp-1022, 0x0p+0, 0x0.000003ffp-1022},
            {0x0.03ffp-1022, 0x0.00000001ep-1022, 0x0p+0},
            {0x0.600000002p-1022, 0x0.200000007p-1022, 0x1.000000007p+0},
            {0x0.0003fp-1022, 0x0.00000000000fp-1022, 0x0.0f03fp-1022},
            {0x0p+0, 0x1p+0, 0x1p+0},
            {0x1p+0, 0x1.0000000a8p+0, 0x0.00007p-1022},
        };
        pm_mesh torn;
        int v;
        pm_mesh_init(&torn);
        for (v = 0; v < 8; ++v) pm_mesh_add_vertex(&torn, cloud[v][0], cloud[v][1], cloud[v][2]);
        pm_mesh_add_tri(&torn, 0, 1, 2);
        pm_mesh_add_tri(&torn, 3, 4, 5);
        pm_mesh_add_tri(&torn, 6, 7, 0);
        assert_int_equal(compute_with(&got, &provenance, ctx, &torn, &hull),
                         POLYMASS_ERROR_OVERFLOW);
        message_says(ctx, "orientation tests disagreed");
        pm_mesh_free(&torn);
    }
    pm_mesh_free(&l_prism);
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

static void test_shell(void** state) {
    (void)state;
    polymass_context* ctx = pm_context_new();
    polymass_options shell = chain(0, POLYMASS_MODE_SHELL, 0, 0);
    shell.shell_thickness = 0.01;
    pm_mesh cube;
    reference_mesh(&cube, PM_REF_CUBE_QUADS);
    pm_mesh_remove_face(&cube, 0); /* a box without its lid: open, as sheet metal is */
    polymass_mass_properties got;
    polymass_provenance provenance;
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &shell), POLYMASS_OK);
    assert_int_equal(provenance.mode, POLYMASS_MODE_SHELL);
    assert_true(got.warnings & POLYMASS_WARNING_SHELL);
    PM_ASSERT_REL("shell area", 5.0 * 2.25, provenance.shell_area, PM_TOL);
    PM_ASSERT_REL("shell mass", 0.01 * 5.0 * 2.25, got.mass, PM_TOL);
    assert_true(provenance.shell_thickness == 0.01);
    /* A thickness is required with the shell mode. */
    shell.shell_thickness = 0;
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &shell),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    message_says(ctx, "shell_thickness");
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Where repair gives up                                                    */
/* ------------------------------------------------------------------------ */

/* A mesh's message says what is wrong with the surface as given, whichever
   mode answered; when none did, each later mode's reason follows. */
static void test_mesh_message_says_what_is_wrong(void** state) {
    (void)state;
    polymass_context* ctx = pm_context_new();
    polymass_mesh* mesh = NULL;
    pm_mesh cube, sheet;
    polymass_mesh_desc desc;
    const polymass_options repair = chain(0, POLYMASS_MODE_SOLID, POLYMASS_MODE_REPAIR, 0);
    const polymass_options hull = chain(0, POLYMASS_MODE_HULL, 0, 0);
    pm_mesh_unit_cube(&cube, 1);
    pm_mesh_remove_face(&cube, 3);
    desc = pm_mesh_desc(&cube);
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc, &repair));
    assert_string_equal(polymass_context_message(ctx), "");
    assert_non_null(strstr(polymass_mesh_message(mesh), "used by one face only"));
    assert_null(strstr(polymass_mesh_message(mesh), "solid: "));
    polymass_mesh_destroy(mesh);
    /* A valid solid: nothing to say, whatever answers. */
    pm_mesh_free(&cube);
    pm_mesh_unit_cube(&cube, 1);
    desc = pm_mesh_desc(&cube);
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc, &hull));
    assert_string_equal(polymass_mesh_message(mesh), "");
    polymass_mesh_destroy(mesh);
    /* No mode answers: the surface's defect, then the hull's reason. */
    pm_mesh_init(&sheet);
    for (int v = 0; v < 4; ++v) pm_mesh_add_vertex(&sheet, v & 1, v >> 1, 0);
    pm_mesh_add_tri(&sheet, 0, 1, 3);
    pm_mesh_add_tri(&sheet, 0, 3, 2);
    desc = pm_mesh_desc(&sheet);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_VOLUME,
                     polymass_mesh_create(&mesh, ctx, &desc, &hull));
    assert_string_equal(polymass_context_message(ctx), polymass_mesh_message(mesh));
    assert_non_null(strstr(polymass_mesh_message(mesh), "used by one face only"));
    assert_non_null(strstr(polymass_mesh_message(mesh), "; hull: the convex hull has no volume"));
    polymass_mesh_destroy(mesh);
    pm_mesh_free(&sheet);
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

static void test_repair_gives_up(void** state) {
    (void)state;
    polymass_context* ctx = pm_context_new();
    const polymass_options repair = chain(0, POLYMASS_MODE_REPAIR, 0, 0);
    polymass_mass_properties got;
    polymass_provenance provenance;

    /* A Moebius strip of 8 quads. */
    pm_mesh strip;
    pm_mesh_init(&strip);
    const int n = 8;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < n; ++i) {
        const double u = 2 * pi * i / n, c = cos(u / 2);
        for (int side = -1; side <= 1; side += 2)
            pm_mesh_add_vertex(&strip, (1 + 0.3 * side * c) * cos(u), (1 + 0.3 * side * c) * sin(u),
                               0.3 * side * sin(u / 2));
    }
    for (int i = 0; i < n; ++i) {
        const uint32_t a = 2 * i, b = 2 * i + 1;
        const uint32_t c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
        pm_mesh_add_quad(&strip, a, c, d, b);
    }
    assert_int_equal(compute_with(&got, &provenance, ctx, &strip, &repair), POLYMASS_ERROR_OPEN);
    message_says(ctx, "cannot be oriented");
    pm_mesh_free(&strip);

    /* A fin on a cube's edge: the edge is used by three faces. */
    pm_mesh fin;
    reference_mesh(&fin, PM_REF_CUBE_TRIS);
    const uint32_t a = 1, b = 3; /* (1.75, -0.5, 0.75) and (1.75, 1, 0.75): a cube edge */
    const uint32_t tip = pm_mesh_add_vertex(&fin, 3, 0.25, 0);
    pm_mesh_add_tri(&fin, a, b, tip);
    assert_int_equal(compute_with(&got, &provenance, ctx, &fin, &repair), POLYMASS_ERROR_OPEN);
    message_says(ctx, "repair: edge");
    /* The hull answers what repair cannot. */
    const polymass_options fallback =
        chain(0, POLYMASS_MODE_SOLID, POLYMASS_MODE_REPAIR, POLYMASS_MODE_HULL);
    assert_int_equal(compute_with(&got, &provenance, ctx, &fin, &fallback), POLYMASS_OK);
    assert_int_equal(provenance.mode, POLYMASS_MODE_HULL);
    pm_mesh_free(&fin);

    /* Two overlapping cubes: intersecting shells are not repaired. */
    pm_mesh overlap;
    pm_mesh_init(&overlap);
    const double lo1[3] = {0, 0, 0}, hi1[3] = {1, 1, 1}, lo2[3] = {0.5, 0.5, 0.5},
                 hi2[3] = {1.5, 1.5, 1.5};
    pm_mesh_add_box(&overlap, lo1, hi1, 1);
    pm_mesh_add_box(&overlap, lo2, hi2, 1);
    pm_mesh_remove_face(&overlap, 0);
    assert_int_equal(compute_with(&got, &provenance, ctx, &overlap, &repair), POLYMASS_ERROR_OPEN);
    message_says(ctx, "repaired surface");
    message_says(ctx, "cross each other");
    pm_mesh_free(&overlap);

    /* A flat sheet: capped, it encloses nothing. */
    pm_mesh sheet;
    pm_mesh_init(&sheet);
    for (int v = 0; v < 4; ++v) pm_mesh_add_vertex(&sheet, v & 1, v >> 1, 0);
    pm_mesh_add_tri(&sheet, 0, 1, 3);
    pm_mesh_add_tri(&sheet, 0, 3, 2);
    assert_int_equal(compute_with(&got, &provenance, ctx, &sheet, &repair), POLYMASS_ERROR_OPEN);
    message_says(ctx, "no volume");
    /* A chain of repairs only: the solid's reason once, then each repair's. */
    {
        polymass_options repairs =
            chain(0, POLYMASS_MODE_REPAIR, POLYMASS_MODE_REPAIR, POLYMASS_MODE_REPAIR);
        repairs.modes[3] = POLYMASS_MODE_REPAIR;
        assert_int_equal(compute_with(&got, &provenance, ctx, &sheet, &repairs),
                         POLYMASS_ERROR_OPEN);
        message_says(ctx, "solid: ");
        message_says(ctx, "; repair: ");
    }
    pm_mesh_free(&sheet);
    polymass_context_destroy(ctx);
}

/* A NaN coordinate is POLYMASS_ERROR_NON_FINITE in every chain, one call or
   a mesh alike (compute_with), saying which vertex. */
static void expect_non_finite_in_chain(uint32_t mode) {
    polymass_context* ctx = pm_context_new();
    polymass_options options = chain(0, mode, 0, 0);
    polymass_mass_properties got;
    polymass_provenance provenance;
    pm_mesh cube;
    options.shell_thickness = 0.01;
    pm_mesh_unit_cube(&cube, 1);
    cube.positions[3 * 5 + 1] = NAN;
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &options),
                     POLYMASS_ERROR_NON_FINITE);
    PM_ASSERT_MENTIONS(ctx, "vertex", 5);
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

static void test_non_finite_in_solid(void** state) {
    (void)state;
    expect_non_finite_in_chain(POLYMASS_MODE_SOLID);
}

static void test_non_finite_in_repair(void** state) {
    (void)state;
    expect_non_finite_in_chain(POLYMASS_MODE_REPAIR);
}

static void test_non_finite_in_shell(void** state) {
    (void)state;
    expect_non_finite_in_chain(POLYMASS_MODE_SHELL);
}

static void test_non_finite_in_hull(void** state) {
    (void)state;
    expect_non_finite_in_chain(POLYMASS_MODE_HULL);
}

static void test_options_checked(void** state) {
    (void)state;
    polymass_context* ctx = pm_context_new();
    polymass_options options = chain(0, 7, 0, 0);
    polymass_mass_properties got;
    polymass_provenance provenance;
    pm_mesh cube;
    pm_mesh_unit_cube(&cube, 1);
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &options),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    message_says(ctx, "modes[0] is 7");
    options = chain(0, POLYMASS_MODE_SOLID, 0, 0);
    options.shell_thickness = NAN;
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &options),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    options = chain(0, POLYMASS_MODE_SHELL, 0, 0);
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &options),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    message_says(ctx, "shell_thickness");
    /* Only the 2.0 layout of the options is known. */
    options = pm_options(0, 0.0);
    options.struct_size = (uint32_t)offsetof(polymass_options, modes);
    assert_int_equal(compute_with(&got, &provenance, ctx, &cube, &options),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    pm_mesh_free(&cube);
    /* A provenance of an unknown size is refused. */
    assert_int_equal(polymass_provenance_init(&provenance, 3), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_int_equal(polymass_sizeof_provenance(), sizeof(polymass_provenance));
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_holes_in_a_sphere),
        cmocka_unit_test(test_holes_in_reference_solids),
        cmocka_unit_test(test_flipped_faces_and_shells),
        cmocka_unit_test(test_duplicates_and_small_faces),
        cmocka_unit_test(test_bent_quads),
        cmocka_unit_test(test_everything_at_once),
        cmocka_unit_test(test_split_non_manifold_edge),
        cmocka_unit_test(test_median_ratio),
        cmocka_unit_test(test_valid_solids_bit_identical),
        cmocka_unit_test(test_hull),
        cmocka_unit_test(test_shell),
        cmocka_unit_test(test_repair_gives_up),
        cmocka_unit_test(test_mesh_message_says_what_is_wrong),
        cmocka_unit_test(test_non_finite_in_solid),
        cmocka_unit_test(test_non_finite_in_repair),
        cmocka_unit_test(test_non_finite_in_shell),
        cmocka_unit_test(test_non_finite_in_hull),
        cmocka_unit_test(test_options_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
