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

/* A vertex buffer: `stride` bytes per vertex, positions of `type` at the
   start of each record, the rest filled with junk (normals, uv), the whole
   buffer starting `misalign` bytes past a malloc'ed block. */
typedef struct vertex_buffer {
    unsigned char* block;
    const void* positions;
} vertex_buffer;

static vertex_buffer make_vertex_buffer(const pm_reference_solid* ref, uint32_t type, size_t stride,
                                        size_t misalign) {
    const size_t element = type == POLYMASS_POSITION_FLOAT32 ? sizeof(float) : sizeof(double);
    const size_t record = stride ? stride : 3 * element;
    vertex_buffer vb;
    unsigned char* base;
    size_t v;
    int i;
    vb.block = malloc(record * ref->vertex_count + misalign + 16);
    assert_non_null(vb.block);
    memset(vb.block, 0x7F, record * ref->vertex_count + misalign + 16); /* junk */
    base = vb.block + misalign;
    for (v = 0; v < ref->vertex_count; ++v) {
        unsigned char* r = base + v * record;
        for (i = 0; i < 3; ++i) {
            const double x = ref->positions[3 * v + (size_t)i];
            if (type == POLYMASS_POSITION_FLOAT32) {
                const float f = (float)x;
                assert_true((double)f == x); /* the same data */
                memcpy(r + (size_t)i * sizeof f, &f, sizeof f);
            } else {
                memcpy(r + (size_t)i * sizeof x, &x, sizeof x);
            }
        }
        /* a "normal" after the position, where the record has room */
        if (record >= 6 * element) {
            for (i = 3; i < 6; ++i) {
                if (type == POLYMASS_POSITION_FLOAT32) {
                    const float n = -1.0f / (float)i;
                    memcpy(r + (size_t)i * sizeof n, &n, sizeof n);
                } else {
                    const double n = NAN; /* not a position: must not be read */
                    memcpy(r + (size_t)i * sizeof n, &n, sizeof n);
                }
            }
        }
    }
    vb.positions = base;
    return vb;
}

static uint16_t* make_uint16_indices(const pm_reference_solid* ref) {
    uint16_t* out = malloc(ref->index_count * sizeof *out);
    uint32_t i;
    assert_non_null(out);
    for (i = 0; i < ref->index_count; ++i) {
        assert_true(ref->indices[i] <= 0xFFFF);
        out[i] = (uint16_t)ref->indices[i];
    }
    return out;
}

typedef struct variant {
    const char* name;
    uint32_t position_type;
    size_t stride; /* 0: packed */
    size_t misalign;
    int uint16_indices;
} variant;

static const variant variants[] = {
    {"float64 packed, stride 24 given explicitly", POLYMASS_POSITION_FLOAT64, 24, 0, 0},
    {"float64, stride 48 (position + normal)", POLYMASS_POSITION_FLOAT64, 48, 0, 0},
    {"float64, unaligned stride 28", POLYMASS_POSITION_FLOAT64, 28, 0, 0},
    {"float64, packed, buffer misaligned by 3 bytes", POLYMASS_POSITION_FLOAT64, 0, 3, 0},
    {"float64, stride 28, misaligned by 1, uint16", POLYMASS_POSITION_FLOAT64, 28, 1, 1},
    {"float64 packed, uint16 indices", POLYMASS_POSITION_FLOAT64, 0, 0, 1},
    {"float32 packed", POLYMASS_POSITION_FLOAT32, 0, 0, 0},
    {"float32, stride 12 given explicitly", POLYMASS_POSITION_FLOAT32, 12, 0, 0},
    {"float32, stride 32 (position, normal, uv)", POLYMASS_POSITION_FLOAT32, 32, 0, 0},
    {"float32, unaligned stride 28", POLYMASS_POSITION_FLOAT32, 28, 0, 0},
    {"float32, stride 13, misaligned by 1", POLYMASS_POSITION_FLOAT32, 13, 1, 0},
    {"float32 packed, uint16 indices", POLYMASS_POSITION_FLOAT32, 0, 0, 1},
    {"float32, stride 32, uint16 indices", POLYMASS_POSITION_FLOAT32, 32, 2, 1},
};
#define VARIANT_COUNT (sizeof variants / sizeof variants[0])

static void test_variants_equal_packed_double(void** state) {
    polymass_context* ctx = pm_context_new(0);
    size_t s, v;
    (void)state;
    for (s = 0; s < SOLID_COUNT; ++s) {
        const pm_reference_solid* ref = &pm_reference_solids[solids[s]];
        const polymass_mesh_desc base_desc = pm_reference_desc(ref);
        const pm_expected e = pm_expected_from_reference(ref);
        polymass_mass_properties base;
        pm_props_init(&base);
        PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&base, ctx, &base_desc, NULL));
        PM_ASSERT_PROPERTIES(ref->name, &e, &base, PM_TOL);
        for (v = 0; v < VARIANT_COUNT; ++v) {
            const variant* var = &variants[v];
            vertex_buffer vb =
                make_vertex_buffer(ref, var->position_type, var->stride, var->misalign);
            uint16_t* idx16 = var->uint16_indices ? make_uint16_indices(ref) : NULL;
            polymass_mesh_desc d = base_desc;
            polymass_mass_properties p;
            char label[256];
            d.position_type = var->position_type;
            d.positions = vb.positions;
            d.position_stride = var->stride;
            if (idx16) {
                d.index_type = POLYMASS_INDEX_UINT16;
                d.indices = idx16;
            }
            pm_props_init(&p);
            snprintf(label, sizeof label, "%s, %s", ref->name, var->name);
            PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, ctx, &d, NULL));
            PM_ASSERT_SAME_PROPERTIES(label, &base, &p);
            free(idx16);
            free(vb.block);
        }
    }
    polymass_context_destroy(ctx);
}

/* Vertices the faces do not use change nothing but rounding (the bounding
   box, hence the reference point, may differ). */
static void test_unused_vertices(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_PRISM_12GON];
    const pm_expected e = pm_expected_from_reference(ref);
    polymass_context* ctx = pm_context_new(0);
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

/* The mesh keeps the integrals, not the caller's arrays. */
static void test_mesh_does_not_keep_caller_arrays(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_HOUSE];
    const polymass_mesh_desc ref_desc = pm_reference_desc(ref);
    polymass_context* ctx = pm_context_new(0);
    polymass_mass_properties before, after;
    polymass_mesh* mesh = NULL;
    pm_mesh m;
    (void)state;
    pm_props_init(&before);
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&before, ctx, &ref_desc, NULL));
    pm_mesh_from_reference(&m, ref);
    {
        const polymass_mesh_desc d = pm_mesh_desc(&m);
        PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d));
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
    polymass_context* maker = pm_context_new(0);
    polymass_context* reader = pm_context_new(0);
    polymass_mesh* mesh = NULL;
    polymass_mass_properties p;
    (void)state;
    PM_ASSERT_OK(maker, polymass_mesh_create(&mesh, maker, &d));
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
    polymass_context* ctx = pm_context_new(0);
    const float lo[3] = {0.1f, -0.3f, 0.7f}, hi[3] = {1.3f, 0.9f, 2.9f};
    const double dlo[3] = {lo[0], lo[1], lo[2]}, dhi[3] = {hi[0], hi[1], hi[2]};
    const pm_expected e = pm_expected_box(dlo, dhi);
    pm_mesh m;
    float* positions;
    polymass_mesh_desc d;
    polymass_mass_properties p, pd;
    size_t k;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_box(&m, dlo, dhi, 1);
    positions = malloc(m.vertex_count * 3 * sizeof *positions);
    assert_non_null(positions);
    for (k = 0; k < 3 * m.vertex_count; ++k) {
        positions[k] = (float)m.positions[k];
    }
    d = pm_mesh_desc(&m);
    d.position_type = POLYMASS_POSITION_FLOAT32;
    d.positions = positions;
    pm_props_init(&p);
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, ctx, &d, NULL));
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
        cmocka_unit_test(test_mesh_does_not_keep_caller_arrays),
        cmocka_unit_test(test_mesh_outlives_its_context),
        cmocka_unit_test(test_float32_rounded_values),
    };
    return cmocka_run_group_tests_name("input_variants", tests, NULL, NULL);
}
