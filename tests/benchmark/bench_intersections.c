/* What the intersection check (on by default) costs: polymass_mesh_check with
   the default options against the same call with
   POLYMASS_OPTION_SKIP_INTERSECTION_CHECK (the topology checks alone, the
   bound), on the same mesh in the same round, on one thread
   and on two. Three meshes:
   - a torus far from the origin: a valid solid, every triangle near others
     and none crossing;
   - the same torus written twice in one mesh: two coincident shells, every
     triangle with a copy (copies are paired without the box tree);
   - a pile of coincident cubes: k copies of one part, whose face pairs in
     contact grow as k squared (the count stops at its limit);
   - about as many cubes stacked in a cube, each resting against its
     neighbours: many shells touching, each triangle that touches another
     shell probed for how the others wind around it.
   Runs are interleaved (every measure once per round) and the median of the
   rounds is printed, with the status the check gave. Prints figures; asserts
   nothing about speed.
   Usage: bench_intersections [rounds] [torus triangles] [cubes] */
#include <polymass/polymass.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"

typedef struct bench_mesh {
    const char* name;
    polymass_mesh_desc desc;
    size_t triangles;
} bench_mesh;

/* The torus of about `wanted` triangles, written `times` times over (copy c's
   vertices after copy c - 1's, its indices offset to them). */
static bench_mesh make_tori(const char* name, size_t wanted, uint32_t times) {
    const uint32_t segments = 500, rings = (uint32_t)(wanted / (2.0 * segments));
    const size_t vertices = (size_t)rings * segments, indices = 6 * vertices;
    double* positions = malloc(times * 3 * vertices * sizeof *positions);
    uint32_t* index_array = malloc(times * indices * sizeof *index_array);
    if (!positions || !index_array) exit(1);
    make_torus(rings, segments, positions, index_array);
    for (uint32_t c = 1; c < times; ++c) {
        memcpy(positions + c * 3 * vertices, positions, 3 * vertices * sizeof *positions);
        for (size_t i = 0; i < indices; ++i)
            index_array[c * indices + i] = index_array[i] + c * (uint32_t)vertices;
    }
    bench_mesh mesh = {name, {sizeof mesh.desc}, times * indices / 3};
    mesh.desc.positions = positions;
    mesh.desc.vertex_count = times * vertices;
    mesh.desc.indices = index_array;
    mesh.desc.index_count = times * indices;
    return mesh;
}

/* k unit cubes, 1e6 from the origin, each its own 8 vertices and 12 outward
   triangles: at one place (side 0), or stacked side x side x side, each
   resting against its neighbours. */
static bench_mesh make_cubes(const char* name, uint32_t k, uint32_t side) {
    static const uint32_t cube[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                      1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    double* positions = malloc((size_t)k * 24 * sizeof *positions);
    uint32_t* indices = malloc((size_t)k * 36 * sizeof *indices);
    if (!positions || !indices) exit(1);
    for (uint32_t c = 0; c < k; ++c) {
        const uint32_t at[3] = {side ? c % side : 0, side ? c / side % side : 0,
                                side ? c / side / side : 0};
        for (int v = 0; v < 8; ++v) {
            double* p = positions + 24 * (size_t)c + 3 * v;
            p[0] = 1e6 + at[0] + (double)((v == 1 || v == 2 || v == 5 || v == 6));
            p[1] = 1e6 + at[1] + (double)((v == 2 || v == 3 || v == 6 || v == 7));
            p[2] = 1e6 + at[2] + (double)(v >= 4);
        }
        for (int i = 0; i < 36; ++i) indices[36 * (size_t)c + i] = cube[i] + 8 * c;
    }
    bench_mesh mesh = {name, {sizeof mesh.desc}, 12 * (size_t)k};
    mesh.desc.positions = positions;
    mesh.desc.vertex_count = 8 * (size_t)k;
    mesh.desc.indices = indices;
    mesh.desc.index_count = 36 * (size_t)k;
    return mesh;
}

static double check_seconds(polymass_context* context, const polymass_mesh_desc* desc,
                            uint32_t flags, uint32_t threads, polymass_diagnostics* report) {
    polymass_options options = POLYMASS_OPTIONS_INIT;
    options.flags = flags;
    options.threads = threads;
    polymass_diagnostics_init(report, sizeof *report);
    const double start = now_seconds();
    polymass_mesh_check_with_options(report, context, desc, &options);
    const double elapsed = now_seconds() - start;
    if (report->status == POLYMASS_ERROR_INVALID_ARGUMENT ||
        report->status == POLYMASS_ERROR_OUT_OF_MEMORY) {
        fprintf(stderr, "error: %s\n", polymass_context_message(context));
        exit(1);
    }
    return elapsed;
}

enum { topology_1, intersections_1, topology_2, intersections_2, measures };
static const char* const names[measures] = {"topology checks", "with intersections",
                                            "topology checks, 2 threads",
                                            "with intersections, 2 threads"};

static void run(const bench_mesh* mesh, int rounds, polymass_context* context) {
    double* seconds = malloc((size_t)measures * (size_t)rounds * sizeof *seconds);
    polymass_diagnostics reports[measures];
    if (!seconds) exit(1);
    for (int r = 0; r < rounds; ++r) {
        double* s = seconds + (size_t)r * measures;
        const uint32_t skip = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
        s[topology_1] = check_seconds(context, &mesh->desc, skip, 1, &reports[topology_1]);
        s[intersections_1] = check_seconds(context, &mesh->desc, 0, 1, &reports[intersections_1]);
        s[topology_2] = check_seconds(context, &mesh->desc, skip, 2, &reports[topology_2]);
        s[intersections_2] = check_seconds(context, &mesh->desc, 0, 2, &reports[intersections_2]);
    }
    double medians[measures];
    medians_of(seconds, rounds, measures, medians);
    const polymass_diagnostics* found = &reports[intersections_1];
    printf(
        "%s, %zu triangles: %s (%llu shells, %llu overlapping; %llu face pairs crossing, "
        "%llu touching)\n",
        mesh->name, mesh->triangles, polymass_status_string(found->status),
        (unsigned long long)found->shell_count, (unsigned long long)found->overlapping_shells,
        (unsigned long long)found->intersecting_face_pairs,
        (unsigned long long)found->touching_face_pairs);
    for (int m = 0; m < measures; ++m) {
        printf("  %-30s %9.3f ms %8.2f M triangles/s", names[m], 1e3 * medians[m],
               (double)mesh->triangles / medians[m] / 1e6);
        if (m == intersections_1 || m == intersections_2)
            printf("  %5.2fx the topology checks' time", medians[m] / medians[m - 1]);
        if (m == topology_2 || m == intersections_2)
            printf("  %4.2fx one thread", medians[m - 2] / medians[m]);
        printf("\n");
    }
    free(seconds);
}

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? atoi(argv[1]) : 5;
    const double torus_triangles = argc > 2 ? atof(argv[2]) : 1e6;
    const double cubes = argc > 3 ? atof(argv[3]) : 1000;
    /* The stack: about as many cubes as the pile. */
    const uint32_t stack = (uint32_t)(cbrt(cubes) + 0.5) > 0 ? (uint32_t)(cbrt(cubes) + 0.5) : 1;
    polymass_context* context = NULL;
    if (rounds < 1 || torus_triangles < 1000 || cubes < 1 || cubes > 1e8 ||
        polymass_context_create(&context, NULL) != POLYMASS_OK) {
        fprintf(stderr, "usage: bench_intersections [rounds] [torus triangles >= 1000] [cubes]\n");
        return 1;
    }
    printf("libpolymass %s, median of %d interleaved rounds\n", polymass_version_string(), rounds);
    const bench_mesh meshes[] = {
        make_tori("torus", (size_t)torus_triangles, 1),
        make_tori("torus written twice", (size_t)torus_triangles / 2, 2),
        make_cubes("pile of coincident cubes", (uint32_t)cubes, 0),
        make_cubes("stack of cubes resting on each other", stack * stack * stack, stack)};
    for (size_t i = 0; i < sizeof meshes / sizeof *meshes; ++i) {
        run(&meshes[i], rounds, context);
        free((void*)meshes[i].desc.positions);
        free((void*)meshes[i].desc.indices);
    }
    polymass_context_destroy(context);
    return 0;
}
