/* error_bound_* contains the true error: every exact-reference solid, near the
 * origin, far from it (1e6, 1e8) and scaled, computed from the mesh and from
 * moved moments. The test prints how loose the bounds are (the median ratio
 * of bound to actual error, over the results with a nonzero error). */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const pm_placement placements[] = {
    {"as given", 1.0, {0, 0, 0}},
    {"at (1e6, -1e6, 1e6)", 1.0, {1e6, -1e6, 1e6}},
    {"at (1e8, 1e8, -1e8)", 1.0, {1e8, 1e8, -1e8}},
    {"scaled 2^-20", 1.0 / 1048576.0, {0, 0, 0}},
    {"scaled 2^30, at 1e8", 1073741824.0, {1e8, 0, 0}},
};
#define PLACEMENT_COUNT (sizeof placements / sizeof placements[0])

/* Ratios bound / actual error of the results with a nonzero error. */
typedef struct ratios {
    double values[4096];
    size_t count;
} ratios;

static void record(ratios* r, double bound, double error) {
    if (error > 0 && r->count < sizeof r->values / sizeof r->values[0])
        r->values[r->count++] = bound / error;
}

static int compare(const void* a, const void* b) {
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static double median(ratios* r) {
    if (r->count == 0) return NAN;
    qsort(r->values, r->count, sizeof r->values[0], compare);
    return r->values[r->count / 2];
}

/* The exact value is known to half an ulp (it is printed rounded): the bound
   must hold up to that. */
static void assert_contains(const char* what, const char* quantity, double bound, double exact,
                            double got, ratios* r) {
    const double error = fabs(got - exact);
    const double slack = 0.5 * DBL_EPSILON * fabs(exact);
    if (!(error <= bound + slack)) {
        print_error("%s: %s: error %.3g is outside the bound %.3g (value %.17g, exact %.17g)\n",
                    what, quantity, error, bound, got, exact);
        fail();
    }
    record(r, bound, error);
}

static void check_bounds(const char* what, const pm_expected* e, const polymass_mass_properties* p,
                         ratios* r) {
    int i;
    assert_true(p->error_bound_volume > 0 && isfinite(p->error_bound_volume));
    /* Loose, but not vacuous. */
    assert_true(p->error_bound_volume <= 1e-9 * fabs(p->volume));
    assert_true(p->error_bound_inertia <= 1e-6 * fabs(p->principal_moments[2]));
    assert_true(p->error_bound_inertia > 0 && isfinite(p->error_bound_inertia));
    assert_true(p->error_bound_principal_axes >= 0 && p->error_bound_principal_axes <= 1.5708);
    assert_contains(what, "volume", p->error_bound_volume, e->volume, p->volume, &r[0]);
    for (i = 0; i < 3; ++i)
        assert_contains(what, "centre of mass", p->error_bound_center_of_mass, e->center_of_mass[i],
                        p->center_of_mass[i], &r[1]);
    for (i = 0; i < 9; ++i)
        assert_contains(what, "inertia", p->error_bound_inertia, e->inertia[i], p->inertia[i],
                        &r[2]);
}

static void test_bounds_contain_the_error(void** state) {
    polymass_context* ctx = pm_context_new();
    ratios r[3] = {{{0}, 0}, {{0}, 0}, {{0}, 0}};
    static const char* names[3] = {"volume", "centre of mass", "inertia"};
    size_t t;
    int k, q;
    (void)state;
    for (t = 0; t < PLACEMENT_COUNT; ++t) {
        const pm_placement* pl = &placements[t];
        for (k = 0; k < PM_REF_COUNT; ++k) {
            const pm_reference_solid* ref = &pm_reference_solids[k];
            const pm_expected e0 = pm_expected_from_reference(ref);
            const pm_expected e = pm_expected_transform(&e0, NULL, pl->scale, pl->translation);
            pm_mesh m;
            polymass_mesh_desc desc;
            polymass_mass_properties p;
            polymass_moments moments = POLYMASS_MOMENTS_INIT;
            char label[200];
            pm_mesh_from_reference(&m, ref);
            pm_mesh_transform(&m, NULL, pl->scale, pl->translation);
            snprintf(label, sizeof label, "%s %s", ref->name, pl->name);
            PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
            check_bounds(label, &e, &p, r);

            /* The same solid as moments made near the origin and moved. */
            pm_mesh_free(&m);
            pm_mesh_from_reference(&m, ref);
            desc = pm_mesh_desc(&m);
            PM_ASSERT_OK(ctx, pm_moments(&moments, ctx, &desc, NULL));
            {
                const double factors[3] = {pl->scale, pl->scale, pl->scale};
                static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
                PM_ASSERT_OK(ctx, polymass_moments_scale(&moments, ctx, &moments, factors));
                PM_ASSERT_OK(ctx, polymass_moments_transform(&moments, ctx, &moments, identity,
                                                             pl->translation));
            }
            pm_props_init(&p);
            PM_ASSERT_OK(ctx, polymass_moments_mass_properties(&p, ctx, &moments, NULL));
            snprintf(label, sizeof label, "%s %s, as moved moments", ref->name, pl->name);
            check_bounds(label, &e, &p, r);
            pm_mesh_free(&m);
        }
    }
    for (q = 0; q < 3; ++q)
        printf("error_bound_%s: median bound / actual error %.3g over %zu results with an error\n",
               names[q], median(&r[q]), r[q].count);
    polymass_context_destroy(ctx);
}

/* The axes' bound grows as two moments approach each other, and says pi/2
   when they are closer than the bounds tell apart. */
static void test_axes_bound_grows_as_moments_meet(void** state) {
    polymass_context* ctx = pm_context_new();
    static const double sides[][3] = {{1, 2, 3}, {1, 1.001, 3}, {1, 1 + 1e-9, 3}};
    double previous = 0;
    size_t s;
    (void)state;
    for (s = 0; s < sizeof sides / sizeof sides[0]; ++s) {
        static const double lo[3] = {0, 0, 0};
        pm_mesh m;
        polymass_mass_properties p;
        double q[9];
        pm_mesh_box(&m, lo, sides[s], 1);
        pm_rotation_from_quaternion(q, 0.9, 0.3, -0.2, 0.25);
        pm_mesh_transform(&m, q, 1.0, NULL);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_true(p.error_bound_principal_axes > previous);
        previous = p.error_bound_principal_axes;
        pm_mesh_free(&m);
    }
    assert_true(previous > 1e-8);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bounds_contain_the_error),
        cmocka_unit_test(test_axes_bound_grows_as_moments_meet),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
