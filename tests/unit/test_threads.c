/* "A mesh is immutable once created: any number of threads may read it at
 * once, each through its own context"; distinct contexts are independent. */
#include "test_support.h"

#include <pthread.h>
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
            if (polymass_mass_properties_compute(&p, ctx, r->desc, NULL) != POLYMASS_OK) {
                r->failures++;
            }
            pm_diagnostics_init(&d);
            if (polymass_mesh_check(&d, ctx, r->desc) != POLYMASS_OK) {
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
    polymass_context* ctx = pm_context_new(0);
    polymass_mesh* mesh = NULL;
    polymass_mass_properties expected;
    pthread_t threads[THREADS];
    reader readers[THREADS];
    int i;
    (void)state;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &desc));
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
    polymass_context* a = pm_context_new(0);
    polymass_context* b = pm_context_new(POLYMASS_OPTION_ACCEPT_INVERTED);
    pm_mesh m;
    polymass_mass_properties p;
    polymass_options o;
    (void)state;
    pm_mesh_from_reference(&m, &pm_reference_solids[PM_REF_HOUSE]);
    pm_mesh_reverse_all(&m);
    PM_ASSERT_OK(b, pm_compute(&p, b, &m, NULL));
    PM_ASSERT_STATUS(a, POLYMASS_ERROR_INVERTED, pm_compute(&p, a, &m, NULL));
    assert_true(strlen(polymass_context_message(a)) > 0);
    assert_string_equal(polymass_context_message(b), "");
    o = pm_options(0, 0.0);
    PM_ASSERT_OK(a, polymass_context_get_options(&o, a));
    assert_int_equal(o.flags, 0);
    PM_ASSERT_OK(b, polymass_context_get_options(&o, b));
    assert_int_equal(o.flags, POLYMASS_OPTION_ACCEPT_INVERTED);
    pm_mesh_free(&m);
    polymass_context_destroy(a);
    polymass_context_destroy(b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_concurrent_readers),
        cmocka_unit_test(test_contexts_are_independent),
    };
    return cmocka_run_group_tests_name("threads", tests, NULL, NULL);
}
