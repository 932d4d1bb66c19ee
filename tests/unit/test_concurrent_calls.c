/* What the header promises to threads, exercised at once (run under
 * ThreadSanitizer by the tsan step of scripts/test.sh, with test_threads and
 * test_batch): calls that are "thread-safe" (context creation), one mesh read
 * through many contexts by moments, diagnostics and mass properties, meshes
 * made and checked at once, batches run by
 * several threads each with its own context over shared descriptions, and
 * contexts created, configured and destroyed while others work. Every thread
 * must get the answer the main thread got, bit for bit. */
#include "test_support.h"

#include <pthread.h>
#include <string.h>

enum { THREADS = 4, ROUNDS = 20, BATCH = 6 };

typedef struct shared_input {
    const polymass_mesh* mesh;
    const polymass_mesh_desc* descs; /* BATCH of them */
    polymass_moments moments;        /* of mesh, by the main thread */
    polymass_mass_properties batch[BATCH];
} shared_input;

typedef struct worker {
    const shared_input* input;
    int index;
    int failures;
} worker;

static void* work(void* arg) {
    worker* w = arg;
    const shared_input* in = w->input;
    int round;
    for (round = 0; round < ROUNDS; ++round) {
        polymass_context* ctx = NULL;
        polymass_moments m;
        polymass_diagnostics d;
        polymass_batch_item items[BATCH];
        polymass_mass_properties out[BATCH];
        polymass_options options;
        polymass_mesh* own = NULL;
        uint64_t failed = 1;
        int i;
        /* A context of its own, and options of its own, every round. */
        if (polymass_context_create(&ctx, NULL) != POLYMASS_OK) {
            w->failures++;
            continue;
        }
        options =
            pm_options((unsigned)(w->index + round) % 2 ? POLYMASS_OPTION_ACCEPT_INVERTED : 0, 0.0);
        memset(&m, 0, sizeof m);
        m.struct_size = sizeof m;
        if (polymass_mesh_moments(&m, ctx, in->mesh) != POLYMASS_OK ||
            memcmp(&m, &in->moments, sizeof m) != 0)
            w->failures++;
        pm_diagnostics_init(&d);
        if (polymass_mesh_create(&own, ctx, &in->descs[w->index % BATCH], &options) !=
                POLYMASS_OK ||
            polymass_mesh_diagnostics(&d, ctx, own) != POLYMASS_OK || d.status != POLYMASS_OK)
            w->failures++;
        polymass_mesh_destroy(own);
        pm_diagnostics_init(&d);
        if (polymass_mesh_diagnostics(&d, ctx, in->mesh) != POLYMASS_OK ||
            d.status != POLYMASS_OK || d.shell_count != 1)
            w->failures++;
        for (i = 0; i < BATCH; ++i) {
            memset(&items[i], 0, sizeof items[i]);
            items[i].struct_size = sizeof items[i];
            items[i].desc = &in->descs[i];
            items[i].options = &options;
            pm_props_init(&out[i]);
            items[i].properties = &out[i];
        }
        if (polymass_batch_compute(items, BATCH, &failed, ctx) != POLYMASS_OK || failed != 0)
            w->failures++;
        for (i = 0; i < BATCH; ++i)
            if (memcmp(&out[i], &in->batch[i], sizeof out[i]) != 0) w->failures++;
        polymass_context_destroy(ctx);
    }
    return NULL;
}

static void test_many_threads_share_meshes_and_batches(void** state) {
    polymass_mesh_desc descs[BATCH];
    shared_input input;
    polymass_context* ctx = pm_context_new();
    polymass_mesh* mesh = NULL;
    pthread_t threads[THREADS];
    worker workers[THREADS];
    int i;
    (void)state;
    memset(&input, 0, sizeof input);
    for (i = 0; i < BATCH; ++i) descs[i] = pm_reference_desc(&pm_reference_solids[i]);
    input.descs = descs;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &descs[BATCH - 1], NULL));
    input.mesh = mesh;
    input.moments.struct_size = sizeof input.moments;
    PM_ASSERT_OK(ctx, polymass_mesh_moments(&input.moments, ctx, mesh));
    for (i = 0; i < BATCH; ++i) {
        pm_props_init(&input.batch[i]);
        PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&input.batch[i], NULL, ctx, &descs[i],
                                                           NULL, NULL));
    }
    for (i = 0; i < THREADS; ++i) {
        workers[i].input = &input;
        workers[i].index = i;
        workers[i].failures = 0;
        assert_int_equal(pthread_create(&threads[i], NULL, work, &workers[i]), 0);
    }
    for (i = 0; i < THREADS; ++i) assert_int_equal(pthread_join(threads[i], NULL), 0);
    for (i = 0; i < THREADS; ++i) assert_int_equal(workers[i].failures, 0);
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_many_threads_share_meshes_and_batches),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
