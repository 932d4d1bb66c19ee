/* polymass_packed_compute: every mesh's row bit for bit its single call's
 * result (float32 and float64 positions, 16- and 32-bit indices counted from
 * each mesh's first vertex or from the packed array's, on one thread and on
 * three), a failed mesh's row (status, NaN numbers, message) among good
 * ones, and every argument the set as a whole can get wrong. */
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MESHES 9
#define OPEN_MESH 4 /* a face removed: fails, the others do not */

/* The columns of polymass_packed_results, owned. */
typedef struct packed_rows {
    int32_t status[MESHES];
    uint32_t warnings[MESHES];
    double volume[MESHES], mass[MESHES], surface_area[MESHES];
    double center_of_mass[3 * MESHES], inertia[9 * MESHES];
    double principal_moments[3 * MESHES], principal_axes[9 * MESHES];
    double error_bound_volume[MESHES], error_bound_center_of_mass[MESHES];
    double error_bound_inertia[MESHES];
    char messages[MESHES * POLYMASS_BATCH_MESSAGE_SIZE];
    polymass_packed_results results;
} packed_rows;

static void rows_init(packed_rows* rows) {
    memset(rows, 0x5a, sizeof *rows); /* junk: every wanted cell must be written */
    assert_int_equal(polymass_packed_results_init(&rows->results, sizeof rows->results),
                     POLYMASS_OK);
    rows->results.status = rows->status;
    rows->results.warnings = rows->warnings;
    rows->results.volume = rows->volume;
    rows->results.mass = rows->mass;
    rows->results.surface_area = rows->surface_area;
    rows->results.center_of_mass = rows->center_of_mass;
    rows->results.inertia = rows->inertia;
    rows->results.principal_moments = rows->principal_moments;
    rows->results.principal_axes = rows->principal_axes;
    rows->results.error_bound_volume = rows->error_bound_volume;
    rows->results.error_bound_center_of_mass = rows->error_bound_center_of_mass;
    rows->results.error_bound_inertia = rows->error_bound_inertia;
    rows->results.messages = rows->messages;
}

/* Triangle meshes of several kinds and sizes, far from each other and from
   the origin; mesh OPEN_MESH open. */
static void make_meshes(pm_mesh meshes[MESHES]) {
    int i;
    for (i = 0; i < MESHES; ++i) {
        const double at = 10.0 * i + 1e3;
        const double lo[3] = {at, -1.0 - i, 0.5}, hi[3] = {at + 1.0 + 0.25 * i, 2.0, 3.0 + i};
        const double centre[3] = {at, 5.0, -2.0};
        if (i % 3 == 0) {
            pm_mesh_box(&meshes[i], lo, hi, 1);
        } else {
            pm_mesh_init(&meshes[i]);
            pm_mesh_add_torus(&meshes[i], 6 + (uint32_t)i, 4 + (uint32_t)i % 3, 3.0, 1.0 + 0.1 * i,
                              centre);
            if (i % 3 == 2) pm_mesh_add_box(&meshes[i], lo, hi, 1); /* two shells */
        }
    }
    pm_mesh_remove_face(&meshes[OPEN_MESH], 3);
}

/* The meshes in shared arrays as the layout asks, and each mesh's own
   description of its part of them (local indices) for the single calls. */
typedef struct packed_set {
    void* positions;
    void* indices;       /* as the packed call reads them */
    void* local_indices; /* counted from each mesh's first vertex */
    uint64_t vertex_offsets[MESHES + 1], index_offsets[MESHES + 1];
    polymass_packed_meshes meshes;
    polymass_mesh_desc descs[MESHES];
} packed_set;

static void pack(packed_set* set, const pm_mesh meshes[MESHES], uint32_t position_type,
                 uint32_t index_type, uint32_t index_base) {
    const size_t coordinate = position_type == POLYMASS_POSITION_FLOAT32 ? 4 : 8;
    const size_t index_bytes = index_type == POLYMASS_INDEX_UINT16   ? 2
                               : index_type == POLYMASS_INDEX_UINT64 ? 8
                                                                     : 4;
    /* A single mesh's description takes 16 or 32 bits: 64-bit sets are
       compared with 32-bit single calls. */
    const uint32_t single_type =
        index_type == POLYMASS_INDEX_UINT64 ? POLYMASS_INDEX_UINT32 : index_type;
    const size_t single_bytes = single_type == POLYMASS_INDEX_UINT16 ? 2 : 4;
    size_t vertices = 0, indices = 0, v, k;
    int i;
    for (i = 0; i < MESHES; ++i) {
        set->vertex_offsets[i] = vertices, set->index_offsets[i] = indices;
        vertices += meshes[i].vertex_count, indices += meshes[i].index_count;
    }
    set->vertex_offsets[MESHES] = vertices, set->index_offsets[MESHES] = indices;
    set->positions = malloc(3 * coordinate * vertices);
    set->indices = malloc(index_bytes * indices);
    set->local_indices = malloc(single_bytes * indices);
    assert_non_null(set->positions);
    assert_non_null(set->indices);
    assert_non_null(set->local_indices);
    for (i = 0; i < MESHES; ++i) {
        const size_t first_vertex = set->vertex_offsets[i], first_index = set->index_offsets[i];
        const size_t base = index_base == POLYMASS_INDICES_GLOBAL ? first_vertex : 0;
        assert_true(pm_mesh_all_triangles(&meshes[i]));
        for (v = 0; v < 3 * meshes[i].vertex_count; ++v) {
            const double value = meshes[i].positions[v];
            if (position_type == POLYMASS_POSITION_FLOAT32)
                ((float*)set->positions)[3 * first_vertex + v] = (float)value;
            else
                ((double*)set->positions)[3 * first_vertex + v] = value;
        }
        for (k = 0; k < meshes[i].index_count; ++k) {
            const uint32_t local = meshes[i].indices[k];
            assert_true(base + local <= (index_type == POLYMASS_INDEX_UINT16 ? 0xffffu : ~0u));
            if (index_type == POLYMASS_INDEX_UINT16) {
                ((uint16_t*)set->indices)[first_index + k] = (uint16_t)(base + local);
                ((uint16_t*)set->local_indices)[first_index + k] = (uint16_t)local;
            } else if (index_type == POLYMASS_INDEX_UINT64) {
                ((uint64_t*)set->indices)[first_index + k] = (uint64_t)(base + local);
                ((uint32_t*)set->local_indices)[first_index + k] = local;
            } else {
                ((uint32_t*)set->indices)[first_index + k] = (uint32_t)(base + local);
                ((uint32_t*)set->local_indices)[first_index + k] = local;
            }
        }
        polymass_mesh_desc_init(&set->descs[i], sizeof set->descs[i]);
        set->descs[i].position_type = position_type;
        set->descs[i].positions = (unsigned char*)set->positions + 3 * coordinate * first_vertex;
        set->descs[i].vertex_count = meshes[i].vertex_count;
        set->descs[i].index_type = single_type;
        set->descs[i].indices = (unsigned char*)set->local_indices + single_bytes * first_index;
        set->descs[i].index_count = meshes[i].index_count;
    }
    assert_int_equal(polymass_packed_meshes_init(&set->meshes, sizeof set->meshes), POLYMASS_OK);
    set->meshes.position_type = position_type;
    set->meshes.positions = set->positions;
    set->meshes.index_type = index_type;
    set->meshes.index_base = index_base;
    set->meshes.indices = set->indices;
    set->meshes.mesh_count = MESHES;
    set->meshes.vertex_offsets = set->vertex_offsets;
    set->meshes.index_offsets = set->index_offsets;
}

static void pack_free(packed_set* set) {
    free(set->positions), free(set->indices), free(set->local_indices);
}

static int all_nan(const double* values, size_t count) {
    size_t k;
    for (k = 0; k < count; ++k)
        if (!isnan(values[k])) return 0;
    return 1;
}

/* Row i is bit for bit the single call's result, or its status, message and
   NaN numbers. */
static void assert_row_is_single_call(const packed_rows* rows, int i, polymass_context* single,
                                      const polymass_mesh_desc* desc,
                                      const polymass_options* options,
                                      const polymass_mass_desc* mass) {
    polymass_mass_properties p;
    int32_t status;
    pm_props_init(&p);
    status = polymass_mass_properties_compute(&p, NULL, single, desc, options, mass);
    assert_int_equal(rows->status[i], status);
    if (status != POLYMASS_OK) {
        assert_string_equal(rows->messages + i * POLYMASS_BATCH_MESSAGE_SIZE,
                            polymass_context_message(single));
        assert_int_equal(rows->warnings[i], 0);
        assert_true(all_nan(&rows->volume[i], 1) && all_nan(&rows->mass[i], 1));
        assert_true(all_nan(&rows->surface_area[i], 1));
        assert_true(all_nan(&rows->center_of_mass[3 * i], 3));
        assert_true(all_nan(&rows->inertia[9 * i], 9));
        assert_true(all_nan(&rows->principal_moments[3 * i], 3));
        assert_true(all_nan(&rows->principal_axes[9 * i], 9));
        assert_true(all_nan(&rows->error_bound_volume[i], 1));
        assert_true(all_nan(&rows->error_bound_center_of_mass[i], 1));
        assert_true(all_nan(&rows->error_bound_inertia[i], 1));
        return;
    }
    assert_string_equal(rows->messages + i * POLYMASS_BATCH_MESSAGE_SIZE, "");
    assert_int_equal(rows->warnings[i], p.warnings);
    assert_memory_equal(&rows->volume[i], &p.volume, sizeof p.volume);
    assert_memory_equal(&rows->mass[i], &p.mass, sizeof p.mass);
    assert_memory_equal(&rows->surface_area[i], &p.surface_area, sizeof p.surface_area);
    assert_memory_equal(&rows->center_of_mass[3 * i], p.center_of_mass, sizeof p.center_of_mass);
    assert_memory_equal(&rows->inertia[9 * i], p.inertia, sizeof p.inertia);
    assert_memory_equal(&rows->principal_moments[3 * i], p.principal_moments,
                        sizeof p.principal_moments);
    assert_memory_equal(&rows->principal_axes[9 * i], p.principal_axes, sizeof p.principal_axes);
    assert_memory_equal(&rows->error_bound_volume[i], &p.error_bound_volume,
                        sizeof p.error_bound_volume);
    assert_memory_equal(&rows->error_bound_center_of_mass[i], &p.error_bound_center_of_mass,
                        sizeof p.error_bound_center_of_mass);
    assert_memory_equal(&rows->error_bound_inertia[i], &p.error_bound_inertia,
                        sizeof p.error_bound_inertia);
}

static void test_packed_matches_single_calls(void** state) {
    static const uint32_t position_types[] = {POLYMASS_POSITION_FLOAT64, POLYMASS_POSITION_FLOAT32};
    static const uint32_t index_types[] = {POLYMASS_INDEX_UINT32, POLYMASS_INDEX_UINT16,
                                           POLYMASS_INDEX_UINT64};
    static const uint32_t index_bases[] = {POLYMASS_INDICES_LOCAL, POLYMASS_INDICES_GLOBAL};
    static const uint32_t thread_counts[] = {1, 3};
    polymass_context* packed = pm_context_new();
    polymass_context* single = pm_context_new();
    pm_mesh meshes[MESHES];
    double densities[MESHES];
    int p, x, b, t, weighting, i;
    (void)state;
    make_meshes(meshes);
    for (i = 0; i < MESHES; ++i) densities[i] = 0.5 + 0.375 * i;
    for (p = 0; p < 2; ++p)
        for (x = 0; x < 3; ++x)
            for (b = 0; b < 2; ++b) {
                packed_set set;
                pack(&set, meshes, position_types[p], index_types[x], index_bases[b]);
                for (t = 0; t < 2; ++t) /* Unit density, per-mesh densities, per-mesh masses. */
                    for (weighting = 0; weighting < 3; ++weighting) {
                        packed_rows rows;
                        uint64_t failed = 99;
                        polymass_mass_desc mass;
                        set.meshes.mass_values = weighting ? densities : NULL;
                        set.meshes.mass_mode =
                            weighting == 2 ? POLYMASS_MASS_FROM_TOTAL : POLYMASS_MASS_FROM_DENSITY;
                        rows_init(&rows);
                        PM_ASSERT_OK(packed,
                                     polymass_context_set_threads(packed, thread_counts[t]));
                        PM_ASSERT_OK(packed, polymass_packed_compute(&rows.results, &failed, packed,
                                                                     &set.meshes, NULL));
                        assert_string_equal(polymass_context_message(packed), "");
                        assert_int_equal(failed, 1);
                        assert_int_equal(rows.status[OPEN_MESH], POLYMASS_ERROR_OPEN);
                        for (i = 0; i < MESHES; ++i) {
                            mass = weighting == 2 ? pm_mass_total(densities[i])
                                                  : pm_mass_density(densities[i]);
                            assert_row_is_single_call(&rows, i, single, &set.descs[i], NULL,
                                                      weighting ? &mass : NULL);
                        }
                    }
                pack_free(&set);
            }
    for (i = 0; i < MESHES; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(packed);
    polymass_context_destroy(single);
}

/* The call's options are every mesh's: a surface inverted as a whole fails
   with the defaults and is answered, turned, with ACCEPT_INVERTED. */
static void test_packed_options_apply_to_every_mesh(void** state) {
    polymass_context* ctx = pm_context_new();
    const polymass_options accept = pm_options(POLYMASS_OPTION_ACCEPT_INVERTED, 0.0);
    pm_mesh meshes[MESHES];
    packed_set set;
    packed_rows rows;
    uint64_t failed = 0;
    int i;
    (void)state;
    make_meshes(meshes);
    pm_mesh_reverse_all(&meshes[1]);
    pack(&set, meshes, POLYMASS_POSITION_FLOAT64, POLYMASS_INDEX_UINT32, POLYMASS_INDICES_LOCAL);
    rows_init(&rows);
    PM_ASSERT_OK(ctx, polymass_packed_compute(&rows.results, &failed, ctx, &set.meshes, NULL));
    assert_int_equal(failed, 2);
    assert_int_equal(rows.status[1], POLYMASS_ERROR_INVERTED);
    rows_init(&rows);
    PM_ASSERT_OK(ctx, polymass_packed_compute(&rows.results, &failed, ctx, &set.meshes, &accept));
    assert_int_equal(failed, 1);
    assert_int_equal(rows.status[1], POLYMASS_OK);
    assert_true(rows.warnings[1] & POLYMASS_WARNING_INVERTED);
    for (i = 0; i < MESHES; ++i)
        assert_row_is_single_call(&rows, i, ctx, &set.descs[i], &accept, NULL);
    pack_free(&set);
    for (i = 0; i < MESHES; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(ctx);
}

/* Meshes that fail on their own: a density that is no density, no faces,
   global indices outside the mesh's own vertices (those of the next mesh, and
   below its first); each fails its row only. */
static void test_packed_failures_are_the_meshes_own(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh meshes[MESHES];
    double densities[MESHES];
    packed_set set;
    packed_rows rows;
    uint64_t failed = 0;
    uint32_t* global;
    int i;
    (void)state;
    make_meshes(meshes);
    for (i = 0; i < MESHES; ++i) densities[i] = 2.0;
    densities[1] = -1.0;
    pack(&set, meshes, POLYMASS_POSITION_FLOAT64, POLYMASS_INDEX_UINT32, POLYMASS_INDICES_GLOBAL);
    set.meshes.mass_values = densities;
    global = set.indices;
    global[set.index_offsets[2] + 4] = (uint32_t)set.vertex_offsets[3];     /* the next mesh's */
    global[set.index_offsets[3] + 7] = (uint32_t)set.vertex_offsets[3] - 1; /* below its first */
    /* Mesh 5 has no faces; mesh 6 has 5's too, outside its own vertices. */
    set.index_offsets[6] = set.index_offsets[5];
    rows_init(&rows);
    PM_ASSERT_OK(ctx, polymass_packed_compute(&rows.results, &failed, ctx, &set.meshes, NULL));
    assert_int_equal(rows.status[1], POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(rows.messages + 1 * POLYMASS_BATCH_MESSAGE_SIZE, "density"));
    assert_int_equal(rows.status[2], POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    assert_int_equal(rows.status[3], POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    assert_int_equal(rows.status[OPEN_MESH], POLYMASS_ERROR_OPEN);
    assert_int_equal(rows.status[5], POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(rows.messages + 5 * POLYMASS_BATCH_MESSAGE_SIZE, "no faces"));
    assert_int_equal(rows.status[6], POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    assert_int_equal(failed, 6);
    {
        /* The index named as written, with the mesh's own vertices. */
        char expected[POLYMASS_BATCH_MESSAGE_SIZE];
        snprintf(expected, sizeof expected,
                 "face 1 refers to vertex %u, but the mesh's %u vertices start at %u",
                 (unsigned)set.vertex_offsets[3], (unsigned)meshes[2].vertex_count,
                 (unsigned)set.vertex_offsets[2]);
        assert_non_null(strstr(rows.messages + 2 * POLYMASS_BATCH_MESSAGE_SIZE, expected));
        snprintf(expected, sizeof expected,
                 "face 2 refers to vertex %u, but the mesh's %u vertices start at %u",
                 (unsigned)set.vertex_offsets[3] - 1, (unsigned)meshes[3].vertex_count,
                 (unsigned)set.vertex_offsets[3]);
        assert_non_null(strstr(rows.messages + 3 * POLYMASS_BATCH_MESSAGE_SIZE, expected));
    }
    for (i = 0; i < MESHES; ++i) {
        polymass_mass_desc mass = pm_mass_density(densities[i]);
        if (i == 2 || i == 3 || i == 5 || i == 6) continue; /* nothing single to compare */
        assert_row_is_single_call(&rows, i, ctx, &set.descs[i], NULL, &mass);
    }
    pack_free(&set);
    for (i = 0; i < MESHES; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(ctx);
}

/* 64-bit indices outside the mesh's vertices (a negative int64, one below
   the first vertex, one 2^32 past it, one past 2^32 but within 32 bits of
   the first vertex) fail their own mesh, named as written; the other meshes are answered as single
   calls. */
static void test_packed_64_bit_indices_out_of_range(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh meshes[MESHES];
    packed_set set;
    packed_rows rows;
    uint64_t failed = 0;
    uint64_t* global;
    int i;
    (void)state;
    make_meshes(meshes);
    pack(&set, meshes, POLYMASS_POSITION_FLOAT64, POLYMASS_INDEX_UINT64, POLYMASS_INDICES_GLOBAL);
    global = set.indices;
    global[set.index_offsets[1] + 5] = (uint64_t)-1;                         /* int64 -1 */
    global[set.index_offsets[2] + 4] = set.vertex_offsets[2] - 1;            /* below its first */
    global[set.index_offsets[3] + 7] = set.vertex_offsets[3] + (1ull << 32); /* 2^32 past it */
    global[set.index_offsets[5] + 3] = (1ull << 32) + 5; /* past 2^32, 32 bits from its first */
    rows_init(&rows);
    PM_ASSERT_OK(ctx, polymass_packed_compute(&rows.results, &failed, ctx, &set.meshes, NULL));
    for (i = 1; i <= 5; ++i)
        if (i != OPEN_MESH) assert_int_equal(rows.status[i], POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    assert_int_equal(failed, 5); /* and the open mesh */
    {
        char expected[POLYMASS_BATCH_MESSAGE_SIZE];
        snprintf(expected, sizeof expected, "face 1 refers to vertex %llu, beyond the mesh's",
                 (unsigned long long)UINT64_MAX);
        assert_non_null(strstr(rows.messages + 1 * POLYMASS_BATCH_MESSAGE_SIZE, expected));
        snprintf(expected, sizeof expected, "face 1 refers to vertex %llu",
                 (unsigned long long)set.vertex_offsets[2] - 1);
        assert_non_null(strstr(rows.messages + 2 * POLYMASS_BATCH_MESSAGE_SIZE, expected));
        snprintf(expected, sizeof expected, "face 2 refers to vertex %llu",
                 (unsigned long long)(set.vertex_offsets[3] + (1ull << 32)));
        assert_non_null(strstr(rows.messages + 3 * POLYMASS_BATCH_MESSAGE_SIZE, expected));
        snprintf(expected, sizeof expected, "face 1 refers to vertex %llu",
                 (unsigned long long)((1ull << 32) + 5));
        assert_non_null(strstr(rows.messages + 5 * POLYMASS_BATCH_MESSAGE_SIZE, expected));
    }
    for (i = 0; i < MESHES; ++i) {
        if (i >= 1 && i <= 5) continue;
        assert_row_is_single_call(&rows, i, ctx, &set.descs[i], NULL, NULL);
    }
    pack_free(&set);
    for (i = 0; i < MESHES; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(ctx);
}

/* Columns not wanted are NULL; with none at all, the call still counts the
   meshes that failed. */
static void test_packed_columns_may_be_null(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh meshes[MESHES];
    packed_set set;
    packed_rows rows;
    polymass_packed_results only_volume = POLYMASS_PACKED_RESULTS_INIT;
    polymass_packed_results none = POLYMASS_PACKED_RESULTS_INIT;
    double volume[MESHES];
    uint64_t failed = 0;
    int i;
    (void)state;
    make_meshes(meshes);
    pack(&set, meshes, POLYMASS_POSITION_FLOAT32, POLYMASS_INDEX_UINT16, POLYMASS_INDICES_LOCAL);
    rows_init(&rows);
    PM_ASSERT_OK(ctx, polymass_packed_compute(&rows.results, NULL, ctx, &set.meshes, NULL));
    only_volume.volume = volume;
    PM_ASSERT_OK(ctx, polymass_packed_compute(&only_volume, &failed, ctx, &set.meshes, NULL));
    assert_int_equal(failed, 1);
    assert_memory_equal(volume, rows.volume, sizeof volume);
    failed = 0;
    PM_ASSERT_OK(ctx, polymass_packed_compute(&none, &failed, ctx, &set.meshes, NULL));
    assert_int_equal(failed, 1);
    pack_free(&set);
    for (i = 0; i < MESHES; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(ctx);
}

/* What keeps the set from running: the call's status, nothing written. */
static void assert_refused(polymass_context* ctx, const polymass_packed_meshes* meshes,
                           const char* mentioned) {
    packed_rows rows;
    uint64_t failed = 99;
    rows_init(&rows);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_packed_compute(&rows.results, &failed, ctx, meshes, NULL));
    assert_int_equal(failed, 0);
    assert_non_null(strstr(polymass_context_message(ctx), mentioned));
    assert_int_equal(rows.status[0], 0x5a5a5a5a); /* untouched */
}

static void test_packed_refuses_bad_sets(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh meshes[MESHES];
    packed_set set;
    polymass_packed_meshes bad;
    packed_rows rows;
    polymass_options bad_options = pm_options(0, 0.0);
    uint64_t failed = 99;
    int i;
    (void)state;
    make_meshes(meshes);
    pack(&set, meshes, POLYMASS_POSITION_FLOAT64, POLYMASS_INDEX_UINT32, POLYMASS_INDICES_LOCAL);
    rows_init(&rows);
    assert_int_equal(polymass_packed_compute(&rows.results, NULL, NULL, &set.meshes, NULL),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_packed_compute(NULL, &failed, ctx, &set.meshes, NULL));
    assert_int_equal(failed, 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_packed_compute(&rows.results, NULL, ctx, NULL, NULL));
    rows.results.struct_size = 8;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_packed_compute(&rows.results, NULL, ctx, &set.meshes, NULL));
    rows_init(&rows);
    rows.results.reserved = 1;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_packed_compute(&rows.results, NULL, ctx, &set.meshes, NULL));
    bad_options.struct_size = 3;
    rows_init(&rows);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_packed_compute(&rows.results, NULL, ctx, &set.meshes, &bad_options));

#define REFUSED(change, mentioned)            \
    do {                                      \
        bad = set.meshes;                     \
        change;                               \
        assert_refused(ctx, &bad, mentioned); \
    } while (0)
    REFUSED(bad.struct_size = 4, "struct_size");
    REFUSED(bad.reserved = 2, "reserved");
    REFUSED(bad.index_base = 2, "index_base");
    REFUSED(bad.mass_mode = 2, "mass_mode");
    REFUSED(bad.index_type = 7, "index_type");
    REFUSED(bad.position_type = 9, "position_type");
    REFUSED(bad.position_stride = 8, "position_stride");
    REFUSED(bad.positions = NULL, "positions");
    REFUSED(bad.indices = NULL, "indices");
    REFUSED(bad.vertex_offsets = NULL, "vertex_offsets");
    REFUSED(bad.index_offsets = NULL, "index_offsets");
    REFUSED(bad.mesh_count = UINT64_MAX, "mesh_count");
#undef REFUSED
    /* Offsets that do not start at 0, do not ascend, or cut a triangle. */
    set.vertex_offsets[0] = 1;
    assert_refused(ctx, &set.meshes, "vertex_offsets[0]");
    set.vertex_offsets[0] = 0;
    {
        const uint64_t kept = set.vertex_offsets[3];
        set.vertex_offsets[3] = set.vertex_offsets[4] + 1;
        assert_refused(ctx, &set.meshes, "vertex_offsets[4]");
        set.vertex_offsets[3] = kept;
    }
    set.index_offsets[0] = 3;
    assert_refused(ctx, &set.meshes, "index_offsets[0]");
    set.index_offsets[0] = 0;
    set.index_offsets[2] += 1;
    assert_refused(ctx, &set.meshes, "not a multiple of 3");
    set.index_offsets[2] -= 1;
    set.index_offsets[MESHES] -= 2;
    assert_refused(ctx, &set.meshes, "not a multiple of 3");
    set.index_offsets[MESHES] -= 1;
    set.index_offsets[MESHES - 1] = set.index_offsets[MESHES] + 3;
    assert_refused(ctx, &set.meshes, "ascend");
    pack_free(&set);

    /* No mesh at all: nothing to do. */
    {
        const uint64_t zero = 0;
        polymass_packed_meshes empty = POLYMASS_PACKED_MESHES_INIT;
        empty.vertex_offsets = &zero;
        empty.index_offsets = &zero;
        failed = 99;
        rows_init(&rows);
        PM_ASSERT_OK(ctx, polymass_packed_compute(&rows.results, &failed, ctx, &empty, NULL));
        assert_int_equal(failed, 0);
    }
    for (i = 0; i < MESHES; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(ctx);
}

static void test_packed_struct_sizes_and_defaults(void** state) {
    const polymass_packed_meshes meshes_init = POLYMASS_PACKED_MESHES_INIT;
    const polymass_packed_results results_init = POLYMASS_PACKED_RESULTS_INIT;
    polymass_packed_meshes meshes;
    polymass_packed_results results;
    (void)state;
    assert_int_equal(polymass_sizeof_packed_meshes(), sizeof(polymass_packed_meshes));
    assert_int_equal(polymass_sizeof_packed_results(), sizeof(polymass_packed_results));
    memset(&meshes, 0xff, sizeof meshes);
    memset(&results, 0xff, sizeof results);
    assert_int_equal(polymass_packed_meshes_init(&meshes, sizeof meshes), POLYMASS_OK);
    assert_int_equal(polymass_packed_results_init(&results, sizeof results), POLYMASS_OK);
    assert_memory_equal(&meshes, &meshes_init, sizeof meshes);
    assert_memory_equal(&results, &results_init, sizeof results);
    assert_int_equal(meshes.index_base, POLYMASS_INDICES_LOCAL);
    assert_int_equal(meshes.mass_mode, POLYMASS_MASS_FROM_DENSITY);
    assert_int_equal(polymass_packed_meshes_init(&meshes, 3), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_int_equal(polymass_packed_results_init(NULL, sizeof results),
                     POLYMASS_ERROR_INVALID_ARGUMENT);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_packed_matches_single_calls),
        cmocka_unit_test(test_packed_options_apply_to_every_mesh),
        cmocka_unit_test(test_packed_failures_are_the_meshes_own),
        cmocka_unit_test(test_packed_64_bit_indices_out_of_range),
        cmocka_unit_test(test_packed_columns_may_be_null),
        cmocka_unit_test(test_packed_refuses_bad_sets),
        cmocka_unit_test(test_packed_struct_sizes_and_defaults),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
