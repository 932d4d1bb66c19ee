/* The same solids given as float32 positions, interleaved/strided and
 * unaligned vertex buffers, uint16 indices: the same data must give the very
 * same result (bitwise) as packed doubles with uint32 indices. Also: the mesh
 * keeps no pointer to the caller's arrays, and outlives its context. */
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const int solids[] = {PM_REF_CUBE_QUADS, PM_REF_CUBE_TRIS,   PM_REF_PRISM_STAR,
                             PM_REF_HOUSE,      PM_REF_CUBE_CAVITY, PM_REF_TORUS_TRIS};
#define SOLID_COUNT (sizeof solids / sizeof solids[0])

/* Every combination of: float64 or float32 positions; a stride of 0 (packed,
   the default), 3 elements (packed, given explicitly), 3 elements + 1 byte
   (unaligned), 6 elements (position + normal), 28 bytes (unaligned for
   doubles) or 32 bytes (float position, normal, uv); the buffer misaligned
   by 0 to 3 bytes; uint32 or uint16 indices. */
#define POSITION_TYPE_COUNT 2
#define STRIDE_COUNT 6
#define MISALIGN_COUNT 4
#define INDEX_TYPE_COUNT 2
#define LAYOUT_COUNT (POSITION_TYPE_COUNT * STRIDE_COUNT * MISALIGN_COUNT * INDEX_TYPE_COUNT)

static pm_layout layout_number(size_t n) {
    pm_layout layout;
    size_t element, strides[STRIDE_COUNT];
    layout.position_type =
        n % POSITION_TYPE_COUNT ? POLYMASS_POSITION_FLOAT32 : POLYMASS_POSITION_FLOAT64;
    n /= POSITION_TYPE_COUNT;
    element = layout.position_type == POLYMASS_POSITION_FLOAT32 ? sizeof(float) : sizeof(double);
    strides[0] = 0;
    strides[1] = 3 * element;
    strides[2] = 3 * element + 1;
    strides[3] = 6 * element;
    strides[4] = 28;
    strides[5] = 32;
    layout.stride = strides[n % STRIDE_COUNT];
    n /= STRIDE_COUNT;
    layout.misalign = n % MISALIGN_COUNT;
    n /= MISALIGN_COUNT;
    layout.index_type = n % INDEX_TYPE_COUNT ? POLYMASS_INDEX_UINT16 : POLYMASS_INDEX_UINT32;
    return layout;
}

static void test_variants_equal_packed_double(void** state) {
    polymass_context* ctx = pm_context_new();
    size_t s, n;
    (void)state;
    for (s = 0; s < SOLID_COUNT; ++s) {
        const pm_reference_solid* ref = &pm_reference_solids[solids[s]];
        polymass_mass_properties base;
        pm_mesh m;
        PM_ASSERT_REFERENCE_COMPUTE(ctx, ref, &base);
        pm_mesh_from_reference(&m, ref);
        for (n = 0; n < LAYOUT_COUNT; ++n) {
            const pm_layout layout = layout_number(n);
            pm_laid_out_mesh laid_out;
            polymass_mass_properties p;
            char label[256];
            pm_lay_out(&laid_out, &m, &layout);
            snprintf(label, sizeof label, "%s, %s, stride %u, misaligned by %u, %s indices",
                     ref->name,
                     layout.position_type == POLYMASS_POSITION_FLOAT32 ? "float32" : "float64",
                     (unsigned)layout.stride, (unsigned)layout.misalign,
                     layout.index_type == POLYMASS_INDEX_UINT16 ? "uint16" : "uint32");
            pm_props_init(&p);
            PM_ASSERT_OK(
                ctx, polymass_mass_properties_compute(&p, NULL, ctx, &laid_out.desc, NULL, NULL));
            PM_ASSERT_SAME_PROPERTIES(label, &base, &p);
            pm_laid_out_free(&laid_out);
        }
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* Vertices the faces do not use change nothing but rounding (the bounding
   box, hence the reference point, may differ). */
static void test_unused_vertices(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_PRISM_12GON];
    const pm_expected e = pm_expected_from_reference(ref);
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    polymass_diagnostics d;
    pm_mesh m;
    size_t k;
    (void)state;
    pm_mesh_from_reference(&m, ref);
    pm_mesh_add_vertex(&m, 100, -50, 7);
    pm_mesh_add_vertex(&m, -3, 2, 1e3);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_PROPERTIES("12-gon prism with unused vertices", &e, &p, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&d, ctx, &m));
    assert_int_equal(d.used_vertex_count, ref->vertex_count);
    /* The same with the unused vertices first: every index shifts. */
    pm_mesh_free(&m);
    pm_mesh_init(&m);
    pm_mesh_add_vertex(&m, 1e4, 1e4, 1e4);
    pm_mesh_add_vertex(&m, -1e4, 0, 0);
    {
        pm_mesh tmp;
        pm_mesh_from_reference(&tmp, ref);
        pm_mesh_append(&m, &tmp);
        pm_mesh_free(&tmp);
    }
    for (k = 0; k < m.index_count; ++k) {
        assert_true(m.indices[k] >= 2);
    }
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_PROPERTIES("12-gon prism after unused vertices", &e, &p, PM_TOL);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* The trusted path (topology unchecked), and the checked one without a
   weld, find the used vertices as they integrate, about the centre of the
   bounds of every vertex, and integrate again when the used ones' bounds
   differ: with vertices unused inside the solid's box, outside it, not
   finite, or none, their results are those of a welded analysis, whose scan
   marks the used vertices before the integration, bit for bit, and the exact
   ones to the usual tolerance. */
static void test_unused_vertices_trusted(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TORUS_TRIS];
    const pm_expected e = pm_expected_from_reference(ref);
    polymass_context* ctx = pm_context_new();
    const uint32_t trusted = POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
    const uint32_t checked_flags = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    int extra;
    (void)state;
    for (extra = 0; extra < 4; ++extra) {
        static const char* const labels[] = {"none unused", "unused inside the box",
                                             "unused far outside", "unused, not finite"};
        polymass_mass_properties scanned_first, checked, p;
        pm_mesh m;
        pm_mesh_from_reference(&m, ref);
        if (extra == 1) pm_mesh_add_vertex(&m, m.positions[0], m.positions[1], m.positions[2]);
        if (extra == 2) pm_mesh_add_vertex(&m, 1e4, -1e4, 1e3);
        if (extra == 3) pm_mesh_add_vertex(&m, NAN, 0, 0);
        pm_props_init(&scanned_first);
        pm_props_init(&checked);
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, pm_compute_flags(&scanned_first, ctx, &m,
                                           checked_flags | POLYMASS_OPTION_WELD_VERTICES, NULL));
        PM_ASSERT_OK(ctx, pm_compute_flags(&checked, ctx, &m, checked_flags, NULL));
        PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, trusted, NULL));
        PM_ASSERT_SAME_PROPERTIES(labels[extra], &scanned_first, &checked);
        /* The one difference: the trusted answer says it is unchecked. */
        assert_int_equal(p.warnings, checked.warnings | POLYMASS_WARNING_UNCHECKED);
        checked.warnings = p.warnings;
        PM_ASSERT_SAME_PROPERTIES(labels[extra], &checked, &p);
        PM_ASSERT_PROPERTIES(labels[extra], &e, &p, PM_TOL);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* A mesh's positions and indices copied into blocks of exactly their size
   (one byte when empty), so that AddressSanitizer sees a read past either. */
typedef struct exact_arrays {
    void* positions;
    void* indices;
    polymass_mesh_desc desc;
} exact_arrays;

static void exact_arrays_make(exact_arrays* out, const pm_mesh* m, uint32_t position_type,
                              uint32_t index_type) {
    const size_t element = position_type == POLYMASS_POSITION_FLOAT32 ? 4 : 8;
    const size_t index_size = index_type == POLYMASS_INDEX_UINT16 ? 2 : 4;
    size_t i;
    out->positions = malloc(m->vertex_count ? 3 * m->vertex_count * element : 1);
    out->indices = malloc(m->index_count ? m->index_count * index_size : 1);
    assert_non_null(out->positions);
    assert_non_null(out->indices);
    for (i = 0; i < 3 * m->vertex_count; ++i) {
        if (element == 4)
            ((float*)out->positions)[i] = (float)m->positions[i];
        else
            ((double*)out->positions)[i] = m->positions[i];
    }
    for (i = 0; i < m->index_count; ++i) {
        if (index_size == 2)
            ((uint16_t*)out->indices)[i] = (uint16_t)m->indices[i];
        else
            ((uint32_t*)out->indices)[i] = m->indices[i];
    }
    out->desc = pm_mesh_desc(m);
    out->desc.position_type = position_type;
    out->desc.positions = out->positions;
    out->desc.index_type = index_type;
    out->desc.indices = out->indices;
}

static void exact_arrays_free(exact_arrays* arrays) {
    free(arrays->positions);
    free(arrays->indices);
}

/* The status of the checked path for the mesh's arrays (in exact blocks:
   exact_arrays_make) with vertex_count vertices; the trusted path (topology
   unchecked) gives the same status and message. */
static int32_t trusted_as_checked(polymass_context* ctx, const pm_mesh* m, uint32_t position_type,
                                  uint32_t index_type, uint64_t vertex_count) {
    const polymass_options trusted = pm_options(POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS, 0.0);
    const polymass_options checked = pm_options(POLYMASS_OPTION_SKIP_INTERSECTION_CHECK, 0.0);
    polymass_mass_properties props;
    exact_arrays arrays;
    char message[512];
    int32_t status;
    exact_arrays_make(&arrays, m, position_type, index_type);
    arrays.desc.vertex_count = vertex_count;
    pm_props_init(&props);
    status = polymass_mass_properties_compute(&props, NULL, ctx, &arrays.desc, &checked, NULL);
    snprintf(message, sizeof message, "%s", polymass_context_message(ctx));
    assert_int_equal(
        polymass_mass_properties_compute(&props, NULL, ctx, &arrays.desc, &trusted, NULL), status);
    assert_string_equal(polymass_context_message(ctx), message);
    exact_arrays_free(&arrays);
    return status;
}

/* The trusted path checks each index before it reads the vertex: whatever
   the position and index types, an index one past the last vertex in the
   first triangle, in a later batch of 64 triangles, past a block of 65,536 or
   in the last triangle, or any index with no vertex at all (the position
   array a single byte), is refused as the checked path refuses it, on one
   thread and on two, and nothing past the arrays is read; an index at the
   last vertex is read like any other. No vertex and no face: the checked
   path's answer. */
static void test_trusted_reads_only_in_range(void** state) {
    static const size_t out_of_range_at[] = {0, 3 * 2048 + 1, 3 * 65536 + 2, (size_t)-1};
    static const uint32_t position_types[] = {POLYMASS_POSITION_FLOAT64, POLYMASS_POSITION_FLOAT32};
    static const uint32_t index_types[] = {POLYMASS_INDEX_UINT32, POLYMASS_INDEX_UINT16};
    static const double centre[3] = {1e6, -1e6, 0.0};
    polymass_context* ctx = pm_context_new();
    pm_mesh torus, no_vertex, empty;
    size_t p, i, at, threads;
    (void)state;
    /* 70,000 triangles over 35,000 vertices: two blocks, 16-bit indices. */
    pm_mesh_init(&torus);
    pm_mesh_add_torus(&torus, 175, 200, 2.0, 0.5, centre);
    assert_true(torus.index_count > 3 * 65536 + 3 && torus.vertex_count < 65535);
    pm_mesh_init(&no_vertex);
    for (i = 0; i < 300; ++i) pm_mesh_add_tri(&no_vertex, 0, 0, i % 7 ? 0 : 1);
    pm_mesh_init(&empty);
    for (threads = 1; threads <= 2; ++threads) {
        assert_int_equal(polymass_context_set_threads(ctx, (uint32_t)threads), POLYMASS_OK);
        for (p = 0; p < 2; ++p)
            for (i = 0; i < 2; ++i) {
                assert_int_equal(
                    trusted_as_checked(ctx, &no_vertex, position_types[p], index_types[i], 0),
                    POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
                assert_int_not_equal(
                    trusted_as_checked(ctx, &empty, position_types[p], index_types[i], 0),
                    POLYMASS_OK);
                for (at = 0; at < sizeof out_of_range_at / sizeof out_of_range_at[0]; ++at) {
                    const size_t corner = out_of_range_at[at] == (size_t)-1 ? torus.index_count - 1
                                                                            : out_of_range_at[at];
                    pm_mesh broken;
                    pm_mesh_copy(&broken, &torus);
                    broken.indices[corner == 0 ? 1 : corner - 1] = (uint32_t)torus.vertex_count - 1;
                    broken.indices[corner] = (uint32_t)torus.vertex_count;
                    assert_int_equal(trusted_as_checked(ctx, &broken, position_types[p],
                                                        index_types[i], broken.vertex_count),
                                     POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
                    pm_mesh_free(&broken);
                }
            }
    }
    pm_mesh_free(&torus);
    pm_mesh_free(&no_vertex);
    pm_mesh_free(&empty);
    polymass_context_destroy(ctx);
}

/* The mesh keeps the integrals, not the caller's arrays. */
static void test_mesh_does_not_keep_caller_arrays(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_HOUSE];
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties before, after;
    polymass_mesh* mesh = NULL;
    pm_mesh m;
    (void)state;
    PM_ASSERT_OK(ctx, pm_compute_reference(&before, ctx, ref));
    pm_mesh_from_reference(&m, ref);
    {
        const polymass_mesh_desc d = pm_mesh_desc(&m);
        PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d, NULL));
    }
    /* scribble over, then free the arrays (ASan catches any later read) */
    memset(m.positions, 0xFF, m.vertex_count * 3 * sizeof(double));
    memset(m.indices, 0xFF, m.index_count * sizeof(uint32_t));
    memset(m.face_sizes, 0xFF, m.face_count * sizeof(uint32_t));
    pm_mesh_free(&m);
    pm_props_init(&after);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&after, ctx, mesh, NULL));
    PM_ASSERT_SAME_PROPERTIES("after the caller's arrays were freed", &before, &after);
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(ctx);
}

/* A mesh stays valid after the context that made it is destroyed, and is
   read through another context. */
static void test_mesh_outlives_its_context(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_OCTAHEDRON_IRREGULAR];
    const polymass_mesh_desc d = pm_reference_desc(ref);
    const pm_expected e = pm_expected_from_reference(ref);
    polymass_context* maker = pm_context_new();
    polymass_context* reader = pm_context_new();
    polymass_mesh* mesh = NULL;
    polymass_mass_properties p;
    (void)state;
    PM_ASSERT_OK(maker, polymass_mesh_create(&mesh, maker, &d, NULL));
    polymass_context_destroy(maker);
    pm_props_init(&p);
    PM_ASSERT_OK(reader, polymass_mesh_mass_properties(&p, reader, mesh, NULL));
    PM_ASSERT_PROPERTIES(ref->name, &e, &p, PM_TOL);
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(reader);
}

/* A float32 vertex buffer whose values are not doubles' neighbours: the
   result is that of the float values widened to double. */
static void test_float32_rounded_values(void** state) {
    polymass_context* ctx = pm_context_new();
    const float lo[3] = {0.1f, -0.3f, 0.7f}, hi[3] = {1.3f, 0.9f, 2.9f};
    const double dlo[3] = {lo[0], lo[1], lo[2]}, dhi[3] = {hi[0], hi[1], hi[2]};
    const pm_expected e = pm_expected_box(dlo, dhi);
    pm_mesh m;
    float* positions;
    polymass_mesh_desc d;
    polymass_mass_properties p, pd;
    size_t k;
    (void)state;
    pm_mesh_box(&m, dlo, dhi, 1);
    positions = malloc(m.vertex_count * 3 * sizeof *positions);
    assert_non_null(positions);
    for (k = 0; k < 3 * m.vertex_count; ++k) {
        positions[k] = (float)m.positions[k];
    }
    d = pm_mesh_desc(&m);
    d.position_type = POLYMASS_POSITION_FLOAT32;
    d.positions = positions;
    pm_props_init(&p);
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));
    PM_ASSERT_PROPERTIES("float32 box", &e, &p, PM_TOL);
    PM_ASSERT_OK(ctx, pm_compute(&pd, ctx, &m, NULL));
    PM_ASSERT_SAME_PROPERTIES("float32 box vs the same values in double", &pd, &p);
    free(positions);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_variants_equal_packed_double),
        cmocka_unit_test(test_unused_vertices),
        cmocka_unit_test(test_unused_vertices_trusted),
        cmocka_unit_test(test_trusted_reads_only_in_range),
        cmocka_unit_test(test_mesh_does_not_keep_caller_arrays),
        cmocka_unit_test(test_mesh_outlives_its_context),
        cmocka_unit_test(test_float32_rounded_values),
    };
    return cmocka_run_group_tests_name("input_variants", tests, NULL, NULL);
}
