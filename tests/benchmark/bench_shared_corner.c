/* Whether the intersection check grows with its input alone where very many
   separate parts touch at one place: k thin tetrahedra whose apexes are one
   point (a fan of needles spread over the sphere), and k thin tetrahedra
   sharing one edge (the pages of a book around its spine), for k = 1,000,
   4,000 and 8,000, far from the origin. No two parts cross; every part
   touches every other at the apex or along the spine, so every pair of
   parts' boxes overlap there. Prints the analysis (polymass_mesh_create)
   with the default options and with POLYMASS_OPTION_SKIP_INTERSECTION_CHECK,
   on one thread, the check's own time, and its ratio to the previous size's
   (8x the parts must be at most 10x the time). Asserts nothing about speed.

   Usage: bench_shared_corner [rounds] [meshes] (default 3 rounds; meshes: run
   only those whose name contains this text). */
#include <polymass/polymass.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"

static const double pi = 3.14159265358979323846;

/* Tetrahedron `part` of k, its four corners: a needle from the common apex
   out along the part's direction (spread over the sphere), or a page from
   the common spine out at the part's angle. */
static void part_corners(int book, uint32_t part, uint32_t k, double corner[4][3]) {
    const double origin[3] = {1e6, 2e6, -3e6};
    double local[4][3];
    if (book) {
        const double angle = 2 * pi * part / k, width = pi / k;
        const double spine[2][3] = {{0, 0, 0}, {0, 0, 1}};
        memcpy(local[0], spine[0], sizeof local[0]);
        memcpy(local[1], spine[1], sizeof local[1]);
        for (int e = 0; e < 2; ++e) {
            local[2 + e][0] = cos(angle + e * width);
            local[2 + e][1] = sin(angle + e * width);
            local[2 + e][2] = 0.5;
        }
    } else {
        /* Fibonacci directions: the needles' cones (width 0.2 of the spacing) never meet. */
        const double z = 1 - (2 * part + 1.0) / k, r = sqrt(1 - z * z);
        const double turn = part * pi * (3 - sqrt(5.0));
        const double d[3] = {r * cos(turn), r * sin(turn), z};
        /* two directions across d */
        double u[3] = {-d[1], d[0], 0};
        if (fabs(d[2]) > 0.9) u[0] = 0, u[1] = -d[2], u[2] = d[1];
        const double nu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int i = 0; i < 3; ++i) u[i] /= nu;
        const double v[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2],
                             d[0] * u[1] - d[1] * u[0]};
        const double width = 0.2 * sqrt(4 * pi / k);
        memset(local[0], 0, sizeof local[0]);
        for (int c = 0; c < 3; ++c) {
            const double a = 2 * pi * c / 3;
            for (int i = 0; i < 3; ++i)
                local[1 + c][i] = d[i] + width * (cos(a) * u[i] + sin(a) * v[i]);
        }
    }
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 3; ++i) corner[c][i] = origin[i] + local[c][i];
}

/* k parts, each its own 4 vertices, faces turned outward. */
static polymass_mesh_desc make_parts(int book, uint32_t k) {
    polymass_mesh_desc desc = {sizeof desc};
    double* positions = checked_malloc(12 * (size_t)k * sizeof *positions);
    uint32_t* indices = checked_malloc(12 * (size_t)k * sizeof *indices);
    for (uint32_t part = 0; part < k; ++part) {
        double corner[4][3];
        part_corners(book, part, k, corner);
        memcpy(positions + 12 * (size_t)part, corner, sizeof corner);
        double e[3][3];
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 3; ++i) e[c][i] = corner[c + 1][i] - corner[0][i];
        const double volume = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                              e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                              e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        /* With corner 0..3 positively turned, faces 0 2 1, 0 1 3, 0 3 2, 1 2 3 face out. */
        static const uint32_t faces[2][12] = {{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3},
                                              {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2}};
        for (int i = 0; i < 12; ++i)
            indices[12 * (size_t)part + (size_t)i] = faces[volume < 0][i] + 4 * part;
    }
    desc.positions = positions;
    desc.vertex_count = 4 * (size_t)k;
    desc.indices = indices;
    desc.index_count = 12 * (size_t)k;
    return desc;
}

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? atoi(argv[1]) : 3;
    const char* only = argc > 2 ? argv[2] : "";
    polymass_context* context = NULL;
    if (rounds < 1 || polymass_context_create(&context, NULL) != POLYMASS_OK ||
        polymass_context_set_threads(context, 1) != POLYMASS_OK) {
        fprintf(stderr, "usage: bench_shared_corner [rounds] [meshes]\n");
        return 1;
    }
    printf("libpolymass %s, one thread, median of %d interleaved rounds\n",
           polymass_version_string(), rounds);
    static const char* const kinds[2] = {"needles at one apex", "pages around one spine"};
    static const uint32_t sizes[3] = {1000, 4000, 8000};
    const polymass_options every_check = POLYMASS_OPTIONS_INIT;
    polymass_options skip = POLYMASS_OPTIONS_INIT;
    skip.flags = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    for (int book = 0; book < 2; ++book) {
        if (!strstr(kinds[book], only)) continue;
        double previous = 0;
        for (int s = 0; s < 3; ++s) {
            const polymass_mesh_desc desc = make_parts(book, sizes[s]);
            double* seconds = checked_malloc(2 * (size_t)rounds * sizeof *seconds);
            polymass_diagnostics reports[2];
            for (int r = 0; r < rounds; ++r) {
                seconds[2 * r] = analysis_seconds(context, &desc, &skip, &reports[0]);
                seconds[2 * r + 1] = analysis_seconds(context, &desc, &every_check, &reports[1]);
            }
            double medians[2];
            medians_of(seconds, rounds, 2, medians);
            const double own = medians[1] - medians[0];
            printf(
                "%u %s, %u triangles: %s (%llu shells, %llu overlapping; %llu touching)\n"
                "  topology checks %9.3f ms, with intersections %9.3f ms, the check alone "
                "%9.3f ms (%.2f M triangles/s)",
                sizes[s], kinds[book], 12 * sizes[s], polymass_status_string(reports[1].status),
                (unsigned long long)reports[1].shell_count,
                (unsigned long long)reports[1].overlapping_shells,
                (unsigned long long)reports[1].touching_face_pairs, 1e3 * medians[0],
                1e3 * medians[1], 1e3 * own, 12e-6 * sizes[s] / own);
            if (previous > 0)
                printf(", %.1fx the time of %ux fewer parts", own / previous,
                       sizes[s] / sizes[s - 1]);
            printf("\n");
            fflush(stdout);
            previous = own;
            free(seconds);
            free((void*)desc.positions);
            free((void*)desc.indices);
        }
    }
    polymass_context_destroy(context);
    return 0;
}
