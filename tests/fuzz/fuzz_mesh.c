/* libFuzzer target: arbitrary bytes as a mesh (and as a 2D polygon) through the
 * C API, with the documented invariants checked on every result.
 *
 * Input format (little-endian; tests/fuzz/make_corpus.py writes it; bytes past
 * the end of the input read as 0, bytes after what the header asks for are
 * ignored):
 *
 *   offset size
 *   0      1    layout bits
 *                 0    position type: 0 FLOAT64, 1 FLOAT32
 *                 1    index type: 0 UINT32, 1 UINT16
 *                 2    face_sizes given (else NULL: triangles)
 *                 3-4  position_stride: 0 packed (0), 1 one vertex (12/24),
 *                      2 one vertex + 8 bytes, 3 one vertex - 4 (too small: invalid)
 *                 5    index_count = the faces' total + the signed byte at 7
 *                      (indices past the total are 0; a negative delta cuts)
 *                 6    polygon points: 0 x, y of each vertex (the position array
 *                      itself when FLOAT64); 1 every coordinate as packed pairs
 *                 7    positions and indices at an odd address
 *   1      1    option flags (low 5 bits: POLYMASS_OPTION_*, but bit 4 asks for
 *               the intersection check, POLYMASS_OPTION_SKIP_INTERSECTION_CHECK
 *               inverted: the corpus was written when the check was opt-in,
 *               and its inputs keep their meaning); the high 3 bits
 *               choose the chain of modes of a last call, entry (byte >> 5)
 *               of `chains` below
 *   2      1    planarity tolerance: entry (byte % 8) of `tolerances` below;
 *               weld tolerance: entry (byte / 8 % 4) of `weld_tolerances`
 *   3      1    mass: bits 0-1: 0 NULL, 1 FROM_DENSITY, 2 FROM_TOTAL, 3 an
 *               unknown mode (2 + the byte's high bits)
 *   4      1    vertex_count V of one copy
 *   5      1    face_count F of one copy
 *   6      1    copies - 1: the mesh is repeated, copy c's indices + c * V
 *               (truncated to the index type) and its vertices the same;
 *               fewer copies when they would pass 2048 vertices or indices
 *   7      1    index_count delta (int8), when layout bit 5 is set
 *   8      8    density or mass (double, raw bits)
 *   16     24   a point for polymass_inertia_about (3 doubles, raw bits)
 *   40          F face sizes, one byte each (only when layout bit 2 is set;
 *               faces past 2048 indices are dropped)
 *               V vertices: 3 doubles or 3 floats each, raw bits
 *               the indices of one copy (sum of the face sizes, or 3 F): raw
 *               uint32 or uint16
 *
 * Every array handed to the library is exactly as large as the counts and
 * stride claim (allocated to that size, so AddressSanitizer sees any read
 * past it), never larger. A violated invariant prints what failed and traps.
 * The invariants: every status is one the function documents (never
 * POLYMASS_ERROR_INTERNAL), and the context's message is "" exactly after a
 * success; after a success every output is finite, volume, mass, density and
 * surface area are positive, principal moments ascend and the axes are a
 * rotation (orthonormal to 1e-9, det +1), the warnings match the options, and
 * the density or mass is the one asked for; after a failure the output struct
 * is untouched. Options are given per call: a refused option gives
 * INVALID_ARGUMENT and no mesh (the rest of the run then takes the defaults).
 * polymass_mesh_create gives a mesh exactly when the analysis ran, whose
 * polymass_mesh_status is what it returned and whose message is "" exactly
 * when it answered; its diagnostics have consistent counts, first locations
 * and checks, and the surface's verdict (the status, with the solid alone);
 * its shells and the shell of each face agree, numbered in the order of
 * their first faces, judged exactly when the shells were checked; its mass
 * properties, provenance and moments are there exactly when it answered, and
 * the inertia about the input's point follows the parallel-axis theorem.
 * polymass_mass_properties_compute is the same analysis: its status, message,
 * properties and provenance are those of polymass_mesh_create +
 * polymass_mesh_mass_properties + polymass_mesh_provenance, bit for bit, with
 * the solid alone and with a chain of modes; a chain answers with a mode of
 * the chain (or the solid, for repair), says so in its warnings, leaves the
 * diagnostics as they were, and answers a mesh the solid accepts bit for bit
 * as the solid does when it starts with the solid or repair.
 * polymass_weld_positions over the positions welds each vertex to the lowest
 * of its group, at the same position when the tolerance is 0.
 *
 * POLYMASS_FUZZ_VERBOSE=1 in the environment prints the decoded input and the
 * statuses, for reproducing a finding by hand. */
#include <math.h>
#include <polymass/polymass.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_checks.h"
#include "fuzz_input.h"

#define HEADER_SIZE 40
/* Bounds on the mesh, to keep one execution fast: under the sanitizers the
   campaign corpus's inputs take 3 ms on average, 27 ms at most (with 8192
   they took 13 ms on average, and a campaign ran a fourth as many; with 2048
   vertices and 6144 indices, 3.7 times as long as now). How the library
   scales with size is the business of the unit tests (piles of 1,000 cubes,
   300,000-triangle meshes, which take the radix sorts past 2048 keys that no
   mesh of these bounds reaches) and of the benchmarks, not of the fuzzer. */
#define MAX_TOTAL_VERTICES 2048u
#define MAX_TOTAL_INDICES 2048u

static const double tolerances[8] = {0.0, 1e-15, 1e-9, 1e-6, 1e-3, 0.5, 0.999999, 1.0 /* bad */};
/* With POLYMASS_OPTION_WELD_VERTICES: exact, finer than rounding, CAD noise, the largest. */
static const double weld_tolerances[4] = {0.0, 1e-18, 1e-9, POLYMASS_MAX_WELD_TOLERANCE};

static int verbose = -1;

static const char* current_call = "";

static void fail(const char* file, int line, const char* what, int32_t status,
                 const polymass_context* context) {
    fprintf(stderr, "\n%s:%d: invariant violated after %s: %s\n  status %d (%s), message \"%s\"\n",
            file, line, current_call, what, (int)status, polymass_status_string(status),
            context ? polymass_context_message(context) : "");
    fflush(stderr);
    __builtin_trap();
}

#define CHECK(condition, status, context)                                        \
    do {                                                                         \
        if (!(condition)) fail(__FILE__, __LINE__, #condition, status, context); \
    } while (0)

/* ------------------------------------------------------------------------ */
/* Invariants                                                               */
/* ------------------------------------------------------------------------ */

static int is_mesh_status(int32_t status) {
    switch (status) {
        case POLYMASS_OK:
        case POLYMASS_ERROR_INVALID_ARGUMENT:
        case POLYMASS_ERROR_OUT_OF_MEMORY:
        case POLYMASS_ERROR_NON_FINITE:
        case POLYMASS_ERROR_INDEX_OUT_OF_RANGE:
        case POLYMASS_ERROR_FACE_TOO_SMALL:
        case POLYMASS_ERROR_OPEN:
        case POLYMASS_ERROR_NON_MANIFOLD:
        case POLYMASS_ERROR_INCONSISTENT_ORIENTATION:
        case POLYMASS_ERROR_NON_PLANAR_FACE:
        case POLYMASS_ERROR_INTERSECTING:
        case POLYMASS_ERROR_INVERTED:
        case POLYMASS_ERROR_ZERO_VOLUME:
        case POLYMASS_ERROR_OVERFLOW:
            return 1;
        default: /* POLYMASS_ERROR_INTERNAL is a library bug */
            return 0;
    }
}

static int is_polygon_status(int32_t status) {
    switch (status) {
        case POLYMASS_OK:
        case POLYMASS_ERROR_INVALID_ARGUMENT:
        case POLYMASS_ERROR_OUT_OF_MEMORY:
        case POLYMASS_ERROR_NON_FINITE:
        case POLYMASS_ERROR_FACE_TOO_SMALL:
        case POLYMASS_ERROR_ZERO_AREA:
        case POLYMASS_ERROR_OVERFLOW:
            return 1;
        default:
            return 0;
    }
}

/* A status is named, and the message is "" exactly after a success. */
static void check_status_and_message(int32_t status, const polymass_context* context) {
    const char* message = polymass_context_message(context);
    CHECK(message != NULL, status, context);
    CHECK(strcmp(polymass_status_string(status), "unknown status") != 0, status, context);
    if (status == POLYMASS_OK)
        CHECK(message[0] == '\0', status, context);
    else
        CHECK(message[0] != '\0', status, context);
}

/* The locations of a face or vertex finding: `kept` of them (all the count
   allows when exact, else at least one when count > 0), ascending, below
   limit, then POLYMASS_NONE. */
static int faces_listed(uint64_t count, const uint64_t first[POLYMASS_DIAGNOSTIC_LOCATIONS],
                        uint64_t limit, int exact) {
    const uint64_t most =
        count < POLYMASS_DIAGNOSTIC_LOCATIONS ? count : POLYMASS_DIAGNOSTIC_LOCATIONS;
    uint64_t kept = 0;
    size_t i;
    while (kept < POLYMASS_DIAGNOSTIC_LOCATIONS && first[kept] != POLYMASS_NONE) ++kept;
    for (i = kept; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i)
        if (first[i] != POLYMASS_NONE) return 0;
    if (exact ? kept != most : (kept > most || (count > 0) != (kept > 0))) return 0;
    for (i = 0; i < kept; ++i)
        if (first[i] >= limit || (i > 0 && first[i] <= first[i - 1])) return 0;
    return 1;
}

/* The same for edges: min(count, POLYMASS_DIAGNOSTIC_LOCATIONS) vertex pairs
   in range, of two distinct vertices, then POLYMASS_NONE pairs. */
static int edges_listed(uint64_t count, const uint64_t first[POLYMASS_DIAGNOSTIC_LOCATIONS][2],
                        uint64_t vertex_count) {
    const uint64_t most =
        count < POLYMASS_DIAGNOSTIC_LOCATIONS ? count : POLYMASS_DIAGNOSTIC_LOCATIONS;
    size_t i;
    for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
        if (i < most) {
            if (first[i][0] >= vertex_count || first[i][1] >= vertex_count ||
                first[i][0] == first[i][1])
                return 0;
        } else if (first[i][0] != POLYMASS_NONE || first[i][1] != POLYMASS_NONE) {
            return 0;
        }
    }
    return 1;
}

/* Face pairs: min(count, POLYMASS_DIAGNOSTIC_LOCATIONS) pairs (lower face,
   higher face) below face_count, lowest pairs first, then POLYMASS_NONE
   pairs; the count no more than the header says is counted. */
static int pairs_listed(uint64_t count, const uint64_t first[POLYMASS_DIAGNOSTIC_LOCATIONS][2],
                        uint64_t face_count) {
    const uint64_t most =
        count < POLYMASS_DIAGNOSTIC_LOCATIONS ? count : POLYMASS_DIAGNOSTIC_LOCATIONS;
    size_t i;
    if (count > POLYMASS_MAX_COUNTED_FACE_PAIRS) return 0;
    for (i = 0; i < POLYMASS_DIAGNOSTIC_LOCATIONS; ++i) {
        if (i < most) {
            if (first[i][0] >= first[i][1] || first[i][1] >= face_count) return 0;
            if (i > 0 && (first[i][0] < first[i - 1][0] ||
                          (first[i][0] == first[i - 1][0] && first[i][1] <= first[i - 1][1])))
                return 0;
        } else if (first[i][0] != POLYMASS_NONE || first[i][1] != POLYMASS_NONE) {
            return 0;
        }
    }
    return 1;
}

/* What an analysis with these option flags found. */
static void check_report(const polymass_diagnostics* d, uint32_t flags, uint64_t vertex_count,
                         const polymass_context* context) {
    const int32_t status = d->status;
    const uint32_t all_checks =
        POLYMASS_CHECKED_TOPOLOGY | POLYMASS_CHECKED_SHELLS | POLYMASS_CHECKED_INTERSECTIONS;
    CHECK(d->struct_size == sizeof *d, status, context);
    CHECK(is_mesh_status(status) && status != POLYMASS_ERROR_INVALID_ARGUMENT &&
              status != POLYMASS_ERROR_OUT_OF_MEMORY,
          status, context);
    CHECK(d->reserved == 0 && (d->checks & ~all_checks) == 0, status, context);
    /* A check skipped by name did not run. */
    if (flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS)
        CHECK(!(d->checks & (POLYMASS_CHECKED_TOPOLOGY | POLYMASS_CHECKED_INTERSECTIONS)), status,
              context);
    if (flags & POLYMASS_OPTION_SKIP_INTERSECTION_CHECK)
        CHECK(!(d->checks & POLYMASS_CHECKED_INTERSECTIONS), status, context);
    /* A valid solid with no check skipped passed every check. */
    if (status == POLYMASS_OK &&
        !(flags & (POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_SKIP_INTERSECTION_CHECK)))
        CHECK(d->checks == all_checks, status, context);
    /* Each finding lists min(count, POLYMASS_DIAGNOSTIC_LOCATIONS) locations,
       ascending and in range, then POLYMASS_NONE (bad indices are counted per
       index but listed per face: at least one face when there is any). */
    CHECK(faces_listed(d->non_finite_vertices, d->first_non_finite_vertices, vertex_count, 1),
          status, context);
    CHECK(faces_listed(d->out_of_range_indices, d->first_out_of_range_faces, d->face_count, 0),
          status, context);
    CHECK(faces_listed(d->small_faces, d->first_small_faces, d->face_count, 1), status, context);
    CHECK(faces_listed(d->degenerate_faces, d->first_degenerate_faces, d->face_count, 1), status,
          context);
    CHECK(faces_listed(d->non_planar_faces, d->first_non_planar_faces, d->face_count, 1), status,
          context);
    CHECK(edges_listed(d->open_edges, d->first_open_edges, vertex_count), status, context);
    CHECK(edges_listed(d->non_manifold_edges, d->first_non_manifold_edges, vertex_count), status,
          context);
    CHECK(edges_listed(d->misoriented_edges, d->first_misoriented_edges, vertex_count), status,
          context);
    CHECK(d->shell_count <= d->face_count, status, context);
    CHECK(faces_listed(d->inverted_shells, d->first_inverted_shells, d->face_count, 1), status,
          context);
    CHECK(faces_listed(d->overlapping_shells, d->first_overlapping_shells, d->face_count, 1),
          status, context);
    CHECK(pairs_listed(d->intersecting_face_pairs, d->first_intersecting_face_pairs, d->face_count),
          status, context);
    CHECK(pairs_listed(d->touching_face_pairs, d->first_touching_face_pairs, d->face_count), status,
          context);
    if (status == POLYMASS_OK) {
        CHECK(d->non_finite_vertices == 0 && d->out_of_range_indices == 0 && d->small_faces == 0,
              status, context);
        CHECK(d->open_edges == 0 && d->misoriented_edges == 0 && d->non_planar_faces == 0, status,
              context);
        CHECK(d->intersecting_face_pairs == 0, status, context);
        CHECK(isfinite(d->signed_volume) && d->signed_volume != 0.0, status, context);
        CHECK(d->used_vertex_count <= vertex_count, status, context);
    }
}

/* The principal axes: columns of a proper rotation. */
static void check_rotation(const double* r, int32_t status, const polymass_context* context) {
    int i, j, k;
    double det;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double dot = 0.0;
            for (k = 0; k < 3; ++k) dot += r[3 * k + i] * r[3 * k + j];
            CHECK(fabs(dot - (i == j ? 1.0 : 0.0)) <= 1e-9, status, context);
        }
    det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
          r[2] * (r[3] * r[7] - r[4] * r[6]);
    CHECK(fabs(det - 1.0) <= 1e-9, status, context);
}

/* The warnings of an answer by another mode than the solid. */
static const uint32_t mode_warnings =
    POLYMASS_WARNING_REPAIRED | POLYMASS_WARNING_SHELL | POLYMASS_WARNING_HULL;

static void check_properties(const polymass_mass_properties* p, uint32_t flags,
                             const polymass_mass_desc* mass, int32_t status,
                             const polymass_context* context) {
    const uint32_t known = POLYMASS_WARNING_INVERTED | POLYMASS_WARNING_DEGENERATE_FACES |
                           POLYMASS_WARNING_UNCHECKED | POLYMASS_WARNING_NON_MANIFOLD |
                           POLYMASS_WARNING_TOUCHING_FACES |
                           POLYMASS_WARNING_INTERSECTIONS_UNCHECKED | mode_warnings;
    const uint32_t skip_intersections =
        POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    /* A repaired surface, a wall and a hull are judged with options of their own. */
    const int other_mode = (p->warnings & mode_warnings) != 0;
    CHECK(p->struct_size == sizeof *p, status, context);
    /* Every double of the struct, from volume to principal_axes; the error
       bounds are numbers, infinite where rounding could be the whole mass. */
    CHECK(all_finite(&p->volume, (offsetof(polymass_mass_properties, error_bound_volume) -
                                  offsetof(polymass_mass_properties, volume)) /
                                     sizeof(double)),
          status, context);
    CHECK(p->error_bound_volume >= 0.0 && p->error_bound_center_of_mass >= 0.0 &&
              p->error_bound_inertia >= 0.0 && p->error_bound_principal_moments >= 0.0 &&
              p->error_bound_principal_axes >= 0.0 && p->error_bound_principal_axes <= 1.5708,
          status, context);
    CHECK(p->volume > 0.0, status, context);
    CHECK(p->mass > 0.0 && p->density > 0.0, status, context);
    CHECK(p->surface_area > 0.0, status, context);
    CHECK(p->principal_moments[0] <= p->principal_moments[1] &&
              p->principal_moments[1] <= p->principal_moments[2],
          status, context);
    check_rotation(p->principal_axes, status, context);

    CHECK((p->warnings & ~known) == 0, status, context);
    if (!other_mode) {
        CHECK(!!(p->warnings & POLYMASS_WARNING_UNCHECKED) ==
                  !!(flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS),
              status, context);
        CHECK(!!(p->warnings & POLYMASS_WARNING_INTERSECTIONS_UNCHECKED) ==
                  !!(flags & skip_intersections),
              status, context);
    }
    if (p->warnings & POLYMASS_WARNING_INVERTED)
        CHECK(flags & POLYMASS_OPTION_ACCEPT_INVERTED, status, context);
    if (p->warnings & POLYMASS_WARNING_NON_MANIFOLD)
        CHECK((flags & POLYMASS_OPTION_ACCEPT_NON_MANIFOLD) ||
                  (p->warnings & POLYMASS_WARNING_REPAIRED),
              status, context);

    if (!mass)
        CHECK(p->density == 1.0, status, context);
    else if (mass->mass_mode == POLYMASS_MASS_FROM_DENSITY)
        CHECK(p->density == mass->density, status, context);
    else
        /* mass = (mass / volume) * volume: a few roundings, or the density's
           last place when it is subnormal. */
        CHECK(fabs(p->mass - mass->mass) <=
                  1e-12 * mass->mass + 4.0 * p->volume * 4.9406564584124654e-324,
              status, context);
}

static void check_polygon(const polymass_polygon_properties* q, int32_t status,
                          const polymass_context* context) {
    const double half_pi = 1.5707963267948966;
    CHECK(q->struct_size == sizeof *q, status, context);
    CHECK(q->orientation == POLYMASS_COUNTER_CLOCKWISE || q->orientation == POLYMASS_CLOCKWISE,
          status, context);
    CHECK(all_finite(&q->area,
                     (sizeof *q - offsetof(polymass_polygon_properties, area)) / sizeof(double)),
          status, context);
    CHECK(q->area > 0.0, status, context);
    CHECK(q->principal_moments[0] <= q->principal_moments[1], status, context);
    CHECK(q->principal_angle > -half_pi - 1e-12 && q->principal_angle <= half_pi + 1e-12, status,
          context);
}

static void print_doubles(const char* name, const double* values, size_t count) {
    size_t i;
    fprintf(stderr, "  %s", name);
    for (i = 0; i < count; ++i) fprintf(stderr, " %.17g", values[i]);
    fprintf(stderr, "\n");
}

/* Coordinate k of vertex i of a description whose stride is valid. */
static double vertex_coordinate(const polymass_mesh_desc* d, uint64_t i, int k) {
    const size_t element = d->position_type == POLYMASS_POSITION_FLOAT32 ? 4 : 8;
    const size_t stride = d->position_stride ? (size_t)d->position_stride : 3 * element;
    const unsigned char* at = (const unsigned char*)d->positions + i * stride + k * element;
    double value;
    if (element == 4) {
        float f;
        memcpy(&f, at, 4);
        value = f;
    } else {
        memcpy(&value, at, 8);
    }
    return value;
}

/* The decoded mesh, for POLYMASS_FUZZ_VERBOSE: positions in %a, exactly. */
static void print_mesh(const polymass_mesh_desc* d) {
    uint64_t i;
    int k;
    for (i = 0; i < d->vertex_count; ++i) {
        fprintf(stderr, "  v%llu", (unsigned long long)i);
        for (k = 0; k < 3; ++k) fprintf(stderr, " %a", vertex_coordinate(d, i, k));
        fprintf(stderr, "\n");
    }
    fprintf(stderr, "  indices");
    for (i = 0; i < d->index_count; ++i) {
        uint32_t index;
        if (d->index_type == POLYMASS_INDEX_UINT16) {
            uint16_t small;
            memcpy(&small, (const unsigned char*)d->indices + 2 * i, 2);
            index = small;
        } else {
            memcpy(&index, (const unsigned char*)d->indices + 4 * i, 4);
        }
        fprintf(stderr, " %u", (unsigned)index);
    }
    fprintf(stderr, "\n");
}

static void print_properties(const polymass_mass_properties* p) {
    fprintf(stderr, "  warnings 0x%x\n", (unsigned)p->warnings);
    print_doubles("volume mass density surface_area", &p->volume, 4);
    print_doubles("center_of_mass", p->center_of_mass, 3);
    print_doubles("inertia", p->inertia, 9);
    print_doubles("inertia_origin", p->inertia_origin, 9);
    print_doubles("principal_moments", p->principal_moments, 3);
    print_doubles("principal_axes", p->principal_axes, 9);
}

static void print_polygon(const polymass_polygon_properties* q) {
    fprintf(stderr, "  orientation %d\n", (int)q->orientation);
    print_doubles("area", &q->area, 1);
    print_doubles("centroid", q->centroid, 2);
    print_doubles("second_moments", q->second_moments, 3);
    print_doubles("second_moments_origin", q->second_moments_origin, 3);
    print_doubles("polar_moment", &q->polar_moment, 1);
    print_doubles("principal_moments", q->principal_moments, 2);
    print_doubles("principal_angle", &q->principal_angle, 1);
}

/* ------------------------------------------------------------------------ */
/* Buffers exactly as large as claimed, optionally at an odd address        */
/* ------------------------------------------------------------------------ */

typedef struct buffer {
    uint8_t* block; /* what malloc returned */
    uint8_t* data;  /* block, or block + 1 */
} buffer;

static uint8_t* buffer_make(buffer* b, size_t size, int odd) {
    const size_t total = size + (size_t)odd;
    b->block = (uint8_t*)malloc(total ? total : 1);
    if (!b->block) abort();
    /* The claimed array ends where the block ends: a read past it is a heap
       overflow. */
    b->data = b->block + odd;
    return b->data;
}

static void put_index(uint8_t* indices, int index16, size_t position, uint64_t value) {
    if (index16) {
        const uint16_t v = (uint16_t)value;
        memcpy(indices + 2 * position, &v, 2);
    } else {
        const uint32_t v = (uint32_t)value;
        memcpy(indices + 4 * position, &v, 4);
    }
}

/* The chains of modes the last call tries (header byte 1's high bits). */
static const uint32_t chains[8][POLYMASS_MAX_MODES] = {
    {POLYMASS_MODE_REPAIR},
    {POLYMASS_MODE_SOLID, POLYMASS_MODE_REPAIR, POLYMASS_MODE_HULL},
    {POLYMASS_MODE_HULL},
    {POLYMASS_MODE_SHELL},
    {POLYMASS_MODE_SOLID, POLYMASS_MODE_REPAIR, POLYMASS_MODE_SHELL, POLYMASS_MODE_HULL},
    {POLYMASS_MODE_REPAIR, POLYMASS_MODE_HULL},
    {POLYMASS_MODE_SHELL, POLYMASS_MODE_HULL},
    {POLYMASS_MODE_SOLID, POLYMASS_MODE_HULL},
};

static int in_chain(const uint32_t* modes, uint32_t mode) {
    int i;
    for (i = 0; i < POLYMASS_MAX_MODES; ++i)
        if (modes[i] == mode) return 1;
    return 0;
}

/* ------------------------------------------------------------------------ */
/* One analysis and the questions to it                                     */
/* ------------------------------------------------------------------------ */

/* A mesh the library made, and its answers. */
typedef struct analysis {
    polymass_mesh* mesh; /* NULL when the analysis did not run */
    int32_t status;
    char message[1024];          /* the mesh's, or the context's without a mesh */
    polymass_diagnostics report; /* with a mesh */
    int32_t properties_status;   /* polymass_mesh_mass_properties, with a mesh */
    char properties_message[1024];
    polymass_mass_properties properties;
    polymass_provenance provenance;
} analysis;

/* polymass_mesh_create: a mesh exactly when the analysis ran, whose status and
   message are what it says; then its diagnostics. */
static void analyse(analysis* a, polymass_context* context, const polymass_mesh_desc* desc,
                    const polymass_options* options, uint64_t vertex_count) {
    int32_t status;
    current_call = "polymass_mesh_create";
    a->mesh = (polymass_mesh*)&a->mesh; /* garbage: must become a mesh or NULL */
    a->status = polymass_mesh_create(&a->mesh, context, desc, options);
    CHECK(is_mesh_status(a->status), a->status, context);
    if (a->mesh == NULL) {
        /* It did not run: the caller's mistake, or no memory. */
        CHECK(a->status == POLYMASS_ERROR_INVALID_ARGUMENT ||
                  a->status == POLYMASS_ERROR_OUT_OF_MEMORY,
              a->status, context);
        check_status_and_message(a->status, context);
        snprintf(a->message, sizeof a->message, "%s", polymass_context_message(context));
        return;
    }
    CHECK(a->mesh != (polymass_mesh*)&a->mesh && a->status != POLYMASS_ERROR_INVALID_ARGUMENT &&
              a->status != POLYMASS_ERROR_OUT_OF_MEMORY,
          a->status, context);
    current_call = "polymass_mesh_status";
    CHECK(polymass_mesh_status(a->mesh) == a->status, a->status, context);
    snprintf(a->message, sizeof a->message, "%s", polymass_mesh_message(a->mesh));

    current_call = "polymass_mesh_diagnostics";
    memset(&a->report, 0xA5, sizeof a->report);
    a->report.struct_size = sizeof a->report;
    status = polymass_mesh_diagnostics(&a->report, context, a->mesh);
    CHECK(status == POLYMASS_OK, status, context);
    check_status_and_message(status, context);
    check_report(&a->report, options->flags, vertex_count, context);
    /* The message says what is wrong with the surface, also when a later
       mode answered, and why no mode answered: "" exactly for a mesh that
       answered as the valid solid it is. */
    current_call = "polymass_mesh_message";
    CHECK((a->message[0] == '\0') == (a->status == POLYMASS_OK && a->report.status == POLYMASS_OK),
          a->status, context);
    if (verbose)
        fprintf(stderr,
                "fuzz_mesh: create %d (%s)\n  report: status %d, checks 0x%x, faces %llu, used "
                "vertices %llu, edges %llu, shells %llu, degenerate faces %llu, max non-planarity "
                "%.17g, signed volume %.17g\n",
                (int)a->status, a->message, (int)a->report.status, (unsigned)a->report.checks,
                (unsigned long long)a->report.face_count,
                (unsigned long long)a->report.used_vertex_count,
                (unsigned long long)a->report.edge_count, (unsigned long long)a->report.shell_count,
                (unsigned long long)a->report.degenerate_faces, a->report.max_non_planarity,
                a->report.signed_volume);
}

/* The shells and the shell of each face: every face in one shell, shells
   numbered in the order of their first faces, judged exactly when the
   analysis judged them. */
static void check_shells(const analysis* a, polymass_context* context) {
    static polymass_shell shells[MAX_TOTAL_INDICES + 1];
    /* Faces of 0 vertices are faces too: up to 255 per copy, 256 copies. */
    static uint32_t shell_of_face[256 * 256];
    const polymass_diagnostics* d = &a->report;
    const int judged = (d->checks & POLYMASS_CHECKED_SHELLS) != 0;
    uint64_t count = UINT64_MAX, s, f, faces = 0;
    int32_t status;

    current_call = "polymass_mesh_shells";
    status = polymass_mesh_shells(NULL, 0, &count, context, a->mesh);
    CHECK(status == POLYMASS_OK && count == d->shell_count, status, context);
    CHECK(count <= MAX_TOTAL_INDICES, status, context);
    /* Room for one: only the first is written. */
    memset(shells, 0xA5, 2 * sizeof shells[0]);
    polymass_shell_init(&shells[0], sizeof shells[0]);
    status = polymass_mesh_shells(shells, 1, &count, context, a->mesh);
    CHECK(status == POLYMASS_OK && count == d->shell_count, status, context);
    CHECK(shells[1].struct_size == 0xA5A5A5A5u, status, context);
    for (s = 0; s < count; ++s) polymass_shell_init(&shells[s], sizeof shells[s]);
    status = polymass_mesh_shells(shells, count, &count, context, a->mesh);
    CHECK(status == POLYMASS_OK && count == d->shell_count, status, context);
    check_status_and_message(status, context);
    for (s = 0; s < count; ++s) {
        const polymass_shell* shell = &shells[s];
        if (verbose)
            fprintf(stderr, "  shell %llu: kind %d, %llu faces from %llu, signed volume %.17g\n",
                    (unsigned long long)s, (int)shell->kind, (unsigned long long)shell->face_count,
                    (unsigned long long)shell->first_face, shell->signed_volume);
        CHECK(shell->kind >= POLYMASS_SHELL_UNJUDGED && shell->kind <= POLYMASS_SHELL_NO_VOLUME,
              status, context);
        CHECK((shell->kind != POLYMASS_SHELL_UNJUDGED) == judged, status, context);
        /* NaN when unjudged, or for a shell of no volume whose volume is
           beyond a double's range (coordinates near overflow). */
        if (!judged)
            CHECK(isnan(shell->signed_volume), status, context);
        else if (shell->kind != POLYMASS_SHELL_NO_VOLUME)
            CHECK(!isnan(shell->signed_volume), status, context);
        CHECK(shell->face_count > 0 && shell->first_face < d->face_count, status, context);
        CHECK(s == 0 ? shell->first_face == 0 : shell->first_face > shells[s - 1].first_face,
              status, context);
        faces += shell->face_count;
    }
    CHECK(count == 0 || faces == d->face_count, status, context);

    current_call = "polymass_mesh_shell_of_face";
    CHECK(d->face_count <= sizeof shell_of_face / sizeof shell_of_face[0], -1, context);
    status = polymass_mesh_shell_of_face(shell_of_face, d->face_count, context, a->mesh);
    check_status_and_message(status, context);
    if (status != POLYMASS_OK) {
        CHECK(status == a->status && (status == POLYMASS_ERROR_NON_FINITE ||
                                      status == POLYMASS_ERROR_INDEX_OUT_OF_RANGE ||
                                      status == POLYMASS_ERROR_FACE_TOO_SMALL),
              status, context);
        return;
    }
    for (f = 0, s = 0; f < d->face_count; ++f) {
        /* A new shell's number is the next one, and it starts where its
           polymass_shell says. */
        CHECK(shell_of_face[f] <= s && shell_of_face[f] < count, status, context);
        if (shell_of_face[f] == s) CHECK(shells[s++].first_face == f, status, context);
    }
    CHECK(s == count, status, context);
}

/* The answers of a mesh: its mass properties, provenance and moments exactly
   when it answered (the mesh's status and message otherwise), the output
   untouched on a failure, and the inertia about the input's point. */
static void ask(analysis* a, polymass_context* context, const polymass_mass_desc* mass,
                int mass_valid, uint32_t flags, const double point[3]) {
    polymass_mass_properties untouched;
    polymass_provenance provenance_untouched;
    polymass_moments moments, moments_untouched;
    int32_t status;

    current_call = "polymass_mesh_mass_properties";
    memset(&a->properties, 0xA5, sizeof a->properties);
    a->properties.struct_size = sizeof a->properties;
    untouched = a->properties;
    a->properties_status = polymass_mesh_mass_properties(&a->properties, context, a->mesh, mass);
    check_status_and_message(a->properties_status, context);
    snprintf(a->properties_message, sizeof a->properties_message, "%s",
             polymass_context_message(context));
    if (verbose)
        fprintf(stderr, "fuzz_mesh: mesh_mass_properties %d (%s)\n", (int)a->properties_status,
                a->properties_message);
    if (!mass_valid && a->properties_status == POLYMASS_ERROR_INVALID_ARGUMENT) {
        /* the mass refused, whatever the mesh */
    } else if (a->status != POLYMASS_OK) {
        CHECK(a->properties_status == a->status, a->properties_status, context);
        CHECK(strcmp(a->properties_message, a->message) == 0, a->properties_status, context);
    } else {
        CHECK(mass_valid, a->properties_status, context);
        CHECK(a->properties_status == POLYMASS_OK ||
                  a->properties_status == POLYMASS_ERROR_OUT_OF_MEMORY ||
                  a->properties_status == POLYMASS_ERROR_OVERFLOW,
              a->properties_status, context);
    }
    if (a->properties_status == POLYMASS_OK) {
        const char* violation;
        if (verbose) print_properties(&a->properties);
        check_properties(&a->properties, flags, mass, a->properties_status, context);
        violation = inertia_about_violation(&a->properties, point);
        if (violation) fail(__FILE__, __LINE__, violation, a->properties_status, context);
    } else {
        CHECK(memcmp(&a->properties, &untouched, sizeof untouched) == 0, a->properties_status,
              context);
    }

    current_call = "polymass_mesh_provenance";
    memset(&a->provenance, 0xA5, sizeof a->provenance);
    a->provenance.struct_size = sizeof a->provenance;
    provenance_untouched = a->provenance;
    status = polymass_mesh_provenance(&a->provenance, context, a->mesh);
    check_status_and_message(status, context);
    CHECK(status == a->status, status, context);
    if (status != POLYMASS_OK)
        CHECK(memcmp(&a->provenance, &provenance_untouched, sizeof a->provenance) == 0, status,
              context);

    current_call = "polymass_mesh_moments";
    memset(&moments, 0xA5, sizeof moments);
    moments.struct_size = sizeof moments;
    moments_untouched = moments;
    status = polymass_mesh_moments(&moments, context, a->mesh);
    check_status_and_message(status, context);
    /* The mesh's status, or (reported to the lead: the header does not say
       it) the overflow of moments about the reference point of a body whose
       mass properties fit. */
    CHECK(status == a->status || (a->status == POLYMASS_OK && status == POLYMASS_ERROR_OVERFLOW),
          status, context);
    if (status == POLYMASS_OK) {
        CHECK(!(moments.flags & POLYMASS_MOMENTS_PARTIAL), status, context);
        CHECK(all_finite(moments.reference, 3) && isfinite(moments.volume) &&
                  moments.volume > 0.0 && moments.mass == moments.volume &&
                  all_finite(moments.first, 3) && all_finite(moments.second, 6),
              status, context);
    } else {
        CHECK(memcmp(&moments, &moments_untouched, sizeof moments) == 0, status, context);
    }
}

/* polymass_mass_properties_compute is the analysis polymass_mesh_create
   makes: the same status (and message, with the solid alone), and on a
   success the same properties and provenance, bit for bit. A refused mass may be refused before the
   surface is read. */
static void check_one_call(const analysis* a, polymass_context* context,
                           const polymass_mesh_desc* desc, const polymass_options* options,
                           const polymass_mass_desc* mass, int mass_valid) {
    polymass_mass_properties properties, untouched;
    polymass_provenance provenance, provenance_untouched;
    int32_t status;
    current_call = "polymass_mass_properties_compute";
    memset(&properties, 0xA5, sizeof properties);
    properties.struct_size = sizeof properties;
    untouched = properties;
    memset(&provenance, 0xA5, sizeof provenance);
    provenance.struct_size = sizeof provenance;
    provenance_untouched = provenance;
    status =
        polymass_mass_properties_compute(&properties, &provenance, context, desc, options, mass);
    CHECK(is_mesh_status(status), status, context);
    check_status_and_message(status, context);
    if (verbose)
        fprintf(stderr, "fuzz_mesh: compute %d (%s)\n", (int)status,
                polymass_context_message(context));
    if (a->mesh == NULL) {
        CHECK(status == a->status, status, context);
        if (mass_valid)
            CHECK(strcmp(polymass_context_message(context), a->message) == 0, status, context);
    } else if (!mass_valid && status == POLYMASS_ERROR_INVALID_ARGUMENT) {
        /* the mass refused first */
    } else {
        CHECK(status == a->properties_status, status, context);
        /* The same words with the solid alone; a chain's names each mode,
           the solid too, where the mesh's leads with the surface's defect. */
        if (options->modes[0] == POLYMASS_MODE_NONE ||
            (options->modes[0] == POLYMASS_MODE_SOLID && options->modes[1] == POLYMASS_MODE_NONE))
            CHECK(strcmp(polymass_context_message(context), a->properties_message) == 0, status,
                  context);
    }
    if (status == POLYMASS_OK) {
        CHECK(memcmp(&properties, &a->properties, sizeof properties) == 0, status, context);
        CHECK(memcmp(&provenance, &a->provenance, sizeof provenance) == 0, status, context);
    } else {
        CHECK(memcmp(&properties, &untouched, sizeof properties) == 0, status, context);
        CHECK(memcmp(&provenance, &provenance_untouched, sizeof provenance) == 0, status, context);
    }
}

/* A NaN's bits with the quiet bit set: the exact weld reads coordinates as
   values (-0 is +0, a NaN is quiet), so NaNs of one payload are one. */
static uint64_t quiet_bits(double value) {
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits | (UINT64_C(1) << 51);
}

/* polymass_weld_positions over the description's positions: each vertex
   welded to the lowest of its group (itself for the group's lowest, which
   the distinct count counts), at the same position when the tolerance is 0
   (+0 and -0 one, NaNs of one payload one); non-finite coordinates an error only
   above 0; a stride smaller than a vertex refused. */
static void check_weld(polymass_context* context, const polymass_mesh_desc* desc, int stride_valid,
                       double tolerance) {
    static uint32_t vertex_of[MAX_TOTAL_VERTICES];
    uint64_t distinct = UINT64_MAX, own = 0, i;
    int finite = 1, k;
    int32_t status;
    current_call = "polymass_weld_positions";
    status =
        polymass_weld_positions(vertex_of, &distinct, context, desc->positions, desc->position_type,
                                desc->vertex_count, desc->position_stride, tolerance);
    check_status_and_message(status, context);
    if (verbose)
        fprintf(stderr, "fuzz_mesh: weld (tolerance %g) %d (%s), %llu distinct\n", tolerance,
                (int)status, polymass_context_message(context), (unsigned long long)distinct);
    CHECK(status == POLYMASS_OK || status == POLYMASS_ERROR_NON_FINITE ||
              status == POLYMASS_ERROR_INVALID_ARGUMENT,
          status, context);
    if (desc->vertex_count == 0) return; /* nothing to weld: no verdict on the rest */
    CHECK((status == POLYMASS_ERROR_INVALID_ARGUMENT) == !stride_valid, status, context);
    if (!stride_valid) return;
    for (i = 0; i < desc->vertex_count && finite; ++i)
        for (k = 0; k < 3; ++k) finite = finite && isfinite(vertex_coordinate(desc, i, k));
    CHECK((status == POLYMASS_ERROR_NON_FINITE) == (tolerance > 0.0 && !finite), status, context);
    if (status != POLYMASS_OK) return;
    for (i = 0; i < desc->vertex_count; ++i) {
        const uint32_t root = vertex_of[i];
        CHECK(root <= i && vertex_of[root] == root, status, context);
        own += root == i;
        if (tolerance == 0.0)
            for (k = 0; k < 3; ++k) {
                const double a = vertex_coordinate(desc, i, k),
                             b = vertex_coordinate(desc, root, k);
                CHECK(a == b || (isnan(a) && isnan(b) && quiet_bits(a) == quiet_bits(b)), status,
                      context);
            }
    }
    CHECK(distinct == own, status, context);
}

/* ------------------------------------------------------------------------ */

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    reader r = {data, size, 0};
    uint8_t header[HEADER_SIZE];
    int float32, index16, with_face_sizes, stride_choice, adjust_count, packed_pairs, odd;
    uint32_t flags;
    size_t vertex_bytes, index_bytes, one_v, one_f, copies, one_i, total_v, total_f, base_i;
    size_t index_count, c, i, positions_size;
    uint64_t stride;
    uint8_t one_sizes[256];
    polymass_context* context = NULL;
    polymass_options options, chain_options;
    polymass_mass_desc mass_desc, *mass = NULL;
    polymass_mesh_desc desc;
    const uint32_t* chain;
    polymass_polygon_properties q, q_untouched;
    buffer positions_buffer, indices_buffer;
    uint8_t *positions, *indices, *one_positions, *one_indices;
    uint32_t* face_sizes = NULL;
    double* points;
    double point[3];
    size_t point_count;
    uint64_t point_stride;
    int32_t status_polygon;
    int mass_valid;
    /* static: large, and one execution at a time */
    static analysis solid, chained;

    if (verbose < 0) verbose = getenv("POLYMASS_FUZZ_VERBOSE") != NULL;

    take(&r, header, sizeof header);
    float32 = header[0] & 1;
    index16 = (header[0] >> 1) & 1;
    with_face_sizes = (header[0] >> 2) & 1;
    stride_choice = (header[0] >> 3) & 3;
    adjust_count = (header[0] >> 5) & 1;
    packed_pairs = (header[0] >> 6) & 1;
    odd = (header[0] >> 7) & 1;
    flags = (header[1] & 0x1Fu) ^ POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    chain = chains[header[1] >> 5];
    vertex_bytes = float32 ? 12 : 24;
    index_bytes = index16 ? 2 : 4;
    one_v = header[4];
    one_f = header[5];
    copies = (size_t)header[6] + 1;

    /* One copy's face sizes and index count. */
    one_i = 0;
    for (i = 0; i < one_f; ++i) {
        one_sizes[i] = with_face_sizes ? take_u8(&r) : 3;
        one_i += one_sizes[i];
    }
    /* One copy's faces past the bound on indices are dropped (their sizes are
       still read, so the bytes after them mean the same). */
    while (one_i > MAX_TOTAL_INDICES) one_i -= one_sizes[--one_f];
    /* Fewer copies when the whole would be too large. */
    while (copies > 1 &&
           (copies * one_v > MAX_TOTAL_VERTICES || copies * one_i > MAX_TOTAL_INDICES))
        --copies;
    total_v = copies * one_v;
    total_f = copies * one_f;
    base_i = copies * one_i;
    index_count = base_i;
    if (adjust_count) {
        const int delta = (int8_t)header[7];
        if (delta >= 0)
            index_count = base_i + (size_t)delta;
        else
            index_count = (size_t)-delta > base_i ? 0 : base_i - (size_t)-delta;
    }

    /* The stride the description claims, and the position array it implies:
       (V - 1) * stride + one vertex, exactly. */
    switch (stride_choice) {
        case 0:
            stride = 0;
            break;
        case 1:
            stride = vertex_bytes;
            break;
        case 2:
            stride = vertex_bytes + 8;
            break;
        default:
            stride = vertex_bytes - 4; /* invalid: smaller than a vertex */
            break;
    }
    {
        const size_t step = stride >= vertex_bytes ? (size_t)stride : vertex_bytes;
        positions_size = total_v ? (total_v - 1) * step + vertex_bytes : 0;
        positions = buffer_make(&positions_buffer, positions_size, odd);
        memset(positions, 0, positions_size);
        one_positions = (uint8_t*)malloc(one_v * vertex_bytes + 1);
        if (!one_positions) abort();
        take(&r, one_positions, one_v * vertex_bytes);
        for (c = 0; c < copies; ++c)
            for (i = 0; i < one_v; ++i)
                memcpy(positions + (c * one_v + i) * step, one_positions + i * vertex_bytes,
                       vertex_bytes);
        free(one_positions);
    }

    /* Indices: the copies, then zeros up to index_count. */
    indices = buffer_make(&indices_buffer, index_count * index_bytes, odd);
    memset(indices, 0, index_count * index_bytes);
    one_indices = (uint8_t*)malloc(one_i * index_bytes + 1);
    if (!one_indices) abort();
    take(&r, one_indices, one_i * index_bytes);
    for (c = 0; c < copies; ++c)
        for (i = 0; i < one_i && c * one_i + i < index_count; ++i) {
            uint64_t value;
            if (index16) {
                uint16_t v;
                memcpy(&v, one_indices + 2 * i, 2);
                value = v;
            } else {
                uint32_t v;
                memcpy(&v, one_indices + 4 * i, 4);
                value = v;
            }
            put_index(indices, index16, c * one_i + i, value + (uint64_t)c * one_v);
        }
    free(one_indices);

    if (with_face_sizes) {
        face_sizes = (uint32_t*)malloc(total_f ? total_f * sizeof *face_sizes : sizeof *face_sizes);
        if (!face_sizes) abort();
        for (c = 0; c < copies; ++c)
            for (i = 0; i < one_f; ++i) face_sizes[c * one_f + i] = one_sizes[i];
    }

    memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.position_type = float32 ? POLYMASS_POSITION_FLOAT32 : POLYMASS_POSITION_FLOAT64;
    desc.positions = positions;
    desc.vertex_count = total_v;
    desc.position_stride = stride;
    desc.index_type = index16 ? POLYMASS_INDEX_UINT16 : POLYMASS_INDEX_UINT32;
    desc.indices = indices;
    desc.index_count = index_count;
    desc.face_sizes = face_sizes;
    desc.face_count = with_face_sizes ? total_f : 0;

    switch (header[3] & 3) {
        case 0:
            mass = NULL;
            break;
        default:
            memset(&mass_desc, 0, sizeof mass_desc);
            mass_desc.struct_size = sizeof mass_desc;
            mass_desc.mass_mode = (header[3] & 3) == 1   ? POLYMASS_MASS_FROM_DENSITY
                                  : (header[3] & 3) == 2 ? POLYMASS_MASS_FROM_TOTAL
                                                         : 2u + (header[3] >> 2);
            memcpy(&mass_desc.density, header + 8, 8);
            memcpy(&mass_desc.mass, header + 8, 8);
            mass = &mass_desc;
            break;
    }
    memcpy(point, header + 16, sizeof point);
    mass_valid =
        !mass ||
        (mass->mass_mode == POLYMASS_MASS_FROM_DENSITY && isfinite(mass->density) &&
         mass->density > 0.0) ||
        (mass->mass_mode == POLYMASS_MASS_FROM_TOTAL && isfinite(mass->mass) && mass->mass > 0.0);

    if (verbose)
        fprintf(stderr,
                "fuzz_mesh: %s positions, %s indices, vertex_count %llu, stride %llu, "
                "index_count %llu, face_sizes %s, face_count %llu (copies %zu), flags 0x%x, "
                "tolerance %g, mass mode %s %g, point (%g, %g, %g)\n",
                float32 ? "float32" : "float64", index16 ? "uint16" : "uint32",
                (unsigned long long)total_v, (unsigned long long)stride,
                (unsigned long long)index_count, with_face_sizes ? "given" : "NULL",
                (unsigned long long)desc.face_count, copies, (unsigned)flags,
                tolerances[header[2] % 8],
                !mass                                           ? "NULL"
                : mass->mass_mode == POLYMASS_MASS_FROM_DENSITY ? "density"
                : mass->mass_mode == POLYMASS_MASS_FROM_TOTAL   ? "total"
                                                                : "unknown",
                mass ? mass->density : 0.0, point[0], point[1], point[2]);
    if (verbose) print_mesh(&desc);

    /* --- the options, per call ------------------------------------------- */
    current_call = "polymass_context_create";
    CHECK(polymass_context_create(&context, NULL) == POLYMASS_OK && context, -1, NULL);
    polymass_options_init(&options, sizeof options);
    options.flags = flags;
    options.planarity_tolerance = tolerances[header[2] % 8];
    options.weld_tolerance = weld_tolerances[header[2] / 8 % 4];
    if (!(options.planarity_tolerance < 1.0)) {
        /* Refused before any analysis; the rest of the run takes the defaults
           (as the inputs meant when options were a context's). */
        analyse(&solid, context, &desc, &options, total_v);
        CHECK(solid.mesh == NULL && solid.status == POLYMASS_ERROR_INVALID_ARGUMENT, solid.status,
              context);
        polymass_options_init(&options, sizeof options);
    }
    flags = options.flags;

    /* --- one analysis, the solid alone, and its questions ---------------- */
    analyse(&solid, context, &desc, &options, total_v);
    if (solid.mesh != NULL) {
        /* With the solid alone, the mesh's status is the surface's verdict
           (or the overflow of a valid solid's moments). */
        CHECK(solid.report.status == solid.status ||
                  (solid.status == POLYMASS_ERROR_OVERFLOW && solid.report.status == POLYMASS_OK),
              solid.status, context);
        check_shells(&solid, context);
        ask(&solid, context, mass, mass_valid, flags, point);
        if (solid.status == POLYMASS_OK)
            CHECK(solid.provenance.mode == POLYMASS_MODE_SOLID, solid.status, context);
    }
    /* The one call: the same analysis. */
    check_one_call(&solid, context, &desc, &options, mass, mass_valid);

    /* --- a chain of modes ------------------------------------------------ */
    chain_options = options;
    memcpy(chain_options.modes, chain, sizeof chain_options.modes);
    chain_options.shell_thickness = 1e-3;
    analyse(&chained, context, &desc, &chain_options, total_v);
    CHECK((chained.mesh == NULL) == (solid.mesh == NULL), chained.status, context);
    if (chained.mesh != NULL) {
        if (verbose)
            fprintf(stderr, "fuzz_mesh: modes %u,%u,%u,%u\n", (unsigned)chain[0],
                    (unsigned)chain[1], (unsigned)chain[2], (unsigned)chain[3]);
        /* What the checks found does not depend on the modes. */
        CHECK(memcmp(&chained.report, &solid.report, sizeof chained.report) == 0, chained.status,
              context);
        ask(&chained, context, mass, mass_valid, flags, point);
        if (chained.status == POLYMASS_OK) {
            const int32_t mode = chained.provenance.mode;
            CHECK(in_chain(chain, (uint32_t)mode) ||
                      (mode == POLYMASS_MODE_SOLID && in_chain(chain, POLYMASS_MODE_REPAIR)),
                  chained.status, context);
        }
        if (chained.properties_status == POLYMASS_OK) {
            const uint32_t warnings = chained.properties.warnings;
            const int32_t mode = chained.provenance.mode;
            CHECK(!!(warnings & POLYMASS_WARNING_REPAIRED) == (mode == POLYMASS_MODE_REPAIR) &&
                      !!(warnings & POLYMASS_WARNING_SHELL) == (mode == POLYMASS_MODE_SHELL) &&
                      !!(warnings & POLYMASS_WARNING_HULL) == (mode == POLYMASS_MODE_HULL),
                  chained.status, context);
        }
        /* A mesh the solid accepts is the solid's answer, bit for bit. */
        if (solid.status == POLYMASS_OK &&
            (chain[0] == POLYMASS_MODE_SOLID || chain[0] == POLYMASS_MODE_REPAIR)) {
            CHECK(chained.status == POLYMASS_OK && chained.provenance.mode == POLYMASS_MODE_SOLID &&
                      chained.properties_status == solid.properties_status,
                  chained.status, context);
            if (solid.properties_status == POLYMASS_OK)
                CHECK(memcmp(&chained.properties, &solid.properties, sizeof solid.properties) == 0,
                      chained.status, context);
        }
    }
    check_one_call(&chained, context, &desc, &chain_options, mass, mass_valid);
    polymass_mesh_destroy(solid.mesh);
    polymass_mesh_destroy(chained.mesh);

    /* --- welding over the positions alone -------------------------------- */
    check_weld(context, &desc, stride_choice != 3, weld_tolerances[header[2] / 8 % 4]);

    /* --- polymass_polygon_compute on the coordinates as 2D points ---------- */
    if (!float32 && !packed_pairs) {
        /* x, y of each vertex, read in place from the position array, at its
           (possibly odd) address and with the mesh's stride (or 20 bytes when
           that stride was the invalid one: still a whole point). */
        points = NULL;
        point_count = total_v;
        point_stride = stride ? stride : vertex_bytes;
    } else {
        /* Every coordinate, as consecutive (x, y) pairs of doubles. */
        const size_t step = stride >= vertex_bytes ? (size_t)stride : vertex_bytes;
        size_t k, n = 0;
        point_count = 3 * total_v / 2;
        points = (double*)malloc(point_count ? 2 * point_count * sizeof(double) : 1);
        if (!points) abort();
        for (i = 0; i < total_v && n < 2 * point_count; ++i)
            for (k = 0; k < 3 && n < 2 * point_count; ++k) {
                if (float32) {
                    float f;
                    memcpy(&f, positions + i * step + 4 * k, 4);
                    points[n++] = (double)f;
                } else {
                    memcpy(&points[n++], positions + i * step + 8 * k, 8);
                }
            }
        point_stride = 0;
    }
    current_call = "polymass_polygon_compute";
    memset(&q, 0xA5, sizeof q);
    q.struct_size = sizeof q;
    q_untouched = q;
    status_polygon = polymass_polygon_compute(
        &q, context, points ? points : (const double*)(const void*)positions, point_count,
        point_stride);
    CHECK(is_polygon_status(status_polygon), status_polygon, context);
    check_status_and_message(status_polygon, context);
    if (verbose)
        fprintf(stderr, "fuzz_mesh: polygon %d (%s)\n", (int)status_polygon,
                polymass_context_message(context));
    if (verbose && status_polygon == POLYMASS_OK) print_polygon(&q);
    if (verbose) {
        const uint8_t* base = points ? (const uint8_t*)points : positions;
        const uint64_t step = point_stride ? point_stride : 16;
        for (i = 0; i < point_count && i < 64; ++i) {
            double xy[2];
            memcpy(xy, base + i * step, sizeof xy);
            fprintf(stderr, "  point %zu: %.17g %.17g\n", i, xy[0], xy[1]);
        }
    }
    if (status_polygon == POLYMASS_OK)
        check_polygon(&q, status_polygon, context);
    else
        CHECK(memcmp(&q, &q_untouched, sizeof q) == 0, status_polygon, context);
    if (point_count < 3)
        CHECK(status_polygon == POLYMASS_ERROR_FACE_TOO_SMALL, status_polygon, context);

    polymass_context_destroy(context);
    free(points);
    free(face_sizes);
    free(indices_buffer.block);
    free(positions_buffer.block);
    return 0;
}
