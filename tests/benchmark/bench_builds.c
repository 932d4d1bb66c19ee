/* Two or more builds of libpolymass timed against each other in one process,
   for a change whose gain is smaller than the drift of a shared machine's
   speed between two runs (on this project's virtual machines a fifth from
   one minute to the next, which two runs of bench_mass_properties, one per
   build, cannot tell from the change). Each build is loaded into a namespace
   of its own (dlmopen), so that the same symbols of different builds stand
   side by side, and the builds are called in turn, a few calls each, round
   after round: a drift then slows every build alike. One thread, on the
   torus of bench_mass_properties (far from the origin; float32 at the
   origin), through polymass_mass_properties_compute.
   Prints, for each build, the fastest call and the median one, in ms and M
   triangles/s, their ratio to the first build's, and whether its volume has
   the first build's bits (a change in the order of the sums may move the last
   ones). Prints figures; asserts nothing about speed.
   Usage: bench_builds [triangles] [rounds] [trusted|topology|default]
          [float64|float32] LIBRARY...
   e.g. bench_builds 1e5 40 trusted float64 /tmp/before/libpolymass.so
        build/release/src/libpolymass.so */
#include <dlfcn.h>
#include <polymass/polymass.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"

enum { calls_per_turn = 5, max_builds = 8 };

typedef int32_t (*create_fn)(polymass_context**, const polymass_allocator*);
typedef int32_t (*set_threads_fn)(polymass_context*, uint32_t);
typedef int32_t (*compute_fn)(polymass_mass_properties*, polymass_provenance*, polymass_context*,
                              const polymass_mesh_desc*, const polymass_options*,
                              const polymass_mass_desc*);
typedef const char* (*message_fn)(const polymass_context*);

typedef struct build {
    const char* path;
    polymass_context* context;
    compute_fn compute;
    message_fn message;
    double* seconds; /* every call's */
    double volume;
} build;

/* A symbol of a build, or the program ends saying which is missing. */
static void* symbol(void* library, const char* path, const char* name) {
    void* address = dlsym(library, name);
    if (!address) {
        fprintf(stderr, "error: %s has no %s\n", path, name);
        exit(1);
    }
    return address;
}

static void load(build* b, const char* path, size_t calls) {
    void* library = dlmopen(LM_ID_NEWLM, path, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        fprintf(stderr, "error: %s\n", dlerror());
        exit(1);
    }
    b->path = path;
    b->compute = (compute_fn)symbol(library, path, "polymass_mass_properties_compute");
    b->message = (message_fn)symbol(library, path, "polymass_context_message");
    create_fn create = (create_fn)symbol(library, path, "polymass_context_create");
    set_threads_fn set_threads =
        (set_threads_fn)symbol(library, path, "polymass_context_set_threads");
    if (create(&b->context, NULL) != POLYMASS_OK || set_threads(b->context, 1) != POLYMASS_OK) {
        fprintf(stderr, "error: %s: no context\n", path);
        exit(1);
    }
    b->seconds = checked_malloc(calls * sizeof *b->seconds);
}

static double timed_call(build* b, const polymass_mesh_desc* desc,
                         const polymass_options* options) {
    polymass_mass_properties out = POLYMASS_MASS_PROPERTIES_INIT;
    const double start = now_seconds();
    const int32_t status = b->compute(&out, NULL, b->context, desc, options, NULL);
    const double elapsed = now_seconds() - start;
    if (status != POLYMASS_OK) {
        fprintf(stderr, "error: %s: %s\n", b->path, b->message(b->context));
        exit(1);
    }
    b->volume = out.volume;
    return elapsed;
}

static uint32_t flags_named(const char* checks) {
    if (strcmp(checks, "trusted") == 0) return POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
    if (strcmp(checks, "topology") == 0) return POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    if (strcmp(checks, "default") == 0) return 0;
    fprintf(stderr, "error: checks are trusted, topology or default, not %s\n", checks);
    exit(1);
}

int main(int argc, char** argv) {
    if (argc < 6 || argc - 5 > max_builds) {
        fprintf(stderr,
                "usage: bench_builds triangles rounds trusted|topology|default "
                "float64|float32 LIBRARY... (at most %d)\n",
                max_builds);
        return 2;
    }
    const size_t wanted = (size_t)atof(argv[1]);
    const int rounds = atoi(argv[2]);
    polymass_options options = POLYMASS_OPTIONS_INIT;
    options.flags = flags_named(argv[3]);
    const int float32 = strcmp(argv[4], "float32") == 0;
    if (!float32 && strcmp(argv[4], "float64") != 0) {
        fprintf(stderr, "error: positions are float64 or float32, not %s\n", argv[4]);
        return 2;
    }
    const int count = argc - 5;
    if (rounds < 1 || wanted < 1000) {
        fprintf(stderr, "error: at least 1 round and 1000 triangles\n");
        return 2;
    }

    torus_meshes meshes = make_torus_meshes(wanted);
    const size_t triangles = meshes.triangles;
    const polymass_mesh_desc desc = float32 ? meshes.float32 : meshes.float64;

    const size_t calls = (size_t)rounds * calls_per_turn;
    build builds[max_builds];
    for (int b = 0; b < count; ++b) load(&builds[b], argv[5 + b], calls);
    for (int round = 0; round < rounds; ++round)
        for (int b = 0; b < count; ++b)
            for (int call = 0; call < calls_per_turn; ++call)
                builds[b].seconds[(size_t)round * calls_per_turn + (size_t)call] =
                    timed_call(&builds[b], &desc, &options);

    printf("%zu triangles, %s, %s, one thread; %d rounds of %d calls each, builds in turn\n",
           triangles, argv[3], float32 ? "float32" : "float64", rounds, calls_per_turn);
    double first_fastest = 0.0, first_median = 0.0;
    for (int b = 0; b < count; ++b) {
        const double typical = median(builds[b].seconds, (int)calls); /* sorts them */
        const double fastest = builds[b].seconds[0];
        if (b == 0) first_fastest = fastest, first_median = typical;
        printf("  %-40s fastest %8.3f ms %7.1f M triangles/s  median %8.3f ms %7.1f M/s",
               argv[5 + b], 1e3 * fastest, (double)triangles / fastest / 1e6, 1e3 * typical,
               (double)triangles / typical / 1e6);
        if (b > 0)
            printf("  %.3fx, %.3fx the first; volume %s", first_fastest / fastest,
                   first_median / typical,
                   builds[b].volume == builds[0].volume ? "same bits" : "other last bits");
        printf("\n");
    }
    free_torus_meshes(&meshes);
    for (int b = 0; b < count; ++b) free(builds[b].seconds);
    return 0;
}
