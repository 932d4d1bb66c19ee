/* What the tests of the intersection check share: where each case is also
   tried, the solids they are built of, and the verdicts with and without the
   check. */
#include "overlap_cases.h"

#include <stdio.h>

const pm_placement placements[] = {
    {"as given", 1.0, {0, 0, 0}},
    {"at 1e6", 1.0, {1e6, -1e6, 1e6}},
    {"at 1e8", 1.0, {1e8, 1e8, -1e8}},
    {"scaled 1e-60", 1e-60, {0, 0, 0}},
    {"scaled 1e60", 1e60, {0, 0, 0}},
    {"scaled 2^-10 at 2^20", 0.0009765625, {1048576, 1048576, -1048576}},
};
const size_t placement_count = sizeof placements / sizeof placements[0];

void box(pm_mesh* m, double x0, double y0, double z0, double x1, double y1, double z1,
         int triangulate, int inside_out) {
    const double lo[3] = {x0, y0, z0}, hi[3] = {x1, y1, z1};
    pm_mesh part;
    pm_mesh_init(&part);
    pm_mesh_add_box(&part, lo, hi, triangulate);
    if (inside_out) {
        pm_mesh_reverse_all(&part);
    }
    pm_mesh_append(m, &part);
    pm_mesh_free(&part);
}

void octahedron(pm_mesh* m, const double c[3], double r, int inside_out) {
    static const uint32_t faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                         {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const uint32_t base = (uint32_t)m->vertex_count;
    int k;
    pm_mesh_add_vertex(m, c[0] + r, c[1], c[2]);
    pm_mesh_add_vertex(m, c[0] - r, c[1], c[2]);
    pm_mesh_add_vertex(m, c[0], c[1] + r, c[2]);
    pm_mesh_add_vertex(m, c[0], c[1] - r, c[2]);
    pm_mesh_add_vertex(m, c[0], c[1], c[2] + r);
    pm_mesh_add_vertex(m, c[0], c[1], c[2] - r);
    for (k = 0; k < 8; ++k) {
        if (inside_out) {
            pm_mesh_add_tri(m, base + faces[k][0], base + faces[k][2], base + faces[k][1]);
        } else {
            pm_mesh_add_tri(m, base + faces[k][0], base + faces[k][1], base + faces[k][2]);
        }
    }
}

int32_t verdicts(const pm_mesh* m, int32_t* unchecked, uint32_t* warnings, double* volume) {
    polymass_context* plain = pm_context_new();
    polymass_context* checked = pm_context_new();
    polymass_mass_properties p, q;
    int32_t status;
    pm_props_init(&p);
    pm_props_init(&q);
    *unchecked = pm_compute_flags(&p, plain, m, UNCHECKED, NULL);
    status = pm_compute_flags(&q, checked, m, CHECKED, NULL);
    if (status == POLYMASS_OK) {
        *warnings = q.warnings;
        *volume = q.volume;
        /* The check never changes a result it accepts. */
        assert_int_equal(*unchecked, POLYMASS_OK);
        PM_ASSERT_SAME("volume", p.volume, q.volume);
        PM_ASSERT_SAME("Ixx", p.inertia[0], q.inertia[0]);
        PM_ASSERT_SAME("Ixy", p.inertia[1], q.inertia[1]);
    }
    polymass_context_destroy(plain);
    polymass_context_destroy(checked);
    return status;
}

int32_t shell_list(polymass_shell* shells, uint64_t capacity, uint64_t* count,
                   polymass_context* ctx, const pm_mesh* m, uint32_t flags) {
    const polymass_mesh_desc desc = pm_mesh_desc(m);
    const polymass_options options = pm_options(flags, 0.0);
    polymass_mesh* mesh = NULL;
    int32_t status;
    (void)polymass_mesh_create(&mesh, ctx, &desc, &options);
    assert_non_null(mesh);
    status = polymass_mesh_shells(shells, capacity, count, ctx, mesh);
    polymass_mesh_destroy(mesh);
    return status;
}

void expect_everywhere(const char* what, const pm_mesh* original, expectation e) {
    size_t k;
    for (k = 0; k < placement_count; ++k) {
        const pm_placement* at = &placements[k];
        pm_mesh m;
        int32_t unchecked = -1, status;
        uint32_t warnings = 0;
        double volume = 0;
        pm_mesh_placed(&m, original, at);
        status = verdicts(&m, &unchecked, &warnings, &volume);
        if (status != e.checked || unchecked != e.unchecked) {
            fail_msg("%s, %s: checked %s (expected %s), unchecked %s (expected %s)", what, at->name,
                     polymass_status_string(status), polymass_status_string(e.checked),
                     polymass_status_string(unchecked), polymass_status_string(e.unchecked));
        }
        if (status == POLYMASS_OK) {
            const double s3 = at->scale * at->scale * at->scale;
            if (warnings != e.warnings) {
                fail_msg("%s, %s: warnings %#x, expected %#x", what, at->name, warnings,
                         e.warnings);
            }
            PM_ASSERT_REL("volume", e.volume * s3, volume, 1e-12);
        }
        pm_mesh_free(&m);
    }
    printf("  %-58s %s / unchecked %s\n", what, polymass_status_string(e.checked),
           polymass_status_string(e.unchecked));
}

const expectation overlap = {POLYMASS_ERROR_INTERSECTING, POLYMASS_OK, 0, 0};
