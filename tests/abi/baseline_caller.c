/* A caller compiled against the 1.0.0 header (tests/abi/baseline, frozen),
 * run against the library of this tree: every size-prefixed struct is passed
 * with its 1.0.0 size. Inputs must be read, outputs written only up to that
 * size (bytes after each output struct are checked untouched), and the
 * results must be right. Exits non-zero, saying what failed, otherwise. */
#include <math.h>
#include <polymass/polymass.h>
#include <stdio.h>
#include <string.h>

#ifdef POLYMASS_MASS_DESC_INIT
#error "compiled against the current header: this test needs tests/abi/baseline first"
#endif

#define GUARD_BYTES 512
#define GUARD_VALUE 0xA5

static int failures = 0;

static void expect(int condition, const char* what) {
    if (!condition) {
        fprintf(stderr, "FAIL: %s\n", what);
        ++failures;
    }
}

static void expect_near(double actual, double expected, const char* what) {
    const double tolerance = 1e-12 * (fabs(expected) > 1.0 ? fabs(expected) : 1.0);
    if (!(fabs(actual - expected) <= tolerance)) {
        fprintf(stderr, "FAIL: %s is %.17g, expected %.17g\n", what, actual, expected);
        ++failures;
    }
}

/* An output struct followed by bytes the library must not touch. */
#define GUARDED(type)                     \
    struct {                              \
        type value;                       \
        unsigned char guard[GUARD_BYTES]; \
    }

static void arm(unsigned char* guard) { memset(guard, GUARD_VALUE, GUARD_BYTES); }

static void expect_untouched(const unsigned char* guard, const char* what) {
    int i;
    for (i = 0; i < GUARD_BYTES; ++i)
        if (guard[i] != GUARD_VALUE) {
            fprintf(stderr, "FAIL: the library wrote byte %d past the 1.0.0 %s\n", i, what);
            ++failures;
            return;
        }
}

static void check_status(int32_t status, const polymass_context* context, const char* what) {
    if (status != POLYMASS_OK) {
        fprintf(stderr, "FAIL: %s: %s (%s)\n", what, polymass_status_string(status),
                polymass_context_message(context));
        ++failures;
    }
}

/* The box [1, 2] x [10, 12] x [-3, 0] (sides 1, 2, 3), 12 outward triangles. */
static const double box_positions[8][3] = {
    {1, 10, -3}, {2, 10, -3}, {1, 12, -3}, {2, 12, -3},
    {1, 10, 0},  {2, 10, 0},  {1, 12, 0},  {2, 12, 0},
};
static const uint32_t box_indices[36] = {
    0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, /* z = -3, z = 0 */
    0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, /* y = 10, y = 12 */
    0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5, /* x = 1, x = 2 */
};

static void check_box(const polymass_mass_properties* p, double density, const char* what) {
    const double mass = 6.0 * density;
    char name[128];
    snprintf(name, sizeof name, "%s: volume", what);
    expect_near(p->volume, 6.0, name);
    snprintf(name, sizeof name, "%s: mass", what);
    expect_near(p->mass, mass, name);
    snprintf(name, sizeof name, "%s: centre of mass x", what);
    expect_near(p->center_of_mass[0], 1.5, name);
    snprintf(name, sizeof name, "%s: centre of mass y", what);
    expect_near(p->center_of_mass[1], 11.0, name);
    snprintf(name, sizeof name, "%s: centre of mass z", what);
    expect_near(p->center_of_mass[2], -1.5, name);
    snprintf(name, sizeof name, "%s: Ixx", what);
    expect_near(p->inertia[0], mass / 12.0 * (4.0 + 9.0), name);
    snprintf(name, sizeof name, "%s: Iyy", what);
    expect_near(p->inertia[4], mass / 12.0 * (1.0 + 9.0), name);
    snprintf(name, sizeof name, "%s: Izz", what);
    expect_near(p->inertia[8], mass / 12.0 * (1.0 + 4.0), name);
    snprintf(name, sizeof name, "%s: largest principal moment", what);
    expect_near(p->principal_moments[2], mass / 12.0 * 13.0, name);
}

int main(void) {
    polymass_context* context = NULL;
    polymass_mesh* mesh = NULL;
    polymass_options options;
    GUARDED(polymass_options) got_options;
    polymass_mesh_desc desc;
    polymass_mass_desc body;
    GUARDED(polymass_mass_properties) properties;
    GUARDED(polymass_diagnostics) report;
    GUARDED(polymass_polygon_properties) polygon;
    static const double square[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};

    printf(
        "library %s, struct sizes now/1.0.0: options %u/%u, mesh_desc %u/%u, mass_desc %u/%u, "
        "mass_properties %u/%u, diagnostics %u/%u, polygon_properties %u/%u\n",
        polymass_version_string(), polymass_sizeof_options(), (unsigned)sizeof(polymass_options),
        polymass_sizeof_mesh_desc(), (unsigned)sizeof(polymass_mesh_desc),
        polymass_sizeof_mass_desc(), (unsigned)sizeof(polymass_mass_desc),
        polymass_sizeof_mass_properties(), (unsigned)sizeof(polymass_mass_properties),
        polymass_sizeof_diagnostics(), (unsigned)sizeof(polymass_diagnostics),
        polymass_sizeof_polygon_properties(), (unsigned)sizeof(polymass_polygon_properties));
    if (polymass_context_create(&context, NULL) != POLYMASS_OK) {
        fprintf(stderr, "FAIL: polymass_context_create\n");
        return 1;
    }

    /* polymass_options in and out. */
    memset(&options, 0, sizeof options);
    options.struct_size = sizeof options;
    options.flags = POLYMASS_OPTION_WELD_VERTICES;
    options.weld_tolerance = 1e-9;
    check_status(polymass_context_set_options(context, &options), context, "set_options");
    memset(&got_options.value, 0, sizeof got_options.value);
    got_options.value.struct_size = sizeof got_options.value;
    arm(got_options.guard);
    check_status(polymass_context_get_options(&got_options.value, context), context, "get_options");
    expect(got_options.value.struct_size == sizeof(polymass_options),
           "get_options keeps the caller's struct_size");
    expect(got_options.value.flags == POLYMASS_OPTION_WELD_VERTICES, "get_options: flags");
    expect_near(got_options.value.weld_tolerance, 1e-9, "get_options: weld_tolerance");
    expect_untouched(got_options.guard, "polymass_options");

    /* polymass_mesh_desc, polymass_mass_desc in; polymass_mass_properties out. */
    memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.positions = box_positions;
    desc.vertex_count = 8;
    desc.indices = box_indices;
    desc.index_count = 36;
    memset(&body, 0, sizeof body);
    body.struct_size = sizeof body;
    body.mass_mode = POLYMASS_MASS_FROM_DENSITY;
    body.density = 2.5;

    memset(&properties.value, 0, sizeof properties.value);
    properties.value.struct_size = sizeof properties.value;
    arm(properties.guard);
    check_status(polymass_mass_properties_compute(&properties.value, context, &desc, &body),
                 context, "mass_properties_compute");
    check_box(&properties.value, 2.5, "mass_properties_compute");
    expect(properties.value.struct_size == sizeof(polymass_mass_properties),
           "mass_properties keeps the caller's struct_size");
    expect_untouched(properties.guard, "polymass_mass_properties");

    check_status(polymass_mesh_create(&mesh, context, &desc), context, "mesh_create");
    arm(properties.guard);
    check_status(polymass_mesh_mass_properties(&properties.value, context, mesh, NULL), context,
                 "mesh_mass_properties");
    check_box(&properties.value, 1.0, "mesh_mass_properties");
    expect_untouched(properties.guard, "polymass_mass_properties");
    polymass_mesh_destroy(mesh);

    /* polymass_diagnostics out: a box with one face missing. */
    desc.index_count = 33;
    memset(&report.value, 0, sizeof report.value);
    report.value.struct_size = sizeof report.value;
    arm(report.guard);
    expect(polymass_mesh_check(&report.value, context, &desc) == POLYMASS_ERROR_OPEN,
           "mesh_check of an open box returns POLYMASS_ERROR_OPEN");
    expect(report.value.status == POLYMASS_ERROR_OPEN, "diagnostics: status");
    expect(report.value.face_count == 11, "diagnostics: face_count");
    expect(report.value.open_edges == 3, "diagnostics: open_edges");
    expect(report.value.struct_size == sizeof(polymass_diagnostics),
           "diagnostics keeps the caller's struct_size");
    expect_untouched(report.guard, "polymass_diagnostics");

    /* polymass_polygon_properties out. */
    memset(&polygon.value, 0, sizeof polygon.value);
    polygon.value.struct_size = sizeof polygon.value;
    arm(polygon.guard);
    check_status(polymass_polygon_compute(&polygon.value, context, &square[0][0], 4, 0), context,
                 "polygon_compute");
    expect_near(polygon.value.area, 4.0, "polygon: area");
    expect_near(polygon.value.centroid[0], 1.0, "polygon: centroid x");
    expect_near(polygon.value.second_moments[0], 16.0 / 12.0, "polygon: Ixx");
    expect_untouched(polygon.guard, "polymass_polygon_properties");

    polymass_context_destroy(context);
    if (failures) {
        fprintf(stderr, "%d failure(s)\n", failures);
        return 1;
    }
    printf("a 1.0.0 caller works with this library\n");
    return 0;
}
