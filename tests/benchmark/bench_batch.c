/* Throughput of polymass_batch_compute against a loop of single calls
   (polymass_mass_properties_compute) on many small meshes: spheres of
   `faces` triangles (a latitude-longitude grid, closed), each at its own
   place, with the default options (every check, the intersection check
   included). Prints figures; asserts nothing about speed.
   Usage: bench_batch [meshes] [faces per mesh] [repeats] */
#include <polymass/polymass.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

int main(int argc, char** argv) {
    const size_t meshes = argc > 1 ? (size_t)atof(argv[1]) : 10000;
    const size_t wanted_faces = argc > 2 ? (size_t)atof(argv[2]) : 1000;
    const int repeats = argc > 3 ? atoi(argv[3]) : 3;
    /* faces = 2 * rings * (segments - 1): segments = 11, rings = faces / 20. */
    const uint32_t segments = 11, rings = (uint32_t)(wanted_faces / 20 > 3 ? wanted_faces / 20 : 3);
    const size_t vertex_count = 2 + (size_t)(segments - 1) * rings;
    const size_t face_count = 2 * (size_t)rings * (segments - 1);
    double* positions = malloc(meshes * vertex_count * 3 * sizeof *positions);
    uint32_t* indices = malloc(meshes * face_count * 3 * sizeof *indices);
    polymass_mesh_desc* descs = malloc(meshes * sizeof *descs);
    polymass_batch_item* items = malloc(meshes * sizeof *items);
    polymass_mass_properties* results = malloc(meshes * sizeof *results);
    polymass_context* context = NULL;
    double best_loop = 1e300, best_batch = 1e300, volume = 0;
    uint64_t failed = 0;
    if (!positions || !indices || !descs || !items || !results ||
        polymass_context_create(&context, NULL) != POLYMASS_OK) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    for (size_t m = 0; m < meshes; ++m) {
        make_sphere(rings, segments, 3.0 * (double)m, positions + m * vertex_count * 3,
                    indices + m * face_count * 3);
        polymass_mesh_desc_init(&descs[m], sizeof descs[m]);
        descs[m].positions = positions + m * vertex_count * 3;
        descs[m].vertex_count = vertex_count;
        descs[m].indices = indices + m * face_count * 3;
        descs[m].index_count = face_count * 3;
        polymass_mass_properties_init(&results[m], sizeof results[m]);
        polymass_batch_item_init(&items[m], sizeof items[m]);
        items[m].desc = &descs[m];
        items[m].properties = &results[m];
    }
    for (int r = 0; r < repeats; ++r) {
        double start = now_seconds();
        for (size_t m = 0; m < meshes; ++m)
            if (polymass_mass_properties_compute(&results[m], NULL, context, &descs[m], NULL,
                                                 NULL) != POLYMASS_OK) {
                fprintf(stderr, "mesh %zu: %s\n", m, polymass_context_message(context));
                return 1;
            }
        const double loop = now_seconds() - start;
        start = now_seconds();
        if (polymass_batch_compute(items, meshes, &failed, context) != POLYMASS_OK || failed) {
            fprintf(stderr, "batch: %s (%llu failed)\n", polymass_context_message(context),
                    (unsigned long long)failed);
            return 1;
        }
        const double batch = now_seconds() - start;
        best_loop = loop < best_loop ? loop : best_loop;
        best_batch = batch < best_batch ? batch : best_batch;
    }
    for (size_t m = 0; m < meshes; ++m) volume += results[m].volume;
    printf("libpolymass %s: %zu meshes of %zu triangles, best of %d\n", polymass_version_string(),
           meshes, face_count, repeats);
    printf("  loop of single calls: %8.2f ms  %9.0f meshes/s  %6.1f M triangles/s\n",
           1e3 * best_loop, meshes / best_loop, meshes * face_count / best_loop / 1e6);
    printf("  one batch call:       %8.2f ms  %9.0f meshes/s  %6.1f M triangles/s\n",
           1e3 * best_batch, meshes / best_batch, meshes * face_count / best_batch / 1e6);
    printf("  total volume %.6g\n", volume);
    polymass_context_destroy(context);
    free(positions), free(indices), free(descs), free(items), free(results);
    return 0;
}
