/* Throughput on many small meshes, as a dataset holds them: a loop of single
   calls (polymass_mass_properties_compute), the batch of items
   (polymass_batch_compute) and the packed call (polymass_packed_compute, its
   indices counted from each mesh's first vertex and, as PyTorch3D packs them,
   from the packed array's), each on one thread and on two
   (polymass_context_set_threads). The meshes are spheres of `faces` triangles
   (a latitude-longitude grid, closed), each at its own place, in one packed
   array, computed with the options named (default: the default options,
   every check, the intersection check included; "topology": the topology
   checks without the intersection check; "trusted": no check,
   POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS, where the per-mesh costs around the
   computation weigh most). Runs are interleaved (every path once per round) and the
   median of the rounds is printed, in meshes/s and as ratios measured in the
   same run: the packed call against the item batch, two threads against one.
   Every path's volumes are checked bit for bit against the single calls'.
   Prints figures; asserts nothing about speed.
   Usage: bench_batch [meshes] [faces per mesh] [rounds] [default|topology|trusted]
   (default: 5,000 meshes of 1,000 triangles, 5 rounds, the default options) */
#include <polymass/polymass.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_common.h"

/* A closed sphere of 2 * rings * (segments - 1) triangles: poles + rings. */
static size_t make_sphere(uint32_t rings, uint32_t segments, double cx, double* positions,
                          uint32_t* indices) {
    const double pi = 3.14159265358979323846;
    size_t v = 0, t = 0;
    positions[v++] = cx, positions[v++] = 0, positions[v++] = 1; /* north pole: vertex 0 */
    for (uint32_t i = 1; i < segments; ++i)
        for (uint32_t j = 0; j < rings; ++j) {
            const double theta = pi * i / segments, phi = 2 * pi * j / rings;
            positions[v++] = cx + sin(theta) * cos(phi);
            positions[v++] = sin(theta) * sin(phi);
            positions[v++] = cos(theta);
        }
    positions[v++] = cx, positions[v++] = 0, positions[v++] = -1; /* south pole */
    const uint32_t south = 1 + (segments - 1) * rings;
    for (uint32_t j = 0; j < rings; ++j) {
        const uint32_t a = 1 + j, b = 1 + (j + 1) % rings;
        indices[t++] = 0, indices[t++] = a, indices[t++] = b;
        const uint32_t c = 1 + (segments - 2) * rings + j,
                       d = 1 + (segments - 2) * rings + (j + 1) % rings;
        indices[t++] = south, indices[t++] = d, indices[t++] = c;
    }
    for (uint32_t i = 0; i + 2 < segments; ++i)
        for (uint32_t j = 0; j < rings; ++j) {
            const uint32_t a = 1 + i * rings + j, b = 1 + i * rings + (j + 1) % rings;
            const uint32_t c = a + rings, d = b + rings;
            indices[t++] = a, indices[t++] = c, indices[t++] = d;
            indices[t++] = a, indices[t++] = d, indices[t++] = b;
        }
    return t / 3;
}

static void fail(const char* what, polymass_context* context) {
    fprintf(stderr, "%s: %s\n", what, polymass_context_message(context));
    exit(1);
}

/* The paths measured, in the order of the table. */
enum { LOOP, BATCH_1, BATCH_2, PACKED_1, PACKED_2, GLOBAL_1, GLOBAL_2, PATHS };
static const char* const path_names[PATHS] = {"loop of single calls, 1 thread",
                                              "item batch, 1 thread",
                                              "item batch, 2 threads",
                                              "packed call, 1 thread",
                                              "packed call, 2 threads",
                                              "packed, global indices, 1 thread",
                                              "packed, global indices, 2 threads"};

int main(int argc, char** argv) {
    const size_t meshes = argc > 1 ? (size_t)atof(argv[1]) : 5000;
    const size_t wanted_faces = argc > 2 ? (size_t)atof(argv[2]) : 1000;
    const int rounds = argc > 3 ? atoi(argv[3]) : 5;
    const char* checks = argc > 4 ? argv[4] : "default";
    polymass_options options = POLYMASS_OPTIONS_INIT;
    if (strcmp(checks, "topology") == 0) {
        options.flags = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    } else if (strcmp(checks, "trusted") == 0) {
        options.flags = POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
    } else if (strcmp(checks, "default") != 0) {
        fprintf(stderr, "options: default, topology or trusted, not %s\n", checks);
        return 1;
    }
    /* faces = 2 * rings * (segments - 1): segments = 11, rings = faces / 20. */
    const uint32_t segments = 11, rings = (uint32_t)(wanted_faces / 20 > 3 ? wanted_faces / 20 : 3);
    const size_t vertex_count = 2 + (size_t)(segments - 1) * rings;
    const size_t face_count = 2 * (size_t)rings * (segments - 1);
    const size_t index_count = 3 * face_count;
    double* positions = checked_malloc(meshes * vertex_count * 3 * sizeof *positions);
    uint32_t* indices = checked_malloc(meshes * index_count * sizeof *indices);
    uint32_t* global_indices = checked_malloc(meshes * index_count * sizeof *global_indices);
    uint64_t* vertex_offsets = checked_malloc((meshes + 1) * sizeof *vertex_offsets);
    uint64_t* index_offsets = checked_malloc((meshes + 1) * sizeof *index_offsets);
    polymass_mesh_desc* descs = checked_malloc(meshes * sizeof *descs);
    polymass_batch_item* items = checked_malloc(meshes * sizeof *items);
    polymass_mass_properties* single = checked_malloc(meshes * sizeof *single);
    polymass_mass_properties* batch = checked_malloc(meshes * sizeof *batch);
    double* volumes = checked_malloc(meshes * sizeof *volumes);
    int32_t* status = checked_malloc(meshes * sizeof *status);
    double* seconds = checked_malloc((size_t)rounds * PATHS * sizeof *seconds);
    double medians[PATHS];
    polymass_context* context = NULL;
    polymass_packed_meshes local = POLYMASS_PACKED_MESHES_INIT;
    polymass_packed_results results = POLYMASS_PACKED_RESULTS_INIT;
    uint64_t failed = 0;
    if (polymass_context_create(&context, NULL) != POLYMASS_OK) fail("context", context);
    for (size_t m = 0; m < meshes; ++m) {
        make_sphere(rings, segments, 3.0 * (double)m, positions + m * vertex_count * 3,
                    indices + m * index_count);
        for (size_t k = 0; k < index_count; ++k)
            global_indices[m * index_count + k] =
                (uint32_t)(m * vertex_count) + indices[m * index_count + k];
        vertex_offsets[m] = m * vertex_count, index_offsets[m] = m * index_count;
        polymass_mesh_desc_init(&descs[m], sizeof descs[m]);
        descs[m].positions = positions + m * vertex_count * 3;
        descs[m].vertex_count = vertex_count;
        descs[m].indices = indices + m * index_count;
        descs[m].index_count = index_count;
        polymass_mass_properties_init(&single[m], sizeof single[m]);
        polymass_mass_properties_init(&batch[m], sizeof batch[m]);
        polymass_batch_item_init(&items[m], sizeof items[m]);
        items[m].desc = &descs[m];
        items[m].properties = &batch[m];
        items[m].options = &options;
    }
    vertex_offsets[meshes] = meshes * vertex_count, index_offsets[meshes] = meshes * index_count;
    local.positions = positions;
    local.indices = indices;
    local.mesh_count = meshes;
    local.vertex_offsets = vertex_offsets;
    local.index_offsets = index_offsets;
    polymass_packed_meshes global = local;
    global.indices = global_indices;
    global.index_base = POLYMASS_INDICES_GLOBAL;
    results.status = status;
    results.volume = volumes;

    for (int r = 0; r < rounds; ++r)
        for (int path = 0; path < PATHS; ++path) {
            const uint32_t threads = path == LOOP ? 1 : 2 - (path % 2);
            if (polymass_context_set_threads(context, threads) != POLYMASS_OK)
                fail("threads", context);
            memset(volumes, 0, meshes * sizeof *volumes);
            const double start = now_seconds();
            if (path == LOOP) {
                for (size_t m = 0; m < meshes; ++m)
                    if (polymass_mass_properties_compute(&single[m], NULL, context, &descs[m],
                                                         &options, NULL) != POLYMASS_OK)
                        fail("single call", context);
            } else if (path == BATCH_1 || path == BATCH_2) {
                if (polymass_batch_compute(items, meshes, &failed, context) != POLYMASS_OK ||
                    failed)
                    fail("batch", context);
            } else if (polymass_packed_compute(&results, &failed, context,
                                               path < GLOBAL_1 ? &local : &global,
                                               &options) != POLYMASS_OK ||
                       failed) {
                fail("packed call", context);
            }
            seconds[(size_t)r * PATHS + path] = now_seconds() - start;
            /* Every path's results are the single calls', bit for bit. */
            for (size_t m = 0; m < meshes; ++m) {
                const double volume = path == LOOP      ? single[m].volume
                                      : path <= BATCH_2 ? batch[m].volume
                                                        : volumes[m];
                if (memcmp(&volume, &single[m].volume, sizeof volume) != 0) {
                    fprintf(stderr, "%s: mesh %zu's volume differs from its single call's\n",
                            path_names[path], m);
                    return 1;
                }
            }
        }
    medians_of(seconds, rounds, PATHS, medians);

    printf(
        "libpolymass %s: %zu closed meshes of %zu triangles (%zu vertices), %s options, "
        "median of %d rounds\n",
        polymass_version_string(), meshes, face_count, vertex_count, checks, rounds);
    for (int path = 0; path < PATHS; ++path)
        printf("  %-34s %8.1f ms  %8.0f meshes/s  %6.1f M triangles/s\n", path_names[path],
               1e3 * medians[path], meshes / medians[path],
               meshes * face_count / medians[path] / 1e6);
    printf("  packed / item batch:        %.2f (1 thread)  %.2f (2 threads)\n",
           medians[BATCH_1] / medians[PACKED_1], medians[BATCH_2] / medians[PACKED_2]);
    printf("  global / local indices:     %.2f (1 thread)  %.2f (2 threads)\n",
           medians[PACKED_1] / medians[GLOBAL_1], medians[PACKED_2] / medians[GLOBAL_2]);
    printf("  2 threads / 1 thread:       %.2f (item batch)  %.2f (packed)  %.2f (global)\n",
           medians[BATCH_1] / medians[BATCH_2], medians[PACKED_1] / medians[PACKED_2],
           medians[GLOBAL_1] / medians[GLOBAL_2]);
    printf("  every path bit for bit the single calls' volumes\n");
    polymass_context_destroy(context);
    free(positions), free(indices), free(global_indices), free(vertex_offsets);
    free(index_offsets), free(descs), free(items), free(single), free(batch), free(volumes);
    free(status), free(seconds);
    return 0;
}
