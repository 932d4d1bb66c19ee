/* What the intersection check (on by default) costs: the analysis of a mesh
   (polymass_mesh_create, its diagnostics read from the handle) with the
   default options against the same call with
   POLYMASS_OPTION_SKIP_INTERSECTION_CHECK (the topology checks alone, the
   bound), on the same mesh in the same round, on one thread
   and on two; and, when a peer is at hand, the rate of MeshLib's
   findSelfCollidingTriangles on the same mesh, measured in the same run on
   one processor. The meshes:
   - closed tori far from the origin, 1e5, 1e6 (and 1e7) triangles: valid
     solids, every triangle near others and none crossing;
   - the 1e5 torus flattened to a hundredth of its height (300 times as
     wide as it is high: a plate's proportions, for the tree's cells);
   - the 1e5 torus and a copy shifted by a tenth of its tube: crossing along
     two loops (the report stops at its limit);
   - 1,000 and 8,000 cubes stacked in a cube, each resting against its
     neighbours, as separate parts (8 vertices each) and as one welded
     triangle soup (an STL: every triangle its own corners, welded by the
     options; shared edges are then used by 4 faces);
   - piles of 1,000 and 8,000 cubes at one place: coincident, each turned
     about (1, 2, 3) (no two copies: they cross in every pair of cubes), and
     each turned about z alone, whose faces touch each other in more pairs
     than cross before the first crossing one: still quadratic, so its 8,000
     run only when named.
   Sizes grow 8x from one mesh of a kind to the next: the ratio of times
   says whether the check grows with its input alone.
   Runs are interleaved (every measure once per round) and the median of the
   rounds is printed, with the status the check gave. Prints figures; asserts
   nothing about speed.

   Usage: bench_intersections [rounds] [largest torus] [meshes]
   rounds: default 3; largest torus: 1e6 (1e7 adds the largest); meshes: run
   only those whose name contains this text.
   MeshLib: POLYMASS_BENCH_MESHLIB=<python with meshlib> runs
   meshlib_self_collisions.py (beside this source; its path in
   POLYMASS_BENCH_MESHLIB_SCRIPT) under `taskset -c 0` on each mesh, written
   to a temporary file; without it, the column says so. */
#include <polymass/polymass.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"

typedef struct bench_mesh {
    char name[96];
    polymass_mesh_desc desc;
    size_t triangles;
    uint32_t flags; /* options of both measures (welding) */
} bench_mesh;

static bench_mesh new_mesh(const char* name, size_t vertices, size_t triangles) {
    bench_mesh mesh = {{0}, {sizeof mesh.desc}, triangles, 0};
    snprintf(mesh.name, sizeof mesh.name, "%s", name);
    mesh.desc.positions = checked_malloc(3 * vertices * sizeof(double));
    mesh.desc.vertex_count = vertices;
    mesh.desc.indices = checked_malloc(3 * triangles * sizeof(uint32_t));
    mesh.desc.index_count = 3 * triangles;
    return mesh;
}

/* The torus of about `wanted` triangles (500 segments around its tube);
   `copies` 2 adds a copy moved by `shift` along x. */
static bench_mesh make_tori(const char* name, size_t wanted, uint32_t copies, double shift) {
    const uint32_t segments = 500, rings = (uint32_t)(wanted / (2.0 * segments));
    const size_t vertices = (size_t)rings * segments, indices = 6 * vertices;
    bench_mesh mesh = new_mesh(name, copies * vertices, copies * indices / 3);
    double* positions = (double*)mesh.desc.positions;
    uint32_t* index_array = (uint32_t*)mesh.desc.indices;
    make_torus(rings, segments, positions, index_array);
    for (uint32_t c = 1; c < copies; ++c) {
        for (size_t v = 0; v < vertices; ++v) {
            double* p = positions + 3 * (c * vertices + v);
            memcpy(p, positions + 3 * v, 3 * sizeof *p);
            p[0] += c * shift;
        }
        for (size_t i = 0; i < indices; ++i)
            index_array[c * indices + i] = index_array[i] + c * (uint32_t)vertices;
    }
    return mesh;
}

/* k unit cubes, 1e6 from the origin, 12 outward triangles each: at one place
   (side 0), or stacked side x side x side, each resting against its
   neighbours. Each cube its own 8 vertices, or (soup) each triangle its own
   3, welded by the options, which accept the edges four faces share. */
static bench_mesh make_cubes(const char* name, uint32_t k, uint32_t side, int soup) {
    static const uint32_t cube[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                      1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    bench_mesh mesh = new_mesh(name, (size_t)k * (soup ? 36 : 8), 12 * (size_t)k);
    double* positions = (double*)mesh.desc.positions;
    uint32_t* indices = (uint32_t*)mesh.desc.indices;
    for (uint32_t c = 0; c < k; ++c) {
        const uint32_t at[3] = {side ? c % side : 0, side ? c / side % side : 0,
                                side ? c / side / side : 0};
        double corner[8][3];
        for (int v = 0; v < 8; ++v) {
            corner[v][0] = 1e6 + at[0] + (double)((v == 1 || v == 2 || v == 5 || v == 6));
            corner[v][1] = 1e6 + at[1] + (double)((v == 2 || v == 3 || v == 6 || v == 7));
            corner[v][2] = 1e6 + at[2] + (double)(v >= 4);
        }
        for (int i = 0; i < 36; ++i) {
            const size_t index = 36 * (size_t)c + (size_t)i;
            indices[index] = soup ? (uint32_t)index : cube[i] + 8 * c;
            if (soup) memcpy(positions + 3 * index, corner[cube[i]], sizeof corner[0]);
        }
        if (!soup) memcpy(positions + 24 * (size_t)c, corner, sizeof corner);
    }
    mesh.flags = soup ? POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD : 0;
    return mesh;
}

/* Turns point p about the unit axis k through (centre, centre, centre) by
   `angle` radians (Rodrigues' formula). */
static void turn_about(double* p, const double k[3], double centre, double angle) {
    const double v[3] = {p[0] - centre, p[1] - centre, p[2] - centre};
    const double cross[3] = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2],
                             k[0] * v[1] - k[1] * v[0]};
    const double along = (k[0] * v[0] + k[1] * v[1] + k[2] * v[2]) * (1 - cos(angle));
    for (int axis = 0; axis < 3; ++axis)
        p[axis] = centre + v[axis] * cos(angle) + cross[axis] * sin(angle) + k[axis] * along;
}

static double check_seconds(polymass_context* context, const bench_mesh* mesh, uint32_t flags,
                            uint32_t threads, polymass_diagnostics* report) {
    polymass_options options = POLYMASS_OPTIONS_INIT;
    options.flags = flags | mesh->flags;
    if (polymass_context_set_threads(context, threads) != POLYMASS_OK) {
        fprintf(stderr, "error: %s\n", polymass_context_message(context));
        exit(1);
    }
    return analysis_seconds(context, &mesh->desc, &options, report);
}

/* MeshLib's seconds on the mesh (the median of `rounds`, on one processor),
   or a negative value when it is not at hand or failed. */
static double meshlib_seconds(const bench_mesh* mesh, int rounds) {
    const char* python = getenv("POLYMASS_BENCH_MESHLIB");
    const char* script = getenv("POLYMASS_BENCH_MESHLIB_SCRIPT");
    if (!python || !*python || !script || !*script) return -1;
    char path[] = "/tmp/bench_intersections_XXXXXX";
    const int fd = mkstemp(path);
    if (fd < 0) return -1;
    FILE* file = fdopen(fd, "wb");
    const uint64_t counts[2] = {mesh->desc.vertex_count, mesh->triangles};
    fwrite(counts, sizeof counts, 1, file);
    fwrite(mesh->desc.positions, 3 * sizeof(double), mesh->desc.vertex_count, file);
    fwrite(mesh->desc.indices, 3 * sizeof(uint32_t), mesh->triangles, file);
    fclose(file);
    char command[1024];
    snprintf(command, sizeof command, "taskset -c 0 '%s' '%s' '%s' %d", python, script, path,
             rounds);
    FILE* output = popen(command, "r");
    double seconds = -1;
    if (output) {
        char line[256];
        if (fgets(line, sizeof line, output) && sscanf(line, "%lf", &seconds) != 1) seconds = -1;
        while (fgets(line, sizeof line, output)) continue;
        if (pclose(output) != 0) seconds = -1;
    }
    remove(path);
    return seconds;
}

enum { topology_1, intersections_1, topology_2, intersections_2, measures };
static const char* const names[measures] = {"topology checks", "with intersections",
                                            "topology checks, 2 threads",
                                            "with intersections, 2 threads"};

/* peer: whether MeshLib is measured too (it lists every pair, k^2 of a pile of k). */
static void run(const bench_mesh* mesh, int rounds, int peer, polymass_context* context) {
    double* seconds = checked_malloc((size_t)measures * (size_t)rounds * sizeof *seconds);
    polymass_diagnostics reports[measures];
    for (int r = 0; r < rounds; ++r) {
        double* s = seconds + (size_t)r * measures;
        const uint32_t skip = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
        s[topology_1] = check_seconds(context, mesh, skip, 1, &reports[topology_1]);
        s[intersections_1] = check_seconds(context, mesh, 0, 1, &reports[intersections_1]);
        s[topology_2] = check_seconds(context, mesh, skip, 2, &reports[topology_2]);
        s[intersections_2] = check_seconds(context, mesh, 0, 2, &reports[intersections_2]);
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
    /* The check's own time: the call with it less the call without it. */
    const double own_1 = medians[intersections_1] - medians[topology_1];
    const double own_2 = medians[intersections_2] - medians[topology_2];
    for (int m = 0; m < measures; ++m)
        printf("  %-30s %10.3f ms %8.2f M triangles/s\n", names[m], 1e3 * medians[m],
               (double)mesh->triangles / medians[m] / 1e6);
    printf("  %-30s %10.3f ms %8.2f M triangles/s  %6.2fx the topology checks' time\n",
           "the check alone", 1e3 * own_1, (double)mesh->triangles / own_1 / 1e6,
           own_1 / medians[topology_1]);
    printf(
        "  %-30s %10.3f ms %8.2f M triangles/s  %6.2fx the topology checks' time  %4.2fx "
        "one thread\n",
        "the check alone, 2 threads", 1e3 * own_2, (double)mesh->triangles / own_2 / 1e6,
        own_2 / medians[topology_2], own_1 / own_2);
    const double peer_seconds = peer ? meshlib_seconds(mesh, rounds) : -1;
    if (peer_seconds > 0)
        printf("  %-30s %10.3f ms %8.2f M triangles/s  polymass's check alone: %4.2fx its rate\n",
               "MeshLib, 1 processor", 1e3 * peer_seconds,
               (double)mesh->triangles / peer_seconds / 1e6, peer_seconds / own_1);
    else if (!peer)
        printf("  MeshLib: not measured (it lists all k^2 pairs of a pile: minutes)\n");
    else
        printf("  MeshLib: not measured (set POLYMASS_BENCH_MESHLIB to a python with meshlib)\n");
    fflush(stdout);
    free(seconds);
}

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? atoi(argv[1]) : 3;
    const double largest = argc > 2 ? atof(argv[2]) : 1e6;
    const char* only = argc > 3 ? argv[3] : "";
    polymass_context* context = NULL;
    if (rounds < 1 || largest < 1e5 || polymass_context_create(&context, NULL) != POLYMASS_OK) {
        fprintf(stderr, "usage: bench_intersections [rounds] [largest torus >= 1e5] [meshes]\n");
        return 1;
    }
    printf("libpolymass %s, median of %d interleaved rounds\n", polymass_version_string(), rounds);
    /* kind: 0 torus, 1 torus and its shifted copy, 2 separate cubes, 3 welded cubes, 4 pile,
       5 flattened torus, 6 pile of cubes each turned about (1, 2, 3), 7 about z. */
    static const struct {
        const char* name;
        int kind;
        double size;    /* triangles of a torus, or cubes */
        int when_named; /* run only when the meshes argument names it: minutes */
    } cases[] = {{"torus 1e5", 0, 1e5, 0},
                 {"torus 1e6", 0, 1e6, 0},
                 {"torus 1e7", 0, 1e7, 0},
                 {"torus 1e5 flattened to a hundredth of its height", 5, 1e5, 0},
                 {"torus 1e5 and a copy shifted by a tenth of its tube", 1, 1e5, 0},
                 {"1000 separate cubes resting on each other", 2, 1000, 0},
                 {"8000 separate cubes resting on each other", 2, 8000, 0},
                 {"1000 cubes resting on each other, one welded STL", 3, 1000, 0},
                 {"8000 cubes resting on each other, one welded STL", 3, 8000, 0},
                 {"pile of 1000 coincident cubes", 4, 1000, 0},
                 {"pile of 8000 coincident cubes", 4, 8000, 0},
                 {"pile of 1000 cubes, each turned", 6, 1000, 0},
                 {"pile of 8000 cubes, each turned", 6, 8000, 0},
                 {"pile of 1000 cubes turned about z alone", 7, 1000, 0},
                 {"pile of 8000 cubes turned about z alone", 7, 8000, 1}};
    const double norm = sqrt(14.0);
    const double axes[2][3] = {{1 / norm, 2 / norm, 3 / norm}, {0, 0, 1}};
    for (size_t c = 0; c < sizeof cases / sizeof *cases; ++c) {
        const double size = cases[c].size;
        if (!strstr(cases[c].name, only) || (cases[c].when_named && !*only) ||
            (cases[c].kind == 0 && size > largest))
            continue;
        const uint32_t side = (uint32_t)(cbrt(size) + 0.5);
        bench_mesh mesh =
            cases[c].kind == 0 || cases[c].kind == 5 ? make_tori(cases[c].name, (size_t)size, 1, 0)
            : cases[c].kind == 1 ? make_tori(cases[c].name, (size_t)size, 2, 0.1)
                                 : make_cubes(cases[c].name, (uint32_t)size,
                                              cases[c].kind >= 4 ? 0 : side, cases[c].kind == 3);
        if (cases[c].kind == 5) { /* an affine map: still closed, still crossing nowhere */
            double* positions = (double*)mesh.desc.positions;
            for (size_t v = 0; v < mesh.desc.vertex_count; ++v)
                positions[3 * v + 2] = 1e6 + 0.01 * (positions[3 * v + 2] - 1e6);
        }
        if (cases[c].kind >= 6) { /* cube k turned about its centre by 0.3 k radians */
            double* positions = (double*)mesh.desc.positions;
            for (size_t v = 0; v < mesh.desc.vertex_count; ++v)
                turn_about(positions + 3 * v, axes[cases[c].kind - 6], 1e6 + 0.5,
                           0.3 * (double)(v / 8));
        }
        run(&mesh, rounds, !(cases[c].kind >= 4 && cases[c].kind != 5 && size > 1000), context);
        free((void*)mesh.desc.positions);
        free((void*)mesh.desc.indices);
    }
    polymass_context_destroy(context);
    return 0;
}
