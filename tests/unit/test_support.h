/* Shared helpers of the libpolymass unit tests: a growable mesh builder,
 * expected values (closed forms, the exact reference, transformed), and
 * assertions with a stated tolerance that print the quantity, the expected and
 * computed values and the error when they fail.
 *
 * Tolerance convention (PM_TOL = 1e-12 relative):
 *   scalars (volume, mass, area, diagonal moments): relative to themselves;
 *   off-diagonal tensor terms: relative to the tensor's largest entry;
 *   centre of mass: relative to the mesh size (bounding-box diagonal), plus
 *     a few ulps of the coordinate itself (a centre at 1e8 cannot be closer
 *     than its own spacing, 1.5e-8).
 */
#ifndef POLYMASS_TESTS_UNIT_TEST_SUPPORT_H
#define POLYMASS_TESTS_UNIT_TEST_SUPPORT_H

/* cmocka.h needs these first. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <polymass/polymass.h>

#include "reference/exact_reference.h"

#define PM_TOL 1e-12

/* ------------------------------------------------------------------------ */
/* Mesh builder                                                             */
/* ------------------------------------------------------------------------ */

typedef struct pm_mesh {
    double* positions; /* x, y, z per vertex */
    size_t vertex_count;
    size_t vertex_capacity;
    uint32_t* indices;
    size_t index_count;
    size_t index_capacity;
    uint32_t* face_sizes;
    size_t face_count;
    size_t face_capacity;
} pm_mesh;

void pm_mesh_init(pm_mesh* m);
void pm_mesh_free(pm_mesh* m);
void pm_mesh_copy(pm_mesh* dst, const pm_mesh* src);
uint32_t pm_mesh_add_vertex(pm_mesh* m, double x, double y, double z);
void pm_mesh_add_face(pm_mesh* m, size_t n, const uint32_t* indices);
void pm_mesh_add_tri(pm_mesh* m, uint32_t a, uint32_t b, uint32_t c);
void pm_mesh_add_quad(pm_mesh* m, uint32_t a, uint32_t b, uint32_t c, uint32_t d);
/* Adds a shell of its own vertices. */
void pm_mesh_append(pm_mesh* dst, const pm_mesh* src);
/* An axis-aligned box [lo, hi], outward quads (or 12 triangles). */
void pm_mesh_add_box(pm_mesh* m, const double lo[3], const double hi[3], int triangulate);
/* A new mesh holding only the box [lo, hi]. */
void pm_mesh_box(pm_mesh* m, const double lo[3], const double hi[3], int triangulate);
/* A new mesh holding only the unit cube [0, 1]^3: vertex k at (k & 1,
   (k >> 1) & 1, (k >> 2) & 1); faces z = 0, z = 1, y = 0, y = 1, x = 0, x = 1
   (each one quad, or two triangles). */
void pm_mesh_unit_cube(pm_mesh* m, int triangulate);
/* Extrusion of a counter-clockwise polygon (n points, x y pairs) from z0 to
   z1, caps as single polygon faces, sides as quads. */
void pm_mesh_add_prism(pm_mesh* m, const double* xy, size_t n, double z0, double z1);
/* A torus around the z axis through centre: rings x segments quads, two
   triangles each, outward (a large closed mesh of any size). */
void pm_mesh_add_torus(pm_mesh* m, uint32_t rings, uint32_t segments, double major, double minor,
                       const double centre[3]);
void pm_mesh_from_reference(pm_mesh* m, const pm_reference_solid* ref);
size_t pm_mesh_face_offset(const pm_mesh* m, size_t face);
void pm_mesh_reverse_face(pm_mesh* m, size_t face);
void pm_mesh_reverse_all(pm_mesh* m);
void pm_mesh_remove_face(pm_mesh* m, size_t face);
/* Splits every face into a fan from its first vertex (for convex faces). */
void pm_mesh_triangulate_fan(pm_mesh* m);
/* Gives every face its own copies of its vertices (an STL-style soup). */
void pm_mesh_to_soup(pm_mesh* m);
/* x' = scale * R x + t, in long double, rounded once. R or t may be NULL. */
void pm_mesh_transform(pm_mesh* m, const double rotation[9], double scale,
                       const double translation[3]);
int pm_mesh_all_triangles(const pm_mesh* m);
/* Where a case is also tried: x' = scale x + translation. */
typedef struct pm_placement {
    const char* name;
    double scale;
    double translation[3];
} pm_placement;
/* A copy of src (dst initialised here) placed by `at`. */
void pm_mesh_placed(pm_mesh* dst, const pm_mesh* src, const pm_placement* at);
double pm_mesh_size(const pm_mesh* m); /* bounding-box diagonal */
/* Describes the mesh (packed doubles, uint32 indices); face_sizes is NULL
   when every face is a triangle unless force_face_sizes. */
polymass_mesh_desc pm_mesh_desc_ex(const pm_mesh* m, int force_face_sizes);
polymass_mesh_desc pm_mesh_desc(const pm_mesh* m);
polymass_mesh_desc pm_reference_desc(const pm_reference_solid* ref);
/* Whether a reference solid's faces touch by construction (four boxes face
   to face; caps fanned into triangles that overlap outside the star): the
   intersection check of the default options warns of it
   (POLYMASS_WARNING_TOUCHING_FACES). */
int pm_reference_touches_itself(const pm_reference_solid* ref);
/* The flags that compute a reference solid rotated by a rotation rounded to
   doubles. The faces that touch by construction no longer lie exactly in one
   plane once rounded: the boxes of the ring go into each other and the
   star's fan through itself by a rounding error, and the intersection check,
   exact, refuses them. It is skipped for those solids only. */
uint32_t pm_reference_rounded_rotation_flags(const pm_reference_solid* ref);

/* A mesh's data laid out as a caller's vertex and index buffers may be. */
typedef struct pm_layout {
    uint32_t position_type; /* POLYMASS_POSITION_* */
    size_t stride;          /* bytes from one vertex to the next; 0: packed */
    size_t misalign;        /* bytes from the start of a malloc'ed block */
    uint32_t index_type;    /* POLYMASS_INDEX_* */
} pm_layout;

typedef struct pm_laid_out_mesh {
    unsigned char* block; /* the vertex buffer's allocation */
    uint16_t* indices16;  /* the uint16 copy of the indices, or NULL */
    polymass_mesh_desc desc;
} pm_laid_out_mesh;

/* Copies the mesh's positions and indices into buffers of the layout, each
   value converted exactly (asserted; NaN stays NaN). The bytes of a vertex
   record after its position are junk, and where the record has room for a
   normal, one that is not a position (NaN for doubles). desc describes the
   copy, face_sizes as pm_mesh_desc (the mesh's own array). */
void pm_lay_out(pm_laid_out_mesh* out, const pm_mesh* m, const pm_layout* layout);
void pm_laid_out_free(pm_laid_out_mesh* out);

/* ------------------------------------------------------------------------ */
/* Expected values                                                          */
/* ------------------------------------------------------------------------ */

typedef struct pm_expected {
    double volume;
    double center_of_mass[3];
    double inertia[9];
    double inertia_origin[9];
    double surface_area; /* NaN: not checked */
    double size;         /* bounding-box diagonal: the scale of the centre tolerance */
} pm_expected;

pm_expected pm_expected_from_reference(const pm_reference_solid* ref);
/* Closed forms of a box: V = abc, Ixx = m (b^2 + c^2) / 12, ... */
pm_expected pm_expected_box(const double lo[3], const double hi[3]);
/* The solid mapped by x' = scale * R x + t: V s^3, I s^5 R I R^T, ... in long
   double. R or t may be NULL. */
pm_expected pm_expected_transform(const pm_expected* e, const double rotation[9], double scale,
                                  const double translation[3]);
/* Sum of disjoint solids (a composite body). */
pm_expected pm_expected_sum(const pm_expected* a, const pm_expected* b);
/* I_P = I_C + m (|d|^2 Id - d d^T), d = C - P, in long double. */
void pm_parallel_axis(double out[9], const double inertia_com[9], double mass, const double com[3],
                      const double point[3]);

/* ------------------------------------------------------------------------ */
/* Library calls                                                            */
/* ------------------------------------------------------------------------ */

/* Every status code of the header, in the order of its values. */
extern const int32_t pm_all_statuses[];
extern const size_t pm_status_count;
/* The status is one of pm_all_statuses. */
int pm_is_documented_status(int32_t status);

/* A context (asserts success). Options are per call: the helpers below
   that take `flags` pass pm_options(flags, 0). */
polymass_context* pm_context_new(void);
/* Options with struct_size set (tolerance 0 means the default). */
polymass_options pm_options(uint32_t flags, double planarity_tolerance);
/* Output structs zeroed, with struct_size set. */
void pm_props_init(polymass_mass_properties* p);
void pm_diagnostics_init(polymass_diagnostics* d);
void pm_polygon_props_init(polymass_polygon_properties* p);
polymass_mass_desc pm_mass_density(double density);
polymass_mass_desc pm_mass_total(double mass);
/* polymass_mass_properties_compute with the default options, or with the
   option flags given. */
int32_t pm_compute(polymass_mass_properties* out, polymass_context* ctx, const pm_mesh* m,
                   const polymass_mass_desc* mass);
int32_t pm_compute_flags(polymass_mass_properties* out, polymass_context* ctx, const pm_mesh* m,
                         uint32_t flags, const polymass_mass_desc* mass);
/* The diagnostics of the mesh (polymass_mesh_create, then
   polymass_mesh_diagnostics) with the default options, or the option flags
   given; returns their status (the surface's verdict as a solid). The
   context's message is then the mesh's (polymass_mesh_message). */
int32_t pm_check(polymass_diagnostics* out, polymass_context* ctx, const pm_mesh* m);
int32_t pm_check_flags(polymass_diagnostics* out, polymass_context* ctx, const pm_mesh* m,
                       uint32_t flags);
/* The same for a description and options (NULL: the defaults). */
int32_t pm_diagnose(polymass_diagnostics* out, polymass_context* ctx,
                    const polymass_mesh_desc* desc, const polymass_options* options);
/* The moments of a surface (polymass_mesh_create with the options, NULL:
   the defaults, then polymass_mesh_moments); the status of either. */
int32_t pm_moments(polymass_moments* out, polymass_context* ctx, const polymass_mesh_desc* desc,
                   const polymass_options* options);
/* polymass_mass_properties_compute (unit density) of the committed arrays of
   a reference solid. */
int32_t pm_compute_reference(polymass_mass_properties* out, polymass_context* ctx,
                             const pm_reference_solid* ref);
/* pm_compute_reference into *out, asserting success and the exact values. */
void pm_check_reference_compute(const char* file, int line, polymass_context* ctx,
                                const pm_reference_solid* ref, polymass_mass_properties* out);

/* ------------------------------------------------------------------------ */
/* Assertions                                                               */
/* ------------------------------------------------------------------------ */

/* |got - expected| <= allowed, else print and fail at file:line. */
void pm_check_abs(const char* file, int line, const char* what, double expected, double got,
                  double allowed);
/* |got - expected| <= tol * max(|expected|, scale). */
void pm_check_close(const char* file, int line, const char* what, double expected, double got,
                    double tol, double scale);
/* Exact (bitwise for non-NaN) equality of doubles. */
void pm_check_same(const char* file, int line, const char* what, double expected, double got);
void pm_check_vec(const char* file, int line, const char* what, const double* expected,
                  const double* got, size_t n, double tol, double scale);
/* Diagonal relative to itself, off-diagonal relative to the largest entry. */
void pm_check_tensor(const char* file, int line, const char* what, const double expected[9],
                     const double got[9], double tol);
/* Volume, mass and density (unit density), centre of mass, both tensors,
   surface area; all with tolerance tol. */
void pm_check_properties(const char* file, int line, const char* what, const pm_expected* e,
                         const polymass_mass_properties* got, double tol);
/* Every field of two results bitwise equal. */
void pm_check_same_properties(const char* file, int line, const char* what,
                              const polymass_mass_properties* expected,
                              const polymass_mass_properties* got);
void pm_check_status(const char* file, int line, const char* what, int32_t expected, int32_t got,
                     const polymass_context* ctx);
/* The context message mentions "<word> <number>" (e.g. "face 6"). */
void pm_check_message_mentions(const char* file, int line, const polymass_context* ctx,
                               const char* word, uint64_t number);
/* The context message contains the word and every number as a separate
   token (e.g. an edge "(4, 9)" in either order). */
void pm_check_message_tokens(const char* file, int line, const polymass_context* ctx,
                             const char* word, const uint64_t* numbers, size_t count);

#define PM_ASSERT_ABS(what, expected, got, allowed) \
    pm_check_abs(__FILE__, __LINE__, (what), (expected), (got), (allowed))
#define PM_ASSERT_CLOSE(what, expected, got, tol, scale) \
    pm_check_close(__FILE__, __LINE__, (what), (expected), (got), (tol), (scale))
#define PM_ASSERT_REL(what, expected, got, tol) \
    pm_check_close(__FILE__, __LINE__, (what), (expected), (got), (tol), 0.0)
#define PM_ASSERT_SAME(what, expected, got) \
    pm_check_same(__FILE__, __LINE__, (what), (expected), (got))
#define PM_ASSERT_VEC(what, expected, got, n, tol, scale) \
    pm_check_vec(__FILE__, __LINE__, (what), (expected), (got), (n), (tol), (scale))
#define PM_ASSERT_TENSOR(what, expected, got, tol) \
    pm_check_tensor(__FILE__, __LINE__, (what), (expected), (got), (tol))
#define PM_ASSERT_PROPERTIES(what, expected, got, tol) \
    pm_check_properties(__FILE__, __LINE__, (what), (expected), (got), (tol))
#define PM_ASSERT_SAME_PROPERTIES(what, expected, got) \
    pm_check_same_properties(__FILE__, __LINE__, (what), (expected), (got))
#define PM_ASSERT_STATUS(ctx, expected, got) \
    pm_check_status(__FILE__, __LINE__, #got, (expected), (got), (ctx))
#define PM_ASSERT_OK(ctx, got) PM_ASSERT_STATUS((ctx), POLYMASS_OK, (got))
#define PM_ASSERT_REFERENCE_COMPUTE(ctx, ref, out) \
    pm_check_reference_compute(__FILE__, __LINE__, (ctx), (ref), (out))
#define PM_ASSERT_MENTIONS(ctx, word, number) \
    pm_check_message_mentions(__FILE__, __LINE__, (ctx), (word), (number))
#define PM_ASSERT_EDGE_MENTIONED(ctx, a, b)                                      \
    do {                                                                         \
        const uint64_t pm_edge_[2] = {(uint64_t)(a), (uint64_t)(b)};             \
        pm_check_message_tokens(__FILE__, __LINE__, (ctx), "edge", pm_edge_, 2); \
    } while (0)

/* ------------------------------------------------------------------------ */
/* Small linear algebra (row-major 3x3)                                     */
/* ------------------------------------------------------------------------ */

void pm_mat3_mul(double out[9], const double a[9], const double b[9]);
void pm_mat3_transpose(double out[9], const double a[9]);
double pm_mat3_det(const double a[9]);
/* Rotation matrix of the quaternion (w, x, y, z), normalised, in long double. */
void pm_rotation_from_quaternion(double out[9], double w, double x, double y, double z);

#endif /* POLYMASS_TESTS_UNIT_TEST_SUPPORT_H */
