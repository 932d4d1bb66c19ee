/* The caller's allocator: every allocation goes through it and is freed,
 * alignment is honoured, and an allocation failure anywhere gives
 * POLYMASS_ERROR_OUT_OF_MEMORY without a leak or a crash. */
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------------ */
/* A counting, optionally failing allocator                                 */
/* ------------------------------------------------------------------------ */

typedef struct counting_allocator {
    size_t allocations; /* calls to allocate, failed or not */
    size_t deallocations;
    size_t injected_failures;
    size_t bad_alignment_requests; /* alignment not a power of two */
    size_t misaligned_results;
    size_t bad_frees; /* pointers allocate did not return (or freed twice) */
    size_t max_alignment;
    long fail_at;   /* index of the allocation that fails; -1: none */
    int fail_after; /* if set, every allocation from fail_at on fails */
    void** live;
    size_t live_count;
    size_t live_capacity;
} counting_allocator;

static void* counting_allocate(void* user_data, size_t size, size_t alignment) {
    counting_allocator* a = user_data;
    const long index = (long)a->allocations++;
    void* p = NULL;
    size_t align = alignment;
    if (alignment == 0 || (alignment & (alignment - 1)) != 0) {
        a->bad_alignment_requests++;
        align = 16;
        alignment = 1; /* nothing to check the result against */
    }
    if (align > a->max_alignment) {
        a->max_alignment = align;
    }
    if (a->fail_at >= 0 && (index == a->fail_at || (a->fail_after && index > a->fail_at))) {
        a->injected_failures++;
        return NULL;
    }
    if (align < sizeof(void*)) {
        align = sizeof(void*);
    }
    if (posix_memalign(&p, align, size ? size : 1) != 0) {
        return NULL;
    }
    if (((uintptr_t)p & (alignment - 1)) != 0) {
        a->misaligned_results++;
    }
    /* scribble: the library must not rely on zeroed memory */
    memset(p, 0xA5, size);
    if (a->live_count == a->live_capacity) {
        a->live_capacity = a->live_capacity ? 2 * a->live_capacity : 64;
        a->live = realloc(a->live, a->live_capacity * sizeof *a->live);
        if (a->live == NULL) {
            abort();
        }
    }
    a->live[a->live_count++] = p;
    return p;
}

static void counting_deallocate(void* user_data, void* pointer) {
    counting_allocator* a = user_data;
    size_t i;
    a->deallocations++;
    if (pointer == NULL) {
        return;
    }
    for (i = 0; i < a->live_count; ++i) {
        if (a->live[i] == pointer) {
            a->live[i] = a->live[--a->live_count];
            free(pointer);
            return;
        }
    }
    a->bad_frees++;
}

static void counting_init(counting_allocator* a, long fail_at, int fail_after) {
    memset(a, 0, sizeof *a);
    a->fail_at = fail_at;
    a->fail_after = fail_after;
}

static polymass_allocator counting_interface(counting_allocator* a) {
    polymass_allocator alloc;
    assert_int_equal(polymass_allocator_init(&alloc, sizeof alloc), POLYMASS_OK);
    alloc.allocate = counting_allocate;
    alloc.deallocate = counting_deallocate;
    alloc.user_data = a;
    return alloc;
}

/* Nothing leaked, nothing freed twice or foreign, alignment honoured. */
static void assert_clean(const counting_allocator* a, const char* what) {
    if (a->live_count != 0 || a->bad_frees != 0 || a->bad_alignment_requests != 0 ||
        a->misaligned_results != 0) {
        print_error(
            "%s (fail_at %ld%s): %zu allocations, %zu still live, %zu bad frees, "
            "%zu bad alignment requests, %zu misaligned\n",
            what, a->fail_at, a->fail_after ? " and after" : "", a->allocations, a->live_count,
            a->bad_frees, a->bad_alignment_requests, a->misaligned_results);
        fail();
    }
}

static void counting_release(counting_allocator* a) {
    size_t i;
    for (i = 0; i < a->live_count; ++i) {
        free(a->live[i]);
    }
    free(a->live);
    a->live = NULL;
}

/* ------------------------------------------------------------------------ */
/* A scenario touching every allocating entry point                         */
/* ------------------------------------------------------------------------ */

enum { STEP_COUNT = 8 };

typedef struct scenario_result {
    int32_t status[STEP_COUNT];
    polymass_mass_properties props[2];
    polymass_diagnostics diag;
    polymass_polygon_properties polygon;
} scenario_result;

typedef struct scenario_input {
    pm_mesh soup;      /* a torus triangle soup: needs welding */
    pm_mesh star;      /* polygon faces */
    pm_mesh open_cube; /* an error with a message */
} scenario_input;

static void scenario_input_init(scenario_input* in) {
    pm_mesh_from_reference(&in->soup, &pm_reference_solids[PM_REF_TORUS_TRIS]);
    pm_mesh_to_soup(&in->soup);
    pm_mesh_from_reference(&in->star, &pm_reference_solids[PM_REF_PRISM_STAR]);
    pm_mesh_unit_cube(&in->open_cube, 0);
    pm_mesh_remove_face(&in->open_cube, 2);
}

static void scenario_input_free(scenario_input* in) {
    pm_mesh_free(&in->soup);
    pm_mesh_free(&in->star);
    pm_mesh_free(&in->open_cube);
}

/* Runs every step it can; a step that cannot run (no context, no mesh) gets
   status -1. Returns with everything destroyed. */
static void run_scenario(const scenario_input* in, counting_allocator* a, scenario_result* r) {
    static const double hexagon[12] = {2, 0, 1, 1.75, -1, 1.75, -2, 0, -1, -1.75, 1, -1.75};
    polymass_allocator alloc = counting_interface(a);
    polymass_context* ctx = (polymass_context*)&alloc; /* garbage: must be overwritten */
    polymass_mesh* mesh = NULL;
    polymass_options o;
    int i;
    memset(r, 0, sizeof *r);
    for (i = 0; i < STEP_COUNT; ++i) {
        r->status[i] = -1;
    }
    r->status[0] = polymass_context_create(&ctx, &alloc);
    if (r->status[0] != POLYMASS_OK) {
        assert_null(ctx);
        return;
    }
    o = pm_options(POLYMASS_OPTION_WELD_VERTICES, 0.0);
    /* Nothing kept between calls: every block goes back to the allocator. */
    r->status[1] = polymass_context_set_scratch_limit(ctx, 0);
    {
        const polymass_mesh_desc d = pm_mesh_desc(&in->soup);
        mesh = (polymass_mesh*)&alloc;
        r->status[2] = polymass_mesh_create(&mesh, ctx, &d, &o);
        if (r->status[2] != POLYMASS_OK) {
            assert_null(mesh);
        }
    }
    if (mesh) {
        pm_props_init(&r->props[0]);
        r->status[3] = polymass_mesh_mass_properties(&r->props[0], ctx, mesh, NULL);
        polymass_mesh_destroy(mesh);
    }
    {
        const polymass_mesh_desc d = pm_mesh_desc(&in->star);
        pm_props_init(&r->props[1]);
        r->status[4] = polymass_mass_properties_compute(&r->props[1], NULL, ctx, &d, NULL, NULL);
    }
    {
        const polymass_mesh_desc d = pm_mesh_desc(&in->soup);
        pm_diagnostics_init(&r->diag);
        r->status[5] = pm_diagnose(&r->diag, ctx, &d, &o);
    }
    {
        const polymass_mesh_desc d = pm_mesh_desc(&in->open_cube);
        polymass_mass_properties p;
        pm_props_init(&p);
        r->status[6] = polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL);
        assert_true(strlen(polymass_context_message(ctx)) > 0);
    }
    pm_polygon_props_init(&r->polygon);
    r->status[7] = polymass_polygon_compute(&r->polygon, ctx, hexagon, 6, 0);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Tests                                                                    */
/* ------------------------------------------------------------------------ */

static void test_counting_allocator(void** state) {
    scenario_input in;
    scenario_result r, plain;
    counting_allocator a;
    int i;
    (void)state;
    scenario_input_init(&in);
    counting_init(&a, -1, 0);
    run_scenario(&in, &a, &r);
    assert_clean(&a, "full scenario");
    /* the context at least is made through it */
    assert_true(a.allocations >= 2);
    assert_int_equal(a.allocations, a.deallocations);
    assert_true(a.max_alignment >= 8);
    for (i = 0; i < STEP_COUNT; ++i) {
        if (i == 6) {
            PM_ASSERT_STATUS(NULL, POLYMASS_ERROR_OPEN, r.status[i]);
        } else {
            PM_ASSERT_STATUS(NULL, POLYMASS_OK, r.status[i]);
        }
    }
    {
        const pm_expected e = pm_expected_from_reference(&pm_reference_solids[PM_REF_TORUS_TRIS]);
        PM_ASSERT_PROPERTIES("welded torus through the counting allocator", &e, &r.props[0],
                             PM_TOL);
    }
    assert_int_equal(r.diag.used_vertex_count, pm_reference_solids[PM_REF_TORUS_TRIS].vertex_count);
    counting_release(&a);

    /* the same results as with malloc (NULL allocator) */
    {
        polymass_context* ctx = pm_context_new();
        PM_ASSERT_OK(ctx, pm_compute_flags(&plain.props[0], ctx, &in.soup,
                                           POLYMASS_OPTION_WELD_VERTICES, NULL));
        PM_ASSERT_SAME_PROPERTIES("custom allocator vs malloc", &plain.props[0], &r.props[0]);
        polymass_context_destroy(ctx);
    }
    scenario_input_free(&in);
}

/* The allocator struct is copied: the caller's copy may go away. */
static void test_allocator_is_copied(void** state) {
    counting_allocator a;
    polymass_allocator* alloc = malloc(sizeof *alloc);
    polymass_context* ctx = NULL;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    counting_init(&a, -1, 0);
    assert_non_null(alloc);
    *alloc = counting_interface(&a);
    assert_int_equal(polymass_context_create(&ctx, alloc), POLYMASS_OK);
    memset(alloc, 0, sizeof *alloc);
    free(alloc);
    pm_mesh_from_reference(&m, &pm_reference_solids[PM_REF_HOUSE]);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    polymass_context_destroy(ctx);
    assert_true(a.allocations >= 1);
    assert_clean(&a, "copied allocator");
    pm_mesh_free(&m);
    counting_release(&a);
}

/* An allocator with one function of two, an unknown struct_size or reserved
   bits is a caller error; one with neither function means malloc. */
static void test_incomplete_allocator(void** state) {
    counting_allocator a;
    polymass_allocator alloc;
    polymass_context* ctx = NULL;
    (void)state;
    counting_init(&a, -1, 0);
    alloc = counting_interface(&a);
    alloc.allocate = NULL;
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_null(ctx);
    alloc = counting_interface(&a);
    alloc.deallocate = NULL;
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_null(ctx);
    alloc = counting_interface(&a);
    alloc.struct_size = sizeof alloc + 8;
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_null(ctx);
    alloc = counting_interface(&a);
    alloc.reserved = 1;
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_null(ctx);
    assert_int_equal(a.allocations, 0);
    assert_int_equal(polymass_allocator_init(&alloc, sizeof alloc), POLYMASS_OK);
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_OK);
    assert_non_null(ctx);
    polymass_context_destroy(ctx);
    assert_int_equal(a.live_count, 0);
    counting_release(&a);
}

/* A mesh made through a context keeps using (and frees through) that
   context's allocator after the context is gone. */
static void test_mesh_outlives_context_with_allocator(void** state) {
    counting_allocator a;
    polymass_allocator alloc;
    polymass_context* maker = NULL;
    polymass_context* reader = pm_context_new();
    polymass_mesh* mesh = NULL;
    polymass_mass_properties p;
    const polymass_mesh_desc d = pm_reference_desc(&pm_reference_solids[PM_REF_CUBE_CAVITY]);
    (void)state;
    counting_init(&a, -1, 0);
    alloc = counting_interface(&a);
    assert_int_equal(polymass_context_create(&maker, &alloc), POLYMASS_OK);
    PM_ASSERT_OK(maker, polymass_mesh_create(&mesh, maker, &d, NULL));
    polymass_context_destroy(maker);
    assert_true(a.live_count >= 1); /* the mesh */
    pm_props_init(&p);
    PM_ASSERT_OK(reader, polymass_mesh_mass_properties(&p, reader, mesh, NULL));
    PM_ASSERT_REL("volume", pm_reference_solids[PM_REF_CUBE_CAVITY].volume, p.volume, PM_TOL);
    polymass_mesh_destroy(mesh);
    assert_clean(&a, "mesh outliving its context");
    polymass_context_destroy(reader);
    counting_release(&a);
}

/* Fail allocation N (alone, or N and every later one) for every N up to what
   the scenario needs: each step either does what it did without failures or
   reports OUT_OF_MEMORY, never leaks, never crashes. */
static void run_failure_sweep(int fail_after) {
    scenario_input in;
    scenario_result normal, r;
    counting_allocator a;
    size_t needed;
    long n;
    int i, saw_oom = 0;
    scenario_input_init(&in);
    counting_init(&a, -1, 0);
    run_scenario(&in, &a, &normal);
    needed = a.allocations;
    assert_clean(&a, "reference run");
    counting_release(&a);
    assert_true(needed >= 2);
    for (n = 0; n <= (long)needed; ++n) {
        counting_init(&a, n, fail_after);
        run_scenario(&in, &a, &r);
        assert_clean(&a, "failure sweep");
        for (i = 0; i < STEP_COUNT; ++i) {
            if (r.status[i] == POLYMASS_ERROR_OUT_OF_MEMORY) {
                saw_oom = 1;
                continue;
            }
            if (r.status[i] == -1) { /* not run: no context, or no mesh */
                assert_true(i >= 1);
                continue;
            }
            if (r.status[i] != normal.status[i]) {
                print_error(
                    "fail_at %ld%s: step %d returned %d (%s), expected %d or OUT_OF_MEMORY\n", n,
                    fail_after ? " and after" : "", i, (int)r.status[i],
                    polymass_status_string(r.status[i]), (int)normal.status[i]);
                fail();
            }
        }
        /* what succeeded is right */
        if (r.status[3] == POLYMASS_OK) {
            PM_ASSERT_SAME_PROPERTIES("mesh after injected failures", &normal.props[0],
                                      &r.props[0]);
        }
        if (r.status[4] == POLYMASS_OK) {
            PM_ASSERT_SAME_PROPERTIES("compute after injected failures", &normal.props[1],
                                      &r.props[1]);
        }
        if (r.status[5] == POLYMASS_OK) {
            assert_int_equal(r.diag.edge_count, normal.diag.edge_count);
            assert_int_equal(r.diag.used_vertex_count, normal.diag.used_vertex_count);
        }
        if (r.status[7] == POLYMASS_OK) {
            PM_ASSERT_SAME("polygon area", normal.polygon.area, r.polygon.area);
        }
        /* past the need, nothing fails */
        if ((size_t)n >= needed) {
            assert_int_equal(a.injected_failures, 0);
            for (i = 0; i < STEP_COUNT; ++i) {
                assert_int_equal(r.status[i], normal.status[i]);
            }
        }
        counting_release(&a);
    }
    /* failing the very first allocation fails context creation */
    assert_true(saw_oom);
    scenario_input_free(&in);
}

static void test_fail_nth_allocation(void** state) {
    (void)state;
    run_failure_sweep(0);
}

static void test_fail_from_nth_allocation_on(void** state) {
    (void)state;
    run_failure_sweep(1);
}

/* Context creation with the first allocation failing. */
static void test_context_create_out_of_memory(void** state) {
    counting_allocator a;
    polymass_allocator alloc;
    polymass_context* ctx = (polymass_context*)&a;
    (void)state;
    counting_init(&a, 0, 1);
    alloc = counting_interface(&a);
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_ERROR_OUT_OF_MEMORY);
    assert_null(ctx);
    assert_true(a.injected_failures >= 1);
    assert_clean(&a, "context creation");
    counting_release(&a);
}

/* An out-of-memory failure through a live context leaves a message. */
static void test_out_of_memory_message(void** state) {
    counting_allocator a;
    polymass_allocator alloc;
    polymass_context* ctx = NULL;
    polymass_mesh* mesh = (polymass_mesh*)&a;
    const polymass_mesh_desc d = pm_reference_desc(&pm_reference_solids[PM_REF_TORUS_TRIS]);
    (void)state;
    counting_init(&a, -1, 0);
    alloc = counting_interface(&a);
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_OK);
    a.fail_at = (long)a.allocations; /* everything from now on */
    a.fail_after = 1;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OUT_OF_MEMORY, polymass_mesh_create(&mesh, ctx, &d, NULL));
    assert_null(mesh);
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    assert_true(a.injected_failures >= 1);
    polymass_context_destroy(ctx);
    assert_clean(&a, "out of memory in mesh_create");
    counting_release(&a);
}

/* The context keeps its large scratch blocks for the next call (no new
   memory from the allocator for them), within the limit it is given, and
   frees them when destroyed; the results do not change. */
static void test_context_keeps_scratch(void** state) {
    static const double centre[3] = {1e3, 0, 0};
    counting_allocator a;
    polymass_allocator alloc;
    polymass_context* ctx = NULL;
    pm_mesh m;
    polymass_mesh_desc d;
    polymass_mass_properties first, p;
    size_t before, first_call, later_call, unkept_call;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 200, 100, 10.0, 3.0, centre); /* 40,000 triangles */
    d = pm_mesh_desc(&m);
    counting_init(&a, -1, 0);
    alloc = counting_interface(&a);
    assert_int_equal(polymass_context_create(&ctx, &alloc), POLYMASS_OK);
    pm_props_init(&first);
    before = a.allocations;
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&first, NULL, ctx, &d, NULL, NULL));
    first_call = a.allocations - before;
    pm_props_init(&p);
    before = a.allocations;
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));
    later_call = a.allocations - before;
    assert_memory_equal(&first, &p, sizeof p);
    assert_true(later_call < first_call);
    assert_true(a.live_count > 1); /* the context and its kept blocks */
    /* nothing kept: every call allocates all it needs */
    PM_ASSERT_OK(ctx, polymass_context_set_scratch_limit(ctx, 0));
    assert_int_equal(a.live_count, 1); /* the context alone */
    before = a.allocations;
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));
    unkept_call = a.allocations - before;
    assert_true(unkept_call >= first_call && unkept_call > later_call);
    assert_int_equal(a.live_count, 1);
    assert_memory_equal(&first, &p, sizeof p);
    PM_ASSERT_OK(ctx, polymass_context_set_scratch_limit(ctx, UINT64_MAX));
    PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));
    polymass_context_destroy(ctx);
    assert_clean(&a, "kept scratch");
    assert_int_equal(polymass_context_set_scratch_limit(NULL, 0), POLYMASS_ERROR_INVALID_ARGUMENT);
    pm_mesh_free(&m);
    counting_release(&a);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counting_allocator),
        cmocka_unit_test(test_allocator_is_copied),
        cmocka_unit_test(test_incomplete_allocator),
        cmocka_unit_test(test_mesh_outlives_context_with_allocator),
        cmocka_unit_test(test_context_keeps_scratch),
        cmocka_unit_test(test_context_create_out_of_memory),
        cmocka_unit_test(test_out_of_memory_message),
        cmocka_unit_test(test_fail_nth_allocation),
        cmocka_unit_test(test_fail_from_nth_allocation_on),
    };
    return cmocka_run_group_tests_name("allocator", tests, NULL, NULL);
}
