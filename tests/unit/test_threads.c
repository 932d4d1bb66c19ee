/* "A mesh is immutable once created: any number of threads may read it at
 * once, each through its own context"; distinct contexts are independent.
 * The library's own threads (polymass_options.threads): every count gives
 * the same bits, for one large mesh and for a batch. */
#include "test_support.h"

#include <pthread.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

enum { THREADS = 4, ROUNDS = 200 };

typedef struct reader {
    const polymass_mesh* mesh;
    const polymass_mesh_desc* desc; /* for compute/check from each thread */
    polymass_mass_properties first;
    int failures;
} reader;

static void* read_mesh(void* arg) {
    reader* r = arg;
    polymass_context* ctx = NULL;
    polymass_mass_desc md;
    int round;
    if (polymass_context_create(&ctx, NULL) != POLYMASS_OK) {
        r->failures++;
        return NULL;
    }
    md = pm_mass_density(1.0);
    for (round = 0; round < ROUNDS; ++round) {
        polymass_mass_properties p;
        pm_props_init(&p);
        if (polymass_mesh_mass_properties(&p, ctx, r->mesh, &md) != POLYMASS_OK) {
            r->failures++;
            continue;
        }
        if (round == 0) {
            r->first = p;
        } else if (memcmp(&p, &r->first, sizeof p) != 0) {
            r->failures++;
        }
        if (round % 50 == 0) {
            polymass_diagnostics d;
            pm_props_init(&p);
            if (polymass_mass_properties_compute(&p, NULL, ctx, r->desc, NULL, NULL) !=
                POLYMASS_OK) {
                r->failures++;
            }
            pm_diagnostics_init(&d);
            if (pm_diagnose(&d, ctx, r->desc, NULL) != POLYMASS_OK) {
                r->failures++;
            }
        }
    }
    polymass_context_destroy(ctx);
    return NULL;
}

static void test_concurrent_readers(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TORUS_TRIS];
    const polymass_mesh_desc desc = pm_reference_desc(ref);
    polymass_context* ctx = pm_context_new();
    polymass_mesh* mesh = NULL;
    polymass_mass_properties expected;
    pthread_t threads[THREADS];
    reader readers[THREADS];
    int i;
    (void)state;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc, NULL));
    pm_props_init(&expected);
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&expected, ctx, mesh, NULL));
    for (i = 0; i < THREADS; ++i) {
        memset(&readers[i], 0, sizeof readers[i]);
        readers[i].mesh = mesh;
        readers[i].desc = &desc;
        assert_int_equal(pthread_create(&threads[i], NULL, read_mesh, &readers[i]), 0);
    }
    for (i = 0; i < THREADS; ++i) {
        assert_int_equal(pthread_join(threads[i], NULL), 0);
    }
    for (i = 0; i < THREADS; ++i) {
        assert_int_equal(readers[i].failures, 0);
        PM_ASSERT_SAME_PROPERTIES("a reader thread", &expected, &readers[i].first);
    }
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(ctx);
}

/* A failure in one context leaves another context's message alone. */
static void test_contexts_are_independent(void** state) {
    polymass_context* a = pm_context_new();
    polymass_context* b = pm_context_new();
    pm_mesh m;
    polymass_mass_properties p;
    (void)state;
    pm_mesh_from_reference(&m, &pm_reference_solids[PM_REF_HOUSE]);
    pm_mesh_reverse_all(&m);
    PM_ASSERT_OK(b, pm_compute_flags(&p, b, &m, POLYMASS_OPTION_ACCEPT_INVERTED, NULL));
    PM_ASSERT_STATUS(a, POLYMASS_ERROR_INVERTED, pm_compute(&p, a, &m, NULL));
    assert_true(strlen(polymass_context_message(a)) > 0);
    assert_string_equal(polymass_context_message(b), "");
    PM_ASSERT_OK(b, polymass_context_set_threads(b, 2));
    PM_ASSERT_STATUS(a, POLYMASS_ERROR_INVERTED, pm_compute(&p, a, &m, NULL));
    PM_ASSERT_OK(b, pm_compute_flags(&p, b, &m, POLYMASS_OPTION_ACCEPT_INVERTED, NULL));
    assert_true(strlen(polymass_context_message(a)) > 0);
    pm_mesh_free(&m);
    polymass_context_destroy(a);
    polymass_context_destroy(b);
}

/* ------------------------------------------------------------------------ */
/* The library's workers                                                    */
/* ------------------------------------------------------------------------ */

static const uint32_t thread_counts[] = {1, 2, 3, 4, 7};
enum { THREAD_COUNTS = sizeof thread_counts / sizeof thread_counts[0] };

/* The shell of each face, as a mesh made with the options gives it. */
static int32_t shell_of_each_face(polymass_context* ctx, const polymass_mesh_desc* desc,
                                  const polymass_options* options, uint32_t* shell_of_face,
                                  uint64_t face_count, uint64_t* shell_count) {
    polymass_mesh* mesh = NULL;
    (void)polymass_mesh_create(&mesh, ctx, desc, options);
    assert_non_null(mesh);
    PM_ASSERT_OK(ctx, polymass_mesh_shells(NULL, 0, shell_count, ctx, mesh));
    {
        const int32_t status = polymass_mesh_shell_of_face(shell_of_face, face_count, ctx, mesh);
        polymass_mesh_destroy(mesh);
        return status;
    }
}

/* The checked path (scan, topology, integration, the shell) bit for bit for
   every count, on a torus far from the origin: 302,400 triangles, several
   blocks of faces. */
static void test_thread_counts_give_the_same_bits(void** state) {
    static const double centre[3] = {3e6, -2e6, 1e6};
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    polymass_mesh_desc desc;
    polymass_mass_properties first, p;
    int k;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 420, 360, 10.0, 3.0, centre);
    desc = pm_mesh_desc(&m);
    assert_true(m.face_count >= 300000);
    for (k = 0; k < THREAD_COUNTS; ++k) {
        /* The integrals' bits; the intersection check's findings have their
           own test (test_thread_counts_give_the_same_overlaps). */
        const polymass_options o = pm_options(POLYMASS_OPTION_SKIP_INTERSECTION_CHECK, 0.0);
        PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, thread_counts[k]));
        pm_props_init(k == 0 ? &first : &p);
        PM_ASSERT_OK(ctx, polymass_mass_properties_compute(k == 0 ? &first : &p, NULL, ctx, &desc,
                                                           &o, NULL));
        if (k > 0) assert_memory_equal(&first, &p, sizeof p);
    }
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* A defective mesh of several blocks of faces and of vertices: the same
   findings, first locations and message, and the same shells, for every
   count. */
static void test_thread_counts_give_the_same_findings(void** state) {
    static const double centre[3] = {0, 0, 0};
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    polymass_mesh_desc desc;
    polymass_diagnostics first, report;
    char first_message[512];
    uint32_t *first_shells, *shells;
    uint64_t first_shell_count = 0, shell_count = 0;
    int k, face;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 350, 100, 10.0, 3.0, centre); /* 2 blocks of faces, of vertices */
    for (face = 69000; face > 0; face -= 6900) pm_mesh_remove_face(&m, (size_t)face);
    pm_mesh_reverse_face(&m, 123);
    pm_mesh_add_torus(&m, 20, 10, 4.0, 1.0, centre); /* a second shell */
    desc = pm_mesh_desc(&m);
    first_shells = calloc(m.face_count, sizeof *first_shells);
    shells = calloc(m.face_count, sizeof *shells);
    assert_non_null(first_shells);
    assert_non_null(shells);
    for (k = 0; k < THREAD_COUNTS; ++k) {
        /* The topology's findings, as above. */
        const polymass_options o = pm_options(POLYMASS_OPTION_SKIP_INTERSECTION_CHECK, 0.0);
        PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, thread_counts[k]));
        polymass_mass_properties p;
        pm_diagnostics_init(k == 0 ? &first : &report);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN,
                         pm_diagnose(k == 0 ? &first : &report, ctx, &desc, &o));
        pm_props_init(&p);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN,
                         polymass_mass_properties_compute(&p, NULL, ctx, &desc, &o, NULL));
        if (k == 0) {
            strcpy(first_message, polymass_context_message(ctx));
        } else {
            assert_memory_equal(&first, &report, sizeof report);
            assert_string_equal(first_message, polymass_context_message(ctx));
        }
        PM_ASSERT_OK(
            ctx, shell_of_each_face(ctx, &desc, &o, k == 0 ? first_shells : shells, m.face_count,
                                    k == 0 ? &first_shell_count : &shell_count));
        if (k > 0) {
            assert_int_equal(first_shell_count, shell_count);
            assert_memory_equal(first_shells, shells, m.face_count * sizeof *shells);
        }
    }
    assert_int_equal(first_shell_count, 2);
    free(first_shells);
    free(shells);
    assert_true(first.open_edges > 0 && first.misoriented_edges > 0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* The intersection check of `m` for every count: the same status,
   diagnostics (counts, first face pairs) and message as with one thread.
   Returns the one-thread diagnostics and message. */
static polymass_diagnostics overlaps_for_every_count(const pm_mesh* m, int32_t status,
                                                     char first_message[512]) {
    const polymass_mesh_desc desc = pm_mesh_desc(m);
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics first, report;
    int k;
    for (k = 0; k < THREAD_COUNTS; ++k) {
        const polymass_options o = pm_options(0, 0.0);
        PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, thread_counts[k]));
        pm_diagnostics_init(k == 0 ? &first : &report);
        PM_ASSERT_STATUS(ctx, status, pm_diagnose(k == 0 ? &first : &report, ctx, &desc, &o));
        if (k == 0) {
            strcpy(first_message, polymass_context_message(ctx));
        } else {
            assert_memory_equal(&first, &report, sizeof report);
            assert_string_equal(first_message, polymass_context_message(ctx));
        }
    }
    polymass_context_destroy(ctx);
    return first;
}

/* Faces that cross and faces that touch, found among many pieces of the
   search (14,424 triangles), all counted: the same findings for every count. */
static void test_thread_counts_give_the_same_overlaps(void** state) {
    static const double centre[3] = {0, 0, 0}, beside[3] = {10, 0, 0.5};
    static const double lo[3] = {30, 0, 0}, hi[3] = {31, 1, 1};
    static const double lo_above[3] = {30.25, 0.25, 1}, hi_above[3] = {30.75, 0.75, 2};
    pm_mesh m;
    polymass_diagnostics d;
    char message[512];
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 200, 30, 10.0, 3.0, centre);
    pm_mesh_add_torus(&m, 60, 20, 10.0, 3.0, beside); /* its tube crosses the first's twice */
    pm_mesh_add_box(&m, lo, hi, 1);
    pm_mesh_add_box(&m, lo_above, hi_above, 1); /* resting on the box: they touch */
    d = overlaps_for_every_count(&m, POLYMASS_ERROR_INTERSECTING, message);
    assert_true(d.intersecting_face_pairs > POLYMASS_DIAGNOSTIC_LOCATIONS);
    assert_true(d.touching_face_pairs > 0);
    assert_null(strstr(message, "at least"));
    pm_mesh_free(&m);
}

/* Piles past the count's stop: a torus and a copy of it moved a little
   (its faces cross their neighbours'), and a torus with a coincident copy
   (its faces touch): every kind stops at 2048 pairs, "at least", with the
   same lowest pairs for every count. */
static void test_thread_counts_give_the_same_piles(void** state) {
    static const double centre[3] = {0, 0, 0}, moved[3] = {0.05, 0.07, 0.11};
    static const double apart[3] = {40, 0, 0};
    pm_mesh m;
    polymass_diagnostics d;
    char message[512];
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 400, 12, 10.0, 3.0, centre);
    pm_mesh_add_torus(&m, 400, 12, 10.0, 3.0, moved);
    pm_mesh_add_torus(&m, 60, 20, 10.0, 3.0, apart);
    pm_mesh_add_torus(&m, 60, 20, 10.0, 3.0, apart);
    d = overlaps_for_every_count(&m, POLYMASS_ERROR_INTERSECTING, message);
    assert_non_null(strstr(message, "(at least 2048 "));
    assert_int_equal(d.intersecting_face_pairs, 2048);
    assert_int_equal(d.touching_face_pairs, 2048);
    pm_mesh_free(&m);
}

/* A batch spread over the context's threads: each item's status, message
   and properties as with one thread, whatever the items' own options. */
static void test_batch_thread_counts_give_the_same_bits(void** state) {
    enum { ITEMS = 13 };
    pm_mesh meshes[ITEMS];
    polymass_mesh_desc descs[ITEMS];
    polymass_mass_properties first[ITEMS], got[ITEMS];
    polymass_batch_item first_items[ITEMS], items[ITEMS];
    const polymass_options own = pm_options(POLYMASS_OPTION_ACCEPT_INVERTED, 0.0);
    int i, k;
    (void)state;
    for (i = 0; i < ITEMS; ++i) {
        pm_mesh_from_reference(&meshes[i], &pm_reference_solids[i % PM_REF_COUNT]);
        if (i == 3) pm_mesh_remove_face(&meshes[i], 0);        /* open: fails */
        if (i == 5 || i == 8) pm_mesh_reverse_all(&meshes[i]); /* inverted: 8 accepted */
        descs[i] = pm_mesh_desc(&meshes[i]);
    }
    for (k = 0; k < THREAD_COUNTS; ++k) {
        polymass_context* ctx = pm_context_new();
        polymass_batch_item* at = k == 0 ? first_items : items;
        polymass_mass_properties* props = k == 0 ? first : got;
        uint64_t failed = 99;
        PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, thread_counts[k]));
        for (i = 0; i < ITEMS; ++i) {
            assert_int_equal(polymass_batch_item_init(&at[i], sizeof at[i]), POLYMASS_OK);
            pm_props_init(&props[i]);
            at[i].desc = &descs[i];
            at[i].options = i == 8 ? &own : NULL;
            at[i].properties = &props[i];
        }
        PM_ASSERT_OK(ctx, polymass_batch_compute(at, ITEMS, &failed, ctx));
        assert_int_equal(failed, 2);
        for (i = 0; k > 0 && i < ITEMS; ++i) {
            assert_int_equal(items[i].status, first_items[i].status);
            assert_string_equal(items[i].message, first_items[i].message);
            assert_memory_equal(&got[i], &first[i], sizeof got[i]);
        }
        polymass_context_destroy(ctx);
    }
    assert_int_equal(first_items[3].status, POLYMASS_ERROR_OPEN);
    assert_int_equal(first_items[5].status, POLYMASS_ERROR_INVERTED);
    assert_int_equal(first_items[8].status, POLYMASS_OK);
    for (i = 0; i < ITEMS; ++i) pm_mesh_free(&meshes[i]);
}

/* The context's threads are checked and kept; more threads than the
   hardware has still give the answer. */
static void test_threads_of_a_context(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_mass_properties p;
    (void)state;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_context_set_threads(ctx, POLYMASS_MAX_THREADS + 1));
    assert_non_null(strstr(polymass_context_message(ctx), "threads is 257"));
    PM_ASSERT_OK(ctx, polymass_context_set_threads(ctx, POLYMASS_MAX_THREADS));
    PM_ASSERT_REFERENCE_COMPUTE(ctx, &pm_reference_solids[PM_REF_TORUS_TRIS], &p);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_concurrent_readers),
        cmocka_unit_test(test_contexts_are_independent),
        cmocka_unit_test(test_thread_counts_give_the_same_bits),
        cmocka_unit_test(test_thread_counts_give_the_same_findings),
        cmocka_unit_test(test_thread_counts_give_the_same_overlaps),
        cmocka_unit_test(test_thread_counts_give_the_same_piles),
        cmocka_unit_test(test_batch_thread_counts_give_the_same_bits),
        cmocka_unit_test(test_threads_of_a_context),
    };
    return cmocka_run_group_tests_name("threads", tests, NULL, NULL);
}
