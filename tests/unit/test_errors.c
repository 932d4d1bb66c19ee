/* Every status code, with its message, the diagnostics report, and the
 * options that relax the checks (skip, accept inverted, accept non-manifold,
 * weld, planarity tolerance). */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double unit_lo[3] = {0, 0, 0}, unit_hi[3] = {1, 1, 1};

/* ------------------------------------------------------------------------ */
/* Helpers                                                                  */
/* ------------------------------------------------------------------------ */

/* The description fails with `status` through polymass_mesh_create (which
   leaves *out_mesh NULL), polymass_mass_properties_compute and
   polymass_mesh_check (same status, in the report too, same message). The
   message is non-empty. The context then holds the message. */
static void expect_failure_at(const char* file, int line, polymass_context* ctx,
                              const polymass_mesh_desc* desc, int32_t status) {
    polymass_mesh* mesh = (polymass_mesh*)&mesh; /* garbage, must become NULL */
    polymass_mass_properties p;
    polymass_diagnostics d;
    char message[1024];
    pm_check_status(file, line, "polymass_mesh_create", status,
                    polymass_mesh_create(&mesh, ctx, desc), ctx);
    if (mesh != NULL) {
        print_error("%s:%d: *out_mesh not NULL after a failure\n", file, line);
        _fail(file, line);
    }
    snprintf(message, sizeof message, "%s", polymass_context_message(ctx));
    if (message[0] == '\0') {
        print_error("%s:%d: empty message for status %d\n", file, line, (int)status);
        _fail(file, line);
    }
    pm_props_init(&p);
    pm_check_status(file, line, "polymass_mass_properties_compute", status,
                    polymass_mass_properties_compute(&p, ctx, desc, NULL), ctx);
    if (strcmp(message, polymass_context_message(ctx)) != 0) {
        print_error("%s:%d: compute's message \"%s\" differs from create's \"%s\"\n", file, line,
                    polymass_context_message(ctx), message);
        _fail(file, line);
    }
    pm_diagnostics_init(&d);
    pm_check_status(file, line, "polymass_mesh_check", status, polymass_mesh_check(&d, ctx, desc),
                    ctx);
    /* (the report's status for an invalid description: see
       test_check_report_status_on_invalid_argument) */
    if (status != POLYMASS_ERROR_INVALID_ARGUMENT) {
        pm_check_status(file, line, "polymass_diagnostics.status", status, d.status, ctx);
    }
    if (strcmp(message, polymass_context_message(ctx)) != 0) {
        print_error("%s:%d: check's message \"%s\" differs from create's \"%s\"\n", file, line,
                    polymass_context_message(ctx), message);
        _fail(file, line);
    }
}
#define EXPECT_FAILURE(ctx, desc, status) \
    expect_failure_at(__FILE__, __LINE__, (ctx), (desc), (status))

static void expect_mesh_failure_at(const char* file, int line, polymass_context* ctx,
                                   const pm_mesh* m, int32_t status) {
    const polymass_mesh_desc d = pm_mesh_desc(m);
    expect_failure_at(file, line, ctx, &d, status);
}
#define EXPECT_MESH_FAILURE(ctx, m, status) \
    expect_mesh_failure_at(__FILE__, __LINE__, (ctx), (m), (status))

/* The same with the mesh's data laid out another way (the failing value set
   in the mesh, converted exactly). */
static const pm_layout float32_positions = {POLYMASS_POSITION_FLOAT32, 0, 0, POLYMASS_INDEX_UINT32};
static const pm_layout uint16_indices = {POLYMASS_POSITION_FLOAT64, 0, 0, POLYMASS_INDEX_UINT16};

static void expect_laid_out_failure_at(const char* file, int line, polymass_context* ctx,
                                       const pm_mesh* m, const pm_layout* layout, int32_t status) {
    pm_laid_out_mesh laid_out;
    pm_lay_out(&laid_out, m, layout);
    expect_failure_at(file, line, ctx, &laid_out.desc, status);
    pm_laid_out_free(&laid_out);
}
#define EXPECT_LAID_OUT_FAILURE(ctx, m, layout, status) \
    expect_laid_out_failure_at(__FILE__, __LINE__, (ctx), (m), (layout), (status))

/* Only the argument check: create fails with INVALID_ARGUMENT, out NULL. */
static void expect_invalid_at(const char* file, int line, polymass_context* ctx,
                              const polymass_mesh_desc* desc) {
    expect_failure_at(file, line, ctx, desc, POLYMASS_ERROR_INVALID_ARGUMENT);
}
#define EXPECT_INVALID(ctx, desc) expect_invalid_at(__FILE__, __LINE__, (ctx), (desc))

/* Each of the values in turn in one field of a copy of *base: EXPECT_INVALID.
   values is an array (its size is taken). */
#define EXPECT_EACH_INVALID(ctx, base, field, values)                            \
    do {                                                                         \
        size_t each_;                                                            \
        for (each_ = 0; each_ < sizeof(values) / sizeof((values)[0]); ++each_) { \
            polymass_mesh_desc changed_ = *(base);                               \
            changed_.field = (values)[each_];                                    \
            expect_invalid_at(__FILE__, __LINE__, (ctx), &changed_);             \
        }                                                                        \
    } while (0)

/* EXPECT_MESH_FAILURE, the message mentions "<word> <number>", and *diag is
   polymass_mesh_check's report (same status) with signed_volume NaN: input
   rejected before anything was integrated. */
static void expect_input_rejected_at(const char* file, int line, polymass_context* ctx,
                                     const pm_mesh* m, int32_t status, const char* word,
                                     uint64_t number, polymass_diagnostics* diag) {
    expect_mesh_failure_at(file, line, ctx, m, status);
    pm_check_message_mentions(file, line, ctx, word, number);
    pm_check_status(file, line, "polymass_mesh_check", status, pm_check(diag, ctx, m), ctx);
    if (!isnan(diag->signed_volume)) {
        print_error("%s:%d: signed_volume %.17g, expected NaN\n", file, line, diag->signed_volume);
        _fail(file, line);
    }
}
#define EXPECT_INPUT_REJECTED(ctx, m, status, word, number, diag) \
    expect_input_rejected_at(__FILE__, __LINE__, (ctx), (m), (status), (word), (number), (diag))

/* Vertices at exactly equal positions become one (the first). */
static void weld_exact(pm_mesh* m) {
    size_t i, k;
    for (k = 0; k < m->index_count; ++k) {
        const size_t v = m->indices[k];
        for (i = 0; i < v; ++i) {
            if (memcmp(m->positions + 3 * i, m->positions + 3 * v, 3 * sizeof(double)) == 0) {
                m->indices[k] = (uint32_t)i;
                break;
            }
        }
    }
}

static int is_edge(const uint64_t e[2], uint64_t a, uint64_t b) {
    return (e[0] == a && e[1] == b) || (e[0] == b && e[1] == a);
}

/* The edge e is one of the face's edges. */
static int edge_of_face(const pm_mesh* m, size_t face, const uint64_t e[2]) {
    const size_t offset = pm_mesh_face_offset(m, face), n = m->face_sizes[face];
    size_t k;
    for (k = 0; k < n; ++k) {
        if (is_edge(e, m->indices[offset + k], m->indices[offset + (k + 1) % n])) {
            return 1;
        }
    }
    return 0;
}

/* The three kinds of bad edge polymass_mesh_check counts. */
typedef enum edge_defect { OPEN_EDGE, NON_MANIFOLD_EDGE, MISORIENTED_EDGE } edge_defect;

static uint64_t defect_count(const polymass_diagnostics* d, edge_defect kind) {
    switch (kind) {
        case OPEN_EDGE:
            return d->open_edges;
        case NON_MANIFOLD_EDGE:
            return d->non_manifold_edges;
        default:
            return d->misoriented_edges;
    }
}

static const uint64_t* first_defect(const polymass_diagnostics* d, edge_defect kind) {
    switch (kind) {
        case OPEN_EDGE:
            return d->first_open_edges[0];
        case NON_MANIFOLD_EDGE:
            return d->first_non_manifold_edges[0];
        default:
            return d->first_misoriented_edges[0];
    }
}

/* The mesh fails with `status` (as EXPECT_MESH_FAILURE) and the report of
   polymass_mesh_check, left in *diag, has the same status and counts `count`
   edges of `kind`. */
static void expect_edge_defect_at(const char* file, int line, polymass_context* ctx,
                                  const pm_mesh* m, int32_t status, edge_defect kind,
                                  uint64_t count, polymass_diagnostics* diag) {
    expect_mesh_failure_at(file, line, ctx, m, status);
    pm_check_status(file, line, "polymass_mesh_check", status, pm_check(diag, ctx, m), ctx);
    if (defect_count(diag, kind) != count) {
        print_error("%s:%d: %llu bad edges of kind %d reported, expected %llu\n", file, line,
                    (unsigned long long)defect_count(diag, kind), (int)kind,
                    (unsigned long long)count);
        _fail(file, line);
    }
}
#define EXPECT_EDGE_DEFECT(ctx, m, status, kind, count, diag) \
    expect_edge_defect_at(__FILE__, __LINE__, (ctx), (m), (status), (kind), (count), (diag))

/* For each face f of the unit cube (quads), the cube with only face f changed
   by change_face (removed, reversed): EXPECT_EDGE_DEFECT with `bad_edges`
   edges of `kind`, the first of them an edge of face f and named in the
   message; no bad edge of another kind; face_count faces on the cube's 8
   vertices and 12 edges. */
static void expect_defect_on_each_cube_face(void (*change_face)(pm_mesh*, size_t), int32_t status,
                                            edge_defect kind, uint64_t bad_edges,
                                            uint64_t face_count) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh cube, m;
    size_t f;
    int other;
    pm_mesh_unit_cube(&cube, 0);
    for (f = 0; f < cube.face_count; ++f) {
        const uint64_t* first;
        pm_mesh_copy(&m, &cube);
        change_face(&m, f);
        EXPECT_EDGE_DEFECT(ctx, &m, status, kind, bad_edges, &diag);
        assert_int_equal(diag.face_count, face_count);
        assert_int_equal(diag.used_vertex_count, 8);
        assert_int_equal(diag.edge_count, 12);
        first = first_defect(&diag, kind);
        assert_true(edge_of_face(&cube, f, first));
        PM_ASSERT_EDGE_MENTIONED(ctx, first[0], first[1]);
        for (other = OPEN_EDGE; other <= MISORIENTED_EDGE; ++other) {
            if (other != (int)kind) {
                assert_int_equal(defect_count(&diag, (edge_defect)other), 0);
                assert_true(first_defect(&diag, (edge_defect)other)[0] == POLYMASS_NONE);
            }
        }
        pm_mesh_free(&m);
    }
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* INVALID_ARGUMENT                                                         */
/* ------------------------------------------------------------------------ */

static void test_null_pointers(void** state) {
    polymass_context* ctx = pm_context_new(0);
    pm_mesh m;
    polymass_mesh_desc d;
    polymass_mass_properties p;
    polymass_diagnostics diag;
    polymass_polygon_properties pp;
    polymass_mesh* mesh = NULL;
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);
    pm_props_init(&p);
    pm_diagnostics_init(&diag);
    pm_polygon_props_init(&pp);

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_create(NULL, ctx, &d));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_create(&mesh, NULL, &d));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_create(&mesh, ctx, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(NULL, ctx, &d, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, &d, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, ctx, NULL, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_check(NULL, ctx, &d));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_check(&diag, NULL, &d));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_check(&diag, ctx, NULL));

    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(NULL, ctx, mesh, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, NULL, mesh, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, NULL, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    polymass_mesh_destroy(mesh);
    mesh = NULL;

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(NULL, ctx, square, 4, 0));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, NULL, square, 4, 0));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, ctx, NULL, 4, 0));

    /* NULL arrays with nonzero counts */
    d = pm_mesh_desc(&m);
    d.positions = NULL;
    EXPECT_INVALID(ctx, &d);
    d = pm_mesh_desc(&m);
    d.indices = NULL;
    EXPECT_INVALID(ctx, &d);
    d = pm_mesh_desc(&m);
    d.face_sizes = NULL; /* face_count stays 6 */
    EXPECT_INVALID(ctx, &d);

    /* A later success clears the message. */
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_string_equal(polymass_context_message(ctx), "");

    /* Destroy functions accept NULL. */
    polymass_mesh_destroy(NULL);
    polymass_context_destroy(NULL);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* "On failure *out_mesh is NULL": also when the failure is a NULL context or
   a NULL description. */
static void test_out_mesh_cleared_on_every_failure(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_mesh* mesh;
    pm_mesh m;
    polymass_mesh_desc d;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);
    mesh = (polymass_mesh*)&mesh;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_create(&mesh, ctx, NULL));
    assert_null(mesh);
    mesh = (polymass_mesh*)&mesh;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_create(&mesh, NULL, &d));
    assert_null(mesh);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* polymass_mesh_check "returns the status polymass_mesh_create would (also in
   out_report->status)": also for an invalid description (the report itself
   is valid). */
static void test_check_report_status_on_invalid_argument(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh m;
    polymass_mesh_desc d;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);
    d.reserved = 1;
    pm_diagnostics_init(&diag);
    diag.status = 12345;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_check(&diag, ctx, &d));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, diag.status);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_struct_sizes_checked(void** state) {
    polymass_context* ctx = pm_context_new(0);
    pm_mesh m;
    polymass_mesh_desc d;
    polymass_mass_properties p;
    polymass_diagnostics diag;
    polymass_mass_desc md = pm_mass_density(1.0);
    polymass_polygon_properties pp;
    polymass_mesh* mesh = NULL;
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const uint32_t bad_sizes[] = {0,
                                         1,
                                         8,
                                         sizeof(polymass_mesh_desc) - 1,
                                         sizeof(polymass_mesh_desc) + 4096,
                                         0x7FFFFFFFu,
                                         0xFFFFFFFFu};
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);
    EXPECT_EACH_INVALID(ctx, &d, struct_size, bad_sizes);

    pm_props_init(&p);
    p.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, ctx, &d, NULL));
    p.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, ctx, &d, NULL));

    pm_diagnostics_init(&diag);
    diag.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_check(&diag, ctx, &d));
    diag.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_check(&diag, ctx, &d));

    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d));
    pm_props_init(&p);
    md.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    md.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    polymass_mesh_destroy(mesh);

    memset(&pp, 0, sizeof pp);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, ctx, square, 4, 0));
    pp.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, ctx, square, 4, 0));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_bad_types_strides_reserved(void** state) {
    static const uint64_t small_double_strides[] = {1, 8, 16, 23};
    static const uint64_t small_float_strides[] = {4, 8, 11};
    static const uint32_t bad_types[] = {2, 0xFFFFFFFFu, 0x80000000u};
    static const uint32_t bad_reserved[] = {1, 0x80000000u};
    polymass_context* ctx = pm_context_new(0);
    pm_mesh m;
    polymass_mesh_desc doubles, floats;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    doubles = pm_mesh_desc(&m);
    floats = doubles;
    floats.position_type = POLYMASS_POSITION_FLOAT32;
    EXPECT_EACH_INVALID(ctx, &doubles, position_stride, small_double_strides);
    EXPECT_EACH_INVALID(ctx, &floats, position_stride, small_float_strides);
    EXPECT_EACH_INVALID(ctx, &doubles, position_type, bad_types);
    EXPECT_EACH_INVALID(ctx, &doubles, index_type, bad_types);
    EXPECT_EACH_INVALID(ctx, &doubles, reserved, bad_reserved);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_counts_that_do_not_add_up(void** state) {
    polymass_context* ctx = pm_context_new(0);
    pm_mesh quads, tris;
    polymass_mesh_desc d;
    uint32_t sizes[6];
    (void)state;
    pm_mesh_unit_cube(&quads, 0);
    pm_mesh_unit_cube(&tris, 1);
    memcpy(sizes, quads.face_sizes, sizeof sizes);

    /* face sizes adding up to more, and to less, than index_count */
    d = pm_mesh_desc(&quads);
    d.face_sizes = sizes;
    sizes[5] = 5;
    EXPECT_INVALID(ctx, &d);
    sizes[5] = 3;
    EXPECT_INVALID(ctx, &d);
    sizes[5] = 4;
    d.face_count = 5;
    EXPECT_INVALID(ctx, &d);
    /* face_sizes given with face_count 0 while there are indices */
    d.face_count = 0;
    EXPECT_INVALID(ctx, &d);
    /* triangles: index_count not a multiple of 3 */
    d = pm_mesh_desc(&tris);
    assert_null(d.face_sizes);
    d.index_count = 35;
    EXPECT_INVALID(ctx, &d);
    d.index_count = 34;
    EXPECT_INVALID(ctx, &d);
    pm_mesh_free(&tris);
    pm_mesh_free(&quads);
    polymass_context_destroy(ctx);
}

/* Counts whose byte sizes overflow 64 bits are rejected before anything is
   read (ASan would catch a read past the small arrays given). */
static void test_overflowing_counts(void** state) {
    polymass_context* ctx = pm_context_new(0);
    pm_mesh m;
    polymass_mesh_desc d;
    uint32_t sizes[2] = {3, 3};
    (void)state;
    pm_mesh_unit_cube(&m, 1);

    d = pm_mesh_desc(&m);
    d.vertex_count = UINT64_MAX / 8; /* * 24 bytes overflows */
    d.position_stride = 24;
    EXPECT_INVALID(ctx, &d);
    d.position_stride = 0; /* packed: still 24 bytes a vertex */
    EXPECT_INVALID(ctx, &d);
    d.vertex_count = 8;
    d.position_stride = UINT64_MAX / 4; /* 8 * stride overflows */
    EXPECT_INVALID(ctx, &d);

    d = pm_mesh_desc(&m);
    d.index_count = UINT64_MAX / 2; /* not a multiple of 3 either */
    EXPECT_INVALID(ctx, &d);
    d.index_count = UINT64_MAX / 2 - 1; /* a multiple of 3; * 4 bytes overflows */
    assert_int_equal(d.index_count % 3, 0);
    EXPECT_INVALID(ctx, &d);
    d.index_count = UINT64_MAX;
    EXPECT_INVALID(ctx, &d);

    d = pm_mesh_desc(&m);
    d.face_sizes = sizes;
    d.face_count = UINT64_MAX / 2; /* * 4 bytes overflows */
    EXPECT_INVALID(ctx, &d);
    d.face_count = UINT64_MAX;
    EXPECT_INVALID(ctx, &d);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_invalid_mass_desc(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_BOX];
    const polymass_mesh_desc d = pm_reference_desc(ref);
    static const double bad_values[] = {0.0, -0.0, -1.0, NAN, INFINITY, -INFINITY};
    polymass_context* ctx = pm_context_new(0);
    polymass_mesh* mesh = NULL;
    polymass_mass_properties p;
    polymass_mass_desc md;
    size_t k;
    (void)state;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d));
    for (k = 0; k < sizeof bad_values / sizeof bad_values[0]; ++k) {
        md = pm_mass_density(bad_values[k]);
        pm_props_init(&p);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mesh_mass_properties(&p, ctx, mesh, &md));
        assert_true(strlen(polymass_context_message(ctx)) > 0);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mass_properties_compute(&p, ctx, &d, &md));
        md = pm_mass_total(bad_values[k]);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mesh_mass_properties(&p, ctx, mesh, &md));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mass_properties_compute(&p, ctx, &d, &md));
    }
    md = pm_mass_density(1.0);
    md.mass_mode = 2;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    /* A non-finite point is a caller error (or a non-finite input). */
    md = pm_mass_density(1.0);
    md.point[1] = NAN;
    {
        const int32_t s = polymass_mesh_mass_properties(&p, ctx, mesh, &md);
        assert_true(s == POLYMASS_ERROR_INVALID_ARGUMENT || s == POLYMASS_ERROR_NON_FINITE);
    }
    /* The field the mode does not read is not checked. */
    md = pm_mass_density(2.0);
    md.mass = NAN;
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    PM_ASSERT_REL("mass = density * volume", 2.0 * ref->volume, p.mass, PM_TOL);
    md = pm_mass_total(3.0);
    md.density = -INFINITY;
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    PM_ASSERT_REL("mass as given", 3.0, p.mass, PM_TOL);
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* NON_FINITE, INDEX_OUT_OF_RANGE, FACE_TOO_SMALL                           */
/* ------------------------------------------------------------------------ */

static void test_non_finite(void** state) {
    static const double bad[] = {NAN, INFINITY, -INFINITY};
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    int k, axis;
    (void)state;
    for (k = 0; k < 3; ++k) {
        for (axis = 0; axis < 3; ++axis) {
            pm_mesh_unit_cube(&m, 0);
            m.positions[3 * 5 + axis] = bad[k];
            EXPECT_INPUT_REJECTED(ctx, &m, POLYMASS_ERROR_NON_FINITE, "vertex", 5, &diag);
            assert_int_equal(diag.non_finite_vertices, 1);
            assert_int_equal(diag.first_non_finite_vertices[0], 5);
            /* Never skipped. */
            pm_context_set_flags(
                ctx, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_ACCEPT_INVERTED |
                         POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
            PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_compute(&p, ctx, &m, NULL));
            pm_context_set_flags(ctx, 0);
            pm_mesh_free(&m);
        }
    }
    /* Two bad vertices: both counted, the first reported. */
    pm_mesh_unit_cube(&m, 1);
    m.positions[3 * 6] = NAN;
    m.positions[3 * 2 + 1] = INFINITY;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_finite_vertices, 2);
    assert_int_equal(diag.first_non_finite_vertices[0], 2);
    pm_mesh_free(&m);

    /* An unused NaN vertex is fine. */
    pm_mesh_unit_cube(&m, 0);
    pm_mesh_add_vertex(&m, NAN, INFINITY, -INFINITY);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_REL("volume with an unused NaN vertex", 1.0, p.volume, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_finite_vertices, 0);
    assert_true(diag.first_non_finite_vertices[0] == POLYMASS_NONE);
    pm_mesh_free(&m);

    /* float32 NaN */
    pm_mesh_unit_cube(&m, 0);
    m.positions[3 * 7 + 2] = NAN;
    EXPECT_LAID_OUT_FAILURE(ctx, &m, &float32_positions, POLYMASS_ERROR_NON_FINITE);
    PM_ASSERT_MENTIONS(ctx, "vertex", 7);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_index_out_of_range(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    m.indices[pm_mesh_face_offset(&m, 3) + 2] = 8; /* vertex_count is 8 */
    EXPECT_INPUT_REJECTED(ctx, &m, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, "face", 3, &diag);
    assert_int_equal(diag.out_of_range_indices, 1);
    assert_int_equal(diag.first_out_of_range_faces[0], 3);
    /* never skipped */
    pm_context_set_flags(ctx, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, pm_compute(&p, ctx, &m, NULL));
    pm_context_set_flags(ctx, POLYMASS_OPTION_WELD_VERTICES);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, pm_compute(&p, ctx, &m, NULL));
    pm_context_set_flags(ctx, 0);
    m.indices[pm_mesh_face_offset(&m, 3) + 2] = UINT32_MAX;
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    /* two bad faces: both counted, the first reported */
    m.indices[pm_mesh_face_offset(&m, 5)] = 1000;
    EXPECT_INPUT_REJECTED(ctx, &m, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, "face", 3, &diag);
    assert_int_equal(diag.out_of_range_indices, 2);
    assert_int_equal(diag.first_out_of_range_faces[0], 3);
    pm_mesh_free(&m);

    /* uint16 indices */
    pm_mesh_unit_cube(&m, 1);
    m.indices[3 * 7 + 1] = 0xFFFF;
    EXPECT_LAID_OUT_FAILURE(ctx, &m, &uint16_indices, POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    PM_ASSERT_MENTIONS(ctx, "face", 7);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_face_too_small(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    polymass_mesh_desc d;
    uint32_t sizes[7];
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);
    d.face_sizes = sizes;
    /* faces 4 and 5 of 2 vertices each instead of one quad */
    sizes[0] = sizes[1] = sizes[2] = sizes[3] = 4;
    sizes[4] = 2;
    sizes[5] = 2;
    sizes[6] = 4;
    d.face_count = 7;
    EXPECT_FAILURE(ctx, &d, POLYMASS_ERROR_FACE_TOO_SMALL);
    PM_ASSERT_MENTIONS(ctx, "face", 4);
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_FACE_TOO_SMALL, polymass_mesh_check(&diag, ctx, &d));
    assert_int_equal(diag.small_faces, 2);
    assert_int_equal(diag.first_small_faces[0], 4);
    /* a face of 0 vertices */
    sizes[4] = 4;
    sizes[5] = 0;
    sizes[6] = 4;
    EXPECT_FAILURE(ctx, &d, POLYMASS_ERROR_FACE_TOO_SMALL);
    PM_ASSERT_MENTIONS(ctx, "face", 5);
    /* faces of 0 vertices only, so no indices at all: still faces too small */
    sizes[0] = sizes[1] = 0;
    d.face_count = 2;
    d.index_count = 0;
    d.indices = NULL;
    EXPECT_FAILURE(ctx, &d, POLYMASS_ERROR_FACE_TOO_SMALL);
    PM_ASSERT_MENTIONS(ctx, "face", 0);
    d = pm_mesh_desc(&m);
    d.face_sizes = sizes;
    d.face_count = 7;
    sizes[0] = sizes[1] = 4;
    /* never skipped */
    pm_context_set_flags(ctx, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    pm_props_init(&p);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_FACE_TOO_SMALL,
                     polymass_mass_properties_compute(&p, ctx, &d, NULL));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Topology                                                                 */
/* ------------------------------------------------------------------------ */

/* Each finding lists its first POLYMASS_DIAGNOSTIC_LOCATIONS locations:
   the lowest face or vertex indices, the edges with the lowest vertex pairs,
   ascending; POLYMASS_NONE after them. */
static void test_report_lists_the_first_locations(void** state) {
    enum { N = 4, SIDE = N + 1 }; /* a flat N x N grid of squares, two triangles each */
    static const uint32_t nan_vertices[] = {24, 3, 22, 5, 20, 18, 12, 21, 7, 9}; /* any order */
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh grid;
    uint32_t i, j, k;
    (void)state;
    pm_mesh_init(&grid);
    for (i = 0; i < SIDE; ++i) {
        for (j = 0; j < SIDE; ++j) {
            pm_mesh_add_vertex(&grid, j, i, 0);
        }
    }
    for (i = 0; i < N; ++i) {
        for (j = 0; j < N; ++j) {
            const uint32_t a = i * SIDE + j;
            pm_mesh_add_tri(&grid, a, a + 1, a + SIDE + 1);
            pm_mesh_add_tri(&grid, a, a + SIDE + 1, a + SIDE);
        }
    }
    /* The rim: 4 N open edges; the lowest pairs are on the row y = 0 and the
       column x = 0: (0,1) (0,5) (1,2) (2,3) (3,4) (4,9) (5,10) (9,14). */
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, pm_check(&diag, ctx, &grid));
    assert_int_equal(diag.open_edges, 4 * N);
    {
        static const uint64_t lowest[8][2] = {{0, 1}, {0, 5}, {1, 2},  {2, 3},
                                              {3, 4}, {4, 9}, {5, 10}, {9, 14}};
        for (k = 0; k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
            const uint64_t* e = diag.first_open_edges[k];
            assert_true((e[0] == lowest[k][0] && e[1] == lowest[k][1]) ||
                        (e[0] == lowest[k][1] && e[1] == lowest[k][0]));
        }
    }
    /* Ten NaN vertices: the eight lowest, sorted. */
    for (k = 0; k < sizeof nan_vertices / sizeof nan_vertices[0]; ++k) {
        grid.positions[3 * nan_vertices[k] + 2] = NAN;
    }
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &grid));
    assert_int_equal(diag.non_finite_vertices, 10);
    {
        static const uint64_t lowest[8] = {3, 5, 7, 9, 12, 18, 20, 21};
        for (k = 0; k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
            assert_int_equal(diag.first_non_finite_vertices[k], lowest[k]);
        }
    }
    /* Fewer findings than places: POLYMASS_NONE after them. */
    for (k = 0; k < 8; ++k) {
        grid.positions[3 * nan_vertices[k] + 2] = 0.0;
    }
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &grid));
    assert_int_equal(diag.non_finite_vertices, 2);
    assert_int_equal(diag.first_non_finite_vertices[0], 7);
    assert_int_equal(diag.first_non_finite_vertices[1], 9);
    for (k = 2; k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
        assert_true(diag.first_non_finite_vertices[k] == POLYMASS_NONE);
    }
    pm_mesh_free(&grid);
    polymass_context_destroy(ctx);
}

static void test_open(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh m;
    (void)state;
    expect_defect_on_each_cube_face(pm_mesh_remove_face, POLYMASS_ERROR_OPEN, OPEN_EDGE, 4, 5);
    /* a single triangle */
    pm_mesh_init(&m);
    pm_mesh_add_vertex(&m, 0, 0, 0);
    pm_mesh_add_vertex(&m, 1, 0, 0);
    pm_mesh_add_vertex(&m, 0, 1, 0);
    pm_mesh_add_tri(&m, 0, 1, 2);
    EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_OPEN, OPEN_EDGE, 3, &diag);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Two unit cubes sharing one edge (x = 1, y = 1): the edge is used by four
   faces, twice in each direction. */
static void make_two_cubes_sharing_an_edge(pm_mesh* m, int share_indices) {
    static const double lo2[3] = {1, 1, 0}, hi2[3] = {2, 2, 1};
    pm_mesh_unit_cube(m, 0);
    pm_mesh_add_box(m, lo2, hi2, 1);
    if (share_indices) {
        weld_exact(m);
    }
}

static void test_non_manifold(void** state) {
    static const double lo2[3] = {1, 1, 0}, hi2[3] = {2, 2, 1};
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    const pm_expected a = pm_expected_box(unit_lo, unit_hi), b = pm_expected_box(lo2, hi2);
    pm_expected both = pm_expected_sum(&a, &b);
    (void)state;
    both.size = 3.0; /* [0, 2] x [0, 2] x [0, 1] */
    make_two_cubes_sharing_an_edge(&m, 1);
    EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_NON_MANIFOLD, NON_MANIFOLD_EDGE, 1, &diag);
    /* the shared edge joins vertices 3 (1, 1, 0) and 7 (1, 1, 1) */
    PM_ASSERT_EDGE_MENTIONED(ctx, 3, 7);
    assert_true(is_edge(diag.first_non_manifold_edges[0], 3, 7));
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.used_vertex_count, 14);

    /* balanced: accepted with the option, and the solid is the two cubes */
    pm_context_set_flags(ctx, POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, POLYMASS_WARNING_NON_MANIFOLD);
    PM_ASSERT_PROPERTIES("two cubes sharing an edge", &both, &p, PM_TOL);
    pm_mesh_free(&m);

    /* the same made of separate vertices, joined by welding */
    make_two_cubes_sharing_an_edge(&m, 0);
    pm_context_set_flags(ctx, POLYMASS_OPTION_WELD_VERTICES);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_NON_MANIFOLD);
    pm_context_set_flags(ctx, POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_true(p.warnings & POLYMASS_WARNING_NON_MANIFOLD);
    PM_ASSERT_PROPERTIES("two welded cubes sharing an edge", &both, &p, PM_TOL);
    /* unwelded they are two separate closed shells touching along the edge:
       fine, with a warning */
    pm_context_set_flags(ctx, 0);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, POLYMASS_WARNING_TOUCHING_FACES);
    PM_ASSERT_PROPERTIES("two cubes touching at an edge", &both, &p, PM_TOL);
    pm_mesh_free(&m);

    /* unbalanced: a tetrahedron with one face listed twice: its edges are
       used three times, twice one way. Never accepted. */
    {
        const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TETRA_IRREGULAR];
        pm_mesh_from_reference(&m, ref);
        pm_mesh_add_tri(&m, m.indices[0], m.indices[1], m.indices[2]);
        EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_NON_MANIFOLD, NON_MANIFOLD_EDGE, 3, &diag);
        pm_context_set_flags(ctx, POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
        {
            const int32_t s = pm_compute(&p, ctx, &m, NULL);
            if (s != POLYMASS_ERROR_NON_MANIFOLD && s != POLYMASS_ERROR_INCONSISTENT_ORIENTATION) {
                PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_MANIFOLD, s);
            }
        }
        pm_context_set_flags(ctx, 0);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

static void test_inconsistent_orientation(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh m;
    (void)state;
    expect_defect_on_each_cube_face(pm_mesh_reverse_face, POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                                    MISORIENTED_EDGE, 4, 6);
    /* triangles: one triangle of the torus flipped */
    pm_mesh_from_reference(&m, &pm_reference_solids[PM_REF_TORUS_TRIS]);
    pm_mesh_reverse_face(&m, 17);
    EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_INCONSISTENT_ORIENTATION, MISORIENTED_EDGE, 3,
                       &diag);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* The unit cube with vertex 4 (0, 0, 1) lifted along z: it stays in the
   planes x = 0 and y = 0, so only the top face (face 1) bends. */
static void make_lifted_cube(pm_mesh* m, double lift) {
    pm_mesh_unit_cube(m, 0);
    m->positions[3 * 4 + 2] += lift;
}

static void test_non_planar_face(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    polymass_options o;
    pm_mesh m;
    (void)state;
    make_lifted_cube(&m, 1e-3);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_NON_PLANAR_FACE);
    PM_ASSERT_MENTIONS(ctx, "face", 1);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_PLANAR_FACE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_planar_faces, 1);
    assert_int_equal(diag.first_non_planar_faces[0], 1);
    assert_true(diag.max_non_planarity > 1e-5 && diag.max_non_planarity < 1e-2);
    assert_int_equal(diag.open_edges + diag.misoriented_edges + diag.non_manifold_edges, 0);

    /* a looser tolerance accepts it */
    o = pm_options(0, 1e-2);
    PM_ASSERT_OK(ctx, polymass_context_set_options(ctx, &o));
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_CLOSE("volume of the slightly bent cube", 1.0, p.volume, 1e-3, 0.0);
    /* skipping the checks accepts it too */
    pm_context_set_flags(ctx, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_true(p.warnings & POLYMASS_WARNING_UNCHECKED);
    pm_context_set_flags(ctx, 0);
    pm_mesh_free(&m);

    /* 1e-9 relative is well within the default 1e-6 */
    make_lifted_cube(&m, 1e-9);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_CLOSE("volume of the cube bent by 1e-9", 1.0, p.volume, 1e-8, 0.0);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_planar_faces, 0);
    assert_true(diag.max_non_planarity > 0 && diag.max_non_planarity < 1e-6);
    /* ... but not within 1e-12 */
    o.planarity_tolerance = 1e-12;
    PM_ASSERT_OK(ctx, polymass_context_set_options(ctx, &o));
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_NON_PLANAR_FACE);
    pm_mesh_free(&m);

    /* The tolerance is relative to the face's size: the same bend scaled by
       2^30 is just as (non-)planar. */
    o.planarity_tolerance = 0;
    PM_ASSERT_OK(ctx, polymass_context_set_options(ctx, &o));
    make_lifted_cube(&m, 1e-3);
    pm_mesh_transform(&m, NULL, 1073741824.0, NULL);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_NON_PLANAR_FACE);
    pm_mesh_free(&m);
    make_lifted_cube(&m, 1e-9);
    pm_mesh_transform(&m, NULL, 1.0 / 1073741824.0, NULL);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* INVERTED, ZERO_VOLUME                                                    */
/* ------------------------------------------------------------------------ */

static void test_inverted(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    int k;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        const pm_reference_solid* ref = &pm_reference_solids[k];
        const pm_expected e = pm_expected_from_reference(ref);
        pm_mesh m;
        pm_mesh_from_reference(&m, ref);
        pm_mesh_reverse_all(&m);
        EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_INVERTED);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED, pm_check(&diag, ctx, &m));
        PM_ASSERT_REL("signed volume of the inverted solid", -ref->volume, diag.signed_volume,
                      PM_TOL);
        pm_context_set_flags(ctx, POLYMASS_OPTION_ACCEPT_INVERTED);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_int_equal(
            p.warnings,
            POLYMASS_WARNING_INVERTED |
                (pm_reference_touches_itself(ref) ? POLYMASS_WARNING_TOUCHING_FACES : 0));
        PM_ASSERT_PROPERTIES(ref->name, &e, &p, PM_TOL);
        pm_context_set_flags(ctx, 0);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

static void test_zero_volume(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    /* a flat double-sided square: two coincident quads of opposite
       orientation; closed, manifold, consistent, planar, and empty */
    pm_mesh_init(&m);
    pm_mesh_add_vertex(&m, 0, 0, 0);
    pm_mesh_add_vertex(&m, 1, 0, 0);
    pm_mesh_add_vertex(&m, 1, 1, 0);
    pm_mesh_add_vertex(&m, 0, 1, 0);
    pm_mesh_add_quad(&m, 0, 1, 2, 3);
    pm_mesh_add_quad(&m, 3, 2, 1, 0);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_ZERO_VOLUME);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_VOLUME, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.open_edges + diag.non_manifold_edges + diag.misoriented_edges, 0);
    PM_ASSERT_ABS("signed volume", 0.0, diag.signed_volume, 1e-15);
    pm_context_set_flags(ctx, POLYMASS_OPTION_ACCEPT_INVERTED);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_VOLUME, pm_compute(&p, ctx, &m, NULL));
    pm_context_set_flags(ctx, 0);
    pm_mesh_free(&m);

    /* a tetrahedron flattened into the plane z = 0.5 (and moved far away) */
    {
        static const double t[3] = {1e6, -1e6, 0};
        int scale;
        for (scale = 0; scale < 2; ++scale) {
            pm_mesh_init(&m);
            pm_mesh_add_vertex(&m, 0, 0, 0.5);
            pm_mesh_add_vertex(&m, 2, 0, 0.5);
            pm_mesh_add_vertex(&m, 0, 1, 0.5);
            pm_mesh_add_vertex(&m, 2, 3, 0.5);
            pm_mesh_add_tri(&m, 0, 2, 1);
            pm_mesh_add_tri(&m, 0, 1, 3);
            pm_mesh_add_tri(&m, 0, 3, 2);
            pm_mesh_add_tri(&m, 1, 2, 3);
            if (scale) {
                pm_mesh_transform(&m, NULL, 1.0, t);
            }
            EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_ZERO_VOLUME);
            pm_mesh_free(&m);
        }
    }
    /* nothing at all */
    pm_mesh_init(&m);
    pm_mesh_add_vertex(&m, 0, 0, 0);
    {
        const int32_t s = pm_compute(&p, ctx, &m, NULL);
        assert_true(s == POLYMASS_ERROR_ZERO_VOLUME || s == POLYMASS_ERROR_INVALID_ARGUMENT);
        assert_true(strlen(polymass_context_message(ctx)) > 0);
    }
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Skip, degenerate faces, welding                                          */
/* ------------------------------------------------------------------------ */

/* A triangle soup of a cube: every triangle has its own three vertices, at
   exactly the positions of its neighbours'. */
static void make_cube_soup(pm_mesh* m) {
    pm_mesh_unit_cube(m, 1);
    pm_mesh_to_soup(m);
    assert_int_equal(m->vertex_count, 36);
}

static void test_skip_topology_checks(void** state) {
    const pm_expected e = pm_expected_box(unit_lo, unit_hi);
    polymass_context* ctx = pm_context_new(POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    /* topologically open (nothing shared), geometrically the closed cube */
    make_cube_soup(&m);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, POLYMASS_WARNING_UNCHECKED);
    PM_ASSERT_PROPERTIES("unchecked soup cube", &e, &p, PM_TOL);
    /* polymass_mesh_check runs the topology checks anyway */
    pm_check(&diag, ctx, &m);
    assert_int_equal(diag.open_edges, 36);
    assert_int_equal(diag.edge_count, 36);
    assert_int_equal(diag.used_vertex_count, 36);
    /* but out-of-range indices and NaN are still rejected */
    m.indices[10] = 36;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, pm_compute(&p, ctx, &m, NULL));
    m.indices[10] = 10;
    m.positions[3 * 10] = NAN;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_compute(&p, ctx, &m, NULL));
    pm_mesh_free(&m);

    /* a valid solid through the unchecked path: same numbers, flagged */
    {
        const pm_reference_solid* ref = &pm_reference_solids[PM_REF_SQUARE_RING];
        const pm_expected r = pm_expected_from_reference(ref);
        pm_mesh_from_reference(&m, ref);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_true(p.warnings & POLYMASS_WARNING_UNCHECKED);
        PM_ASSERT_PROPERTIES(ref->name, &r, &p, PM_TOL);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* The unit cube whose front face (y = 0) is split at x = 0.5 by vertices
   8 (0.5, 0, 0) and 9 (0.5, 0, 1): T-junctions on the bottom and top edges,
   closed by zero-area sliver triangles (collinear distinct vertices), faces 7
   and 8. */
static void make_t_junction_cube(pm_mesh* m) {
    pm_mesh_init(m);
    {
        int k;
        for (k = 0; k < 8; ++k) {
            pm_mesh_add_vertex(m, k & 1, (k >> 1) & 1, (k >> 2) & 1);
        }
    }
    pm_mesh_add_vertex(m, 0.5, 0, 0); /* 8 */
    pm_mesh_add_vertex(m, 0.5, 0, 1); /* 9 */
    pm_mesh_add_quad(m, 0, 2, 3, 1);  /* 0: bottom */
    pm_mesh_add_quad(m, 4, 5, 7, 6);  /* 1: top */
    pm_mesh_add_quad(m, 0, 8, 9, 4);  /* 2: front, left half */
    pm_mesh_add_quad(m, 8, 1, 5, 9);  /* 3: front, right half */
    pm_mesh_add_quad(m, 2, 6, 7, 3);  /* 4: back */
    pm_mesh_add_quad(m, 0, 4, 6, 2);  /* 5: x = 0 */
    pm_mesh_add_quad(m, 1, 3, 7, 5);  /* 6: x = 1 */
    pm_mesh_add_tri(m, 0, 1, 8);      /* 7: sliver on the bottom edge */
    pm_mesh_add_tri(m, 5, 4, 9);      /* 8: sliver on the top edge */
}

/* Faces whose area squared underflows are tiny, not degenerate: a shell of
   size 1e-150 beside one of size 2 has faces of area ~1e-300, whose square is
   0 in double. (A SIMD area test once reported such triangles as degenerate,
   and the polygon path such quads.) The tiny shell sits at the integration's
   reference point, the centre of the bounding box: anywhere else its
   coordinates would round to one point when moved into that frame. */
static void test_tiny_faces_are_not_degenerate(void** state) {
    const double s = 1e-150;
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    /* a regular tetrahedron of volume 8/3 */
    pm_mesh_add_vertex(&m, 1, 1, 1);
    pm_mesh_add_vertex(&m, 1, -1, -1);
    pm_mesh_add_vertex(&m, -1, 1, -1);
    pm_mesh_add_vertex(&m, -1, -1, 1);
    pm_mesh_add_tri(&m, 0, 1, 2);
    pm_mesh_add_tri(&m, 0, 2, 3);
    pm_mesh_add_tri(&m, 0, 3, 1);
    pm_mesh_add_tri(&m, 2, 1, 3);
    /* and a corner tetrahedron of edge 1e-150 at the origin */
    pm_mesh_add_vertex(&m, 0, 0, 0);
    pm_mesh_add_vertex(&m, s, 0, 0);
    pm_mesh_add_vertex(&m, 0, s, 0);
    pm_mesh_add_vertex(&m, 0, 0, s);
    pm_mesh_add_tri(&m, 4, 6, 5);
    pm_mesh_add_tri(&m, 4, 5, 7);
    pm_mesh_add_tri(&m, 4, 7, 6);
    pm_mesh_add_tri(&m, 5, 6, 7);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, 0);
    PM_ASSERT_REL("volume", 8.0 / 3.0, p.volume, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.degenerate_faces, 0);
    pm_mesh_free(&m);

    /* the same with quads: a cube [-1, 1]^3 and one [0, 1e-150]^3 */
    {
        static const double big_lo[3] = {-1, -1, -1}, big_hi[3] = {1, 1, 1};
        static const double tiny_lo[3] = {0, 0, 0};
        const double tiny_hi[3] = {s, s, s};
        pm_mesh_box(&m, big_lo, big_hi, 0);
        pm_mesh_add_box(&m, tiny_lo, tiny_hi, 0);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_int_equal(p.warnings, 0);
        PM_ASSERT_REL("volume", 8.0, p.volume, PM_TOL);
        PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
        assert_int_equal(diag.degenerate_faces, 0);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* A solid whose volume underflows is refused when the mesh is made (and by
   the check), not only when a body is computed from it. */
static void test_volume_underflow_is_found_by_the_check(void** state) {
    static const double lo[3] = {0, 0, 0};
    const double hi[3] = {1e-110, 2e-110, 3e-110};
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh m;
    (void)state;
    pm_mesh_box(&m, lo, hi, 1);
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OVERFLOW, pm_check(&diag, ctx, &m));
    assert_non_null(strstr(polymass_context_message(ctx), "volume"));
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_OVERFLOW);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_degenerate_faces(void** state) {
    const pm_expected e = pm_expected_box(unit_lo, unit_hi);
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    make_t_junction_cube(&m);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    /* The slivers lie along the faces they close without sharing all their
       vertices: touching, for the intersection check. */
    assert_int_equal(p.warnings,
                     POLYMASS_WARNING_DEGENERATE_FACES | POLYMASS_WARNING_TOUCHING_FACES);
    PM_ASSERT_PROPERTIES("cube with T-junctions closed by slivers", &e, &p, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.degenerate_faces, 2);
    assert_int_equal(diag.first_degenerate_faces[0], 7);
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.used_vertex_count, 10);
    pm_mesh_free(&m);

    /* the same translated far away: still exactly degenerate, still exact */
    {
        static const double t[3] = {1e8, 1e8, 1e8};
        const pm_expected et = pm_expected_transform(&e, NULL, 1.0, t);
        make_t_junction_cube(&m);
        pm_mesh_transform(&m, NULL, 1.0, t);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_true(p.warnings & POLYMASS_WARNING_DEGENERATE_FACES);
        PM_ASSERT_PROPERTIES("T-junction cube at 1e8", &et, &p, PM_TOL);
        pm_mesh_free(&m);
    }
    /* the slivers removed: open */
    make_t_junction_cube(&m);
    pm_mesh_remove_face(&m, 8);
    pm_mesh_remove_face(&m, 7);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_OPEN);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_welding(void** state) {
    const pm_expected e = pm_expected_box(unit_lo, unit_hi);
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    make_cube_soup(&m);
    EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_OPEN, OPEN_EDGE, 36, &diag);

    pm_context_set_flags(ctx, POLYMASS_OPTION_WELD_VERTICES);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, 0);
    PM_ASSERT_PROPERTIES("welded soup cube", &e, &p, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.used_vertex_count, 8);
    assert_int_equal(diag.edge_count, 18);
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.face_count, 12);

    /* welded vertex numbers are the lowest index at the position: flip a
       triangle and the misoriented edge is named by such indices */
    pm_mesh_reverse_face(&m, 4);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_INCONSISTENT_ORIENTATION);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INCONSISTENT_ORIENTATION, pm_check(&diag, ctx, &m));
    {
        size_t i, k;
        for (k = 0; k < 2; ++k) {
            const uint64_t v = diag.first_misoriented_edges[0][k];
            assert_true(v < m.vertex_count);
            for (i = 0; i < v; ++i) { /* no lower index at the same position */
                assert_true(memcmp(m.positions + 3 * i, m.positions + 3 * v, 3 * sizeof(double)) !=
                            0);
            }
        }
    }
    pm_mesh_reverse_face(&m, 4);

    /* only exactly equal positions weld: one ulp apart stays open */
    m.positions[3 * 20] = nextafter(m.positions[3 * 20], 2.0);
    EXPECT_MESH_FAILURE(ctx, &m, POLYMASS_ERROR_OPEN);
    pm_mesh_free(&m);

    /* a soup of the reference torus welds into the torus */
    {
        const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TORUS_TRIS];
        const pm_expected t = pm_expected_from_reference(ref);
        pm_mesh_from_reference(&m, ref);
        pm_mesh_to_soup(&m);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        PM_ASSERT_PROPERTIES("welded torus soup", &t, &p, PM_TOL);
        PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
        assert_int_equal(diag.used_vertex_count, ref->vertex_count);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* polymass_mesh_check                                                      */
/* ------------------------------------------------------------------------ */

static void test_check_reports_everything(void** state) {
    polymass_context* ctx = pm_context_new(0);
    polymass_diagnostics diag;
    pm_mesh m;
    (void)state;
    /* A clean cube: counts, NONE locations, signed volume */
    pm_mesh_unit_cube(&m, 0);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.status, POLYMASS_OK);
    assert_string_equal(polymass_context_message(ctx), "");
    assert_int_equal(diag.face_count, 6);
    assert_int_equal(diag.used_vertex_count, 8);
    assert_int_equal(diag.edge_count, 12);
    assert_int_equal(diag.non_finite_vertices, 0);
    assert_true(diag.first_non_finite_vertices[0] == POLYMASS_NONE);
    assert_int_equal(diag.out_of_range_indices, 0);
    assert_true(diag.first_out_of_range_faces[0] == POLYMASS_NONE);
    assert_int_equal(diag.small_faces, 0);
    assert_true(diag.first_small_faces[0] == POLYMASS_NONE);
    assert_int_equal(diag.degenerate_faces, 0);
    assert_true(diag.first_degenerate_faces[0] == POLYMASS_NONE);
    assert_int_equal(diag.open_edges, 0);
    assert_true(diag.first_open_edges[0][0] == POLYMASS_NONE &&
                diag.first_open_edges[0][1] == POLYMASS_NONE);
    assert_int_equal(diag.non_manifold_edges, 0);
    assert_true(diag.first_non_manifold_edges[0][0] == POLYMASS_NONE &&
                diag.first_non_manifold_edges[0][1] == POLYMASS_NONE);
    assert_int_equal(diag.misoriented_edges, 0);
    assert_true(diag.first_misoriented_edges[0][0] == POLYMASS_NONE &&
                diag.first_misoriented_edges[0][1] == POLYMASS_NONE);
    assert_int_equal(diag.non_planar_faces, 0);
    assert_true(diag.first_non_planar_faces[0] == POLYMASS_NONE);
    assert_true(diag.max_non_planarity >= 0 && diag.max_non_planarity < 1e-15);
    PM_ASSERT_REL("signed_volume", 1.0, diag.signed_volume, PM_TOL);
    pm_mesh_free(&m);

    /* Several problems at once: a missing face (open), a flipped face and a
       bent face: every one counted, without stopping at the first. */
    make_lifted_cube(&m, 1e-2);  /* bends face 1 */
    pm_mesh_remove_face(&m, 5);  /* opens the x = 1 side */
    pm_mesh_reverse_face(&m, 4); /* flips x = 0 */
    pm_check(&diag, ctx, &m);
    assert_int_not_equal(diag.status, POLYMASS_OK);
    assert_int_equal(diag.non_planar_faces, 1);
    assert_int_equal(diag.first_non_planar_faces[0], 1);
    assert_true(diag.open_edges >= 4);
    assert_true(diag.misoriented_edges >= 1);
    pm_mesh_free(&m);

    /* an out-of-range index and a NaN: both counted */
    pm_mesh_unit_cube(&m, 0);
    m.indices[5] = 99;
    m.positions[3 * 3 + 1] = NAN;
    pm_check(&diag, ctx, &m);
    assert_true(diag.status == POLYMASS_ERROR_NON_FINITE ||
                diag.status == POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    assert_int_equal(diag.out_of_range_indices, 1);
    assert_int_equal(diag.first_out_of_range_faces[0], 1);
    assert_int_equal(diag.non_finite_vertices, 1);
    assert_int_equal(diag.first_non_finite_vertices[0], 3);
    assert_true(isnan(diag.signed_volume));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_null_pointers),
        cmocka_unit_test(test_out_mesh_cleared_on_every_failure),
        cmocka_unit_test(test_check_report_status_on_invalid_argument),
        cmocka_unit_test(test_struct_sizes_checked),
        cmocka_unit_test(test_bad_types_strides_reserved),
        cmocka_unit_test(test_counts_that_do_not_add_up),
        cmocka_unit_test(test_overflowing_counts),
        cmocka_unit_test(test_invalid_mass_desc),
        cmocka_unit_test(test_non_finite),
        cmocka_unit_test(test_index_out_of_range),
        cmocka_unit_test(test_face_too_small),
        cmocka_unit_test(test_report_lists_the_first_locations),
        cmocka_unit_test(test_open),
        cmocka_unit_test(test_non_manifold),
        cmocka_unit_test(test_inconsistent_orientation),
        cmocka_unit_test(test_non_planar_face),
        cmocka_unit_test(test_inverted),
        cmocka_unit_test(test_zero_volume),
        cmocka_unit_test(test_skip_topology_checks),
        cmocka_unit_test(test_degenerate_faces),
        cmocka_unit_test(test_tiny_faces_are_not_degenerate),
        cmocka_unit_test(test_volume_underflow_is_found_by_the_check),
        cmocka_unit_test(test_welding),
        cmocka_unit_test(test_check_reports_everything),
    };
    return cmocka_run_group_tests_name("errors", tests, NULL, NULL);
}
