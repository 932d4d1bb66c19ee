/* Robustness: thousands of hostile pseudo-random inputs to every entry point,
 * and geometric fuzz of valid solids whose expected status is known exactly.
 *
 * The generator is a fixed-seed splitmix64, so every run makes the same
 * inputs; a failure prints the iteration and the whole input (coordinates in
 * %a) so that it can be replayed. Every array handed to the library is
 * allocated to exactly the size the description claims, so ASan reports any
 * read past what the contract allows, and the test itself never reads out of
 * bounds whatever stride or count it claims.
 *
 * What is asserted for every call:
 *   the status is one of the documented POLYMASS_* codes, and its string is
 *   not "unknown status";
 *   on failure the context message is non-empty; polymass_mesh_create
 *   leaves *out_mesh NULL when the arguments are refused (or memory ran
 *   out) and otherwise gives a mesh whose status is the returned one, whose
 *   mass properties are refused with it, and whose diagnostics' status is
 *   it when the topology is checked;
 *   on success every output double is finite, volume > 0, mass > 0, density
 *   > 0, the inertia tensors are symmetric, the principal moments ascending,
 *   the principal axes orthonormal with det +1 (to 1e-9), and the context
 *   message is ""; for a genuine solid (a valid solid moved or scaled, not
 *   random geometry) the principal moments are also non-negative (to
 *   rounding): random geometry may be a self-intersecting or, with the
 *   topology checks skipped, open surface, whose signed integrals need not
 *   be those of any body.
 *
 * The perturbation test takes a cube of quads or of triangles, moves it
 * rigidly (translations up to 1e8), then splits a vertex, flips faces or
 * removes faces, and expects the exact status of each call with each set of
 * option flags, and the exact edge counts of the mesh's diagnostics.
 *
 * After them, one small test per kind of finding, with the smallest input
 * found for it. To list every finding of the randomized tests instead of
 * stopping at the first, build this file with -DROBUSTNESS_KEEP_GOING.
 */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HOSTILE_ITERATIONS 3000
#define POLYGON_ITERATIONS 3000
#define PERTURBATION_ITERATIONS 2000
#define MAX_RANDOM_VERTICES 50
#define MAX_RANDOM_FACES 12
#define MAX_FACE_SIZE 8
#define MAX_STRIDE 64

/* ------------------------------------------------------------------------ */
/* Deterministic pseudo-random numbers (splitmix64)                         */
/* ------------------------------------------------------------------------ */

typedef struct rng {
    uint64_t state;
} rng;

static uint64_t rng_next(rng* r) {
    uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* 0 .. n-1 (n > 0); the modulo bias is irrelevant here. */
static uint32_t rng_below(rng* r, uint32_t n) { return (uint32_t)(rng_next(r) % n); }

static int rng_one_in(rng* r, uint32_t n) { return rng_below(r, n) == 0; }

/* Uniform in [lo, hi). */
static double rng_uniform(rng* r, double lo, double hi) {
    return lo + (hi - lo) * ((double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0));
}

/* A value that breaks naive arithmetic: NaN, infinities, values whose
   products overflow or underflow, denormals, signed zeros. */
static double hostile_double(rng* r) {
    switch (rng_below(r, 14)) {
        case 0:
            return NAN;
        case 1:
            return INFINITY;
        case 2:
            return -INFINITY;
        case 3:
            return 1e300;
        case 4:
            return -1e300;
        case 5:
            return 1e-300;
        case 6:
            return -1e-300;
        case 7:
            return 4.9406564584124654e-324; /* the smallest denormal */
        case 8:
            return -2.2250738585072009e-308; /* the largest denormal */
        case 9:
            return -0.0;
        case 10:
            return DBL_MAX;
        case 11:
            return 1e154; /* squares overflow, cubes more so */
        case 12:
            return 1e-160; /* squares underflow */
        default:
            return FLT_MAX * 2.0; /* finite double, infinite float */
    }
}

/* Mostly small grid values (so that random shapes are sometimes valid),
   often ordinary reals, sometimes hostile. */
static double random_coordinate(rng* r) {
    switch (rng_below(r, 8)) {
        case 0:
        case 1:
        case 2:
            return (double)rng_below(r, 5) - 2.0;
        case 3:
        case 4:
            return rng_uniform(r, -10.0, 10.0);
        case 5:
            return rng_uniform(r, -1e8, 1e8);
        default:
            return hostile_double(r);
    }
}

/* A positive, zero, negative or non-finite amount (density, mass, tolerance). */
static double random_amount(rng* r) {
    switch (rng_below(r, 6)) {
        case 0:
            return hostile_double(r);
        case 1:
            return -rng_uniform(r, 0.0, 10.0);
        default:
            return rng_uniform(r, 1e-3, 1e3);
    }
}

/* ------------------------------------------------------------------------ */
/* The input being tried, printed when an assertion fails                   */
/* ------------------------------------------------------------------------ */

typedef struct trial {
    const char* phase;
    int iteration;
    const polymass_mesh_desc* desc; /* the mesh description, or NULL */
    const polymass_options* options;
    const polymass_mass_desc* mass;
    const double* points; /* the 2D polygon, or NULL */
    uint64_t point_count, point_stride;
} trial;

static trial current;

static void print_coordinate_bytes(const unsigned char* p, uint32_t position_type) {
    if (position_type == POLYMASS_POSITION_FLOAT32) {
        float f;
        memcpy(&f, p, sizeof f);
        print_error(" %a", (double)f);
    } else {
        double d;
        memcpy(&d, p, sizeof d);
        print_error(" %a", d);
    }
}

static void print_desc(const polymass_mesh_desc* d) {
    uint64_t i;
    print_error(
        "  desc: struct_size %u position_type %u vertex_count %llu stride %llu index_type %u "
        "reserved %u index_count %llu face_count %llu face_sizes %s\n",
        (unsigned)d->struct_size, (unsigned)d->position_type, (unsigned long long)d->vertex_count,
        (unsigned long long)d->position_stride, (unsigned)d->index_type, (unsigned)d->reserved,
        (unsigned long long)d->index_count, (unsigned long long)d->face_count,
        d->face_sizes ? "given" : "NULL");
    if (d->positions != NULL && d->struct_size == sizeof *d && d->position_type <= 1 &&
        d->vertex_count <= 1000) {
        const size_t element = d->position_type == POLYMASS_POSITION_FLOAT32 ? 4 : 8;
        const size_t stride = d->position_stride ? (size_t)d->position_stride : 3 * element;
        print_error("  positions:");
        for (i = 0; i < d->vertex_count && stride >= 3 * element; ++i) {
            int axis;
            print_error("\n    %llu:", (unsigned long long)i);
            for (axis = 0; axis < 3; ++axis) {
                print_coordinate_bytes(
                    (const unsigned char*)d->positions + i * stride + (size_t)axis * element,
                    d->position_type);
            }
        }
        print_error("\n");
    }
    if (d->indices != NULL && d->index_type <= 1 && d->index_count <= 10000) {
        print_error("  indices:");
        for (i = 0; i < d->index_count; ++i) {
            print_error(" %lu", d->index_type == POLYMASS_INDEX_UINT16
                                    ? (unsigned long)((const uint16_t*)d->indices)[i]
                                    : (unsigned long)((const uint32_t*)d->indices)[i]);
        }
        print_error("\n");
    }
    if (d->face_sizes != NULL && d->face_count <= 10000) {
        print_error("  face_sizes:");
        for (i = 0; i < d->face_count; ++i) {
            print_error(" %u", (unsigned)d->face_sizes[i]);
        }
        print_error("\n");
    }
}

static void print_trial(void) {
    print_error("robustness input: phase \"%s\", iteration %d\n", current.phase, current.iteration);
    if (current.options) {
        print_error("  options: struct_size %u flags 0x%x planarity_tolerance %a\n",
                    (unsigned)current.options->struct_size, (unsigned)current.options->flags,
                    current.options->planarity_tolerance);
    }
    if (current.mass) {
        print_error("  mass_desc: struct_size %u mode %u density %a mass %a\n",
                    (unsigned)current.mass->struct_size, (unsigned)current.mass->mass_mode,
                    current.mass->density, current.mass->mass);
    }
    if (current.desc) {
        print_desc(current.desc);
    }
    if (current.points) {
        uint64_t i;
        const uint64_t stride = current.point_stride ? current.point_stride : 16;
        print_error("  polygon: %llu points, stride %llu:", (unsigned long long)current.point_count,
                    (unsigned long long)current.point_stride);
        for (i = 0; i < current.point_count && stride >= 16 && current.point_count <= 1000; ++i) {
            double xy[2];
            memcpy(xy, (const unsigned char*)current.points + i * stride, sizeof xy);
            print_error(" (%a, %a)", xy[0], xy[1]);
        }
        print_error("\n");
    }
}

#ifdef ROBUSTNESS_KEEP_GOING
/* Exploration build (-DROBUSTNESS_KEEP_GOING): report the first findings of
   each assertion (ROBUSTNESS_REPORTS_PER_LINE of them) and go on. */
#ifndef ROBUSTNESS_REPORTS_PER_LINE
#define ROBUSTNESS_REPORTS_PER_LINE 3
#endif
static int reported_lines[4096];
static void fail_trial_at(const char* file, int line, const char* call, const char* what) {
    if (line < 4096 && reported_lines[line]++ < ROBUSTNESS_REPORTS_PER_LINE) {
        print_error("%s:%d: %s: %s\n", file, line, call, what);
        print_trial();
    }
}
#else
static void fail_trial_at(const char* file, int line, const char* call, const char* what) {
    print_error("%s:%d: %s: %s\n", file, line, call, what);
    print_trial();
    _fail(file, line);
}
#endif

/* How often each status came back: printed after each test, to show what
   the inputs reached. */
typedef struct status_tally {
    unsigned count[64];
} status_tally;

static void tally(status_tally* t, int32_t status) {
    if (status >= 0 && status < 64) {
        t->count[status] += 1;
    }
}

static void print_tally(const char* what, const status_tally* t) {
    char line[512];
    size_t used = 0;
    int s;
    for (s = 0; s < 64; ++s) {
        if (t->count[s] && used < sizeof line - 32) {
            used += (size_t)snprintf(line + used, sizeof line - used, " %s %u,",
                                     polymass_status_string(s), t->count[s]);
        }
    }
    if (used > 0) {
        line[used - 1] = '\0';
    } else {
        line[0] = '\0';
    }
    print_message("%s:%s\n", what, line);
}

/* The statuses of the main call (create or polygon) and of mesh_check. */
static status_tally main_tally, check_tally;

static void begin_phase(const char* phase) {
    memset(&current, 0, sizeof current);
    memset(&main_tally, 0, sizeof main_tally);
    memset(&check_tally, 0, sizeof check_tally);
    current.phase = phase;
}

static void end_phase(const char* main_call) {
    char what[160];
    snprintf(what, sizeof what, "%s: %s", current.phase, main_call);
    print_tally(what, &main_tally);
    snprintf(what, sizeof what, "%s: polymass_mesh_diagnostics", current.phase);
    print_tally(what, &check_tally);
}

/* ------------------------------------------------------------------------ */
/* What every call must satisfy                                             */
/* ------------------------------------------------------------------------ */

/* The status is documented and named; a failure leaves a message in the
   context (when there was one), a success leaves "". */
static void check_status_at(const char* file, int line, const char* call, int32_t status,
                            const polymass_context* ctx) {
    char what[256];
    const char* name = polymass_status_string(status);
    if (!pm_is_documented_status(status)) {
        snprintf(what, sizeof what, "undocumented status %d", (int)status);
        fail_trial_at(file, line, call, what);
    }
    if (name == NULL || strcmp(name, "unknown status") == 0) {
        snprintf(what, sizeof what, "status %d is named \"%s\"", (int)status,
                 name ? name : "(null)");
        fail_trial_at(file, line, call, what);
    }
    if (ctx != NULL) {
        const char* message = polymass_context_message(ctx);
        if (message == NULL) {
            fail_trial_at(file, line, call, "polymass_context_message returned NULL");
        } else if (status != POLYMASS_OK && message[0] == '\0') {
            snprintf(what, sizeof what, "status %d (%s) with an empty message", (int)status, name);
            fail_trial_at(file, line, call, what);
        } else if (status == POLYMASS_OK && message[0] != '\0') {
            snprintf(what, sizeof what, "success with the message \"%.150s\"", message);
            fail_trial_at(file, line, call, what);
        }
    }
}
#define CHECK_STATUS(call, status, ctx) check_status_at(__FILE__, __LINE__, (call), (status), (ctx))

static void check_finite_at(const char* file, int line, const char* call, const char* field,
                            const double* values, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i) {
        if (!isfinite(values[i])) {
            char what[160];
            snprintf(what, sizeof what, "success with %s[%u] = %g", field, (unsigned)i, values[i]);
            fail_trial_at(file, line, call, what);
        }
    }
}

static double max_abs(const double* values, size_t n) {
    double m = 0;
    size_t i;
    for (i = 0; i < n; ++i) {
        m = fmax(m, fabs(values[i]));
    }
    return m;
}

static void check_symmetric_at(const char* file, int line, const char* call, const char* field,
                               const double t[9]) {
    const double allowed = 1e-12 * max_abs(t, 9);
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = i + 1; j < 3; ++j) {
            if (!(fabs(t[3 * i + j] - t[3 * j + i]) <= allowed)) {
                char what[200];
                snprintf(what, sizeof what, "%s not symmetric: [%d][%d] = %.17g, [%d][%d] = %.17g",
                         field, i, j, t[3 * i + j], j, i, t[3 * j + i]);
                fail_trial_at(file, line, call, what);
            }
        }
    }
}

/* Every field of a successful result is finite and sane. The principal
   moments of a genuine solid are not negative; those of a self-intersecting
   surface (the library integrates the signed sum of its lobes, as for
   polygons) or of an open one whose checks were skipped may be. */
static void check_properties_at(const char* file, int line, const char* call,
                                const polymass_mass_properties* p, int genuine_solid) {
    static const uint32_t known_warnings =
        POLYMASS_WARNING_INVERTED | POLYMASS_WARNING_DEGENERATE_FACES | POLYMASS_WARNING_UNCHECKED |
        POLYMASS_WARNING_NON_MANIFOLD | POLYMASS_WARNING_TOUCHING_FACES |
        POLYMASS_WARNING_INTERSECTIONS_UNCHECKED;
    char what[300];
    double rt_r[9], rt[9];
    const double moment_scale = max_abs(p->principal_moments, 3);
    int i, j;
    check_finite_at(file, line, call, "volume", &p->volume, 1);
    check_finite_at(file, line, call, "mass", &p->mass, 1);
    check_finite_at(file, line, call, "density", &p->density, 1);
    check_finite_at(file, line, call, "surface_area", &p->surface_area, 1);
    check_finite_at(file, line, call, "center_of_mass", p->center_of_mass, 3);
    check_finite_at(file, line, call, "inertia", p->inertia, 9);
    check_finite_at(file, line, call, "inertia_origin", p->inertia_origin, 9);
    check_finite_at(file, line, call, "principal_moments", p->principal_moments, 3);
    check_finite_at(file, line, call, "principal_axes", p->principal_axes, 9);
    if (!(p->volume > 0 && p->mass > 0 && p->density > 0 && p->surface_area >= 0)) {
        snprintf(what, sizeof what, "success with volume %g, mass %g, density %g, area %g",
                 p->volume, p->mass, p->density, p->surface_area);
        fail_trial_at(file, line, call, what);
    }
    if (p->warnings & ~known_warnings) {
        snprintf(what, sizeof what, "undocumented warning bits 0x%x", (unsigned)p->warnings);
        fail_trial_at(file, line, call, what);
    }
    check_symmetric_at(file, line, call, "inertia", p->inertia);
    check_symmetric_at(file, line, call, "inertia_origin", p->inertia_origin);
    if (!(p->principal_moments[0] <= p->principal_moments[1] &&
          p->principal_moments[1] <= p->principal_moments[2])) {
        snprintf(what, sizeof what, "principal moments not ascending: %.17g %.17g %.17g",
                 p->principal_moments[0], p->principal_moments[1], p->principal_moments[2]);
        fail_trial_at(file, line, call, what);
    }
    if (genuine_solid && !(p->principal_moments[0] >= -1e-12 * moment_scale)) {
        snprintf(what, sizeof what, "negative principal moment: %.17g %.17g %.17g",
                 p->principal_moments[0], p->principal_moments[1], p->principal_moments[2]);
        fail_trial_at(file, line, call, what);
    }
    pm_mat3_transpose(rt, p->principal_axes);
    pm_mat3_mul(rt_r, rt, p->principal_axes);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            if (!(fabs(rt_r[3 * i + j] - (i == j)) <= 1e-9)) {
                snprintf(what, sizeof what,
                         "principal axes not orthonormal: (R^T R)[%d][%d] = %.17g", i, j,
                         rt_r[3 * i + j]);
                fail_trial_at(file, line, call, what);
            }
        }
    }
    if (!(fabs(pm_mat3_det(p->principal_axes) - 1.0) <= 1e-9)) {
        snprintf(what, sizeof what, "det(principal axes) = %.17g", pm_mat3_det(p->principal_axes));
        fail_trial_at(file, line, call, what);
    }
}
#define CHECK_PROPERTIES(call, p, genuine_solid) \
    check_properties_at(__FILE__, __LINE__, (call), (p), (genuine_solid))

static void check_polygon_at(const char* file, int line, const polymass_polygon_properties* p) {
    static const char call[] = "polymass_polygon_compute";
    const double pi = 3.14159265358979323846;
    char what[200];
    check_finite_at(file, line, call, "area", &p->area, 1);
    check_finite_at(file, line, call, "centroid", p->centroid, 2);
    check_finite_at(file, line, call, "second_moments", p->second_moments, 3);
    check_finite_at(file, line, call, "second_moments_origin", p->second_moments_origin, 3);
    check_finite_at(file, line, call, "polar_moment", &p->polar_moment, 1);
    check_finite_at(file, line, call, "principal_moments", p->principal_moments, 2);
    check_finite_at(file, line, call, "principal_angle", &p->principal_angle, 1);
    if (!(p->area > 0)) {
        snprintf(what, sizeof what, "success with area %g", p->area);
        fail_trial_at(file, line, call, what);
    }
    if (p->orientation != POLYMASS_COUNTER_CLOCKWISE && p->orientation != POLYMASS_CLOCKWISE) {
        snprintf(what, sizeof what, "orientation %d", (int)p->orientation);
        fail_trial_at(file, line, call, what);
    }
    if (!(p->principal_moments[0] <= p->principal_moments[1])) {
        snprintf(what, sizeof what, "principal moments not ascending: %.17g %.17g",
                 p->principal_moments[0], p->principal_moments[1]);
        fail_trial_at(file, line, call, what);
    }
    if (!(p->principal_angle > -pi / 2 && p->principal_angle <= pi / 2)) {
        snprintf(what, sizeof what, "principal angle %.17g outside (-pi/2, pi/2]",
                 p->principal_angle);
        fail_trial_at(file, line, call, what);
    }
}

/* ------------------------------------------------------------------------ */
/* An allocator that fails now and then                                     */
/* ------------------------------------------------------------------------ */

typedef struct flaky_allocator {
    rng random;
    uint32_t one_in; /* chance of a failure; 0: never */
} flaky_allocator;

static void* flaky_allocate(void* user_data, size_t size, size_t alignment) {
    flaky_allocator* a = user_data;
    void* p = NULL;
    if (a->one_in && rng_one_in(&a->random, a->one_in)) {
        return NULL;
    }
    if (alignment < sizeof(void*)) {
        alignment = sizeof(void*);
    }
    if (posix_memalign(&p, alignment, size ? size : 1) != 0) {
        return NULL;
    }
    return p;
}

static void flaky_deallocate(void* user_data, void* pointer) {
    (void)user_data;
    free(pointer);
}

/* ------------------------------------------------------------------------ */
/* Hostile mesh descriptions                                                */
/* ------------------------------------------------------------------------ */

/* A description and the exactly sized arrays it points into. The zeros after
   desc are what a library reads of a "newer caller's" larger description
   (struct_size > sizeof desc), so that such a read stays in bounds. */
typedef struct hostile_mesh {
    unsigned char* positions;
    void* indices;
    uint32_t* face_sizes;
    polymass_mesh_desc desc;
    unsigned char zeros_after_desc[64];
    int genuine_solid; /* a valid solid, however placed */
} hostile_mesh;

static void hostile_mesh_free(hostile_mesh* h) {
    free(h->positions);
    free(h->indices);
    free(h->face_sizes);
    memset(h, 0, sizeof *h);
}

/* What a test holds, released by release_held after the test too: a failed
   assertion leaves the test by longjmp, and must not add leak reports to the
   finding. */
static struct held_resources {
    polymass_context* contexts[2];
    polymass_mesh* mesh;
    hostile_mesh hostile;
    unsigned char* polygon;
    pm_mesh cube;
    pm_laid_out_mesh laid_out;
} held;

static void release_mesh_object(void) {
    polymass_mesh_destroy(held.mesh);
    held.mesh = NULL;
}

static int release_held(void** state) {
    (void)state;
    release_mesh_object();
    polymass_context_destroy(held.contexts[0]);
    polymass_context_destroy(held.contexts[1]);
    hostile_mesh_free(&held.hostile);
    free(held.polygon);
    pm_mesh_free(&held.cube);
    pm_laid_out_free(&held.laid_out);
    memset(&held, 0, sizeof held);
    return 0;
}

/* A float of the double without undefined behaviour: out of range is an
   infinity of the same sign. */
static float to_float(double x) {
    if (x > FLT_MAX) {
        return INFINITY;
    }
    if (x < -FLT_MAX) {
        return -INFINITY;
    }
    return (float)x;
}

/* Writes vertex_count vertices (xyz, 3 doubles each) as position_type with
   the given stride; the block is exactly as long as the contract allows the
   library to read when the stride is valid (a smaller, invalid stride gets
   room for vertex_count whole vertices, in case the library reads them). */
static unsigned char* write_positions(const double* xyz, uint64_t vertex_count,
                                      uint32_t position_type, uint64_t stride) {
    const size_t element = position_type == POLYMASS_POSITION_FLOAT32 ? 4 : 8;
    const size_t record = stride ? (size_t)stride : 3 * element;
    size_t bytes, v;
    unsigned char* block;
    if (vertex_count == 0) {
        bytes = 1;
    } else if (record >= 3 * element) {
        bytes = ((size_t)vertex_count - 1) * record + 3 * element;
    } else {
        bytes = (size_t)vertex_count * 3 * element + record;
    }
    block = malloc(bytes);
    assert_non_null(block);
    memset(block, 0xA5, bytes);
    for (v = 0; v < vertex_count && record >= 3 * element; ++v) {
        int axis;
        for (axis = 0; axis < 3; ++axis) {
            unsigned char* dst = block + v * record + (size_t)axis * element;
            const double x = xyz[3 * v + (size_t)axis];
            if (position_type == POLYMASS_POSITION_FLOAT32) {
                const float f = to_float(x);
                memcpy(dst, &f, sizeof f);
            } else {
                memcpy(dst, &x, sizeof x);
            }
        }
    }
    return block;
}

/* An index: mostly in range, sometimes just past the end, far past it or the
   largest value of the type. */
static uint32_t random_index(rng* r, uint64_t vertex_count, uint32_t index_type) {
    const uint32_t largest = index_type == POLYMASS_INDEX_UINT16 ? 0xFFFFu : UINT32_MAX;
    switch (rng_below(r, 12)) {
        case 0:
            return largest;
        case 1:
            return (uint32_t)vertex_count;
        case 2:
            return (uint32_t)vertex_count + rng_below(r, 100);
        default:
            return vertex_count ? rng_below(r, (uint32_t)vertex_count) : 0;
    }
}

static void* write_indices(const uint32_t* values, uint64_t count, uint32_t index_type) {
    const size_t element = index_type == POLYMASS_INDEX_UINT16 ? 2 : 4;
    unsigned char* block = malloc(count ? (size_t)count * element : 1);
    uint64_t k;
    assert_non_null(block);
    for (k = 0; k < count; ++k) {
        if (index_type == POLYMASS_INDEX_UINT16) {
            const uint16_t i = (uint16_t)values[k];
            memcpy(block + k * element, &i, sizeof i);
        } else {
            memcpy(block + k * element, &values[k], sizeof values[k]);
        }
    }
    return block;
}

/* A stride in bytes: often 0 (packed), else anything up to 64, including
   strides smaller than a vertex and unaligned ones. */
static uint64_t random_stride(rng* r) {
    static const uint64_t unaligned[] = {13, 25, 27, 29, 31};
    switch (rng_below(r, 4)) {
        case 0:
            return 0;
        case 1:
            return unaligned[rng_below(r, 5)];
        default:
            return rng_below(r, MAX_STRIDE + 1);
    }
}

/* Random topology: random counts, face sizes (0 to 8) whose sum is
   sometimes index_count and sometimes not, random indices. */
static void random_topology(rng* r, hostile_mesh* h, uint64_t vertex_count) {
    uint32_t values[MAX_RANDOM_FACES * MAX_FACE_SIZE + 8];
    uint64_t index_count = 0, face_count = 0, k;
    const uint32_t index_type = rng_one_in(r, 3) ? POLYMASS_INDEX_UINT16 : POLYMASS_INDEX_UINT32;
    if (rng_one_in(r, 3)) { /* triangles: no face_sizes */
        index_count = 3 * (uint64_t)rng_below(r, MAX_RANDOM_FACES + 1);
        if (rng_one_in(r, 4)) {
            index_count += 1 + rng_below(r, 2); /* not a multiple of 3 */
        }
        if (rng_one_in(r, 8)) {
            face_count = 1 + rng_below(r, 4); /* a count without the array */
        }
    } else {
        uint64_t sum = 0;
        face_count = rng_below(r, MAX_RANDOM_FACES + 1);
        h->face_sizes = malloc(face_count ? (size_t)face_count * sizeof(uint32_t) : 1);
        assert_non_null(h->face_sizes);
        for (k = 0; k < face_count; ++k) {
            h->face_sizes[k] =
                rng_one_in(r, 2) ? 3 + rng_below(r, 2) : rng_below(r, MAX_FACE_SIZE + 1);
            sum += h->face_sizes[k];
        }
        index_count = sum;
        if (rng_one_in(r, 4)) { /* does not add up */
            index_count = sum + 1 + rng_below(r, 4);
            if (sum > 0 && rng_one_in(r, 2)) {
                index_count = sum - 1 - rng_below(r, (uint32_t)sum);
            }
        }
    }
    for (k = 0; k < index_count; ++k) {
        values[k] = random_index(r, vertex_count, index_type);
    }
    h->indices = write_indices(values, index_count, index_type);
    h->desc.index_type = index_type;
    h->desc.indices = h->indices;
    h->desc.index_count = index_count;
    h->desc.face_sizes = h->face_sizes;
    h->desc.face_count = face_count;
}

/* A valid closed surface of the reference set, as the topology. */
static const pm_reference_solid* random_reference(rng* r) {
    return &pm_reference_solids[rng_below(r, PM_REF_COUNT)];
}

static void reference_topology(hostile_mesh* h, const pm_reference_solid* ref,
                               uint32_t index_type) {
    uint32_t k;
    for (k = 0; k < ref->index_count; ++k) {
        if (index_type == POLYMASS_INDEX_UINT16) {
            assert_true(ref->indices[k] <= 0xFFFF);
        }
    }
    h->indices = write_indices(ref->indices, ref->index_count, index_type);
    h->desc.index_type = index_type;
    h->desc.indices = h->indices;
    h->desc.index_count = ref->index_count;
    if (ref->face_sizes) {
        h->face_sizes = malloc(ref->face_count * sizeof(uint32_t));
        assert_non_null(h->face_sizes);
        memcpy(h->face_sizes, ref->face_sizes, ref->face_count * sizeof(uint32_t));
        h->desc.face_sizes = h->face_sizes;
        h->desc.face_count = ref->face_count;
    }
}

/* Scales and offsets that put a valid solid where its integrals overflow or
   underflow. */
static void extreme_placement(rng* r, double* scale, double* offset) {
    static const double scales[] = {1e-300, 1e-200, 1e-160, 1e-110, 1e-60, 1e60,
                                    1e100,  1e102,  1e110,  1e155,  1e200, 1e300};
    static const double offsets[] = {0, 1e300, -1e300, 1e200, 1e155, -1e100, 1e16, 1e-300};
    *scale = scales[rng_below(r, sizeof scales / sizeof scales[0])];
    *offset = offsets[rng_below(r, sizeof offsets / sizeof offsets[0])];
}

/* One hostile mesh description: one of
   0: random coordinates, random topology;
   1: a valid closed surface with a few hostile coordinates;
   2: a valid closed surface scaled and moved to extremes;
   then a random layout, and now and then an invalid header field or a NULL
   array. */
static void make_hostile_mesh(rng* r, hostile_mesh* h) {
    double xyz[3 * 2000];
    uint64_t vertex_count, k;
    const uint32_t position_type =
        rng_one_in(r, 3) ? POLYMASS_POSITION_FLOAT32 : POLYMASS_POSITION_FLOAT64;
    const uint64_t stride = random_stride(r);
    const uint32_t mode = rng_below(r, 3);
    memset(h, 0, sizeof *h);
    h->desc.struct_size = sizeof h->desc;
    h->desc.position_type = position_type;
    h->desc.position_stride = stride;
    if (mode == 0) {
        vertex_count = rng_below(r, MAX_RANDOM_VERTICES + 1);
        for (k = 0; k < 3 * vertex_count; ++k) {
            xyz[k] = random_coordinate(r);
        }
        random_topology(r, h, vertex_count);
    } else {
        const pm_reference_solid* ref = random_reference(r);
        const uint32_t index_type =
            rng_one_in(r, 3) ? POLYMASS_INDEX_UINT16 : POLYMASS_INDEX_UINT32;
        vertex_count = ref->vertex_count;
        assert_true(3 * vertex_count <= sizeof xyz / sizeof xyz[0]);
        memcpy(xyz, ref->positions, 3 * vertex_count * sizeof(double));
        if (mode == 1) {
            const uint32_t spoiled = 1 + rng_below(r, 3);
            for (k = 0; k < spoiled; ++k) {
                xyz[3 * rng_below(r, (uint32_t)vertex_count) + rng_below(r, 3)] = hostile_double(r);
            }
        } else {
            double scale, offset;
            h->genuine_solid = 1;
            extreme_placement(r, &scale, &offset);
            for (k = 0; k < 3 * vertex_count; ++k) {
                xyz[k] = xyz[k] * scale + offset;
            }
        }
        reference_topology(h, ref, index_type);
    }
    h->positions = write_positions(xyz, vertex_count, position_type, stride);
    h->desc.positions = h->positions;
    h->desc.vertex_count = vertex_count;
    /* Now and then a broken header field or a NULL array. */
    switch (rng_below(r, 24)) {
        case 0:
            h->desc.struct_size = rng_below(r, 2) ? 0 : (uint32_t)sizeof h->desc + 8;
            break;
        case 1:
            h->desc.reserved = 1u << rng_below(r, 32);
            break;
        case 2:
            h->desc.position_type = 2 + rng_below(r, 5);
            break;
        case 3:
            h->desc.index_type = 2 + rng_below(r, 5);
            break;
        case 4:
            h->desc.positions = NULL;
            break;
        case 5:
            h->desc.indices = NULL;
            break;
        default:
            break;
    }
}

/* Random options: valid flags, a random tolerance, now and then an unknown
   flag bit or a wrong struct_size. Returns whether they must be rejected. */
static int random_options(rng* r, polymass_options* o) {
    static const double tolerances[] = {0, 1e-12, 1e-6, 1e-3, 1.0, 1e300};
    int invalid = 0;
    *o = pm_options(rng_below(r, 32), 0.0);
    if (rng_one_in(r, 3)) {
        o->planarity_tolerance = rng_one_in(r, 4) ? random_amount(r) : tolerances[rng_below(r, 6)];
    }
    if (rng_one_in(r, 10)) {
        o->flags |= 1u << (5 + rng_below(r, 27)); /* unknown */
        invalid = 1;
    }
    if (rng_one_in(r, 20)) {
        o->struct_size = rng_below(r, 2) ? 0 : 0x7FFFFFFFu;
        invalid = 1;
    }
    return invalid;
}

/* A random mass description, valid or not. */
static polymass_mass_desc random_mass(rng* r) {
    polymass_mass_desc m =
        rng_one_in(r, 2) ? pm_mass_density(random_amount(r)) : pm_mass_total(random_amount(r));
    switch (rng_below(r, 16)) {
        case 0:
            m.mass_mode = 2 + rng_below(r, 100);
            break;
        case 1:
            m.struct_size = 0;
            break;
        case 2: /* the field the mode does not read is hostile */
            m.density = hostile_double(r);
            m.mass = 1.0;
            m.mass_mode = POLYMASS_MASS_FROM_TOTAL;
            break;
        default:
            break;
    }
    return m;
}

/* ------------------------------------------------------------------------ */
/* Hostile inputs to every entry point                                      */
/* ------------------------------------------------------------------------ */

/* The inertia about a random point of a body's properties: a tensor of
   finite, symmetric values, or POLYMASS_ERROR_OVERFLOW; a point that is not
   finite is refused. */
static void try_inertia_about(rng* r, const polymass_mass_properties* p) {
    double point[3], inertia[9];
    int32_t s;
    int axis;
    for (axis = 0; axis < 3; ++axis) point[axis] = rng_one_in(r, 4) ? random_coordinate(r) : 0.0;
    s = polymass_inertia_about(inertia, p, point);
    CHECK_STATUS("polymass_inertia_about", s, NULL);
    if (!(isfinite(point[0]) && isfinite(point[1]) && isfinite(point[2]))) {
        if (s != POLYMASS_ERROR_INVALID_ARGUMENT)
            fail_trial_at(__FILE__, __LINE__, "polymass_inertia_about", "a point not finite taken");
    } else if (s == POLYMASS_OK) {
        check_finite_at(__FILE__, __LINE__, "polymass_inertia_about", "inertia", inertia, 9);
        check_symmetric_at(__FILE__, __LINE__, "polymass_inertia_about", "inertia", inertia);
    } else if (s != POLYMASS_ERROR_OVERFLOW) {
        fail_trial_at(__FILE__, __LINE__, "polymass_inertia_about", "neither OK nor OVERFLOW");
    }
}

/* One description through polymass_mesh_create (its mass properties and
   diagnostics) and polymass_mass_properties_compute, with the options given
   (invalid_options: they must be refused). Statuses must agree where the
   contract says they do. */
static void try_mesh(rng* r, polymass_context* ctx, const polymass_mesh_desc* desc,
                     int genuine_solid, const polymass_options* options, int invalid_options,
                     int flaky) {
    polymass_mesh* mesh = (polymass_mesh*)&mesh; /* garbage: must be overwritten */
    polymass_mass_properties p;
    polymass_diagnostics diag;
    polymass_mass_desc mass = random_mass(r);
    const polymass_mass_desc* mass_or_null = rng_one_in(r, 3) ? NULL : &mass;
    int32_t created, computed, properties = POLYMASS_OK;

    current.mass = mass_or_null;
    created = polymass_mesh_create(&mesh, ctx, desc, options);
    tally(&main_tally, created);
    if (mesh != NULL) {
        held.mesh = mesh;
    }
    CHECK_STATUS("polymass_mesh_create", created, ctx);
    if (invalid_options && created != POLYMASS_ERROR_INVALID_ARGUMENT) {
        fail_trial_at(__FILE__, __LINE__, "polymass_mesh_create",
                      "unknown flag or wrong struct_size accepted");
    }
    if (created == POLYMASS_ERROR_INVALID_ARGUMENT || created == POLYMASS_ERROR_OUT_OF_MEMORY ||
        created == POLYMASS_ERROR_INTERNAL) {
        if (mesh != NULL) {
            fail_trial_at(__FILE__, __LINE__, "polymass_mesh_create",
                          "*out_mesh not NULL when no analysis ran");
        }
    } else if (mesh == NULL) {
        fail_trial_at(__FILE__, __LINE__, "polymass_mesh_create", "no mesh after an analysis");
    } else {
        if (polymass_mesh_status(mesh) != created) {
            fail_trial_at(__FILE__, __LINE__, "polymass_mesh_status", "not what create returned");
        }
        pm_props_init(&p);
        properties = polymass_mesh_mass_properties(&p, ctx, mesh, mass_or_null);
        CHECK_STATUS("polymass_mesh_mass_properties", properties, ctx);
        if (properties == POLYMASS_OK) {
            CHECK_PROPERTIES("polymass_mesh_mass_properties", &p, genuine_solid);
            try_inertia_about(r, &p);
        } else if (created != POLYMASS_OK && properties != created &&
                   properties != POLYMASS_ERROR_INVALID_ARGUMENT) {
            fail_trial_at(__FILE__, __LINE__, "polymass_mesh_mass_properties",
                          "a refused mesh's properties not refused with its status");
        }
        pm_diagnostics_init(&diag);
        diag.status = -12345;
        CHECK_STATUS("polymass_mesh_diagnostics", polymass_mesh_diagnostics(&diag, ctx, mesh), ctx);
        tally(&check_tally, diag.status);
        CHECK_STATUS("polymass_mesh_diagnostics status", diag.status, NULL);
        /* With the topology checked, the verdict is the mesh's. */
        if (!(options->flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS) && diag.status != created) {
            char what[160];
            snprintf(what, sizeof what, "status %d, but polymass_mesh_create's was %d",
                     (int)diag.status, (int)created);
            fail_trial_at(__FILE__, __LINE__, "polymass_mesh_diagnostics", what);
        }
        release_mesh_object();
    }

    pm_props_init(&p);
    computed = polymass_mass_properties_compute(&p, NULL, ctx, desc, options, mass_or_null);
    CHECK_STATUS("polymass_mass_properties_compute", computed, ctx);
    if (computed == POLYMASS_OK) {
        CHECK_PROPERTIES("polymass_mass_properties_compute", &p, genuine_solid);
    }
    /* compute is create, then properties: the first failure of the two.
       (With an invalid mass description and an invalid mesh either may be
       reported.) */
    if (!flaky && (created == POLYMASS_OK || mass_or_null == NULL)) {
        const int32_t expected = created != POLYMASS_OK ? created : properties;
        if (computed != expected) {
            char what[160];
            snprintf(what, sizeof what,
                     "status %d, but polymass_mesh_create + polymass_mesh_mass_properties gave %d",
                     (int)computed, (int)expected);
            fail_trial_at(__FILE__, __LINE__, "polymass_mass_properties_compute", what);
        }
    }
    current.mass = NULL;
}

/* NULL where a pointer is required: INVALID_ARGUMENT, never a crash. */
static void try_null_arguments(rng* r, polymass_context* ctx, const polymass_mesh_desc* desc) {
    polymass_mesh* mesh = (polymass_mesh*)&mesh;
    polymass_mass_properties p;
    polymass_diagnostics diag;
    int32_t s;
    pm_props_init(&p);
    pm_diagnostics_init(&diag);
    switch (rng_below(r, 6)) {
        case 0:
            s = polymass_mesh_create(&mesh, NULL, desc, NULL);
            break;
        case 1:
            s = polymass_mesh_create(&mesh, ctx, NULL, NULL);
            break;
        case 2:
            s = polymass_mesh_create(NULL, ctx, desc, NULL);
            mesh = NULL;
            break;
        case 3:
            s = polymass_mass_properties_compute(NULL, NULL, ctx, desc, NULL, NULL);
            mesh = NULL;
            break;
        case 4:
            s = polymass_mesh_diagnostics(&diag, ctx, NULL);
            mesh = NULL;
            break;
        default:
            s = polymass_mesh_mass_properties(&p, ctx, NULL, NULL);
            mesh = NULL;
            break;
    }
    CHECK_STATUS("a call with a NULL argument", s, NULL);
    if (s != POLYMASS_ERROR_INVALID_ARGUMENT) {
        fail_trial_at(__FILE__, __LINE__, "a call with a NULL argument", "not INVALID_ARGUMENT");
    }
    if (mesh != NULL) {
        fail_trial_at(__FILE__, __LINE__, "polymass_mesh_create",
                      "*out_mesh not NULL after a failure");
    }
}

static void test_hostile_meshes(void** state) {
    static flaky_allocator flaky;
    const polymass_allocator flaky_interface = {sizeof(polymass_allocator), 0, flaky_allocate,
                                                flaky_deallocate, &flaky};
    rng r = {0x5EED0001u};
    polymass_context* plain;
    polymass_context* fragile = NULL;
    hostile_mesh* h = &held.hostile;
    int i;
    (void)state;
    flaky.random.state = 0x5EED0002u;
    flaky.one_in = 0;
    plain = held.contexts[0] = pm_context_new();
    assert_int_equal(polymass_context_create(&fragile, &flaky_interface), POLYMASS_OK);
    held.contexts[1] = fragile;
    begin_phase("hostile meshes");
    for (i = 0; i < HOSTILE_ITERATIONS; ++i) {
        polymass_options o;
        const int use_flaky = rng_one_in(&r, 8);
        polymass_context* ctx = use_flaky ? fragile : plain;
        int invalid_options;
        current.iteration = i;
        make_hostile_mesh(&r, h);
        current.desc = &h->desc;

        invalid_options = random_options(&r, &o);
        current.options = &o;
        flaky.one_in = use_flaky ? 1 + rng_below(&r, 12) : 0;
        try_mesh(&r, ctx, &h->desc, h->genuine_solid, &o, invalid_options, use_flaky);
        flaky.one_in = 0;
        if (rng_one_in(&r, 4)) {
            try_null_arguments(&r, ctx, &h->desc);
        }
        current.options = NULL;
        current.desc = NULL;
        hostile_mesh_free(h);
    }
    end_phase("polymass_mesh_create");
}

/* polymass_polygon_compute with random point counts, strides (also smaller
   than a point and unaligned) and hostile coordinates. */
static void test_hostile_polygons(void** state) {
    rng r = {0x5EED0003u};
    polymass_context* ctx = held.contexts[0] = pm_context_new();
    int i;
    (void)state;
    begin_phase("hostile polygons");
    for (i = 0; i < POLYGON_ITERATIONS; ++i) {
        const uint64_t count = rng_below(&r, MAX_RANDOM_VERTICES + 1);
        const uint64_t stride = rng_one_in(&r, 3) ? 0 : rng_below(&r, MAX_STRIDE + 1);
        const size_t record = stride ? (size_t)stride : 16;
        const size_t bytes = count == 0     ? 1
                             : record >= 16 ? (count - 1) * record + 16
                                            : count * 16 + record;
        unsigned char* block = held.polygon = malloc(bytes);
        polymass_polygon_properties p;
        const double* points;
        int32_t s;
        uint64_t k;
        current.iteration = i;
        assert_non_null(block);
        memset(block, 0x5A, bytes);
        for (k = 0; k < count && record >= 16; ++k) {
            /* mostly a convex-ish ring, to reach the integration often */
            const double angle = 6.283185307179586 * (double)k / (double)count;
            double xy[2];
            xy[0] = rng_one_in(&r, 6) ? random_coordinate(&r) : cos(angle) * 3.0 + 1.0;
            xy[1] = rng_one_in(&r, 6) ? random_coordinate(&r) : sin(angle) * 2.0 - 1.0;
            memcpy(block + k * record, xy, sizeof xy);
        }
        points = rng_one_in(&r, 40) ? NULL : (const double*)(const void*)block;
        current.points = points;
        current.point_count = count;
        current.point_stride = stride;
        pm_polygon_props_init(&p);
        if (rng_one_in(&r, 40)) {
            p.struct_size = rng_below(&r, 8);
        }
        s = polymass_polygon_compute(&p, ctx, points, count, stride);
        tally(&main_tally, s);
        CHECK_STATUS("polymass_polygon_compute", s, ctx);
        if (s == POLYMASS_OK) {
            check_polygon_at(__FILE__, __LINE__, &p);
        }
        current.points = NULL;
        free(block);
        held.polygon = NULL;
    }
    print_tally("hostile polygons: polymass_polygon_compute", &main_tally);
}

/* The entry points without a mesh: status strings of any code, the version,
   contexts made and destroyed, given any count of threads, options
   initialised at a wrong struct_size. */
static void test_hostile_small_calls(void** state) {
    rng r = {0x5EED0004u};
    int i;
    (void)state;
    begin_phase("small calls");
    assert_int_equal(polymass_version() / 10000, POLYMASS_VERSION_MAJOR);
    assert_non_null(polymass_version_string());
    for (i = 0; i < HOSTILE_ITERATIONS; ++i) {
        const int32_t code = rng_one_in(&r, 2) ? (int32_t)rng_next(&r) : (int32_t)rng_below(&r, 40);
        const char* name = polymass_status_string(code);
        polymass_context* ctx = NULL;
        /* room for whatever struct_size claims */
        polymass_options o[2];
        current.iteration = i;
        o[0] = o[1] = pm_options(0, 0.0);
        assert_non_null(name);
        assert_true(name[0] != '\0');
        if (pm_is_documented_status(code)) {
            assert_string_not_equal(name, "unknown status");
        } else {
            assert_string_equal(name, "unknown status");
        }
        assert_int_equal(polymass_context_create(&ctx, NULL), POLYMASS_OK);
        held.contexts[0] = ctx;
        o[0].struct_size = rng_one_in(&r, 2) ? rng_below(&r, sizeof o) : (uint32_t)sizeof o[0];
        CHECK_STATUS("polymass_options_init", polymass_options_init(o, o[0].struct_size), NULL);
        CHECK_STATUS("polymass_context_set_threads",
                     polymass_context_set_threads(ctx, rng_below(&r, 2 * POLYMASS_MAX_THREADS)),
                     ctx);
        polymass_context_destroy(ctx);
        held.contexts[0] = NULL;
    }
}

/* ------------------------------------------------------------------------ */
/* Perturbation of valid solids: exact expected statuses                    */
/* ------------------------------------------------------------------------ */

typedef enum mutation {
    INTACT,       /* unchanged: OK */
    SPLIT_VERTEX, /* one face gets its own copy of a vertex: OPEN unless welded */
    FLIP_SOME,    /* 1 to all-but-one faces reversed: INCONSISTENT_ORIENTATION */
    FLIP_ALL,     /* every face reversed: INVERTED unless accepted */
    REMOVE_SOME,  /* 1 to all-but-one faces removed: OPEN */
    MUTATION_COUNT
} mutation;

static const char* const mutation_names[] = {"intact", "vertex split", "some faces flipped",
                                             "all faces flipped", "some faces removed"};

/* Edge counts of a surface, computed here by brute force, as
   polymass_diagnostics defines them (welded: vertices at equal positions are
   one). */
typedef struct topology_counts {
    uint64_t used_vertices, edges, open, non_manifold, misoriented;
} topology_counts;

static topology_counts count_topology(const pm_mesh* m, int weld) {
    topology_counts c;
    uint32_t canonical[256], from[512], to[512];
    size_t f, k, e, n = 0, offset = 0;
    memset(&c, 0, sizeof c);
    assert_true(m->vertex_count <= 256 && m->index_count <= 512);
    for (k = 0; k < m->vertex_count; ++k) {
        size_t j;
        canonical[k] = (uint32_t)k;
        for (j = 0; weld && j < k; ++j) {
            const double* a = m->positions + 3 * j;
            const double* b = m->positions + 3 * k;
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {
                canonical[k] = canonical[j];
                break;
            }
        }
    }
    for (f = 0; f < m->face_count; ++f) {
        const size_t size = m->face_sizes[f];
        for (k = 0; k < size; ++k) {
            from[n] = canonical[m->indices[offset + k]];
            to[n] = canonical[m->indices[offset + (k + 1) % size]];
            ++n;
        }
        offset += size;
    }
    for (k = 0; k < m->vertex_count; ++k) {
        int used = 0;
        for (e = 0; e < n && !used; ++e) {
            used = from[e] == k;
        }
        c.used_vertices += used && canonical[k] == k;
    }
    for (e = 0; e < n; ++e) {
        size_t j, forward = 0, backward = 0, first = e;
        for (j = 0; j < n; ++j) {
            const int same = from[j] == from[e] && to[j] == to[e];
            const int reverse = from[j] == to[e] && to[j] == from[e];
            if ((same || reverse) && j < first) {
                first = j;
            }
            forward += same;
            backward += reverse;
        }
        if (first != e) {
            continue; /* counted at its first directed use */
        }
        c.edges += 1;
        if (forward + backward == 1) {
            c.open += 1;
        } else if (forward + backward > 2) {
            c.non_manifold += 1;
        } else if (forward == 2 || backward == 2) {
            c.misoriented += 1;
        }
    }
    return c;
}

/* The expected status of polymass_mesh_create (and compute) with the flags,
   or -1 where the contract leaves it open (a hole or a flipped face with the
   topology checks skipped: the integrals of a non-closed surface).
   expected_check_status is the diagnostics' status of a mesh made with the
   topology checked. */
static int32_t expected_create_status(mutation mu, uint32_t flags) {
    const int skip = (flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS) != 0;
    switch (mu) {
        case INTACT:
            return POLYMASS_OK;
        case SPLIT_VERTEX:
            return skip || (flags & POLYMASS_OPTION_WELD_VERTICES) ? POLYMASS_OK
                                                                   : POLYMASS_ERROR_OPEN;
        case FLIP_SOME:
            return skip ? -1 : POLYMASS_ERROR_INCONSISTENT_ORIENTATION;
        case FLIP_ALL:
            return flags & POLYMASS_OPTION_ACCEPT_INVERTED ? POLYMASS_OK : POLYMASS_ERROR_INVERTED;
        default:
            return skip ? -1 : POLYMASS_ERROR_OPEN;
    }
}

static int32_t expected_check_status(mutation mu, uint32_t flags) {
    return expected_create_status(mu, flags & ~POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
}

static void shuffle(rng* r, size_t* items, size_t n) {
    size_t i;
    for (i = n; i > 1; --i) {
        const size_t j = rng_below(r, (uint32_t)i), t = items[i - 1];
        items[i - 1] = items[j];
        items[j] = t;
    }
}

/* Applies the mutation to m (faces and vertices chosen at random). */
static void mutate(rng* r, pm_mesh* m, mutation mu) {
    size_t order[16], k, count;
    const size_t faces = m->face_count;
    assert_true(faces <= 16);
    for (k = 0; k < faces; ++k) {
        order[k] = k;
    }
    shuffle(r, order, faces);
    switch (mu) {
        case SPLIT_VERTEX: {
            const size_t face = order[0];
            const size_t slot = pm_mesh_face_offset(m, face) + rng_below(r, m->face_sizes[face]);
            const double* p = m->positions + 3 * (size_t)m->indices[slot];
            m->indices[slot] = pm_mesh_add_vertex(m, p[0], p[1], p[2]);
            break;
        }
        case FLIP_SOME:
            count = 1 + rng_below(r, (uint32_t)faces - 1);
            for (k = 0; k < count; ++k) {
                pm_mesh_reverse_face(m, order[k]);
            }
            break;
        case FLIP_ALL:
            pm_mesh_reverse_all(m);
            break;
        case REMOVE_SOME: {
            /* remove from the highest face number down, so that the numbers
               of the faces still to remove do not shift */
            size_t removed[16];
            count = 1 + rng_below(r, (uint32_t)faces - 1);
            memcpy(removed, order, count * sizeof order[0]);
            for (k = 0; k < count; ++k) {
                size_t j, top = k;
                for (j = k + 1; j < count; ++j) {
                    if (removed[j] > removed[top]) {
                        top = j;
                    }
                }
                j = removed[k];
                removed[k] = removed[top];
                removed[top] = j;
                pm_mesh_remove_face(m, removed[k]);
            }
            break;
        }
        default:
            break;
    }
}

/* A random rotation (a normalised random quaternion) and a translation of
   up to 1e8 in each coordinate. */
static void random_rigid_motion(rng* r, double rotation[9], double translation[3]) {
    double q[4], norm2;
    int i;
    do {
        norm2 = 0;
        for (i = 0; i < 4; ++i) {
            q[i] = rng_uniform(r, -1.0, 1.0);
            norm2 += q[i] * q[i];
        }
    } while (norm2 < 1e-3 || norm2 > 1.0);
    pm_rotation_from_quaternion(rotation, q[0], q[1], q[2], q[3]);
    for (i = 0; i < 3; ++i) {
        const double magnitude = pow(10.0, rng_uniform(r, -1.0, 8.0));
        translation[i] = rng_one_in(r, 5) ? 0.0 : rng_uniform(r, -magnitude, magnitude);
    }
}

/* A random double layout of the mesh (strides up to 64, unaligned ones, a
   misaligned buffer, uint16 or uint32 indices). */
static pm_layout random_double_layout(rng* r) {
    static const size_t strides[] = {0, 24, 25, 27, 31, 32, 48, 64};
    pm_layout layout;
    layout.position_type = POLYMASS_POSITION_FLOAT64;
    layout.stride = strides[rng_below(r, sizeof strides / sizeof strides[0])];
    layout.misalign = rng_below(r, 8);
    layout.index_type = rng_one_in(r, 2) ? POLYMASS_INDEX_UINT16 : POLYMASS_INDEX_UINT32;
    return layout;
}

static void expect_status_at(const char* file, int line, const char* call, int32_t expected,
                             int32_t got) {
    if (got != expected) {
        char what[200];
        snprintf(what, sizeof what, "expected status %d (%s), got %d (%s)", (int)expected,
                 polymass_status_string(expected), (int)got, polymass_status_string(got));
        fail_trial_at(file, line, call, what);
    }
}

static void expect_count_at(const char* file, int line, const char* field, uint64_t expected,
                            uint64_t got) {
    if (got != expected) {
        char what[200];
        snprintf(what, sizeof what, "%s is %llu, expected %llu", field, (unsigned long long)got,
                 (unsigned long long)expected);
        fail_trial_at(file, line, "polymass_mesh_diagnostics", what);
    }
}
#define EXPECT_COUNT(field, expected, got) \
    expect_count_at(__FILE__, __LINE__, (field), (expected), (got))

/* A successful result of the moved unit cube: volume 1, the given mass,
   centre at the moved (0.5, 0.5, 0.5), isotropic inertia m/6. The cube's
   coordinates were rounded to doubles of up to 1e8: 1e-6 relative. */
static void expect_near_at(const char* file, int line, const char* what, double expected,
                           double got, double allowed) {
    if (!(fabs(got - expected) <= allowed)) {
        char text[200];
        snprintf(text, sizeof text, "%s: expected %.17g, got %.17g (allowed error %.3g)", what,
                 expected, got, allowed);
        fail_trial_at(file, line, "moved cube", text);
    }
}

static void check_moved_cube_at(const char* file, int line, const polymass_mass_properties* p,
                                double mass, const double center[3]) {
    static const double tol = 1e-6;
    int i;
    check_properties_at(file, line, "moved cube", p, 1);
    expect_near_at(file, line, "volume", 1.0, p->volume, tol);
    expect_near_at(file, line, "mass", mass, p->mass, tol * mass);
    for (i = 0; i < 3; ++i) {
        expect_near_at(file, line, "centre of mass", center[i], p->center_of_mass[i],
                       tol + 1e-15 * fabs(center[i]));
        expect_near_at(file, line, "principal moment = m / 6", mass / 6, p->principal_moments[i],
                       tol * mass);
    }
    for (i = 0; i < 9; ++i) {
        expect_near_at(file, line, "inertia = m / 6 Id", i % 4 == 0 ? mass / 6 : 0.0, p->inertia[i],
                       tol * mass);
    }
}

static void test_perturbed_cubes(void** state) {
    rng r = {0x5EED0005u};
    polymass_context* ctx = held.contexts[0] = pm_context_new();
    pm_laid_out_mesh* laid_out = &held.laid_out;
    pm_mesh* m = &held.cube;
    int i;
    (void)state;
    begin_phase("perturbed cubes");
    for (i = 0; i < PERTURBATION_ITERATIONS; ++i) {
        static const double half[3] = {0.5, 0.5, 0.5};
        const int triangulated = rng_one_in(&r, 2);
        const mutation mu = (mutation)rng_below(&r, MUTATION_COUNT);
        const uint32_t flags = rng_below(&r, 16);
        const pm_layout layout = random_double_layout(&r);
        const double density = rng_uniform(&r, 0.1, 10.0);
        const polymass_mass_desc mass = pm_mass_density(density);
        const int32_t expect_create = expected_create_status(mu, flags);
        const int32_t expect_check = expected_check_status(mu, flags);
        double rotation[9], translation[3], center[3];
        polymass_options o = pm_options(flags, 0.0);
        polymass_mesh* mesh = (polymass_mesh*)&mesh;
        polymass_mass_properties p;
        polymass_diagnostics diag;
        topology_counts expected;
        int32_t s;
        char call[160];
        current.iteration = i;
        current.options = &o;
        current.mass = &mass;

        pm_mesh_unit_cube(m, triangulated);
        random_rigid_motion(&r, rotation, translation);
        pm_mesh_transform(m, rotation, 1.0, translation);
        center[0] = center[1] = center[2] = 0;
        {
            int a, b;
            for (a = 0; a < 3; ++a) {
                long double c = translation[a];
                for (b = 0; b < 3; ++b) {
                    c += (long double)rotation[3 * a + b] * half[b];
                }
                center[a] = (double)c;
            }
        }
        mutate(&r, m, mu);
        expected = count_topology(m, (flags & POLYMASS_OPTION_WELD_VERTICES) != 0);
        pm_lay_out(laid_out, m, &layout);
        current.desc = &laid_out->desc;
        snprintf(call, sizeof call, "%s cube, %s, flags 0x%x",
                 triangulated ? "triangulated" : "quad", mutation_names[mu], (unsigned)flags);

        s = polymass_mesh_create(&mesh, ctx, &laid_out->desc, &o);
        tally(&main_tally, s);
        held.mesh = mesh;
        CHECK_STATUS(call, s, ctx);
        if (expect_create >= 0) {
            expect_status_at(__FILE__, __LINE__, call, expect_create, s);
        }
        if (mesh == NULL) {
            fail_trial_at(__FILE__, __LINE__, call, "no mesh after an analysis");
        } else {
            int32_t properties_status;
            pm_props_init(&p);
            properties_status = polymass_mesh_mass_properties(&p, ctx, mesh, &mass);
            CHECK_STATUS(call, properties_status, ctx);
            if (s != POLYMASS_OK) {
                expect_status_at(__FILE__, __LINE__, call, s, properties_status);
            } else if (expect_create == POLYMASS_OK) {
                PM_ASSERT_OK(ctx, properties_status);
                check_moved_cube_at(__FILE__, __LINE__, &p, density, center);
            } else if (properties_status == POLYMASS_OK) {
                CHECK_PROPERTIES(call, &p, 0); /* open or flipped, unchecked */
            }
            pm_diagnostics_init(&diag);
            PM_ASSERT_OK(ctx, polymass_mesh_diagnostics(&diag, ctx, mesh));
            if (((diag.checks & POLYMASS_CHECKED_TOPOLOGY) != 0) !=
                !(flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS)) {
                fail_trial_at(__FILE__, __LINE__, call, "diagnostics.checks not the options'");
            }
            release_mesh_object();
        }

        pm_props_init(&p);
        s = polymass_mass_properties_compute(&p, NULL, ctx, &laid_out->desc, &o, &mass);
        CHECK_STATUS(call, s, ctx);
        if (expect_create >= 0) {
            expect_status_at(__FILE__, __LINE__, call, expect_create, s);
        }
        if (s == POLYMASS_OK && expect_create == POLYMASS_OK) {
            check_moved_cube_at(__FILE__, __LINE__, &p, density, center);
            if ((flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS) &&
                !(p.warnings & POLYMASS_WARNING_UNCHECKED)) {
                fail_trial_at(__FILE__, __LINE__, call, "no UNCHECKED warning");
            }
            if (mu == FLIP_ALL && !(p.warnings & POLYMASS_WARNING_INVERTED)) {
                fail_trial_at(__FILE__, __LINE__, call, "no INVERTED warning");
            }
        } else if (s == POLYMASS_OK) {
            CHECK_PROPERTIES(call, &p, 0); /* open or flipped, unchecked */
        }

        /* The findings with the topology checked, whatever the flags. */
        o.flags &= ~POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
        s = pm_diagnose(&diag, ctx, &laid_out->desc, &o);
        tally(&check_tally, s);
        CHECK_STATUS(call, s, ctx);
        expect_status_at(__FILE__, __LINE__, call, expect_check, s);
        expect_status_at(__FILE__, __LINE__, "polymass_mesh_diagnostics", s, diag.status);
        EXPECT_COUNT("face_count", m->face_count, diag.face_count);
        EXPECT_COUNT("used_vertex_count", expected.used_vertices, diag.used_vertex_count);
        EXPECT_COUNT("edge_count", expected.edges, diag.edge_count);
        EXPECT_COUNT("open_edges", expected.open, diag.open_edges);
        EXPECT_COUNT("non_manifold_edges", expected.non_manifold, diag.non_manifold_edges);
        EXPECT_COUNT("misoriented_edges", expected.misoriented, diag.misoriented_edges);

        current.desc = NULL;
        current.options = NULL;
        current.mass = NULL;
        pm_laid_out_free(laid_out);
        pm_mesh_free(m);
    }
    end_phase("polymass_mesh_create");
}

/* ------------------------------------------------------------------------ */
/* The smallest inputs found for each kind of finding, one test each        */
/* ------------------------------------------------------------------------ */

/* The corner tetrahedron (0,0,0), (s,0,0), (0,s,0), (0,0,s) with a body
   description: finite, valid input whose results overflow or underflow. */
typedef struct corner_tetra_case {
    const char* name;
    double scale;
    uint32_t mass_mode;
    double amount; /* density or mass */
    double point_x;
    const char* says; /* part of the message; NULL: the inertia about (point_x, 0, 0) */
} corner_tetra_case;

static const corner_tetra_case corner_tetra_cases[] = {
    {"corner tetrahedron of side 1e62: inertia overflows", 1e62, POLYMASS_MASS_FROM_DENSITY, 1.0,
     0.0, "do not fit in a double"},
    {"corner tetrahedron of side 1e103: volume overflows", 1e103, POLYMASS_MASS_FROM_DENSITY, 1.0,
     0.0, "too large"},
    {"corner tetrahedron of side 1e-120: volume underflows", 1e-120, POLYMASS_MASS_FROM_TOTAL, 1.0,
     0.0, "too small"},
    /* Subnormal coordinates: the unit of the integration stops at 2^-1022,
       whose inverse is finite (the inverse of a subnormal unit overflowed,
       and the mesh was said to be too large). */
    {"corner tetrahedron of side 1e-313: volume underflows", 1e-313, POLYMASS_MASS_FROM_TOTAL, 1.0,
     0.0, "too small"},
    {"unit corner tetrahedron, density 4.9e-324: mass underflows", 1.0, POLYMASS_MASS_FROM_DENSITY,
     4.9406564584124654e-324, 0.0, "mass"},
    {"corner tetrahedron of side 4, density DBL_MAX: mass overflows", 4.0,
     POLYMASS_MASS_FROM_DENSITY, DBL_MAX, 0.0, "mass"},
    /* The properties fit; the inertia about a point that far does not. */
    {"unit corner tetrahedron, point (1e160, 0, 0): the inertia about it overflows", 1.0,
     POLYMASS_MASS_FROM_DENSITY, 1.0, 1e160, NULL},
};
#define CORNER_TETRA_CASE_COUNT (sizeof corner_tetra_cases / sizeof corner_tetra_cases[0])

static void test_corner_tetra_case(void** state) {
    static const uint32_t faces[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const corner_tetra_case* c = *state;
    double positions[12] = {0};
    polymass_mesh_desc d;
    polymass_mass_desc mass = c->mass_mode == POLYMASS_MASS_FROM_TOTAL ? pm_mass_total(c->amount)
                                                                       : pm_mass_density(c->amount);
    polymass_mass_properties p;
    polymass_context* ctx = held.contexts[0] = pm_context_new();
    int32_t s;
    begin_phase(c->name);
    positions[3] = positions[7] = positions[11] = c->scale;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.positions = positions;
    d.vertex_count = 4;
    d.indices = faces;
    d.index_count = 12;
    current.desc = &d;
    current.mass = &mass;
    pm_props_init(&p);
    s = polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, &mass);
    CHECK_STATUS("polymass_mass_properties_compute", s, ctx);
    if (c->says == NULL) {
        const double point[3] = {c->point_x, 0, 0};
        double inertia[9];
        PM_ASSERT_OK(ctx, s);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OVERFLOW, polymass_inertia_about(inertia, &p, point));
        return;
    }
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OVERFLOW, s);
    /* The message names what overflowed, not a NaN it led to. */
    if (strstr(polymass_context_message(ctx), "nan") ||
        !strstr(polymass_context_message(ctx), c->says)) {
        fail_msg("%s: \"%s\" does not say \"%s\"", c->name, polymass_context_message(ctx), c->says);
    }
}

/* The right triangle (0,0), (s,0), (0,s). */
typedef struct triangle_case {
    const char* name;
    double scale;
} triangle_case;

static const triangle_case triangle_cases[] = {
    {"right triangle of side 1e78: second moments overflow", 1e78},
    {"right triangle of side 1e155: area overflows", 1e155},
};
#define TRIANGLE_CASE_COUNT (sizeof triangle_cases / sizeof triangle_cases[0])

static void test_triangle_case(void** state) {
    const triangle_case* c = *state;
    double xy[6] = {0};
    polymass_polygon_properties p;
    polymass_context* ctx = held.contexts[0] = pm_context_new();
    int32_t s;
    begin_phase(c->name);
    xy[2] = xy[5] = c->scale;
    current.points = xy;
    current.point_count = 3;
    pm_polygon_props_init(&p);
    s = polymass_polygon_compute(&p, ctx, xy, 3, 0);
    CHECK_STATUS("polymass_polygon_compute", s, ctx);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OVERFLOW, s);
}

/* A mesh that cannot be made for want of memory: OUT_OF_MEMORY, no mesh, a
   message. */
static void test_mesh_create_when_out_of_memory(void** state) {
    static flaky_allocator always_failing;
    const polymass_allocator failing = {sizeof(polymass_allocator), 0, flaky_allocate,
                                        flaky_deallocate, &always_failing};
    polymass_mesh* mesh = (polymass_mesh*)&mesh;
    polymass_context* ctx = NULL;
    int32_t s;
    (void)state;
    begin_phase("mesh_create out of memory");
    always_failing.one_in = 0;
    assert_int_equal(polymass_context_create(&ctx, &failing), POLYMASS_OK);
    held.contexts[0] = ctx;
    pm_mesh_unit_cube(&held.cube, 1);
    {
        const polymass_mesh_desc d = pm_mesh_desc(&held.cube);
        always_failing.one_in = 1; /* every allocation fails from here */
        s = polymass_mesh_create(&mesh, ctx, &d, NULL);
        always_failing.one_in = 0;
    }
    CHECK_STATUS("polymass_mesh_create", s, ctx);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OUT_OF_MEMORY, s);
    assert_null(mesh);
}

/* A test of the table: its name is the case's. */
static struct CMUnitTest case_test(const char* name, CMUnitTestFunction test, const void* c) {
    struct CMUnitTest t;
    memset(&t, 0, sizeof t);
    t.name = name;
    t.test_func = test;
    t.teardown_func = release_held;
    t.initial_state = (void*)c;
    return t;
}

int main(void) {
    struct CMUnitTest tests[4 + CORNER_TETRA_CASE_COUNT + TRIANGLE_CASE_COUNT + 1] = {
        cmocka_unit_test_teardown(test_hostile_small_calls, release_held),
        cmocka_unit_test_teardown(test_hostile_meshes, release_held),
        cmocka_unit_test_teardown(test_hostile_polygons, release_held),
        cmocka_unit_test_teardown(test_perturbed_cubes, release_held),
    };
    size_t n = 4, k;
    for (k = 0; k < CORNER_TETRA_CASE_COUNT; ++k) {
        tests[n++] =
            case_test(corner_tetra_cases[k].name, test_corner_tetra_case, &corner_tetra_cases[k]);
    }
    for (k = 0; k < TRIANGLE_CASE_COUNT; ++k) {
        tests[n++] = case_test(triangle_cases[k].name, test_triangle_case, &triangle_cases[k]);
    }
    tests[n++] = (struct CMUnitTest)cmocka_unit_test_teardown(test_mesh_create_when_out_of_memory,
                                                              release_held);
    return _cmocka_run_group_tests("robustness", tests, n, NULL, NULL);
}
