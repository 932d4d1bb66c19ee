/* Principal moments and axes, the inertia about a given point, and the body
 * from a density or a total mass. */
#include "test_support.h"

#include <math.h>
#include <string.h>

/* Moments ascending, axes a proper rotation, R diag(moments) R^T = inertia. */
static void assert_principal_decomposition(const char* what, const polymass_mass_properties* p) {
    double rt[9], rtr[9], d[9], rebuilt[9];
    static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double* m = p->principal_moments;
    int i;
    if (!(m[0] <= m[1] && m[1] <= m[2])) {
        print_error("%s: principal moments not ascending: %.17g %.17g %.17g\n", what, m[0], m[1],
                    m[2]);
        fail();
    }
    assert_true(m[0] > 0);
    /* the triangle inequality of a real body */
    PM_ASSERT_ABS("I0 + I1 >= I2", 0.0, fmin(0.0, m[0] + m[1] - m[2]), PM_TOL * m[2]);
    PM_ASSERT_REL("trace = sum of principal moments", p->inertia[0] + p->inertia[4] + p->inertia[8],
                  m[0] + m[1] + m[2], PM_TOL);
    pm_mat3_transpose(rt, p->principal_axes);
    pm_mat3_mul(rtr, rt, p->principal_axes);
    for (i = 0; i < 9; ++i) {
        PM_ASSERT_ABS("R^T R = I", identity[i], rtr[i], PM_TOL);
    }
    PM_ASSERT_ABS("det R = +1", 1.0, pm_mat3_det(p->principal_axes), PM_TOL);
    memset(d, 0, sizeof d);
    d[0] = m[0];
    d[4] = m[1];
    d[8] = m[2];
    pm_mat3_mul(rebuilt, p->principal_axes, d);
    pm_mat3_mul(rebuilt, rebuilt, rt);
    for (i = 0; i < 9; ++i) {
        PM_ASSERT_ABS("R diag R^T = inertia (relative to the largest moment)", p->inertia[i],
                      rebuilt[i], PM_TOL * m[2]);
    }
}

static void test_decomposition_of_every_solid(void** state) {
    polymass_context* ctx = pm_context_new();
    double q[9];
    int k, rotated;
    (void)state;
    pm_rotation_from_quaternion(q, 0.6, -0.2, 0.5, 0.3);
    for (k = 0; k < PM_REF_COUNT; ++k) {
        for (rotated = 0; rotated < 2; ++rotated) {
            pm_mesh m;
            polymass_mass_properties p;
            pm_mesh_from_reference(&m, &pm_reference_solids[k]);
            if (rotated) {
                pm_mesh_transform(&m, q, 1.0, NULL);
            }
            PM_ASSERT_OK(
                ctx, pm_compute_flags(
                         &p, ctx, &m,
                         rotated ? pm_reference_rounded_rotation_flags(&pm_reference_solids[k]) : 0,
                         NULL));
            assert_principal_decomposition(pm_reference_solids[k].name, &p);
            pm_mesh_free(&m);
        }
    }
    polymass_context_destroy(ctx);
}

/* Box 4 x 2 x 1: moments m(b^2+c^2)/12 < m(a^2+c^2)/12 < m(a^2+b^2)/12 about
   x, y, z; rotated by Q, the axes are the columns of Q (up to sign). */
static void test_box_axes(void** state) {
    static const double lo[3] = {-2, -1, -0.5}, hi[3] = {2, 1, 0.5};
    polymass_context* ctx = pm_context_new();
    const double v = 8.0;
    const double expected[3] = {v * 5 / 12, v * 17 / 12, v * 20 / 12};
    double q[9];
    int rotated, i, j;
    (void)state;
    pm_rotation_from_quaternion(q, 0.9, 0.1, -0.3, 0.2);
    for (rotated = 0; rotated < 2; ++rotated) {
        static const double t[3] = {3.25, -1.5, 7};
        pm_mesh m;
        polymass_mass_properties p;
        pm_mesh_box(&m, lo, hi, 1);
        pm_mesh_transform(&m, rotated ? q : NULL, 1.0, t);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_principal_decomposition("box 4 x 2 x 1", &p);
        for (i = 0; i < 3; ++i) {
            double dot = 0;
            PM_ASSERT_REL("principal moment", expected[i], p.principal_moments[i], PM_TOL);
            /* column i of R is +-(column i of Q), or +-e_i unrotated */
            for (j = 0; j < 3; ++j) {
                dot += p.principal_axes[3 * j + i] * (rotated ? q[3 * j + i] : (i == j));
            }
            PM_ASSERT_ABS("|axis . expected axis| = 1", 1.0, fabs(dot), PM_TOL);
        }
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* All three moments equal: the coordinate axes (identity). */
static void test_isotropic_axes_are_identity(void** state) {
    static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const double lo[3] = {0.25, -0.5, 0.75}, hi[3] = {1.75, 1.0, 2.25};
    polymass_context* ctx = pm_context_new();
    double q[9];
    int variant, i;
    (void)state;
    pm_rotation_from_quaternion(q, 0.8, 0.4, -0.2, 0.4);
    for (variant = 0; variant < 5; ++variant) {
        pm_mesh m;
        polymass_mass_properties p;
        const char* what = "";
        if (variant < 2) {
            what = variant ? "cube (triangles)" : "cube (quads)";
            pm_mesh_box(&m, lo, hi, variant);
        } else if (variant == 2) {
            what = "cube rotated by a general rotation";
            pm_mesh_box(&m, lo, hi, 0);
            pm_mesh_transform(&m, q, 1.0, NULL);
        } else {
            what = variant == 3 ? "regular tetrahedron" : "regular tetrahedron rotated";
            pm_mesh_from_reference(&m, &pm_reference_solids[PM_REF_TETRA_REGULAR]);
            if (variant == 4) {
                pm_mesh_transform(&m, q, 1.0, NULL);
            }
        }
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_principal_decomposition(what, &p);
        PM_ASSERT_REL(what, p.principal_moments[0], p.principal_moments[2], PM_TOL);
        for (i = 0; i < 9; ++i) {
            PM_ASSERT_ABS(what, identity[i], p.principal_axes[i], PM_TOL);
        }
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* Two equal moments (a square-section box 1 x 1 x 3): the distinct axis is
   +-z (smallest moment), the other two span the xy plane; the choice is
   deterministic (the same bits every time, through either path). */
static void test_two_equal_moments(void** state) {
    static const double lo[3] = {-0.5, 0.5, 1}, hi[3] = {0.5, 1.5, 4};
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties a, b, c;
    polymass_mesh* mesh = NULL;
    pm_mesh m;
    int i;
    (void)state;
    pm_mesh_box(&m, lo, hi, 0);
    PM_ASSERT_OK(ctx, pm_compute(&a, ctx, &m, NULL));
    assert_principal_decomposition("square-section box", &a);
    PM_ASSERT_REL("Izz = m (1 + 1) / 12", 3.0 * 2 / 12, a.principal_moments[0], PM_TOL);
    PM_ASSERT_REL("Ixx = m (1 + 9) / 12", 3.0 * 10 / 12, a.principal_moments[1], PM_TOL);
    PM_ASSERT_REL("Iyy = Ixx", a.principal_moments[1], a.principal_moments[2], PM_TOL);
    /* column k of R is (R[0][k], R[1][k], R[2][k]): z components at 6, 7, 8 */
    PM_ASSERT_ABS("first axis is +-z", 1.0, fabs(a.principal_axes[6]), PM_TOL);
    for (i = 1; i < 3; ++i) {
        PM_ASSERT_ABS("the other axes lie in the xy plane", 0.0, a.principal_axes[6 + i], PM_TOL);
    }
    PM_ASSERT_OK(ctx, pm_compute(&b, ctx, &m, NULL));
    PM_ASSERT_SAME_PROPERTIES("the same box twice", &a, &b);
    {
        const polymass_mesh_desc d = pm_mesh_desc(&m);
        PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d, NULL));
    }
    pm_props_init(&c);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&c, ctx, mesh, NULL));
    PM_ASSERT_SAME_PROPERTIES("through a mesh object", &a, &c);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&c, ctx, mesh, NULL));
    PM_ASSERT_SAME_PROPERTIES("through a mesh object, again", &a, &c);
    polymass_mesh_destroy(mesh);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* polymass_inertia_about: I_P = I_C + m (|d|^2 Id - d d^T), d = C - P,
   against the closed form in long double; about the origin it is
   inertia_origin bit for bit, about the centre of mass I_C. */
static void test_inertia_about_a_point(void** state) {
    static const double points[][3] = {{1, -2, 0.5}, {0, 0, 0}, {-100, 250, 3}, {1e6, 0, -1e6}};
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_HOUSE];
    const polymass_mesh_desc d = pm_reference_desc(ref);
    polymass_context* ctx = pm_context_new();
    polymass_mesh* mesh = NULL;
    polymass_mass_properties p;
    polymass_mass_desc md;
    size_t k;
    int i;
    (void)state;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d, NULL));
    pm_props_init(&p);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, NULL));
    {
        static const double origin[3] = {0, 0, 0};
        double about[9];
        assert_int_equal(polymass_inertia_about(about, &p, origin), POLYMASS_OK);
        for (i = 0; i < 9; ++i) {
            PM_ASSERT_SAME("inertia about the origin = inertia_origin", p.inertia_origin[i],
                           about[i]);
        }
    }
    md = pm_mass_density(2.5);
    pm_props_init(&p);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    for (k = 0; k < sizeof points / sizeof points[0]; ++k) {
        double expected[9], about[9];
        {
            double ic[9];
            for (i = 0; i < 9; ++i) {
                ic[i] = 2.5 * ref->inertia[i];
            }
            pm_parallel_axis(expected, ic, 2.5 * ref->volume, ref->center_of_mass, points[k]);
        }
        assert_int_equal(polymass_inertia_about(about, &p, points[k]), POLYMASS_OK);
        PM_ASSERT_TENSOR("inertia about the point", expected, about, PM_TOL);
    }
    /* about the centre of mass itself */
    {
        double about[9];
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, NULL));
        assert_int_equal(polymass_inertia_about(about, &p, ref->center_of_mass), POLYMASS_OK);
        PM_ASSERT_TENSOR("inertia about the centre of mass", ref->inertia, about, PM_TOL);
    }
    /* What it refuses: NULL pointers, a point that is not finite, properties
       of an unknown size; a moment beyond a double overflows. */
    {
        static const double nan_point[3] = {0, NAN, 0}, far_point[3] = {1e300, 0, 0};
        double about[9];
        assert_int_equal(polymass_inertia_about(NULL, &p, points[0]),
                         POLYMASS_ERROR_INVALID_ARGUMENT);
        assert_int_equal(polymass_inertia_about(about, NULL, points[0]),
                         POLYMASS_ERROR_INVALID_ARGUMENT);
        assert_int_equal(polymass_inertia_about(about, &p, NULL), POLYMASS_ERROR_INVALID_ARGUMENT);
        assert_int_equal(polymass_inertia_about(about, &p, nan_point),
                         POLYMASS_ERROR_INVALID_ARGUMENT);
        assert_int_equal(polymass_inertia_about(about, &p, far_point), POLYMASS_ERROR_OVERFLOW);
        p.struct_size = 8;
        assert_int_equal(polymass_inertia_about(about, &p, points[0]),
                         POLYMASS_ERROR_INVALID_ARGUMENT);
    }
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(ctx);
}

/* Density scales mass and every inertia; a total mass sets the density. */
static void test_mass_from_density_and_density_from_mass(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_PRISM_12GON];
    const polymass_mesh_desc d = pm_reference_desc(ref);
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties unit, p;
    polymass_mass_desc md;
    double factor;
    int i, mode;
    (void)state;
    pm_props_init(&unit);
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&unit, NULL, ctx, &d, NULL, NULL));
    PM_ASSERT_REL("unit density: mass = volume", unit.volume, unit.mass, PM_TOL);
    PM_ASSERT_REL("unit density", 1.0, unit.density, PM_TOL);
    for (mode = 0; mode < 2; ++mode) {
        if (mode == 0) {
            md = pm_mass_density(7850.0); /* steel, kg/m^3 */
            factor = 7850.0;
        } else {
            md = pm_mass_total(10.0);
            factor = 10.0 / ref->volume;
        }
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, &md));
        PM_ASSERT_REL("volume does not depend on density", ref->volume, p.volume, PM_TOL);
        PM_ASSERT_REL("density", factor, p.density, PM_TOL);
        PM_ASSERT_REL("mass", factor * ref->volume, p.mass, PM_TOL);
        if (mode == 1) {
            PM_ASSERT_REL("the given total mass", 10.0, p.mass, PM_TOL);
        }
        PM_ASSERT_REL("surface area does not depend on density", unit.surface_area, p.surface_area,
                      PM_TOL);
        for (i = 0; i < 3; ++i) {
            PM_ASSERT_CLOSE("centre of mass does not depend on density", unit.center_of_mass[i],
                            p.center_of_mass[i], PM_TOL, 1.0);
            PM_ASSERT_REL("principal moments scale", factor * unit.principal_moments[i],
                          p.principal_moments[i], PM_TOL);
        }
        {
            double ic[9], io[9];
            for (i = 0; i < 9; ++i) {
                ic[i] = factor * ref->inertia[i];
                io[i] = factor * ref->inertia_origin[i];
            }
            PM_ASSERT_TENSOR("inertia scales", ic, p.inertia, PM_TOL);
            PM_ASSERT_TENSOR("inertia_origin scales", io, p.inertia_origin, PM_TOL);
        }
    }
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decomposition_of_every_solid),
        cmocka_unit_test(test_box_axes),
        cmocka_unit_test(test_isotropic_axes_are_identity),
        cmocka_unit_test(test_two_equal_moments),
        cmocka_unit_test(test_inertia_about_a_point),
        cmocka_unit_test(test_mass_from_density_and_density_from_mass),
    };
    return cmocka_run_group_tests_name("principal_axes", tests, NULL, NULL);
}
