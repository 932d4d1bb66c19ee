/* polymass_polygon_compute: area, centroid and second moments of area
 * (engineering sign: Ixy = +integral x y dA) against closed forms. */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

typedef struct polygon_expected {
    double area;
    double centroid[2];
    double second_moments[3]; /* Ixx, Iyy, Ixy about the centroid */
    double size;              /* the polygon's diameter: scale of the centroid tolerance */
} polygon_expected;

/* About the origin from about the centroid: Ixx + A cy^2, Iyy + A cx^2,
   Ixy + A cx cy. */
static void to_origin(const polygon_expected* e, long double out[3]) {
    const long double a = e->area, cx = e->centroid[0], cy = e->centroid[1];
    out[0] = e->second_moments[0] + a * cy * cy;
    out[1] = e->second_moments[1] + a * cx * cx;
    out[2] = e->second_moments[2] + a * cx * cy;
}

static polygon_expected rectangle_expected(double x0, double y0, double w, double h) {
    polygon_expected e;
    e.area = w * h;
    e.centroid[0] = x0 + w / 2;
    e.centroid[1] = y0 + h / 2;
    e.second_moments[0] = w * h * h * h / 12;
    e.second_moments[1] = h * w * w * w / 12;
    e.second_moments[2] = 0;
    e.size = sqrt(w * w + h * h);
    return e;
}

/* Union of two polygons that do not overlap. */
static polygon_expected combine(const polygon_expected* a, const polygon_expected* b) {
    polygon_expected e;
    long double oa[3], ob[3];
    int i;
    e.area = a->area + b->area;
    for (i = 0; i < 2; ++i) {
        e.centroid[i] = (a->area * a->centroid[i] + b->area * b->centroid[i]) / e.area;
    }
    to_origin(a, oa);
    to_origin(b, ob);
    e.second_moments[0] =
        (double)(oa[0] + ob[0] - (long double)e.area * e.centroid[1] * e.centroid[1]);
    e.second_moments[1] =
        (double)(oa[1] + ob[1] - (long double)e.area * e.centroid[0] * e.centroid[0]);
    e.second_moments[2] =
        (double)(oa[2] + ob[2] - (long double)e.area * e.centroid[0] * e.centroid[1]);
    e.size = a->size + b->size;
    return e;
}

static void check_polygon_at(const char* file, int line, const char* what,
                             const polygon_expected* e, const polymass_polygon_properties* p) {
    long double origin[3];
    double o[3], max_c, max_o;
    int i;
    pm_check_close(file, line, "area", e->area, p->area, PM_TOL, 0.0);
    for (i = 0; i < 2; ++i) {
        pm_check_abs(file, line, "centroid (relative to the polygon's size)", e->centroid[i],
                     p->centroid[i], PM_TOL * e->size + 4 * DBL_EPSILON * fabs(e->centroid[i]));
    }
    max_c = fmax(fabs(e->second_moments[0]), fabs(e->second_moments[1]));
    pm_check_close(file, line, "Ixx about the centroid", e->second_moments[0], p->second_moments[0],
                   PM_TOL, 0.0);
    pm_check_close(file, line, "Iyy about the centroid", e->second_moments[1], p->second_moments[1],
                   PM_TOL, 0.0);
    pm_check_abs(file, line, "Ixy about the centroid (relative to max(Ixx, Iyy))",
                 e->second_moments[2], p->second_moments[2], PM_TOL * max_c);
    to_origin(e, origin);
    for (i = 0; i < 3; ++i) {
        o[i] = (double)origin[i];
    }
    max_o = fmax(fabs(o[0]), fabs(o[1]));
    pm_check_close(file, line, "Ixx about the origin", o[0], p->second_moments_origin[0], PM_TOL,
                   0.0);
    pm_check_close(file, line, "Iyy about the origin", o[1], p->second_moments_origin[1], PM_TOL,
                   0.0);
    pm_check_abs(file, line, "Ixy about the origin (relative to max(Ixx, Iyy))", o[2],
                 p->second_moments_origin[2], PM_TOL * max_o);
    pm_check_close(file, line, "polar moment = Ixx + Iyy",
                   e->second_moments[0] + e->second_moments[1], p->polar_moment, PM_TOL, 0.0);
    /* principal moments: eigenvalues of [[Ixx, -Ixy], [-Ixy, Iyy]] */
    {
        const double mean = 0.5 * (e->second_moments[0] + e->second_moments[1]);
        const double half = 0.5 * (e->second_moments[0] - e->second_moments[1]);
        const double r = hypot(half, e->second_moments[2]);
        pm_check_abs(file, line, "smaller principal moment", mean - r, p->principal_moments[0],
                     PM_TOL * max_c);
        pm_check_abs(file, line, "larger principal moment", mean + r, p->principal_moments[1],
                     PM_TOL * max_c);
    }
    if (!(p->principal_angle > -PI / 2 && p->principal_angle <= PI / 2)) {
        print_error("%s:%d: %s: principal angle %.17g outside (-pi/2, pi/2]\n", file, line, what,
                    p->principal_angle);
        _fail(file, line);
    }
}
#define CHECK_POLYGON(what, e, p) check_polygon_at(__FILE__, __LINE__, (what), (e), (p))

static int32_t polygon(polymass_polygon_properties* out, polymass_context* ctx, const double* xy,
                       size_t n) {
    pm_polygon_props_init(out);
    return polymass_polygon_compute(out, ctx, xy, n, 0);
}

static void reverse_points(double* xy, size_t n) {
    size_t i;
    for (i = 0; i < n / 2; ++i) {
        const double x = xy[2 * i], y = xy[2 * i + 1];
        xy[2 * i] = xy[2 * (n - 1 - i)];
        xy[2 * i + 1] = xy[2 * (n - 1 - i) + 1];
        xy[2 * (n - 1 - i)] = x;
        xy[2 * (n - 1 - i) + 1] = y;
    }
}

static void test_rectangle(void** state) {
    static const double rects[][4] = {
        {0, 0, 1, 1}, {0, 0, 4, 1}, {-2.5, 1.25, 3, 0.5}, {1, -3, 0.25, 6}};
    polymass_context* ctx = pm_context_new();
    size_t k;
    (void)state;
    for (k = 0; k < sizeof rects / sizeof rects[0]; ++k) {
        const double x0 = rects[k][0], y0 = rects[k][1], w = rects[k][2], h = rects[k][3];
        double xy[8] = {x0, y0, x0 + w, y0, x0 + w, y0 + h, x0, y0 + h};
        const polygon_expected e = rectangle_expected(x0, y0, w, h);
        polymass_polygon_properties p;
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 4));
        CHECK_POLYGON("rectangle", &e, &p);
        assert_int_equal(p.orientation, POLYMASS_COUNTER_CLOCKWISE);
        /* axis of the smaller moment: x for a wide rectangle, y for a tall one */
        if (w > h) {
            PM_ASSERT_ABS("principal angle of a wide rectangle", 0.0, p.principal_angle, PM_TOL);
        } else if (h > w) {
            PM_ASSERT_ABS("principal angle of a tall rectangle", PI / 2, p.principal_angle, PM_TOL);
        }
        reverse_points(xy, 4);
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 4));
        CHECK_POLYGON("rectangle, clockwise", &e, &p);
        assert_int_equal(p.orientation, POLYMASS_CLOCKWISE);
    }
    polymass_context_destroy(ctx);
}

/* Triangle about the origin (closed forms over the vertices):
   Ixx = A/6 (y1^2 + y2^2 + y3^2 + y1 y2 + y2 y3 + y3 y1), Iyy likewise,
   Ixy = A/12 (2 sum xi yi + x1 y2 + x2 y1 + x1 y3 + x3 y1 + x2 y3 + x3 y2). */
static polygon_expected triangle_expected(const double xy[6]) {
    const double x1 = xy[0], y1 = xy[1], x2 = xy[2], y2 = xy[3], x3 = xy[4], y3 = xy[5];
    const double a = 0.5 * fabs((x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1));
    polygon_expected e;
    const double cx = (x1 + x2 + x3) / 3, cy = (y1 + y2 + y3) / 3;
    const double ixx = a / 6 * (y1 * y1 + y2 * y2 + y3 * y3 + y1 * y2 + y2 * y3 + y3 * y1);
    const double iyy = a / 6 * (x1 * x1 + x2 * x2 + x3 * x3 + x1 * x2 + x2 * x3 + x3 * x1);
    const double ixy = a / 12 *
                       (2 * (x1 * y1 + x2 * y2 + x3 * y3) + x1 * y2 + x2 * y1 + x1 * y3 + x3 * y1 +
                        x2 * y3 + x3 * y2);
    e.area = a;
    e.centroid[0] = cx;
    e.centroid[1] = cy;
    e.second_moments[0] = ixx - a * cy * cy;
    e.second_moments[1] = iyy - a * cx * cx;
    e.second_moments[2] = ixy - a * cx * cy;
    e.size = fmax(hypot(x2 - x1, y2 - y1), fmax(hypot(x3 - x1, y3 - y1), hypot(x3 - x2, y3 - y2)));
    return e;
}

static void test_triangle(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_polygon_properties p;
    (void)state;
    /* right triangle, legs b = 3 (x) and h = 2 (y) at the origin:
       Ixx = b h^3 / 36, Iyy = h b^3 / 36, Ixy = -b^2 h^2 / 72 about the centroid */
    {
        double xy[6] = {0, 0, 3, 0, 0, 2};
        polygon_expected e;
        e.area = 3.0;
        e.centroid[0] = 1.0;
        e.centroid[1] = 2.0 / 3.0;
        e.second_moments[0] = 3.0 * 8 / 36;
        e.second_moments[1] = 2.0 * 27 / 36;
        e.second_moments[2] = -9.0 * 4 / 72;
        e.size = sqrt(13.0);
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 3));
        CHECK_POLYGON("right triangle", &e, &p);
        assert_int_equal(p.orientation, POLYMASS_COUNTER_CLOCKWISE);
        PM_ASSERT_REL("Ixy about the origin = +b^2 h^2 / 24 (engineering sign)", 9.0 * 4 / 24,
                      p.second_moments_origin[2], PM_TOL);
    }
    /* a general triangle */
    {
        double xy[6] = {-1.25, 0.5, 2.75, -0.375, 0.625, 3.5};
        const polygon_expected e = triangle_expected(xy);
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 3));
        CHECK_POLYGON("general triangle", &e, &p);
        reverse_points(xy, 3);
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 3));
        CHECK_POLYGON("general triangle, clockwise", &e, &p);
        assert_int_equal(p.orientation, POLYMASS_CLOCKWISE);
    }
    polymass_context_destroy(ctx);
}

/* Non-convex: an L of a 4 x 1 bar and a 1 x 2 upright on its left end. */
static void test_l_shape(void** state) {
    double xy[12] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 3, 0, 3};
    const polygon_expected bar = rectangle_expected(0, 0, 4, 1);
    const polygon_expected upright = rectangle_expected(0, 1, 1, 2);
    polygon_expected e = combine(&bar, &upright);
    polymass_context* ctx = pm_context_new();
    polymass_polygon_properties p;
    int start;
    (void)state;
    e.size = 5.0;
    for (start = 0; start < 6; ++start) { /* any starting vertex, reflex ones too */
        double rotated[12];
        int i;
        for (i = 0; i < 6; ++i) {
            rotated[2 * i] = xy[2 * ((i + start) % 6)];
            rotated[2 * i + 1] = xy[2 * ((i + start) % 6) + 1];
        }
        PM_ASSERT_OK(ctx, polygon(&p, ctx, rotated, 6));
        CHECK_POLYGON("L shape", &e, &p);
        assert_int_equal(p.orientation, POLYMASS_COUNTER_CLOCKWISE);
        reverse_points(rotated, 6);
        PM_ASSERT_OK(ctx, polygon(&p, ctx, rotated, 6));
        CHECK_POLYGON("L shape, clockwise", &e, &p);
        assert_int_equal(p.orientation, POLYMASS_CLOCKWISE);
    }
    /* non-zero product of inertia about the centroid: the L is not symmetric */
    assert_true(fabs(e.second_moments[2]) > 0.1);
    polymass_context_destroy(ctx);
}

/* Far from the origin the moments about the centroid keep their digits. */
static void test_far_from_origin(void** state) {
    static const double offsets[][2] = {{1e8, 1e8}, {-1e8, 3e7}, {1e6, -1e6}, {134217728.0, 0}};
    polymass_context* ctx = pm_context_new();
    size_t k;
    (void)state;
    for (k = 0; k < sizeof offsets / sizeof offsets[0]; ++k) {
        const double ox = offsets[k][0], oy = offsets[k][1];
        double xy[12] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 3, 0, 3};
        const polygon_expected bar = rectangle_expected(ox, oy, 4, 1);
        const polygon_expected upright = rectangle_expected(ox, oy + 1, 1, 2);
        polygon_expected e = combine(&bar, &upright);
        polymass_polygon_properties p;
        int i;
        e.size = 5.0;
        /* the moments about the centroid do not depend on where the L is */
        {
            const polygon_expected bar0 = rectangle_expected(0, 0, 4, 1);
            const polygon_expected upright0 = rectangle_expected(0, 1, 1, 2);
            const polygon_expected e0 = combine(&bar0, &upright0);
            memcpy(e.second_moments, e0.second_moments, sizeof e.second_moments);
        }
        for (i = 0; i < 6; ++i) {
            xy[2 * i] += ox;
            xy[2 * i + 1] += oy;
        }
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 6));
        CHECK_POLYGON("L shape far from the origin", &e, &p);
    }
    polymass_context_destroy(ctx);
}

/* A 4 x 1 rectangle rotated by theta about its centre: principal moments
   w h^3/12 and h w^3/12, the smaller about the long axis, at angle theta
   (brought into (-pi/2, pi/2]). */
static void test_rotated_rectangle_principal_angle(void** state) {
    static const double angles[] = {0.3, -0.7, 1.2, 2.0, -2.5, PI / 2 - 0.01};
    polymass_context* ctx = pm_context_new();
    size_t k;
    (void)state;
    for (k = 0; k < sizeof angles / sizeof angles[0]; ++k) {
        const double t = angles[k], c = cos(t), s = sin(t);
        static const double corners[8] = {-2, -0.5, 2, -0.5, 2, 0.5, -2, 0.5};
        double xy[8], expected_angle = t;
        polymass_polygon_properties p;
        int i;
        for (i = 0; i < 4; ++i) {
            xy[2 * i] = 10 + c * corners[2 * i] - s * corners[2 * i + 1];
            xy[2 * i + 1] = -5 + s * corners[2 * i] + c * corners[2 * i + 1];
        }
        while (expected_angle > PI / 2) {
            expected_angle -= PI;
        }
        while (expected_angle <= -PI / 2) {
            expected_angle += PI;
        }
        PM_ASSERT_OK(ctx, polygon(&p, ctx, xy, 4));
        PM_ASSERT_REL("area", 4.0, p.area, PM_TOL);
        PM_ASSERT_ABS("centroid x", 10.0, p.centroid[0], PM_TOL * 10);
        PM_ASSERT_ABS("centroid y", -5.0, p.centroid[1], PM_TOL * 10);
        PM_ASSERT_REL("smaller principal moment", 4.0 / 12, p.principal_moments[0], PM_TOL);
        PM_ASSERT_REL("larger principal moment", 64.0 / 12, p.principal_moments[1], PM_TOL);
        PM_ASSERT_ABS("principal angle", expected_angle, p.principal_angle, PM_TOL);
        PM_ASSERT_REL("polar moment is invariant", 68.0 / 12, p.polar_moment, PM_TOL);
        /* Ixy about the centroid: (Iyy_body - Ixx_body) sin(2t) / 2 with the
           engineering sign: the long axis along (cos t, sin t) */
        PM_ASSERT_ABS("Ixy about the centroid", (64.0 - 4.0) / 12 * sin(2 * t) / 2,
                      p.second_moments[2], PM_TOL * 64.0 / 12);
    }
    polymass_context_destroy(ctx);
}

/* Points interleaved with other data. */
static void test_stride(void** state) {
    static const double xy[12] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 3, 0, 3};
    static const size_t strides[] = {16, 24, 32, 40};
    polymass_context* ctx = pm_context_new();
    polymass_polygon_properties packed, p;
    size_t k;
    (void)state;
    PM_ASSERT_OK(ctx, polygon(&packed, ctx, xy, 6));
    for (k = 0; k < sizeof strides / sizeof strides[0]; ++k) {
        const size_t doubles = strides[k] / sizeof(double);
        double* buffer = malloc(6 * strides[k]);
        int i;
        size_t j;
        assert_non_null(buffer);
        for (i = 0; i < 6; ++i) {
            buffer[doubles * (size_t)i] = xy[2 * i];
            buffer[doubles * (size_t)i + 1] = xy[2 * i + 1];
            for (j = 2; j < doubles; ++j) {
                buffer[doubles * (size_t)i + j] = NAN; /* not a point: never read */
            }
        }
        pm_polygon_props_init(&p);
        PM_ASSERT_OK(ctx, polymass_polygon_compute(&p, ctx, buffer, 6, strides[k]));
        assert_memory_equal(&packed, &p, sizeof p);
        free(buffer);
    }
    polymass_context_destroy(ctx);
}

static void test_polygon_errors(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_polygon_properties p;
    double xy[8] = {0, 0, 1, 1, 2, 2, 3, 3};
    (void)state;
    /* collinear */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_AREA, polygon(&p, ctx, xy, 4));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    /* all points equal */
    {
        double same[6] = {5, 5, 5, 5, 5, 5};
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_AREA, polygon(&p, ctx, same, 3));
    }
    /* too few points */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_FACE_TOO_SMALL, polygon(&p, ctx, xy, 2));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_FACE_TOO_SMALL, polygon(&p, ctx, xy, 1));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_FACE_TOO_SMALL, polygon(&p, ctx, xy, 0));
    /* non-finite */
    {
        double bad[6] = {0, 0, 1, 0, 0, 1};
        bad[3] = NAN;
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, polygon(&p, ctx, bad, 3));
        assert_true(strlen(polymass_context_message(ctx)) > 0);
        bad[3] = INFINITY;
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, polygon(&p, ctx, bad, 3));
    }
    /* a right triangle with legs L: area L^2/2 and polar moment L^4/18 must
       both be normal doubles - at L = 1e+-70 they are, at L = 1e80 the polar
       moment overflows, at L = 1e-80 it is subnormal */
    {
        static const double legs[] = {1e70, 1e-70, 1e80, 1e-80};
        size_t i;
        for (i = 0; i < 4; ++i) {
            const double l = legs[i];
            double tri[6] = {0, 0, 0, 0, 0, 0};
            tri[2] = l;
            tri[5] = l;
            if (i < 2) {
                PM_ASSERT_OK(ctx, polygon(&p, ctx, tri, 3));
                PM_ASSERT_REL("area", l * l / 2, p.area, PM_TOL);
                PM_ASSERT_REL("polar moment", l * l * l * l / 18, p.polar_moment, PM_TOL);
            } else {
                PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OVERFLOW, polygon(&p, ctx, tri, 3));
                assert_non_null(strstr(polymass_context_message(ctx), "do not fit in a double"));
            }
        }
    }
    /* stride smaller than a point; counts whose size overflows */
    {
        double tri[6] = {0, 0, 1, 0, 0, 1};
        pm_polygon_props_init(&p);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_polygon_compute(&p, ctx, tri, 3, 8));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_polygon_compute(&p, ctx, tri, 3, 15));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_polygon_compute(&p, ctx, tri, UINT64_MAX / 8, 0));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_polygon_compute(&p, ctx, tri, 3, UINT64_MAX / 2));
        /* and a success clears the message */
        PM_ASSERT_OK(ctx, polymass_polygon_compute(&p, ctx, tri, 3, 0));
        assert_string_equal(polymass_context_message(ctx), "");
        PM_ASSERT_REL("area", 0.5, p.area, PM_TOL);
    }
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rectangle),
        cmocka_unit_test(test_triangle),
        cmocka_unit_test(test_l_shape),
        cmocka_unit_test(test_far_from_origin),
        cmocka_unit_test(test_rotated_rectangle_principal_angle),
        cmocka_unit_test(test_stride),
        cmocka_unit_test(test_polygon_errors),
    };
    return cmocka_run_group_tests_name("polygon2d", tests, NULL, NULL);
}
