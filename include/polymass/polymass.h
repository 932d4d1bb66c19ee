/*
 * libpolymass — mass properties of solid polyhedra and planar polygons.
 *
 * WHAT IT COMPUTES
 *   For a closed polyhedral surface (triangles and/or planar polygons, convex or
 *   not, any number of shells): volume, mass, centre of mass, the inertia tensor
 *   about the centre of mass, the origin or any point, principal moments and
 *   axes, and surface area. For a simple planar polygon: area, centroid and
 *   second moments of area. The method is Mirtich's (divergence theorem to face
 *   integrals, Green's theorem to edge sums), integrated about a reference point
 *   inside the mesh's bounding box so that a part far from the origin keeps its
 *   digits.
 *
 * UNITS
 *   The library has none of its own: lengths are in the caller's unit L,
 *   density in M/L^3, mass in M, inertia in M*L^2. Without a density or a mass
 *   the density is 1, so mass == volume.
 *
 * ORIENTATION
 *   Faces are listed counter-clockwise seen from outside the solid (right-hand
 *   rule: the face normal points out). Such a surface has positive volume. A
 *   surface whose faces are all reversed is reported as POLYMASS_ERROR_INVERTED
 *   unless POLYMASS_OPTION_ACCEPT_INVERTED is set.
 *
 * INERTIA SIGN CONVENTION
 *   I = integral of rho * (|r|^2 * Identity - r r^T) dV, so the diagonal is
 *   Ixx = integral rho (y^2 + z^2) dV and the off-diagonal terms are the NEGATED
 *   products of inertia: Ixy = -integral rho x y dV. This is the tensor that
 *   URDF (ixy), SDFormat, MuJoCo (fullinertia), PhysX and Bullet expect.
 *   Matrices are 3x3, row-major, symmetric. The point-about rule is the
 *   parallel-axis theorem I_P = I_C + m (|d|^2 Identity - d d^T), d = C - P.
 *
 * THREADING
 *   The library has no global mutable state. A context is used by one thread at
 *   a time (it holds the last error message); distinct contexts are
 *   independent. A mesh is immutable once created: any number of threads may
 *   read it at once, each through its own context.
 *   The library starts threads only when polymass_options.threads asks for
 *   more than one: a context then starts that many workers, less one (the
 *   calling thread works too), on the first call that needs them, reuses them
 *   for later calls and joins them in polymass_context_destroy (a context
 *   asked for another count replaces its workers). Work is cut into pieces
 *   fixed by the input alone (blocks of faces, the items of a batch) and the
 *   pieces' results are combined in a fixed order, so every thread count gives
 *   the same bits. The context's allocator may then be called from the
 *   workers, but from one thread at a time.
 *
 * ERRORS
 *   Every fallible function returns an int32_t status (POLYMASS_OK == 0) and
 *   never throws, asserts or aborts on bad input. Output structs are written
 *   only on success (polymass_mesh_check's report: whenever out_report itself
 *   is valid). polymass_status_string() names a status;
 *   polymass_context_message() says what and where ("face 17 has 2 vertices",
 *   "edge (4, 9) is used by 3 faces").
 *
 * STABILITY
 *   Within a major version the ABI only grows: functions and status codes are
 *   added, never changed or removed, status values are never reused, and
 *   public structs only gain fields at their end. Every struct passed in or out
 *   starts with struct_size, which the caller sets to sizeof(the struct) it was
 *   compiled with (the polymass_*_init functions and POLYMASS_*_INIT macros do
 *   it), so an older caller keeps working with a newer library: the library
 *   accepts the size of every version of a struct since 1.0.0, reads an input
 *   struct only up to its struct_size (later fields take their defaults) and
 *   writes an output struct only up to its struct_size.
 */
#ifndef POLYMASS_POLYMASS_H
#define POLYMASS_POLYMASS_H

#include <stddef.h>
#include <stdint.h>

#include "polymass/polymass_version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ========================================================================== */
/* Export                                                                     */
/* ========================================================================== */

#if defined(POLYMASS_STATIC)
#define POLYMASS_API
#elif defined(_WIN32)
#if defined(POLYMASS_BUILDING)
#define POLYMASS_API __declspec(dllexport)
#else
#define POLYMASS_API __declspec(dllimport)
#endif
#elif defined(__GNUC__)
#define POLYMASS_API __attribute__((visibility("default")))
#else
#define POLYMASS_API
#endif

/* ========================================================================== */
/* Status codes (explicit values, never reused)                               */
/* ========================================================================== */

#define POLYMASS_OK 0
/* Caller errors: NULL pointer, wrong struct_size, count that overflows, stride
   smaller than a vertex, unknown type or flag, face sizes that do not add up. */
#define POLYMASS_ERROR_INVALID_ARGUMENT 1
/* The allocator returned NULL. */
#define POLYMASS_ERROR_OUT_OF_MEMORY 2
/* A bug in the library; please report it with the message. */
#define POLYMASS_ERROR_INTERNAL 3
/* A coordinate used by a face is NaN or infinite. */
#define POLYMASS_ERROR_NON_FINITE 10
/* A face refers to a vertex past the end of the vertex array. */
#define POLYMASS_ERROR_INDEX_OUT_OF_RANGE 11
/* A face (or a 2D polygon) has fewer than 3 vertices. */
#define POLYMASS_ERROR_FACE_TOO_SMALL 12
/* An edge is used by one face only: the surface has a hole. */
#define POLYMASS_ERROR_OPEN 20
/* An edge is used by more than two faces. */
#define POLYMASS_ERROR_NON_MANIFOLD 21
/* Two faces traverse an edge in the same direction: one of them is flipped. */
#define POLYMASS_ERROR_INCONSISTENT_ORIENTATION 22
/* A polygon face's vertices are off its plane by more than the tolerance. */
#define POLYMASS_ERROR_NON_PLANAR_FACE 23
/* Faces cross each other (or lie on faces of another shell, facing the same
   way), or a shell lies inside a solid of the same sense or passes through
   another's surface where the two touch: the surface bounds some region twice
   and its volume would be counted twice (two overlapping parts exported as
   one file, a surface written twice, a surface folded through itself).
   Checked by default; not with POLYMASS_OPTION_SKIP_INTERSECTION_CHECK or
   POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS. */
#define POLYMASS_ERROR_INTERSECTING 24
/* The enclosed volume is negative: every face is reversed - or one shell is
   inside out (negative volume) while lying inside no solid shell. */
#define POLYMASS_ERROR_INVERTED 30
/* The surface encloses no volume (to rounding), e.g. a flat double-sided sheet. */
#define POLYMASS_ERROR_ZERO_VOLUME 31
/* A 2D polygon encloses no area (to rounding). */
#define POLYMASS_ERROR_ZERO_AREA 32
/* A result does not fit in a double (the coordinates, density, mass or point
   are so large or small that a moment overflows or the mass underflows). */
#define POLYMASS_ERROR_OVERFLOW 40

/* ========================================================================== */
/* Version                                                                    */
/* ========================================================================== */

/* POLYMASS_VERSION_MAJOR/MINOR/PATCH and POLYMASS_VERSION_NUMBER (major * 10000
   + minor * 100 + patch) come from polymass_version.h, generated by CMake. */

/* The version of the library loaded at run time, as POLYMASS_VERSION_NUMBER.
   Compare its major part with the header's before use. Thread-safe. */
POLYMASS_API uint32_t polymass_version(void);

/* "MAJOR.MINOR.PATCH" of the library loaded at run time. Static text. */
POLYMASS_API const char* polymass_version_string(void);

/* Static text naming a status ("open surface", ...); unknown codes give
   "unknown status". Thread-safe. */
POLYMASS_API const char* polymass_status_string(int32_t status);

/* ========================================================================== */
/* Types                                                                      */
/* ========================================================================== */

typedef struct polymass_context polymass_context;
typedef struct polymass_mesh polymass_mesh;

/* Memory for a context and everything made through it. allocate returns memory
   aligned to at least `alignment` (a power of two) or NULL on failure;
   deallocate accepts what allocate returned. A NULL allocator means malloc.
   The functions and user_data must stay valid until the context and every
   mesh made through it are destroyed (a mesh frees itself through them). */
typedef struct polymass_allocator {
    void* (*allocate)(void* user_data, size_t size, size_t alignment);
    void (*deallocate)(void* user_data, void* pointer);
    void* user_data;
} polymass_allocator;

/* polymass_options.flags */
/* Trusted input (a game engine at load time): skip the open, non-manifold,
   orientation and planarity checks, and the intersection check with them
   (see POLYMASS_OPTION_SKIP_INTERSECTION_CHECK). Index range and finiteness
   are always checked, so bad input still cannot crash the library. */
#define POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS (1u << 0)
/* Accept an inverted solid: report it with POLYMASS_WARNING_INVERTED and the
   properties of the solid with its faces turned the right way. */
#define POLYMASS_OPTION_ACCEPT_INVERTED (1u << 1)
/* Treat vertices at the same position as one (STL-style triangle soups) for
   the topology checks: exactly equal positions, or within
   polymass_options.weld_tolerance. The integrals do not depend on it. */
#define POLYMASS_OPTION_WELD_VERTICES (1u << 2)
/* Accept edges shared by more than two faces when they are traversed as often
   in one direction as in the other (two solids touching along an edge). */
#define POLYMASS_OPTION_ACCEPT_NON_MANIFOLD (1u << 3)
/* For trusted input only: skip the intersection check. By default (this bit
   clear) the library also checks that no faces cross each other and that no
   shell lies inside a solid of the same sense (POLYMASS_ERROR_INTERSECTING),
   counting how shells nest exactly; faces that touch without crossing (parts
   resting on each other) give POLYMASS_WARNING_TOUCHING_FACES. Exact
   predicates decide every case. Skipping it saves most of the time of
   polymass_mesh_create (see the README for figures), but two overlapping
   parts exported as one surface then pass, their overlap counted twice, and
   a shell turned inside out is refused only when it lies outside every solid
   shell's bounding box. polymass_mesh_check follows it too (set it there not
   to list crossing and touching faces). The check needs the topology checks:
   POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS skips it as well. */
#define POLYMASS_OPTION_SKIP_INTERSECTION_CHECK (1u << 4)

/* polymass_options.modes: how a surface is turned into a body. Since 1.2. */
/* The chain's end (and an empty chain: solid only). */
#define POLYMASS_MODE_NONE 0
/* Exact for a valid closed solid; otherwise the solid's error (the default). */
#define POLYMASS_MODE_SOLID 1
/* A valid solid as it is; otherwise the surface repaired (orientation,
   duplicate and two-vertex faces, non-planar polygons, holes, non-manifold
   edges used as often each way), each fix recorded in polymass_provenance
   and the error bounds widened by what the fixes that are not exact may have
   changed (docs/repair.md). */
#define POLYMASS_MODE_REPAIR 2
/* The surface as a thin wall of thickness polymass_options.shell_thickness:
   volume = thickness * area, exact for the sheet; needs neither closure nor
   orientation. */
#define POLYMASS_MODE_SHELL 3
/* The convex hull of the vertices the faces use, integrated exactly; the
   error bounds say how far it can be from the surface (docs/repair.md). */
#define POLYMASS_MODE_HULL 4
/* Room in polymass_options.modes. */
#define POLYMASS_MAX_MODES 4

/* Default of polymass_options.planarity_tolerance. */
#define POLYMASS_DEFAULT_PLANARITY_TOLERANCE 1e-6
/* Largest polymass_options.weld_tolerance: a coarser weld would merge
   vertices of distinct features. */
#define POLYMASS_MAX_WELD_TOLERANCE 1e-3
/* Largest polymass_options.threads. */
#define POLYMASS_MAX_THREADS 256

typedef struct polymass_options {
    uint32_t struct_size; /* sizeof(polymass_options) */
    uint32_t flags;       /* POLYMASS_OPTION_* bits */
    /* Largest distance of a polygon face's vertex from the face's plane,
       relative to the face's diameter; 0 means the default. */
    double planarity_tolerance;
    /* With POLYMASS_OPTION_WELD_VERTICES: two vertices whose coordinates each
       differ by at most weld_tolerance times the largest extent of the used
       vertices' bounding box are one vertex (up to rounding), and so are
       chains of such vertices. 0 (the default) welds exactly equal positions
       only; CAD exports whose coordinates carry rounding noise want about
       1e-9. A non-zero value below 2^-50 acts as 2^-50. In
       [0, POLYMASS_MAX_WELD_TOLERANCE]. */
    double weld_tolerance;
    /* Since 1.2. The modes to try, in order, up to the first
       POLYMASS_MODE_NONE: the first that gives an answer answers (say SOLID,
       REPAIR, HULL). All NONE (the default) means SOLID alone. A chain
       without SOLID still answers a valid solid exactly as SOLID does, but
       for SHELL and HULL, which describe another body. Followed by
       polymass_mesh_create*, polymass_mass_properties_compute* and
       polymass_batch_compute; polymass_mass_properties_with_provenance says
       which mode answered and what it did. The checks, shells and moments
       functions judge the surface as given (SOLID) whatever the chain. */
    uint32_t modes[POLYMASS_MAX_MODES];
    /* Since 1.2. The wall thickness of POLYMASS_MODE_SHELL, > 0 and finite
       when the chain holds SHELL. */
    double shell_thickness;
    /* Since 1.3. How many threads one call may use: the calling thread and
       threads - 1 of the context's workers (see THREADING), at most
       POLYMASS_MAX_THREADS. 0 (the default) means 1: the library starts no
       thread unless asked (a host with its own scheduler can spread meshes
       or face ranges itself, see polymass_moments). Followed by
       polymass_batch_compute (items spread over the threads) and by the
       passes over one mesh's faces. Results are bit for bit the same for
       every value. */
    uint32_t threads;
} polymass_options;

/* polymass_mesh_desc.position_type */
#define POLYMASS_POSITION_FLOAT64 0
#define POLYMASS_POSITION_FLOAT32 1
/* polymass_mesh_desc.index_type */
#define POLYMASS_INDEX_UINT32 0
#define POLYMASS_INDEX_UINT16 1

/* A surface as the caller's own arrays; nothing is copied. */
typedef struct polymass_mesh_desc {
    uint32_t struct_size;   /* sizeof(polymass_mesh_desc) */
    uint32_t position_type; /* POLYMASS_POSITION_* */
    /* x, y, z of vertex i start at (const char*)positions + i * position_stride.
       Any alignment is accepted. */
    const void* positions;
    uint64_t vertex_count;
    /* Bytes from one vertex to the next, at least 3 elements; 0 means packed
       (3 elements), so an interleaved vertex buffer is read in place. */
    uint64_t position_stride;
    uint32_t index_type; /* POLYMASS_INDEX_* */
    uint32_t reserved;   /* must be 0 */
    const void* indices; /* the faces' vertex indices, one face after another */
    uint64_t index_count;
    /* Number of vertices of each face, face_count of them, adding up to
       index_count. NULL (and face_count 0) means all faces are triangles. */
    const uint32_t* face_sizes;
    uint64_t face_count;
} polymass_mesh_desc;

/* polymass_mass_desc.mass_mode */
#define POLYMASS_MASS_FROM_DENSITY 0 /* mass = density * volume */
#define POLYMASS_MASS_FROM_TOTAL 1   /* density = mass / volume */

/* How to turn a solid into a body. NULL where one is taken means unit density
   and point = origin. */
typedef struct polymass_mass_desc {
    uint32_t struct_size; /* sizeof(polymass_mass_desc) */
    uint32_t mass_mode;   /* POLYMASS_MASS_FROM_* */
    double density;       /* > 0, finite; read when mass_mode is FROM_DENSITY */
    double mass;          /* > 0, finite; read when mass_mode is FROM_TOTAL */
    double point[3];      /* polymass_mass_properties.inertia_point is about it */
} polymass_mass_desc;

/* polymass_mass_properties.warnings */
#define POLYMASS_WARNING_INVERTED (1u << 0)         /* accepted and turned */
#define POLYMASS_WARNING_DEGENERATE_FACES (1u << 1) /* zero-area faces, harmless */
#define POLYMASS_WARNING_UNCHECKED (1u << 2)        /* topology checks skipped */
#define POLYMASS_WARNING_NON_MANIFOLD (1u << 3)     /* accepted non-manifold edges */
#define POLYMASS_WARNING_TOUCHING_FACES (1u << 4)   /* faces touch without crossing */
/* Since 1.2: the mode that answered, when not SOLID (see polymass_provenance). */
#define POLYMASS_WARNING_REPAIRED (1u << 5) /* a repaired surface */
#define POLYMASS_WARNING_SHELL (1u << 6)    /* a thin wall */
#define POLYMASS_WARNING_HULL (1u << 7)     /* the convex hull */

typedef struct polymass_mass_properties {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_mass_properties) */
    uint32_t warnings;    /* POLYMASS_WARNING_* bits */
    double volume;
    double mass;
    double density;
    double surface_area;
    double center_of_mass[3];
    double inertia[9];           /* about the centre of mass */
    double inertia_origin[9];    /* about (0, 0, 0) */
    double inertia_point[9];     /* about polymass_mass_desc.point */
    double principal_moments[3]; /* eigenvalues of `inertia`, ascending */
    /* Row-major rotation R (det R = +1) whose columns are the principal axes:
       inertia = R diag(principal_moments) R^T. Where moments coincide the axes
       are chosen deterministically (coordinate axes when all three do). */
    double principal_axes[9];
    /* Bounds on the rounding errors of the results above: absolute, in their
       units, from sums of absolute terms carried through the integration,
       the move to the centre of mass and the principal-axes step
       (docs/error_bound.md). They hold for the surface as given: its
       coordinates are taken as exact. The axes' bound, in radians, grows as
       the bound over the gap between the nearest moments, so as moments
       approach each other; it is pi/2 when moments are closer than their
       bounds can tell apart, and covers only axes the moments determine
       (where moments coincide the axes are chosen by convention). Infinite
       when rounding could be the whole mass. */
    double error_bound_volume;
    double error_bound_center_of_mass;    /* of each coordinate */
    double error_bound_inertia;           /* of each entry of `inertia` */
    double error_bound_principal_moments; /* of each */
    double error_bound_principal_axes;    /* angle of each axis, radians */
} polymass_mass_properties;

/* How many locations of each finding polymass_diagnostics lists: the lowest
   face or vertex indices, the edges with the lowest vertex pairs. */
#define POLYMASS_DIAGNOSTIC_LOCATIONS 8

/* No location: the value of the "first_*" entries past the count beside them
   (all of them when it is 0). */
#define POLYMASS_NONE UINT64_MAX

/* What polymass_mesh_check finds: for each kind of finding its count and its
   first (lowest) min(count, POLYMASS_DIAGNOSTIC_LOCATIONS) locations, in
   ascending order. Vertex numbers are the caller's indices (after welding: the
   lowest index at that position); an edge is a vertex pair in the direction
   the faces traverse it (most often). */
typedef struct polymass_diagnostics {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_diagnostics) */
    int32_t status;       /* what polymass_mesh_create would return */
    uint64_t face_count;
    uint64_t used_vertex_count; /* distinct vertices the faces use */
    uint64_t edge_count;        /* distinct undirected edges */
    uint64_t non_finite_vertices;
    uint64_t first_non_finite_vertices[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t out_of_range_indices;
    uint64_t first_out_of_range_faces[POLYMASS_DIAGNOSTIC_LOCATIONS]; /* faces holding them */
    uint64_t small_faces;                                             /* fewer than 3 vertices */
    uint64_t first_small_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t degenerate_faces; /* zero area: legal, harmless */
    uint64_t first_degenerate_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t open_edges; /* used by one face */
    uint64_t first_open_edges[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
    uint64_t non_manifold_edges; /* used by more than two faces */
    uint64_t first_non_manifold_edges[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
    uint64_t misoriented_edges; /* traversed twice the same way */
    uint64_t first_misoriented_edges[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
    uint64_t non_planar_faces;
    uint64_t first_non_planar_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    double max_non_planarity; /* largest relative off-plane distance seen */
    double signed_volume;     /* NaN when the faces could not be integrated */
    /* Since 1.1. Shells are counted on a closed, oriented surface; the face
       pairs unless POLYMASS_OPTION_SKIP_INTERSECTION_CHECK, each pair (lower face,
       higher face), lowest pairs first. Face pairs are counted up to 1024 of
       a kind: past that the count is a lower bound (the message says "at
       least"), and the first pairs are still the lowest. */
    uint64_t shell_count;
    uint64_t inverted_shells; /* inside out, inside no solid shell */
    uint64_t first_inverted_shells[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t overlapping_shells; /* inside a solid of the same sense, or through another */
    uint64_t first_overlapping_shells[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t intersecting_face_pairs; /* faces that cross, or coincide facing the same way */
    uint64_t first_intersecting_face_pairs[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
    uint64_t touching_face_pairs; /* faces that touch without crossing nor sharing a vertex */
    uint64_t first_touching_face_pairs[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
} polymass_diagnostics;

/* polymass_shell.kind */
#define POLYMASS_SHELL_SOLID 1       /* encloses positive volume, in no other solid */
#define POLYMASS_SHELL_CAVITY 2      /* negative volume, inside a solid */
#define POLYMASS_SHELL_INVERTED 3    /* negative volume, inside no solid: inside out */
#define POLYMASS_SHELL_OVERLAPPING 4 /* inside a solid of the same sense: counted twice */
#define POLYMASS_SHELL_NO_VOLUME 5   /* encloses no volume (to rounding) */

/* One shell of a closed surface, as polymass_mesh_shell_list describes it.
   Since 1.1. */
typedef struct polymass_shell {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_shell) */
    int32_t kind;         /* POLYMASS_SHELL_* */
    uint64_t face_count;
    uint64_t first_face;
    /* Signed so that the whole surface's volume is positive (a surface
       accepted inside out as a whole counts turned). */
    double signed_volume;
} polymass_shell;

/* polymass_polygon_properties.orientation */
#define POLYMASS_COUNTER_CLOCKWISE 1
#define POLYMASS_CLOCKWISE (-1)

/* A simple planar polygon in the xy plane. Second moments of AREA, with the
   engineering sign: Ixx = integral y^2 dA, Iyy = integral x^2 dA,
   Ixy = +integral x y dA (not negated, unlike the 3D inertia tensor). */
typedef struct polymass_polygon_properties {
    uint32_t struct_size; /* set by the caller */
    int32_t orientation;  /* POLYMASS_COUNTER_CLOCKWISE or POLYMASS_CLOCKWISE */
    double area;          /* > 0 whatever the orientation */
    double centroid[2];
    double second_moments[3];        /* Ixx, Iyy, Ixy about the centroid */
    double second_moments_origin[3]; /* Ixx, Iyy, Ixy about (0, 0) */
    double polar_moment;             /* Ixx + Iyy about the centroid */
    double principal_moments[2];     /* about the centroid, ascending */
    /* Angle in radians, counter-clockwise from +x, in (-pi/2, pi/2], of the
       axis about which the second moment is principal_moments[0]. */
    double principal_angle;
} polymass_polygon_properties;

/* Sizes of the public structs as this library was compiled: for bindings to
   check their layouts. Thread-safe. */
POLYMASS_API uint32_t polymass_sizeof_allocator(void);
POLYMASS_API uint32_t polymass_sizeof_options(void);
POLYMASS_API uint32_t polymass_sizeof_mesh_desc(void);
POLYMASS_API uint32_t polymass_sizeof_mass_desc(void);
POLYMASS_API uint32_t polymass_sizeof_mass_properties(void);
POLYMASS_API uint32_t polymass_sizeof_diagnostics(void);
POLYMASS_API uint32_t polymass_sizeof_polygon_properties(void);
POLYMASS_API uint32_t polymass_sizeof_shell(void); /* since 1.1 */

/* Initialisers. Each writes a struct's defaults, struct_size included, up to
   the struct_size given, which must be the size of a version of the struct
   this library knows (sizeof the struct as the caller's header declares it):
     polymass_mesh_desc desc;
     polymass_mesh_desc_init(&desc, sizeof desc);
   The defaults are zeros, except polymass_mass_desc's: unit density
   (POLYMASS_MASS_FROM_DENSITY, density 1). Options' zero tolerances mean the
   default tolerances. Return POLYMASS_ERROR_INVALID_ARGUMENT (writing
   nothing) for a NULL struct or an unknown size. Thread-safe. */
POLYMASS_API int32_t polymass_options_init(polymass_options* options, uint32_t struct_size);
POLYMASS_API int32_t polymass_mesh_desc_init(polymass_mesh_desc* desc, uint32_t struct_size);
POLYMASS_API int32_t polymass_mass_desc_init(polymass_mass_desc* mass, uint32_t struct_size);
POLYMASS_API int32_t polymass_mass_properties_init(polymass_mass_properties* properties,
                                                   uint32_t struct_size);
POLYMASS_API int32_t polymass_diagnostics_init(polymass_diagnostics* report, uint32_t struct_size);
POLYMASS_API int32_t polymass_polygon_properties_init(polymass_polygon_properties* properties,
                                                      uint32_t struct_size);

/* The same defaults as static initialisers, for C (designated initialisers
   are C99; C++ before C++20 has none: call the functions above there):
     polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
     body.density = 2700.0; */
#ifndef __cplusplus
#define POLYMASS_OPTIONS_INIT \
    { .struct_size = sizeof(polymass_options) }
#define POLYMASS_MESH_DESC_INIT \
    { .struct_size = sizeof(polymass_mesh_desc) }
#define POLYMASS_MASS_DESC_INIT                                                             \
    {                                                                                       \
        .struct_size = sizeof(polymass_mass_desc), .mass_mode = POLYMASS_MASS_FROM_DENSITY, \
        .density = 1.0                                                                      \
    }
#define POLYMASS_MASS_PROPERTIES_INIT \
    { .struct_size = sizeof(polymass_mass_properties) }
#define POLYMASS_DIAGNOSTICS_INIT \
    { .struct_size = sizeof(polymass_diagnostics) }
#define POLYMASS_POLYGON_PROPERTIES_INIT \
    { .struct_size = sizeof(polymass_polygon_properties) }
#endif

/* ========================================================================== */
/* Context                                                                    */
/* ========================================================================== */

/* Creates a context with default options (all flags off, default planarity
   tolerance). allocator may be NULL (malloc); it is copied. Thread-safe. */
POLYMASS_API int32_t polymass_context_create(polymass_context** out_context,
                                             const polymass_allocator* allocator);

/* Frees a context. NULL is accepted. Meshes made through it stay valid.
   Not while another thread uses the context. */
POLYMASS_API void polymass_context_destroy(polymass_context* context);

/* Sets the options used by later calls through this context.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_context_set_options(polymass_context* context,
                                                  const polymass_options* options);

/* Reads the context's options; out_options->struct_size must be set.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_context_get_options(polymass_options* out_options,
                                                  polymass_context* context);

/* Since 1.3. A context keeps the large scratch blocks of its calls (the
   topology check's edge lists, the shells' tables: up to about 16 bytes per
   triangle, from the context's allocator) for its next calls, so that a call
   on a large mesh does not map fresh memory from the system and fault on
   every page of it each time; polymass_context_destroy frees them. This
   bounds what it keeps between calls (and frees what is beyond now): 0 keeps
   nothing. The default, UINT64_MAX, keeps what the largest recent call used.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_context_set_scratch_limit(polymass_context* context,
                                                        uint64_t max_kept_bytes);

/* The detailed message of the last call through this context that failed
   ("" after a success). Valid until the next call through the context, from
   the thread that made that call. Never NULL. */
POLYMASS_API const char* polymass_context_message(const polymass_context* context);

/* ========================================================================== */
/* Solids                                                                     */
/* ========================================================================== */

/* Validates the surface (arguments, indices, finiteness, then unless skipped:
   closed, manifold, consistently oriented, planar polygon faces, then not
   inverted and not of zero volume) and integrates it in one pass over the
   faces (the checks make their own). The mesh keeps the integrals, not the caller's arrays: they
   may be freed once this returns. On failure *out_mesh is NULL and the context holds the message.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_mesh_create(polymass_mesh** out_mesh, polymass_context* context,
                                          const polymass_mesh_desc* desc);

/* Frees a mesh. NULL is accepted. Not while another thread reads the mesh. */
POLYMASS_API void polymass_mesh_destroy(polymass_mesh* mesh);

/* The mass properties of a mesh as a body of the given density or mass (NULL:
   unit density, point = origin). Cheap: no pass over the faces. The mesh may
   be read by several threads at once, each with its own context. */
POLYMASS_API int32_t polymass_mesh_mass_properties(polymass_mass_properties* out_properties,
                                                   polymass_context* context,
                                                   const polymass_mesh* mesh,
                                                   const polymass_mass_desc* mass);

/* polymass_mesh_create followed by polymass_mesh_mass_properties, with no
   mesh left to free. Context: one thread at a time. */
POLYMASS_API int32_t polymass_mass_properties_compute(polymass_mass_properties* out_properties,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_mass_desc* mass);

/* Runs every check without stopping at the first finding and fills the report.
   The topology checks run even when the context's options skip them; the other
   options (welding, tolerance, what is accepted) apply. Faces of fewer than 3
   vertices, indices out of range and non-finite coordinates leave the faces
   unreadable: the report then holds only those findings and the counts. The
   report is written whenever out_report is non-NULL with the right
   struct_size; the return value is then out_report->status: the status
   polymass_mesh_create would return with the topology checks on, with the same
   message. Otherwise nothing is written and the return value says why.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_mesh_check(polymass_diagnostics* out_report,
                                         polymass_context* context, const polymass_mesh_desc* desc);

/* The shells of a surface: its connected pieces, faces sharing a vertex being
   in one shell (after welding, when the context's options weld, so a triangle
   soup splits as its solid does). Writes each face's shell, numbered from 0 in
   the order of the shells' first faces, to out_shell_of_face (room for the
   mesh's face count: face_count, or index_count / 3 for triangles), and the
   number of shells to *out_shell_count. Indices out of range and non-finite
   coordinates are errors, as for polymass_mesh_create; the topology is not
   checked. A caller can then check or compute each shell on its own (a cavity
   is a shell whose signed volume is negative). Context: one thread at a
   time. */
POLYMASS_API int32_t polymass_mesh_shells(uint32_t* out_shell_of_face, uint64_t* out_shell_count,
                                          polymass_context* context,
                                          const polymass_mesh_desc* desc);

/* The shells of a closed surface and what each one is: a solid, a cavity in
   a solid, inside out, overlapping another, or without volume - the
   classification polymass_mesh_create judges by (by how the shells nest,
   counted exactly; with POLYMASS_OPTION_SKIP_INTERSECTION_CHECK: by bounding
   boxes, which can show a shell to be inside out but take any negative shell
   within a solid's box for a cavity). Shell
   i is the one polymass_mesh_shells numbers i. Writes the first
   min(capacity, count) shells to out_shells, an array whose elements all
   have struct_size set, and the count to *out_shell_count (out_shells may be
   NULL when capacity is 0, to ask for the count). The surface must pass the
   checks before the shells (closed, manifold, oriented, planar, with a
   volume): otherwise that status and message, and nothing written.
   Since 1.1. Context: one thread at a time. */
POLYMASS_API int32_t polymass_mesh_shell_list(polymass_shell* out_shells, uint64_t capacity,
                                              uint64_t* out_shell_count, polymass_context* context,
                                              const polymass_mesh_desc* desc);

/* ========================================================================== */
/* Planar polygons                                                            */
/* ========================================================================== */

/* Area, centroid and second moments of area of a simple polygon (convex or
   not, either orientation) given as point_count (x, y) pairs of doubles, each
   pair `stride` bytes after the previous (0: packed). The polygon closes
   itself: do not repeat the first point. A self-intersecting polygon is not
   detected: its result is the signed sum over its lobes.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_polygon_compute(polymass_polygon_properties* out_properties,
                                              polymass_context* context, const double* points,
                                              uint64_t point_count, uint64_t stride);

/* ========================================================================== */
/* Options per call                                                           */
/* ========================================================================== */

/* The functions above with options given for the one call (NULL: the
   context's), checked as polymass_context_set_options checks them; the
   context's options are left as they are. So items of a batch and parts of an
   assembly can each have their own. Context: one thread at a time. */
POLYMASS_API int32_t polymass_mesh_create_with_options(polymass_mesh** out_mesh,
                                                       polymass_context* context,
                                                       const polymass_mesh_desc* desc,
                                                       const polymass_options* options);
POLYMASS_API int32_t polymass_mass_properties_compute_with_options(
    polymass_mass_properties* out_properties, polymass_context* context,
    const polymass_mesh_desc* desc, const polymass_mass_desc* mass,
    const polymass_options* options);
POLYMASS_API int32_t polymass_mesh_check_with_options(polymass_diagnostics* out_report,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_options* options);
POLYMASS_API int32_t polymass_mesh_shells_with_options(uint32_t* out_shell_of_face,
                                                       uint64_t* out_shell_count,
                                                       polymass_context* context,
                                                       const polymass_mesh_desc* desc,
                                                       const polymass_options* options);

/* ========================================================================== */
/* Moments: mass integrals that compose                                       */
/* ========================================================================== */

/* polymass_moments.flags */
/* The moments of a range of faces, not of a closed surface: they add only to
   moments about the same reference point (the other ranges of the same
   surface) and are refused by everything else. Once ranges covering the whole
   closed surface are added up, the caller clears the flag. */
#define POLYMASS_MOMENTS_PARTIAL (1u << 0)

/* The mass integrals of a body about its own reference point, which the
   library puts near the body (the centre of its bounding box) so that a body
   far from the origin keeps its digits. With r the position relative to
   `reference` and rho the density:
     mass = integral rho dV, first = integral rho r dV,
     second = integral rho (x^2, y^2, z^2, x y, y z, z x) dV.
   A plain struct of doubles rather than a handle: moments are values, copied,
   stored in arrays (one per item of a batch, per thread's range of faces, per
   part of an assembly) and passed through any FFI without allocation, and
   what they hold is the documented mathematics above, which cannot change.
   Composition (add, subtract, transform, scale, weight) goes through the
   functions below; each may write its result over one of its operands.
   Combining re-expresses the second operand about the first's reference
   point with the parallel-axis identities (docs/moments.md): sums are
   deterministic given the order of the operands, and equal, to rounding,
   whatever the grouping. */
typedef struct polymass_moments {
    uint32_t struct_size; /* sizeof(polymass_moments) */
    uint32_t flags;       /* POLYMASS_MOMENTS_* bits */
    double reference[3];  /* the point the integrals are about */
    double volume;        /* integral dV: the solid's volume (a difference may be 0 or less) */
    double mass;          /* integral rho dV: the volume until a density is applied */
    double first[3];
    double second[6]; /* xx, yy, zz, xy, yz, zx */
    /* Bounds on the rounding errors carried so far, absolute: of each
       coordinate of reference, of volume, of mass, of each first moment, of
       each second moment. Operations carry them; mass properties turn them
       into their error bounds. Zero for moments a caller writes. */
    double reference_error_bound;
    double volume_error_bound;
    double mass_error_bound;
    double first_error_bound;
    double second_error_bound;
} polymass_moments;

POLYMASS_API uint32_t polymass_sizeof_moments(void);
POLYMASS_API int32_t polymass_moments_init(polymass_moments* moments, uint32_t struct_size);
#ifndef __cplusplus
#define POLYMASS_MOMENTS_INIT \
    { .struct_size = sizeof(polymass_moments) }
#endif

/* The moments (unit density) of a closed surface, validated as by
   polymass_mesh_create_with_options (options NULL: the context's).
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_moments_compute(polymass_moments* out_moments,
                                              polymass_context* context,
                                              const polymass_mesh_desc* desc,
                                              const polymass_options* options);

/* The moments of faces [first_face, first_face + face_count) of the surface,
   about `reference` (every range of one surface must use the same point; one
   near the surface keeps the digits), flagged POLYMASS_MOMENTS_PARTIAL. For a
   caller's own threads: each takes a range, and the ranges added up (in a
   fixed order for a deterministic result) are the surface's moments. Indices
   and coordinates are checked, and polygon faces' planarity unless the
   options skip the topology checks; face numbers in messages count from
   first_face. Context: one thread at a time. */
POLYMASS_API int32_t polymass_moments_compute_faces(polymass_moments* out_moments,
                                                    polymass_context* context,
                                                    const polymass_mesh_desc* desc,
                                                    uint64_t first_face, uint64_t face_count,
                                                    const double reference[3],
                                                    const polymass_options* options);

/* The moments (unit density) of a mesh. The mesh may be read by several
   threads at once, each with its own context. */
POLYMASS_API int32_t polymass_mesh_moments(polymass_moments* out_moments, polymass_context* context,
                                           const polymass_mesh* mesh);

/* a + b: two disjoint bodies as one, about a's reference point. */
POLYMASS_API int32_t polymass_moments_add(polymass_moments* out_moments, polymass_context* context,
                                          const polymass_moments* a, const polymass_moments* b);

/* a - b: b removed from a (a bore from a block: b inside a), about a's
   reference point. */
POLYMASS_API int32_t polymass_moments_subtract(polymass_moments* out_moments,
                                               polymass_context* context, const polymass_moments* a,
                                               const polymass_moments* b);

/* The body moved by r -> rotation r + translation: rotation is row-major,
   orthonormal to 1e-12 (a proper rotation, or of determinant -1: a mirror);
   translation may be NULL (none). A mirrored body is the mirror image solid,
   of the same positive volume and mass (its faces reversed, as a mirrored
   mesh must be to stay a valid solid). */
POLYMASS_API int32_t polymass_moments_transform(polymass_moments* out_moments,
                                                polymass_context* context,
                                                const polymass_moments* moments,
                                                const double rotation[9],
                                                const double translation[3]);

/* The body stretched by factors[i] along axis i, about the origin: uniform
   scale (three equal factors, e.g. a unit conversion), per-axis scale, or a
   mirror (negative factors; volume and mass stay positive). Density is kept:
   the mass scales with the volume. Factors must be finite and non-zero. */
POLYMASS_API int32_t polymass_moments_scale(polymass_moments* out_moments,
                                            polymass_context* context,
                                            const polymass_moments* moments,
                                            const double factors[3]);

/* The body with a density or a total mass (mass->point is not used): its
   whole mass distribution rescaled so that its mean density is mass->density
   (POLYMASS_MASS_FROM_DENSITY) or its mass is mass->mass
   (POLYMASS_MASS_FROM_TOTAL). For a single part that is "made of this
   material"; parts weighted first and added keep their own densities. */
POLYMASS_API int32_t polymass_moments_weight(polymass_moments* out_moments,
                                             polymass_context* context,
                                             const polymass_moments* moments,
                                             const polymass_mass_desc* mass);

/* The mass properties of the body: NULL mass takes the moments as weighted
   (inertia_point about the origin); otherwise weighted as by
   polymass_moments_weight, inertia_point about mass->point. density is the
   mean density (mass / volume); surface_area is NaN (moments do not keep the
   surface); warnings are 0. Fails with POLYMASS_ERROR_ZERO_VOLUME when the
   volume or mass is not positive. Context: one thread at a time. */
POLYMASS_API int32_t polymass_moments_mass_properties(polymass_mass_properties* out_properties,
                                                      polymass_context* context,
                                                      const polymass_moments* moments,
                                                      const polymass_mass_desc* mass);

/* ========================================================================== */
/* Provenance: which mode answered, and what it did                           */
/* ========================================================================== */

/* What polymass_mass_properties_with_provenance did to answer. Locations, as
   in polymass_diagnostics, are the first (lowest) min(count,
   POLYMASS_DIAGNOSTIC_LOCATIONS) of each kind, the rest POLYMASS_NONE; faces
   are the caller's face numbers, vertices the caller's indices (after
   welding: the lowest index at that position). Since 1.2. */
typedef struct polymass_provenance {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_provenance) */
    int32_t mode;         /* the POLYMASS_MODE_* that answered */
    /* POLYMASS_MODE_REPAIR: the fixes (all 0 when the surface was a valid
       solid). Faces turned to agree with the rest of their shell: */
    uint64_t reoriented_faces;
    uint64_t first_reoriented_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    /* Shells turned inside out (to enclose positive volume, or negative
       inside another shell: a cavity), each located by its first face: */
    uint64_t turned_shells;
    uint64_t first_turned_shells[POLYMASS_DIAGNOSTIC_LOCATIONS];
    /* Faces dropped as copies of another face (or of its reverse, which
       cancels it): */
    uint64_t duplicate_faces;
    uint64_t first_duplicate_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    /* Faces of fewer than three distinct vertices, dropped: */
    uint64_t degenerate_faces;
    uint64_t first_degenerate_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    /* Non-planar polygon faces triangulated: */
    uint64_t triangulated_faces;
    uint64_t first_triangulated_faces[POLYMASS_DIAGNOSTIC_LOCATIONS];
    /* Non-manifold edges (used as often each way) split into manifold pairs: */
    uint64_t split_edges;
    uint64_t first_split_edges[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
    /* Holes (boundary loops) capped, each located by its lowest vertex: */
    uint64_t holes;
    uint64_t first_holes[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t cap_triangles;
    double cap_area;          /* the caps' area */
    double cap_area_fraction; /* over the repaired surface's area */
    /* The approximation's share of the error_bound_* of the mass properties
       (which add the rounding bound to it), in the same units: 0 for an
       exact answer (a valid solid, exact repairs, a shell). */
    double approximation_bound_volume;
    double approximation_bound_center_of_mass;
    double approximation_bound_inertia;
    /* POLYMASS_MODE_SHELL: the wall's thickness and the surface's area. */
    double shell_thickness;
    double shell_area;
    /* POLYMASS_MODE_HULL: the hull's vertices, triangles and volume. */
    uint64_t hull_vertex_count;
    uint64_t hull_triangle_count;
    double hull_volume;
} polymass_provenance;

POLYMASS_API uint32_t polymass_sizeof_provenance(void);
/* As the other initialisers: zeros, struct_size set. */
POLYMASS_API int32_t polymass_provenance_init(polymass_provenance* provenance,
                                              uint32_t struct_size);
#ifndef __cplusplus
#define POLYMASS_PROVENANCE_INIT \
    { .struct_size = sizeof(polymass_provenance) }
#endif

/* polymass_mass_properties_compute_with_options, and what answered:
   out_provenance (its struct_size set by the caller) says which mode of the
   options' chain gave the answer and what it did; both are written on
   success only. When no mode answers, the status is the first mode's (the
   solid's, most often), and the message says why each mode failed.
   Context: one thread at a time. Since 1.2. */
POLYMASS_API int32_t polymass_mass_properties_with_provenance(
    polymass_mass_properties* out_properties, polymass_provenance* out_provenance,
    polymass_context* context, const polymass_mesh_desc* desc, const polymass_mass_desc* mass,
    const polymass_options* options);

/* ========================================================================== */
/* Batch: many meshes in one call                                             */
/* ========================================================================== */

/* Length of polymass_batch_item.message, its terminating NUL included. */
#define POLYMASS_BATCH_MESSAGE_SIZE 256

/* One mesh of a batch: what polymass_mass_properties_compute_with_options
   takes, and what it gives. */
typedef struct polymass_batch_item {
    uint32_t struct_size;                 /* sizeof(polymass_batch_item) */
    int32_t status;                       /* out: the item's status */
    const polymass_mesh_desc* desc;       /* in */
    const polymass_mass_desc* mass;       /* in; NULL: unit density, point = origin */
    const polymass_options* options;      /* in; NULL: the context's */
    polymass_mass_properties* properties; /* out, written on success; its
                                             struct_size set by the caller */
    /* out: the item's message ("" on success), NUL-terminated, truncated to
       fit. */
    char message[POLYMASS_BATCH_MESSAGE_SIZE];
} polymass_batch_item;

POLYMASS_API uint32_t polymass_sizeof_batch_item(void);
POLYMASS_API int32_t polymass_batch_item_init(polymass_batch_item* item, uint32_t struct_size);
#ifndef __cplusplus
#define POLYMASS_BATCH_ITEM_INIT \
    { .struct_size = sizeof(polymass_batch_item) }
#endif

/* The mass properties of item_count meshes: items[i] is found
   items[0].struct_size bytes after items[i - 1] (every item has that
   struct_size). Each item gets its own status, message and, on success,
   properties, exactly (bit for bit) those of
   polymass_mass_properties_compute_with_options; an item's failure does not
   stop the others. *out_failed (may be NULL) counts the items that failed.
   Returns POLYMASS_OK once every item has its status, or the status of what
   kept the batch from running (items NULL with item_count > 0, an unknown
   struct_size), with the context's message. Items are independent: with the
   context's polymass_options.threads above 1 they are spread over that many
   threads (each item on one thread, its own passes serial), without changing
   any result.
   Context: one thread at a time. */
POLYMASS_API int32_t polymass_batch_compute(polymass_batch_item* items, uint64_t item_count,
                                            uint64_t* out_failed, polymass_context* context);

/* ========================================================================== */
/* Welding on its own                                                         */
/* ========================================================================== */

/* The library's welding, for a caller that numbers vertices before handing a
   mesh over (a triangle soup such as STL repeats a vertex once per face).
   Writes to out_vertex_of (room for vertex_count) the lowest vertex index
   welded to each used vertex, and to *out_distinct_count how many used
   vertices are their own lowest; vertices no face uses map to themselves.
   The weld is the context options' weld_tolerance (whatever their flags):
   0 welds exactly equal positions (+0 and -0 being one, and copies of the
   same NaN: coordinates are compared bit for bit) in one hashing pass;
   above 0, as POLYMASS_OPTION_WELD_VERTICES describes, and then non-finite
   coordinates are an error. Indices out of range are an error, as for
   polymass_mesh_create; the topology is not checked. At most UINT32_MAX
   vertices. Since 1.3. Context: one thread at a time. */
POLYMASS_API int32_t polymass_mesh_weld(uint32_t* out_vertex_of, uint64_t* out_distinct_count,
                                        polymass_context* context, const polymass_mesh_desc* desc);

#ifdef __cplusplus
}
#endif

#endif /* POLYMASS_POLYMASS_H */
