/* polymass_batch_compute: every item bit for bit its single call's result
 * (properties and provenance), per-item errors that do not stop the others,
 * per-item options (NULL: the defaults). */
#include "test_support.h"

#include <string.h>

#define ITEMS 6

static void test_batch_matches_single_calls(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh meshes[ITEMS];
    polymass_mesh_desc descs[ITEMS];
    polymass_mass_desc masses[ITEMS];
    polymass_mass_properties batch[ITEMS], single;
    polymass_provenance provenances[ITEMS], single_provenance;
    polymass_batch_item items[ITEMS];
    polymass_options accept = pm_options(POLYMASS_OPTION_ACCEPT_INVERTED, 0.0);
    uint64_t failed = 99;
    int i;
    (void)state;
    for (i = 0; i < ITEMS; ++i) {
        pm_mesh_from_reference(&meshes[i], &pm_reference_solids[i % PM_REF_COUNT]);
        masses[i] = pm_mass_density(1.0 + i);
        pm_props_init(&batch[i]);
        assert_int_equal(polymass_provenance_init(&provenances[i], sizeof provenances[i]),
                         POLYMASS_OK);
        assert_int_equal(polymass_batch_item_init(&items[i], sizeof items[i]), POLYMASS_OK);
    }
    pm_mesh_remove_face(&meshes[2], 0); /* open: fails */
    pm_mesh_reverse_all(&meshes[4]);    /* inverted: fails with the default options... */
    pm_mesh_reverse_all(&meshes[5]);    /* ...and is accepted with the item's own */
    for (i = 0; i < ITEMS; ++i) {
        descs[i] = pm_mesh_desc(&meshes[i]);
        items[i].desc = &descs[i];
        items[i].mass = i == 0 ? NULL : &masses[i];
        items[i].options = i == 5 ? &accept : NULL;
        items[i].properties = &batch[i];
        items[i].provenance = i % 2 ? &provenances[i] : NULL;
    }
    PM_ASSERT_OK(ctx, polymass_batch_compute(items, ITEMS, &failed, ctx));
    assert_int_equal(failed, 2);
    for (i = 0; i < ITEMS; ++i) {
        int32_t status;
        pm_props_init(&single);
        polymass_provenance_init(&single_provenance, sizeof single_provenance);
        status = polymass_mass_properties_compute(&single, &single_provenance, ctx, &descs[i],
                                                  items[i].options, items[i].mass);
        assert_int_equal(items[i].status, status);
        assert_string_equal(items[i].message, polymass_context_message(ctx));
        if (status == POLYMASS_OK) {
            assert_memory_equal(&batch[i], &single, sizeof single); /* bit for bit */
            if (items[i].provenance) {
                assert_memory_equal(&provenances[i], &single_provenance, sizeof single_provenance);
                assert_int_equal(provenances[i].mode, POLYMASS_MODE_SOLID);
            }
        }
    }
    assert_int_equal(items[2].status, POLYMASS_ERROR_OPEN);
    assert_int_equal(items[4].status, POLYMASS_ERROR_INVERTED);
    assert_int_equal(items[5].status, POLYMASS_OK);
    assert_true(strstr(items[2].message, "edge") != NULL);
    assert_string_equal(items[0].message, "");
    for (i = 0; i < ITEMS; ++i) pm_mesh_free(&meshes[i]);
    polymass_context_destroy(ctx);
}

static void test_batch_refuses_bad_arrays(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_batch_item items[2];
    uint64_t failed = 7;
    (void)state;
    PM_ASSERT_OK(ctx, polymass_batch_compute(NULL, 0, &failed, ctx));
    assert_int_equal(failed, 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_batch_compute(NULL, 1, NULL, ctx));
    polymass_batch_item_init(&items[0], sizeof items[0]);
    polymass_batch_item_init(&items[1], sizeof items[1]);
    items[1].struct_size = 8;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_batch_compute(items, 2, NULL, ctx));
    /* An item with nothing in it fails on its own. */
    items[1].struct_size = sizeof items[1];
    PM_ASSERT_OK(ctx, polymass_batch_compute(items, 2, &failed, ctx));
    assert_int_equal(failed, 2);
    assert_int_equal(items[0].status, POLYMASS_ERROR_INVALID_ARGUMENT);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_batch_matches_single_calls),
        cmocka_unit_test(test_batch_refuses_bad_arrays),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
