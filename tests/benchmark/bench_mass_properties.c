/* Throughput of libpolymass on a large closed triangle mesh (a torus grid),
   fully checked with and without the intersection check, and trusted
   (topology checks skipped) with float64 and with float32 positions; the cost
   of the intersection check on its own is the difference of the first two.
   Prints figures; asserts nothing about speed.
   Usage: bench_mass_properties [triangles] [repeats] */
#include <polymass/polymass.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* A torus of rings x segments quads, two triangles each, far from the origin. */
static void make_torus(uint32_t rings, uint32_t segments, double* positions, uint32_t* indices) {
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

static double best_seconds(polymass_context* context, const polymass_mesh_desc* desc, int repeats,
                           polymass_mass_properties* out) {
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) {
        const double start = now_seconds();
        const int32_t status = polymass_mass_properties_compute(out, context, desc, NULL);
        const double elapsed = now_seconds() - start;
        if (status != POLYMASS_OK) {
            fprintf(stderr, "error: %s\n", polymass_context_message(context));
            exit(1);
        }
        if (elapsed < best) best = elapsed;
    }
    return best;
}

int main(int argc, char** argv) {
    const double wanted = argc > 1 ? atof(argv[1]) : 1e6;
    const int repeats = argc > 2 ? atoi(argv[2]) : 5;
    const uint32_t segments = 500, rings = (uint32_t)(wanted / (2.0 * segments));
    const size_t vertices = (size_t)rings * segments, triangles = 2 * vertices;
    double* positions = malloc(3 * vertices * sizeof *positions);
    uint32_t* indices = malloc(3 * triangles * sizeof *indices);
    if (!positions || !indices) return 1;
    make_torus(rings, segments, positions, indices);

    polymass_context* context = NULL;
    if (polymass_context_create(&context, NULL) != POLYMASS_OK) return 1;
    polymass_mesh_desc desc = {sizeof desc};
    desc.positions = positions;
    desc.vertex_count = vertices;
    desc.indices = indices;
    desc.index_count = 3 * triangles;

    polymass_mass_properties properties = {sizeof properties};
    const double checked = best_seconds(context, &desc, repeats, &properties);
    polymass_options intersections = {sizeof intersections, POLYMASS_OPTION_CHECK_INTERSECTIONS,
                                      0.0};
    polymass_context_set_options(context, &intersections);
    const double with_intersections = best_seconds(context, &desc, repeats, &properties);
    polymass_options options = {sizeof options, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS, 0.0};
    polymass_context_set_options(context, &options);
    const double trusted = best_seconds(context, &desc, repeats, &properties);

    /* The same torus in float, moved to the origin: 1e6 away, float's steps
       of 1/16 would collapse many of its triangles. */
    float* float_positions = malloc(3 * vertices * sizeof *float_positions);
    if (!float_positions) return 1;
    for (size_t i = 0; i < 3 * vertices; ++i) float_positions[i] = (float)(positions[i] - 1e6);
    polymass_mesh_desc float_desc = desc;
    float_desc.position_type = POLYMASS_POSITION_FLOAT32;
    float_desc.positions = float_positions;
    polymass_mass_properties float_properties = {sizeof float_properties};
    const double trusted_float = best_seconds(context, &float_desc, repeats, &float_properties);

    printf("libpolymass %s, %zu triangles, best of %d\n", polymass_version_string(), triangles,
           repeats);
    printf("  checked (topology):  %8.2f ms  %7.1f M triangles/s\n", 1e3 * checked,
           triangles / checked / 1e6);
    printf(
        "  checked + intersect: %8.2f ms  %7.1f M triangles/s (the intersection check alone: "
        "%.2f ms, %.1f M triangles/s)\n",
        1e3 * with_intersections, triangles / with_intersections / 1e6,
        1e3 * (with_intersections - checked), triangles / (with_intersections - checked) / 1e6);
    printf("  trusted (no checks): %8.2f ms  %7.1f M triangles/s\n", 1e3 * trusted,
           triangles / trusted / 1e6);
    printf("  trusted, float32:    %8.2f ms  %7.1f M triangles/s\n", 1e3 * trusted_float,
           triangles / trusted_float / 1e6);
    printf("  volume %.17g (torus: 2 pi^2 R r^2 = %.17g as the grid refines)\n", properties.volume,
           2 * 3.14159265358979323846 * 3.14159265358979323846 * 2);
    polymass_context_destroy(context);
    free(float_positions);
    free(positions);
    free(indices);
    return 0;
}
