/* Every reference solid translated far from the origin, rotated and scaled,
 * against the exact values mapped the same way (in long double):
 *   V' = s^3 V, C' = s R C + t, I' = s^5 R I R^T, area' = s^2 area,
 * with the tolerance PM_TOL = 1e-12 (see test_support.h). One cmocka test per
 * transform, so that one failing transform does not hide the others. */
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Vertices are mapped by x' = M x + t (M NULL-like when !has_matrix); the
   expected values by x' = s R x + t with R = M / divisor, s = divisor. */
typedef struct transform {
    char name[160];
    int has_matrix;
    double matrix[9];
    double divisor; /* 1, or |q|^2 for an integer rotation matrix */
    double scale;   /* applied to the vertices and the expected values alike */
    double translation[3];
    int exact; /* the mapped coordinates are exactly representable */
} transform;

typedef struct exact_entry {
    const char* name;
    int has_matrix;
    double matrix[9];
    double scale;
    double translation[3];
} exact_entry;

/* Rotations whose entries are 0 and +-1 move dyadic coordinates exactly. */
static const exact_entry exact_transforms[] = {
    {"translate (1e6, -1e6, 1e6)", 0, {0}, 1.0, {1e6, -1e6, 1e6}},
    {"translate (1e8, 1e8, -1e8)", 0, {0}, 1.0, {1e8, 1e8, -1e8}},
    {"translate (1e8, 0, 0)", 0, {0}, 1.0, {1e8, 0, 0}},
    {"translate (2^20, 2^20, 2^20)", 0, {0}, 1.0, {1048576.0, 1048576.0, 1048576.0}},
    {"translate (-2^27, 2^27, 2^27)", 0, {0}, 1.0, {-134217728.0, 134217728.0, 134217728.0}},
    {"cyclic permutation (x, y, z) -> (y, z, x)", 1, {0, 1, 0, 0, 0, 1, 1, 0, 0}, 1.0, {0, 0, 0}},
    {"90 degrees about z", 1, {0, -1, 0, 1, 0, 0, 0, 0, 1}, 1.0, {0, 0, 0}},
    {"180 degrees about x", 1, {1, 0, 0, 0, -1, 0, 0, 0, -1}, 1.0, {0, 0, 0}},
    {"-90 degrees about y, then to 1e6", 1, {0, 0, -1, 0, 1, 0, 1, 0, 0}, 1.0, {1e6, 1e6, 1e6}},
    {"scale 2^20", 0, {0}, 1048576.0, {0, 0, 0}},
    {"scale 2^-20", 0, {0}, 1.0 / 1048576.0, {0, 0, 0}},
    {"scale 2^60", 0, {0}, 1152921504606846976.0, {0, 0, 0}},
    {"scale 2^-60", 0, {0}, 1.0 / 1152921504606846976.0, {0, 0, 0}},
    /* Where a coordinate's fourth power underflows and its sixth overflows:
       the library must integrate in a unit near the mesh's size. */
    {"scale 2^-200", 0, {0}, 0x1p-200, {0, 0, 0}},
    {"scale 2^200", 0, {0}, 0x1p200, {0, 0, 0}},
    {"scale 2^-20, translate (1, 2, 3)", 0, {0}, 1.0 / 1048576.0, {1, 2, 3}},
};
#define EXACT_TRANSFORM_COUNT (sizeof exact_transforms / sizeof exact_transforms[0])

/* The transformed coordinates are exactly representable: the solid is the
   same one, so any difference is the library's. */
static void assert_transform_exact(const pm_mesh* original, const pm_mesh* moved,
                                   const transform* t) {
    size_t v;
    int i, j;
    for (v = 0; v < original->vertex_count; ++v) {
        for (i = 0; i < 3; ++i) {
            long double q = t->translation[i];
            for (j = 0; j < 3; ++j) {
                const double r = t->has_matrix ? t->matrix[3 * i + j] : (i == j);
                q += (long double)t->scale * r * original->positions[3 * v + j];
            }
            assert_true((long double)moved->positions[3 * v + i] == q);
        }
    }
}

static void test_transform(void** state) {
    const transform* t = *state;
    polymass_context* ctx = pm_context_new();
    double r[9];
    int k, i;
    for (i = 0; i < 9; ++i) {
        r[i] = t->has_matrix ? t->matrix[i] / t->divisor : (i % 4 == 0);
    }
    for (k = 0; k < PM_REF_COUNT; ++k) {
        const pm_reference_solid* ref = &pm_reference_solids[k];
        const pm_expected e0 = pm_expected_from_reference(ref);
        const pm_expected e = pm_expected_transform(&e0, r, t->scale * t->divisor, t->translation);
        pm_mesh original, moved;
        polymass_mass_properties p;
        char label[256];
        pm_mesh_from_reference(&original, ref);
        pm_mesh_copy(&moved, &original);
        pm_mesh_transform(&moved, t->has_matrix ? t->matrix : NULL, t->scale, t->translation);
        if (t->exact) {
            assert_transform_exact(&original, &moved, t);
        }
        snprintf(label, sizeof label, "%s, %s", ref->name, t->name);
        PM_ASSERT_OK(
            ctx, pm_compute_flags(&p, ctx, &moved,
                                  t->exact ? 0 : pm_reference_rounded_rotation_flags(ref), NULL));
        PM_ASSERT_PROPERTIES(label, &e, &p, PM_TOL);
        pm_mesh_free(&moved);
        pm_mesh_free(&original);
    }
    polymass_context_destroy(ctx);
}

/* Integer matrix of the quaternion (w, x, y, z): |q|^2 R. */
static void integer_rotation(double m[9], int w, int x, int y, int z) {
    m[0] = w * w + x * x - y * y - z * z;
    m[1] = 2 * (x * y - w * z);
    m[2] = 2 * (x * z + w * y);
    m[3] = 2 * (x * y + w * z);
    m[4] = w * w - x * x + y * y - z * z;
    m[5] = 2 * (y * z - w * x);
    m[6] = 2 * (x * z - w * y);
    m[7] = 2 * (y * z + w * x);
    m[8] = w * w - x * x - y * y + z * z;
}

/* General rotations that keep dyadic coordinates exact: for an integer
   quaternion with |q|^2 = n^2 a perfect square, x' = M x with the integer
   matrix M = n^2 R is a rotation R and a scaling by n^2, exact in binary, and
   still exact after a translation by 1e6. */
static const int integer_quaternions[][4] = {
    {1, 2, 2, 0}, /* |q|^2 = 9 */
    {2, 1, 2, 4}, /* 25 */
    {1, 1, 3, 5}, /* 36 */
    {0, 2, 3, 6}, /* 49: a half turn */
};
static const double integer_rotation_translations[][3] = {
    {0, 0, 0}, {1e6, -2e6, 3e6}, {-1e6, 0, 0.5}};

/* M M^T = |q|^4 I and det M = |q|^6 exactly: M / |q|^2 is a rotation. */
static void test_integer_rotation_matrices(void** state) {
    size_t q;
    int i;
    (void)state;
    for (q = 0; q < sizeof integer_quaternions / sizeof integer_quaternions[0]; ++q) {
        const int* c = integer_quaternions[q];
        const double n2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3];
        double m[9], mt[9], mmt[9];
        integer_rotation(m, c[0], c[1], c[2], c[3]);
        pm_mat3_transpose(mt, m);
        pm_mat3_mul(mmt, m, mt);
        for (i = 0; i < 9; ++i) {
            assert_true(mmt[i] == (i % 4 == 0 ? n2 * n2 : 0.0));
        }
        assert_true(pm_mat3_det(m) == n2 * n2 * n2);
    }
}

/* General (irrational) rotations at the origin: the rotated vertices are
   rounded, so the expected R I R^T are those of a solid within 1e-16 of the
   computed one. */
static const double rounded_quaternions[][4] = {{0.9, 0.3, -0.2, 0.25}, {0.1, -0.7, 0.4, 0.6}};

/* Invariants of a rotation: volume, area, principal moments; and the
   principal axes turn with the body: R_rot = Q R up to the order/sign of the
   columns, checked as Q^T I' Q = I. */
static void test_rotation_invariants(void** state) {
    polymass_context* ctx = pm_context_new();
    double q[9];
    int k, i;
    (void)state;
    pm_rotation_from_quaternion(q, 0.3, -0.5, 0.8, 0.1);
    for (k = 0; k < PM_REF_COUNT; ++k) {
        const pm_reference_solid* ref = &pm_reference_solids[k];
        pm_mesh m;
        polymass_mass_properties a, b;
        double qt[9], back[9];
        pm_mesh_from_reference(&m, ref);
        PM_ASSERT_OK(ctx, pm_compute(&a, ctx, &m, NULL));
        pm_mesh_transform(&m, q, 1.0, NULL);
        PM_ASSERT_OK(ctx,
                     pm_compute_flags(&b, ctx, &m, pm_reference_rounded_rotation_flags(ref), NULL));
        PM_ASSERT_REL(ref->name, a.volume, b.volume, PM_TOL);
        if (!isnan(ref->surface_area)) {
            PM_ASSERT_REL(ref->name, a.surface_area, b.surface_area, PM_TOL);
        }
        for (i = 0; i < 3; ++i) {
            PM_ASSERT_CLOSE("principal moment unchanged by a rotation", a.principal_moments[i],
                            b.principal_moments[i], PM_TOL, a.principal_moments[2]);
        }
        /* Q^T I_rotated Q == I */
        pm_mat3_transpose(qt, q);
        pm_mat3_mul(back, qt, b.inertia);
        pm_mat3_mul(back, back, q);
        PM_ASSERT_TENSOR("Q^T I' Q", a.inertia, back, PM_TOL);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* Scaling by a power of two is exact in binary: the results scale exactly
   as s^3, s^4 (first moments: C s), s^5 up to the library's own rounding. */
static void test_power_of_two_scaling_is_consistent(void** state) {
    polymass_context* ctx = pm_context_new();
    const double s = 1048576.0;
    int k, i;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        pm_mesh m;
        polymass_mass_properties a, b;
        pm_mesh_from_reference(&m, &pm_reference_solids[k]);
        PM_ASSERT_OK(ctx, pm_compute(&a, ctx, &m, NULL));
        pm_mesh_transform(&m, NULL, s, NULL);
        PM_ASSERT_OK(ctx, pm_compute(&b, ctx, &m, NULL));
        PM_ASSERT_REL("V s^3", a.volume * s * s * s, b.volume, PM_TOL);
        for (i = 0; i < 3; ++i) {
            PM_ASSERT_REL("principal moments s^5", a.principal_moments[i] * s * s * s * s * s,
                          b.principal_moments[i], PM_TOL);
        }
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

enum { MAX_TESTS = 64 };

int main(void) {
    static transform cases[MAX_TESTS];
    static struct CMUnitTest tests[MAX_TESTS];
    size_t n = 0, i, q, t;
    for (i = 0; i < sizeof exact_transforms / sizeof exact_transforms[0]; ++i, ++n) {
        const exact_entry* x = &exact_transforms[i];
        snprintf(cases[n].name, sizeof cases[n].name, "%s", x->name);
        cases[n].has_matrix = x->has_matrix;
        memcpy(cases[n].matrix, x->matrix, sizeof x->matrix);
        cases[n].divisor = 1.0;
        cases[n].scale = x->scale;
        memcpy(cases[n].translation, x->translation, sizeof x->translation);
        cases[n].exact = 1;
    }
    for (q = 0; q < sizeof integer_quaternions / sizeof integer_quaternions[0]; ++q) {
        const int* c = integer_quaternions[q];
        for (t = 0;
             t < sizeof integer_rotation_translations / sizeof integer_rotation_translations[0];
             ++t, ++n) {
            const double* tr = integer_rotation_translations[t];
            snprintf(cases[n].name, sizeof cases[n].name,
                     "integer rotation of quaternion (%d, %d, %d, %d), then + (%g, %g, %g)", c[0],
                     c[1], c[2], c[3], tr[0], tr[1], tr[2]);
            cases[n].has_matrix = 1;
            integer_rotation(cases[n].matrix, c[0], c[1], c[2], c[3]);
            cases[n].divisor = c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3];
            cases[n].scale = 1.0;
            memcpy(cases[n].translation, tr, sizeof cases[n].translation);
            cases[n].exact = 1;
        }
    }
    for (q = 0; q < sizeof rounded_quaternions / sizeof rounded_quaternions[0]; ++q, ++n) {
        const double* c = rounded_quaternions[q];
        snprintf(cases[n].name, sizeof cases[n].name,
                 "rounded rotation of quaternion (%g, %g, %g, %g)", c[0], c[1], c[2], c[3]);
        cases[n].has_matrix = 1;
        pm_rotation_from_quaternion(cases[n].matrix, c[0], c[1], c[2], c[3]);
        cases[n].divisor = 1.0;
        cases[n].scale = 1.0;
        cases[n].exact = 0;
    }
    for (i = 0; i < n; ++i) {
        tests[i].name = cases[i].name;
        tests[i].test_func = test_transform;
        tests[i].initial_state = &cases[i];
    }
    tests[n].name = "test_integer_rotation_matrices";
    tests[n++].test_func = test_integer_rotation_matrices;
    tests[n].name = "test_rotation_invariants";
    tests[n++].test_func = test_rotation_invariants;
    tests[n].name = "test_power_of_two_scaling_is_consistent";
    tests[n++].test_func = test_power_of_two_scaling_is_consistent;
    return _cmocka_run_group_tests("transforms", tests, n, NULL, NULL);
}
