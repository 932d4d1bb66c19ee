/* A caller compiled against the 2.0.0 header (tests/abi/baseline, frozen),
 * run against the library of this tree: every size-prefixed struct is passed
 * with its 2.0.0 size, through every kind of call (initialisers, context,
 * the one call, a mesh and its questions, a batch, a packed batch,
 * moments, polygons, welding). Inputs must be read, outputs written only up to that size (the
 * bytes after each output struct are checked untouched), and the results
 * must be right. From 2.0 on the structs only grow: this is the caller that
 * shows an older one keeps working. Exits non-zero, saying what failed. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The frozen header, by its path from this file: never the tree's own. */
#include "baseline/polymass/polymass.h"

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

/* An output struct (or array of them) followed by bytes the library must not
   touch. */
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
            fprintf(stderr, "FAIL: the library wrote byte %d past the 2.0.0 %s\n", i, what);
            ++failures;
            return;
        }
}

static void check_status(int32_t status, const polymass_context* context, const char* what) {
    if (status != POLYMASS_OK) {
        fprintf(stderr, "FAIL: %s: %s (%s)\n", what, polymass_status_string(status),
                context ? polymass_context_message(context) : "");
        ++failures;
    }
}

/* A malloc that counts: the context must use the caller's allocator, read
   from a 2.0.0 polymass_allocator, and give back all it took. */
typedef struct counting {
    long live;
    long calls;
} counting;

/* malloc's block, aligned within, its start kept just before what is returned. */
static void* counting_allocate(void* user_data, size_t size, size_t alignment) {
    counting* count = (counting*)user_data;
    unsigned char* block;
    uintptr_t at;
    if (alignment < sizeof(void*)) alignment = sizeof(void*);
    block = (unsigned char*)malloc(size + alignment + sizeof(void*));
    if (!block) return NULL;
    at = ((uintptr_t)(block + sizeof(void*)) + alignment - 1) & ~(uintptr_t)(alignment - 1);
    memcpy((unsigned char*)at - sizeof(void*), &block, sizeof block);
    ++count->live;
    ++count->calls;
    return (void*)at;
}

static void counting_deallocate(void* user_data, void* pointer) {
    unsigned char* block;
    if (!pointer) return;
    memcpy(&block, (unsigned char*)pointer - sizeof(void*), sizeof block);
    free(block);
    --((counting*)user_data)->live;
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
    snprintf(name, sizeof name, "%s: struct_size kept", what);
    expect(p->struct_size == sizeof(polymass_mass_properties), name);
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

/* Every initialiser takes the 2.0.0 size and writes no further. */
#define CHECK_INIT(type, init)                                                    \
    do {                                                                          \
        GUARDED(type) guarded;                                                    \
        arm(guarded.guard);                                                       \
        expect(init(&guarded.value, sizeof guarded.value) == POLYMASS_OK, #init); \
        expect(guarded.value.struct_size == sizeof guarded.value, #init " size"); \
        expect_untouched(guarded.guard, #type " (" #init ")");                    \
    } while (0)

static void check_initialisers(void) {
    CHECK_INIT(polymass_allocator, polymass_allocator_init);
    CHECK_INIT(polymass_options, polymass_options_init);
    CHECK_INIT(polymass_mesh_desc, polymass_mesh_desc_init);
    CHECK_INIT(polymass_mass_desc, polymass_mass_desc_init);
    CHECK_INIT(polymass_mass_properties, polymass_mass_properties_init);
    CHECK_INIT(polymass_diagnostics, polymass_diagnostics_init);
    CHECK_INIT(polymass_shell, polymass_shell_init);
    CHECK_INIT(polymass_provenance, polymass_provenance_init);
    CHECK_INIT(polymass_moments, polymass_moments_init);
    CHECK_INIT(polymass_polygon_properties, polymass_polygon_properties_init);
    CHECK_INIT(polymass_batch_item, polymass_batch_item_init);
    CHECK_INIT(polymass_packed_meshes, polymass_packed_meshes_init);
    CHECK_INIT(polymass_packed_results, polymass_packed_results_init);
    /* The library's own structs are at least as large as the 2.0.0 ones. */
    expect(polymass_sizeof_allocator() >= sizeof(polymass_allocator) &&
               polymass_sizeof_options() >= sizeof(polymass_options) &&
               polymass_sizeof_mesh_desc() >= sizeof(polymass_mesh_desc) &&
               polymass_sizeof_mass_desc() >= sizeof(polymass_mass_desc) &&
               polymass_sizeof_mass_properties() >= sizeof(polymass_mass_properties) &&
               polymass_sizeof_diagnostics() >= sizeof(polymass_diagnostics) &&
               polymass_sizeof_shell() >= sizeof(polymass_shell) &&
               polymass_sizeof_provenance() >= sizeof(polymass_provenance) &&
               polymass_sizeof_moments() >= sizeof(polymass_moments) &&
               polymass_sizeof_polygon_properties() >= sizeof(polymass_polygon_properties) &&
               polymass_sizeof_batch_item() >= sizeof(polymass_batch_item) &&
               polymass_sizeof_packed_meshes() >= sizeof(polymass_packed_meshes) &&
               polymass_sizeof_packed_results() >= sizeof(polymass_packed_results),
           "polymass_sizeof_*: no struct smaller than in 2.0.0");
}

/* The one call, with options, a mass and a provenance of 2.0.0 sizes. */
static void check_one_call(polymass_context* context, const polymass_mesh_desc* desc) {
    polymass_options options = POLYMASS_OPTIONS_INIT;
    polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
    GUARDED(polymass_mass_properties) properties;
    GUARDED(polymass_provenance) provenance;
    options.flags = POLYMASS_OPTION_WELD_VERTICES;
    options.weld_tolerance = 1e-9;
    options.modes[0] = POLYMASS_MODE_SOLID;
    options.modes[1] = POLYMASS_MODE_HULL;
    body.density = 2.5;
    polymass_mass_properties_init(&properties.value, sizeof properties.value);
    polymass_provenance_init(&provenance.value, sizeof provenance.value);
    arm(properties.guard);
    arm(provenance.guard);
    check_status(polymass_mass_properties_compute(&properties.value, &provenance.value, context,
                                                  desc, &options, &body),
                 context, "mass_properties_compute");
    check_box(&properties.value, 2.5, "mass_properties_compute");
    expect(provenance.value.mode == POLYMASS_MODE_SOLID, "provenance: the solid answered");
    expect(provenance.value.struct_size == sizeof provenance.value, "provenance: size kept");
    expect_untouched(properties.guard, "polymass_mass_properties");
    expect_untouched(provenance.guard, "polymass_provenance");
}

/* One analysis, every question, each output guarded. */
static void check_mesh(polymass_context* context, const polymass_mesh_desc* desc) {
    static const double corner[3] = {1, 10, -3};
    polymass_mesh* mesh = NULL;
    GUARDED(polymass_mass_properties) properties;
    GUARDED(polymass_diagnostics) report;
    GUARDED(polymass_shell) shell;
    GUARDED(polymass_provenance) provenance;
    GUARDED(polymass_moments) moments;
    GUARDED(polymass_mass_properties) from_moments;
    double about_corner[9];
    uint64_t shell_count = 0;

    check_status(polymass_mesh_create(&mesh, context, desc, NULL), context, "mesh_create");
    if (!mesh) return;
    expect(polymass_mesh_status(mesh) == POLYMASS_OK && polymass_mesh_message(mesh)[0] == '\0',
           "mesh_status, mesh_message of a valid solid");

    polymass_mass_properties_init(&properties.value, sizeof properties.value);
    arm(properties.guard);
    check_status(polymass_mesh_mass_properties(&properties.value, context, mesh, NULL), context,
                 "mesh_mass_properties");
    check_box(&properties.value, 1.0, "mesh_mass_properties");
    expect_untouched(properties.guard, "polymass_mass_properties");

    /* About a corner, by the parallel-axis theorem with d = C - P =
       (0.5, 1, 1.5): Ixx = m (2^2 + 3^2) / 12 + m (1^2 + 1.5^2), and
       Ixy = -m 0.5 * 1. */
    check_status(polymass_inertia_about(about_corner, &properties.value, corner), NULL,
                 "inertia_about");
    expect_near(about_corner[0], 6.0 * (13.0 / 12.0 + 1.0 + 2.25), "inertia_about: Ixx");
    expect_near(about_corner[1], -6.0 * 0.5 * 1.0, "inertia_about: Ixy");

    polymass_diagnostics_init(&report.value, sizeof report.value);
    arm(report.guard);
    check_status(polymass_mesh_diagnostics(&report.value, context, mesh), context,
                 "mesh_diagnostics");
    expect(report.value.status == POLYMASS_OK && report.value.face_count == 12 &&
               report.value.edge_count == 18 && report.value.shell_count == 1,
           "diagnostics of the box");
    expect_untouched(report.guard, "polymass_diagnostics");

    polymass_shell_init(&shell.value, sizeof shell.value);
    arm(shell.guard);
    check_status(polymass_mesh_shells(&shell.value, 1, &shell_count, context, mesh), context,
                 "mesh_shells");
    expect(shell_count == 1 && shell.value.kind == POLYMASS_SHELL_SOLID &&
               shell.value.face_count == 12 && shell.value.first_face == 0,
           "the box's one shell");
    expect_near(shell.value.signed_volume, 6.0, "shell: signed volume");
    expect_untouched(shell.guard, "polymass_shell");

    polymass_provenance_init(&provenance.value, sizeof provenance.value);
    arm(provenance.guard);
    check_status(polymass_mesh_provenance(&provenance.value, context, mesh), context,
                 "mesh_provenance");
    expect(provenance.value.mode == POLYMASS_MODE_SOLID, "mesh_provenance: the solid");
    expect_untouched(provenance.guard, "polymass_provenance");

    polymass_moments_init(&moments.value, sizeof moments.value);
    arm(moments.guard);
    check_status(polymass_mesh_moments(&moments.value, context, mesh), context, "mesh_moments");
    expect_near(moments.value.volume, 6.0, "mesh_moments: volume");
    expect_untouched(moments.guard, "polymass_moments");

    /* The moments, weighed and turned into properties: the box again. */
    {
        polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
        body.density = 2.5;
        polymass_mass_properties_init(&from_moments.value, sizeof from_moments.value);
        arm(from_moments.guard);
        check_status(
            polymass_moments_mass_properties(&from_moments.value, context, &moments.value, &body),
            context, "moments_mass_properties");
        check_box(&from_moments.value, 2.5, "moments_mass_properties");
        expect_untouched(from_moments.guard, "polymass_mass_properties (moments)");
    }
    polymass_mesh_destroy(mesh);
}

/* A refused surface still gives a mesh that says why. */
static void check_open_box(polymass_context* context, const polymass_mesh_desc* closed) {
    polymass_mesh_desc desc = *closed;
    polymass_mesh* mesh = NULL;
    GUARDED(polymass_diagnostics) report;
    uint32_t shell_of_face[11];
    desc.index_count = 33; /* one triangle missing */
    expect(polymass_mesh_create(&mesh, context, &desc, NULL) == POLYMASS_ERROR_OPEN && mesh,
           "mesh_create of an open box: POLYMASS_ERROR_OPEN, and a mesh");
    if (!mesh) return;
    expect(
        polymass_mesh_status(mesh) == POLYMASS_ERROR_OPEN && polymass_mesh_message(mesh)[0] != '\0',
        "an open box's mesh says why");
    polymass_diagnostics_init(&report.value, sizeof report.value);
    arm(report.guard);
    check_status(polymass_mesh_diagnostics(&report.value, context, mesh), context,
                 "mesh_diagnostics (open)");
    expect(report.value.status == POLYMASS_ERROR_OPEN && report.value.face_count == 11 &&
               report.value.open_edges == 3,
           "diagnostics of the open box");
    expect_untouched(report.guard, "polymass_diagnostics");
    check_status(polymass_mesh_shell_of_face(shell_of_face, 11, context, mesh), context,
                 "mesh_shell_of_face");
    expect(shell_of_face[0] == 0 && shell_of_face[10] == 0, "one shell");
    polymass_mesh_destroy(mesh);
}

/* A batch of two items of the 2.0.0 size, one refused. */
static void check_batch(polymass_context* context, const polymass_mesh_desc* closed) {
    polymass_mesh_desc open = *closed;
    polymass_batch_item items[2];
    GUARDED(polymass_mass_properties) properties[2];
    uint64_t failed = 0;
    int i;
    open.index_count = 33;
    for (i = 0; i < 2; ++i) {
        polymass_batch_item_init(&items[i], sizeof items[i]);
        polymass_mass_properties_init(&properties[i].value, sizeof properties[i].value);
        arm(properties[i].guard);
        items[i].properties = &properties[i].value;
    }
    items[0].desc = closed;
    items[1].desc = &open;
    check_status(polymass_batch_compute(items, 2, &failed, context), context, "batch_compute");
    expect(failed == 1 && items[0].status == POLYMASS_OK &&
               items[1].status == POLYMASS_ERROR_OPEN && items[0].message[0] == '\0' &&
               items[1].message[0] != '\0',
           "batch: one answered, one open");
    check_box(&properties[0].value, 1.0, "batch item");
    expect_untouched(properties[0].guard, "polymass_mass_properties (batch)");
    expect_untouched(properties[1].guard, "polymass_mass_properties (batch, refused)");
}

/* Two boxes packed into shared arrays (the second moved by +10 in x), in
   columns; packed structs of 2.0.0 sizes. */
static void check_packed(polymass_context* context) {
    double positions[16][3];
    uint32_t indices[72];
    static const uint64_t vertex_offsets[3] = {0, 8, 16}, index_offsets[3] = {0, 36, 72};
    static const double densities[2] = {1.0, 2.5};
    polymass_packed_meshes meshes = POLYMASS_PACKED_MESHES_INIT;
    GUARDED(polymass_packed_results) results;
    int32_t status[2] = {-1, -1};
    double volume[2] = {0, 0}, mass[2] = {0, 0}, center_of_mass[6] = {0};
    uint64_t failed = 99;
    int i, k;
    for (i = 0; i < 8; ++i)
        for (k = 0; k < 3; ++k) {
            positions[i][k] = box_positions[i][k];
            positions[8 + i][k] = box_positions[i][k] + (k == 0 ? 10.0 : 0.0);
        }
    for (i = 0; i < 36; ++i) indices[i] = indices[36 + i] = box_indices[i]; /* local */
    meshes.positions = positions;
    meshes.index_base = POLYMASS_INDICES_LOCAL;
    meshes.indices = indices;
    meshes.mesh_count = 2;
    meshes.vertex_offsets = vertex_offsets;
    meshes.index_offsets = index_offsets;
    meshes.mass_mode = POLYMASS_MASS_FROM_DENSITY;
    meshes.mass_values = densities;
    polymass_packed_results_init(&results.value, sizeof results.value);
    arm(results.guard);
    results.value.status = status;
    results.value.volume = volume;
    results.value.mass = mass;
    results.value.center_of_mass = center_of_mass;
    check_status(polymass_packed_compute(&results.value, &failed, context, &meshes, NULL), context,
                 "packed_compute");
    expect(failed == 0 && status[0] == POLYMASS_OK && status[1] == POLYMASS_OK,
           "packed: both boxes answered");
    expect_near(volume[1], 6.0, "packed: volume");
    expect_near(mass[1], 15.0, "packed: mass at density 2.5");
    expect_near(center_of_mass[3], 11.5, "packed: the second box's centre of mass x");
    expect_untouched(results.guard, "polymass_packed_results");
}

int main(void) {
    counting count = {0, 0};
    polymass_allocator allocator = POLYMASS_ALLOCATOR_INIT;
    polymass_context* context = NULL;
    polymass_mesh_desc desc = POLYMASS_MESH_DESC_INIT;
    GUARDED(polymass_polygon_properties) polygon;
    static const double square[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    double twice[16][3];
    uint32_t vertex_of[16];
    uint64_t distinct = 0;

    printf(
        "library %s, struct sizes now/2.0.0: options %u/%u, mesh_desc %u/%u, mass_desc %u/%u, "
        "mass_properties %u/%u, diagnostics %u/%u, provenance %u/%u, batch_item %u/%u\n",
        polymass_version_string(), polymass_sizeof_options(), (unsigned)sizeof(polymass_options),
        polymass_sizeof_mesh_desc(), (unsigned)sizeof(polymass_mesh_desc),
        polymass_sizeof_mass_desc(), (unsigned)sizeof(polymass_mass_desc),
        polymass_sizeof_mass_properties(), (unsigned)sizeof(polymass_mass_properties),
        polymass_sizeof_diagnostics(), (unsigned)sizeof(polymass_diagnostics),
        polymass_sizeof_provenance(), (unsigned)sizeof(polymass_provenance),
        polymass_sizeof_batch_item(), (unsigned)sizeof(polymass_batch_item));
    expect(polymass_version() / 10000 == POLYMASS_VERSION_MAJOR, "the same major version");
    check_initialisers();

    allocator.allocate = counting_allocate;
    allocator.deallocate = counting_deallocate;
    allocator.user_data = &count;
    if (polymass_context_create(&context, &allocator) != POLYMASS_OK) {
        fprintf(stderr, "FAIL: polymass_context_create\n");
        return 1;
    }
    check_status(polymass_context_set_threads(context, 2), context, "context_set_threads");

    desc.positions = box_positions;
    desc.vertex_count = 8;
    desc.indices = box_indices;
    desc.index_count = 36;
    check_one_call(context, &desc);
    check_mesh(context, &desc);
    check_open_box(context, &desc);
    check_batch(context, &desc);
    check_packed(context);

    polymass_polygon_properties_init(&polygon.value, sizeof polygon.value);
    arm(polygon.guard);
    check_status(polymass_polygon_compute(&polygon.value, context, &square[0][0], 4, 0), context,
                 "polygon_compute");
    expect_near(polygon.value.area, 4.0, "polygon: area");
    expect_near(polygon.value.centroid[0], 1.0, "polygon: centroid x");
    expect_near(polygon.value.second_moments[0], 16.0 / 12.0, "polygon: Ixx");
    expect_untouched(polygon.guard, "polymass_polygon_properties");

    /* The box's corners twice over: 8 distinct positions. */
    memcpy(twice, box_positions, sizeof box_positions);
    memcpy(twice[8], box_positions, sizeof box_positions);
    check_status(polymass_weld_positions(vertex_of, &distinct, context, twice,
                                         POLYMASS_POSITION_FLOAT64, 16, 0, 0.0),
                 context, "weld_positions");
    expect(distinct == 8 && vertex_of[8] == 0 && vertex_of[15] == 7, "weld: the corners twice");

    polymass_context_destroy(context);
    expect(count.calls > 0, "the context used the caller's allocator");
    expect(count.live == 0, "everything allocated was given back");
    if (failures) {
        fprintf(stderr, "%d failure(s)\n", failures);
        return 1;
    }
    printf("a 2.0.0 caller works with this library\n");
    return 0;
}
