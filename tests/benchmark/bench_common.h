/* What the benchmarks share: a monotonic clock, the median of rounds, memory
   or an exit, the timed analysis of a mesh, and the torus they measure (a
   closed grid of triangles far from the origin). */
#ifndef POLYMASS_BENCH_COMMON_H
#define POLYMASS_BENCH_COMMON_H

#include <polymass/polymass.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static inline double now_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* malloc, or the program ends saying why. */
static inline void* checked_malloc(size_t bytes) {
    void* memory = malloc(bytes);
    if (!memory) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    return memory;
}

static inline int by_value(const void* a, const void* b) {
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

/* Sorts values. */
static inline double median(double* values, int count) {
    qsort(values, (size_t)count, sizeof *values, by_value);
    return count % 2 ? values[count / 2] : 0.5 * (values[count / 2 - 1] + values[count / 2]);
}

/* The median over the rounds of each measure, seconds[round * measures + m]. */
static inline void medians_of(const double* seconds, int rounds, int measures, double* medians) {
    double* column = malloc((size_t)rounds * sizeof *column);
    if (!column) exit(1);
    for (int m = 0; m < measures; ++m) {
        for (int r = 0; r < rounds; ++r) column[r] = seconds[(size_t)r * measures + m];
        medians[m] = median(column, rounds);
    }
    free(column);
}

/* The seconds of one analysis of the mesh (polymass_mesh_create: every check
   the options leave on, run to its end), its findings in `report`; or the
   program ends saying what failed. */
static inline double analysis_seconds(polymass_context* context, const polymass_mesh_desc* desc,
                                      const polymass_options* options,
                                      polymass_diagnostics* report) {
    polymass_mesh* analysed = NULL;
    polymass_diagnostics_init(report, sizeof *report);
    const double start = now_seconds();
    polymass_mesh_create(&analysed, context, desc, options);
    const double elapsed = now_seconds() - start;
    if (analysed == NULL || polymass_mesh_diagnostics(report, context, analysed) != POLYMASS_OK) {
        fprintf(stderr, "error: %s\n", polymass_context_message(context));
        exit(1);
    }
    polymass_mesh_destroy(analysed);
    return elapsed;
}

/* A torus of rings x segments quads, two triangles each, 1e6 from the origin:
   rings * segments vertices and 2 * rings * segments triangles. */
static inline void make_torus(uint32_t rings, uint32_t segments, double* positions,
                              uint32_t* indices) {
    const double pi = 3.14159265358979323846;
    for (uint32_t i = 0; i < rings; ++i) {
        for (uint32_t j = 0; j < segments; ++j) {
            const double u = 2 * pi * i / rings, v = 2 * pi * j / segments;
            double* p = positions + 3 * ((size_t)i * segments + j);
            p[0] = 1e6 + (2 + cos(v)) * cos(u);
            p[1] = 1e6 + (2 + cos(v)) * sin(u);
            p[2] = 1e6 + sin(v);
        }
    }
    for (uint32_t i = 0; i < rings; ++i) {
        for (uint32_t j = 0; j < segments; ++j) {
            const uint32_t a = i * segments + j, b = ((i + 1) % rings) * segments + j;
            const uint32_t c = ((i + 1) % rings) * segments + (j + 1) % segments;
            const uint32_t d = i * segments + (j + 1) % segments;
            uint32_t* t = indices + 6 * ((size_t)i * segments + j);
            t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
        }
    }
}

/* The torus of about `wanted` triangles (500 segments around its tube) twice:
   in float64, 1e6 from the origin, and in float32 at the origin (1e6 away,
   float's steps of 1/16 would collapse many of its triangles). The meshes
   bench_mass_properties and bench_builds time. */
typedef struct torus_meshes {
    polymass_mesh_desc float64, float32;
    size_t triangles;
} torus_meshes;

static inline torus_meshes make_torus_meshes(size_t wanted) {
    const uint32_t segments = 500, rings = (uint32_t)(wanted / (2.0 * segments));
    const size_t vertices = (size_t)rings * segments, triangles = 2 * vertices;
    double* positions = checked_malloc(3 * vertices * sizeof *positions);
    float* float_positions = checked_malloc(3 * vertices * sizeof *float_positions);
    uint32_t* indices = checked_malloc(3 * triangles * sizeof *indices);
    make_torus(rings, segments, positions, indices);
    for (size_t i = 0; i < 3 * vertices; ++i) float_positions[i] = (float)(positions[i] - 1e6);
    torus_meshes meshes = {{sizeof meshes.float64}, {sizeof meshes.float32}, triangles};
    meshes.float64.positions = positions;
    meshes.float64.vertex_count = vertices;
    meshes.float64.indices = indices;
    meshes.float64.index_count = 3 * triangles;
    meshes.float32 = meshes.float64;
    meshes.float32.position_type = POLYMASS_POSITION_FLOAT32;
    meshes.float32.positions = float_positions;
    return meshes;
}

static inline void free_torus_meshes(torus_meshes* meshes) {
    free((void*)meshes->float64.positions);
    free((void*)meshes->float32.positions);
    free((void*)meshes->float64.indices);
}

#endif
