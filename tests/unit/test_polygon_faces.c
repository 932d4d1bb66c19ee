/* Polygon faces (Green's theorem over the face) against the same solids cut
 * into triangles (the triangle path), non-convex faces, and meshes mixing
 * triangles and polygons. */
#include "test_support.h"

#include <math.h>
#include <string.h>

#define AGREE_TOL 1e-13

/* Volume, centre, both tensors (and area if asked) of two results agree to
   AGREE_TOL. */
static void assert_agree(const char* what, const polymass_mass_properties* a,
                         const polymass_mass_properties* b, double size, int with_area) {
    pm_expected e;
    memset(&e, 0, sizeof e);
    e.volume = a->volume;
    memcpy(e.center_of_mass, a->center_of_mass, sizeof e.center_of_mass);
    memcpy(e.inertia, a->inertia, sizeof e.inertia);
    memcpy(e.inertia_origin, a->inertia_origin, sizeof e.inertia_origin);
    e.surface_area = with_area ? a->surface_area : NAN;
    e.size = size;
    PM_ASSERT_PROPERTIES(what, &e, b, AGREE_TOL);
}

/* Every reference solid with polygon faces vs the same solid fanned into
   triangles (a signed fan is the same 2-chain even for a non-convex face, so
   volume and inertia agree; the area agrees where no fan triangle overlaps). */
static void test_polygon_path_vs_triangle_path(void** state) {
    polymass_context* ctx = pm_context_new();
    int k, polygon_solids = 0;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        const pm_reference_solid* ref = &pm_reference_solids[k];
        pm_mesh poly, tris;
        polymass_mass_properties p, t;
        if (ref->face_sizes == NULL) {
            continue;
        }
        ++polygon_solids;
        pm_mesh_from_reference(&poly, ref);
        pm_mesh_copy(&tris, &poly);
        pm_mesh_triangulate_fan(&tris);
        assert_true(pm_mesh_all_triangles(&tris));
        assert_true(tris.face_count > poly.face_count);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &poly, NULL));
        PM_ASSERT_OK(ctx, pm_compute(&t, ctx, &tris, NULL));
        /* the fans of the non-convex caps overlap (the bottom cap's fan starts
           at another vertex than the top's): compare their area elsewhere */
        assert_agree(ref->name, &p, &t, pm_mesh_size(&poly),
                     k != PM_REF_PRISM_STAR && k != PM_REF_PRISM_L);
        pm_mesh_free(&tris);
        pm_mesh_free(&poly);
    }
    assert_true(polygon_solids >= 8);
    polymass_context_destroy(ctx);
}

/* Area of a face as |sum of fan cross products| / 2, in long double. */
static long double face_area(const pm_mesh* m, size_t offset, size_t n) {
    long double s[3] = {0, 0, 0};
    size_t k;
    const double* p0 = m->positions + 3 * (size_t)m->indices[offset];
    for (k = 1; k + 1 < n; ++k) {
        const double* p1 = m->positions + 3 * (size_t)m->indices[offset + k];
        const double* p2 = m->positions + 3 * (size_t)m->indices[offset + k + 1];
        const long double u[3] = {(long double)p1[0] - p0[0], (long double)p1[1] - p0[1],
                                  (long double)p1[2] - p0[2]};
        const long double v[3] = {(long double)p2[0] - p0[0], (long double)p2[1] - p0[1],
                                  (long double)p2[2] - p0[2]};
        s[0] += u[1] * v[2] - u[2] * v[1];
        s[1] += u[2] * v[0] - u[0] * v[2];
        s[2] += u[0] * v[1] - u[1] * v[0];
    }
    return sqrtl(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) / 2;
}

static double mesh_face_area_sum(const pm_mesh* m) {
    long double total = 0;
    size_t f, offset = 0;
    for (f = 0; f < m->face_count; ++f) {
        total += face_area(m, offset, m->face_sizes[f]);
        offset += m->face_sizes[f];
    }
    return (double)total;
}

/* The star prism: its caps as single non-convex 10-gons, as a correct
   triangulation, and as an overlapping fan from vertex 0. */
static void test_star_prism_polygon_vs_correct_triangulation(void** state) {
    const pm_reference_solid* star = &pm_reference_solids[PM_REF_PRISM_STAR];
    const pm_reference_solid* tris = &pm_reference_solids[PM_REF_PRISM_STAR_TRIS];
    const pm_reference_solid* fan = &pm_reference_solids[PM_REF_PRISM_STAR_FAN];
    const pm_expected e = pm_expected_from_reference(star);
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p, t, f;
    pm_mesh fan_mesh;
    double fan_area;
    (void)state;
    PM_ASSERT_OK(ctx, pm_compute_reference(&p, ctx, star));
    PM_ASSERT_OK(ctx, pm_compute_reference(&t, ctx, tris));
    PM_ASSERT_OK(ctx, pm_compute_reference(&f, ctx, fan));
    PM_ASSERT_PROPERTIES("star prism, polygon caps", &e, &p, PM_TOL);
    PM_ASSERT_PROPERTIES("star prism, ear-clipped caps", &e, &t, PM_TOL);
    assert_agree("star prism: polygon vs correct triangulation", &p, &t, e.size, 1);

    /* The overlapping fan is the same 2-chain: same volume and inertia. Its
       area is the sum of its (overlapping) triangles' areas, larger than the
       star's: a polygon face's area must not be computed that way. */
    {
        pm_expected no_area = e;
        no_area.surface_area = NAN;
        PM_ASSERT_PROPERTIES("star prism, overlapping fan caps", &no_area, &f, PM_TOL);
    }
    pm_mesh_from_reference(&fan_mesh, fan);
    fan_area = mesh_face_area_sum(&fan_mesh);
    PM_ASSERT_REL("fan prism area = sum of its faces' areas", fan_area, f.surface_area, PM_TOL);
    assert_true(fan_area > e.surface_area * (1 + 1e-3));
    pm_mesh_free(&fan_mesh);
    polymass_context_destroy(ctx);
}

/* A polygon face gives the same result whichever vertex it starts at, even a
   reflex one (the star's odd vertices are its inner corners). */
static void test_polygon_face_start_vertex_irrelevant(void** state) {
    static const int solids[] = {PM_REF_PRISM_STAR, PM_REF_PRISM_L, PM_REF_PRISM_12GON,
                                 PM_REF_HOUSE};
    polymass_context* ctx = pm_context_new();
    size_t s;
    (void)state;
    for (s = 0; s < sizeof solids / sizeof solids[0]; ++s) {
        const pm_reference_solid* ref = &pm_reference_solids[solids[s]];
        const pm_expected e = pm_expected_from_reference(ref);
        int shift;
        for (shift = 1; shift < 4; ++shift) {
            pm_mesh m;
            polymass_mass_properties p;
            size_t f, offset = 0;
            pm_mesh_from_reference(&m, ref);
            for (f = 0; f < m.face_count; ++f) {
                const size_t n = m.face_sizes[f];
                uint32_t tmp[64];
                size_t k;
                for (k = 0; k < n; ++k) {
                    tmp[k] = m.indices[offset + (k + (size_t)shift) % n];
                }
                memcpy(m.indices + offset, tmp, n * sizeof(uint32_t));
                offset += n;
            }
            PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
            PM_ASSERT_PROPERTIES(ref->name, &e, &p, PM_TOL);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(ctx);
}

/* Triangles and polygons in one mesh. */
static void test_mixed_triangles_and_polygons(void** state) {
    static const double lo[3] = {-0.5, 0.25, 1.5}, hi[3] = {2.0, 1.0, 2.125};
    const pm_expected box = pm_expected_box(lo, hi);
    const pm_expected hex = pm_expected_from_reference(&pm_reference_solids[PM_REF_PRISM_HEX]);
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    pm_mesh quads, mixed;
    size_t f;
    (void)state;
    /* A box with faces 0, 2, 4 as quads and faces 1, 3, 5 as triangle pairs. */
    pm_mesh_box(&quads, lo, hi, 0);
    pm_mesh_init(&mixed);
    for (f = 0; f < quads.vertex_count; ++f) {
        pm_mesh_add_vertex(&mixed, quads.positions[3 * f], quads.positions[3 * f + 1],
                           quads.positions[3 * f + 2]);
    }
    for (f = 0; f < quads.face_count; ++f) {
        const uint32_t* q = quads.indices + 4 * f;
        if (f % 2 == 0) {
            pm_mesh_add_face(&mixed, 4, q);
        } else {
            pm_mesh_add_tri(&mixed, q[0], q[1], q[2]);
            pm_mesh_add_tri(&mixed, q[0], q[2], q[3]);
        }
    }
    assert_false(pm_mesh_all_triangles(&mixed));
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &mixed, NULL));
    PM_ASSERT_PROPERTIES("box of quads and triangles", &box, &p, PM_TOL);

    /* The reference hexagonal prism with one cap a hexagon and the other in
       triangles, side quads alternately split. */
    PM_ASSERT_OK(ctx, pm_compute_reference(&p, ctx, &pm_reference_solids[PM_REF_PRISM_HEX_MIXED]));
    PM_ASSERT_PROPERTIES("hexagonal prism, mixed faces", &hex, &p, PM_TOL);
    /* All-triangle mesh given with an explicit face_sizes of 3s. */
    {
        const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TORUS_TRIS];
        const pm_expected e = pm_expected_from_reference(ref);
        pm_mesh t;
        polymass_mesh_desc d;
        pm_mesh_from_reference(&t, ref);
        d = pm_mesh_desc_ex(&t, 1);
        assert_non_null(d.face_sizes);
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));
        PM_ASSERT_PROPERTIES("torus with explicit face sizes of 3", &e, &p, PM_TOL);
        pm_mesh_free(&t);
    }
    pm_mesh_free(&mixed);
    pm_mesh_free(&quads);
    polymass_context_destroy(ctx);
}

/* A prism of a 64-gon: large polygon faces, vs its triangulation. */
static void test_many_sided_polygon_faces(void** state) {
    enum { N = 64 };
    double xy[2 * N];
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p, t;
    pm_mesh poly, tris;
    int k;
    (void)state;
    for (k = 0; k < N; ++k) {
        /* dyadic points on (nearly) a circle of radius 3, centre (1, -2) */
        const double a = 2 * 3.14159265358979323846 * k / N;
        xy[2 * k] = 1 + ldexp(floor(ldexp(3 * cos(a), 16) + 0.5), -16);
        xy[2 * k + 1] = -2 + ldexp(floor(ldexp(3 * sin(a), 16) + 0.5), -16);
    }
    pm_mesh_init(&poly);
    pm_mesh_add_prism(&poly, xy, N, -0.5, 0.75);
    pm_mesh_copy(&tris, &poly);
    pm_mesh_triangulate_fan(&tris);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &poly, NULL));
    PM_ASSERT_OK(ctx, pm_compute(&t, ctx, &tris, NULL));
    assert_agree("64-gon prism: polygon vs triangles", &p, &t, pm_mesh_size(&poly), 1);
    /* The shoelace area of the cap times the height is the volume. */
    {
        long double area2 = 0;
        for (k = 0; k < N; ++k) {
            const int j = (k + 1) % N;
            area2 +=
                (long double)xy[2 * k] * xy[2 * j + 1] - (long double)xy[2 * j] * xy[2 * k + 1];
        }
        PM_ASSERT_REL("volume = cap area x height", (double)(area2 / 2 * 1.25), p.volume, PM_TOL);
    }
    pm_mesh_free(&tris);
    pm_mesh_free(&poly);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polygon_path_vs_triangle_path),
        cmocka_unit_test(test_star_prism_polygon_vs_correct_triangulation),
        cmocka_unit_test(test_polygon_face_start_vertex_irrelevant),
        cmocka_unit_test(test_mixed_triangles_and_polygons),
        cmocka_unit_test(test_many_sided_polygon_faces),
    };
    return cmocka_run_group_tests_name("polygon_faces", tests, NULL, NULL);
}
