/*
 * libpolymass 2 — mass properties of solid polyhedra and planar polygons.
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
 * HOW TO USE IT
 *   An engine's load path makes one call: polymass_mass_properties_compute
 *   (description, options and mass in, properties out). A tool that also wants
 *   to know what is wrong with a surface, its shells or what an approximation
 *   did makes one polymass_mesh: polymass_mesh_create analyses the surface
 *   once, and every question after that (status, diagnostics, shells,
 *   provenance, moments, mass properties for any density or mass) is answered
 *   from the handle without analysing again. Both take the same options, per
 *   call; both are the same analysis.
 *
 * SAFE DEFAULTS
 *   With no options (NULL, or POLYMASS_OPTIONS_INIT) every check that can change
 *   the answer runs: closed, manifold, consistently oriented, planar polygon
 *   faces, not inverted, a volume, and no faces crossing nor shells counted
 *   twice. A caller that trusts its input skips checks by name
 *   (POLYMASS_OPTION_SKIP_*); an answer that is not the exact solid (a
 *   repaired surface, a thin wall, a hull) is given only when the caller's
 *   chain of modes asks for it, and says what was done and how far off it can
 *   be (polymass_provenance, the error bounds).
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
 *   The library starts threads only when a context is asked for more than one
 *   (polymass_context_set_threads): the context then starts that many
 *   workers, less one (the calling thread works too), on the first call that
 *   needs them, reuses them for later calls and joins them in
 *   polymass_context_destroy. Work is cut into pieces fixed by the input alone
 *   (blocks of faces, the items of a batch) and the pieces' results are
 *   combined in a fixed order, so every thread count gives the same bits. The
 *   context's allocator may then be called from the workers, but from one
 *   thread at a time.
 *
 * ERRORS
 *   Every fallible function returns an int32_t status (POLYMASS_OK == 0), says
 *   which statuses it can return, and never throws, asserts or aborts on bad
 *   input. Output structs are written only on success. polymass_status_string()
 *   names a status; polymass_context_message() says what and where ("face 17
 *   has 2 vertices", "edge (4, 9) is used by 3 faces").
 *   POLYMASS_ERROR_INVALID_ARGUMENT (a caller's mistake: a NULL pointer, a
 *   wrong struct_size, an unknown flag), POLYMASS_ERROR_OUT_OF_MEMORY and
 *   POLYMASS_ERROR_INTERNAL can come from every function that returns a
 *   status; the lists below name the others.
 *
 * STABILITY
 *   Version 2.0.0 is the first release. Within a major version the ABI only
 *   grows: functions and status codes are added, never changed or removed,
 *   status values are never reused, and public structs only gain fields at
 *   their end. Every public struct starts with struct_size, which the caller
 *   sets to sizeof(the struct) it was compiled with (the polymass_*_init
 *   functions and POLYMASS_*_INIT macros do it), so an older caller keeps
 *   working with a newer library: the library accepts the size of every
 *   version of a struct since 2.0.0, reads an input struct only up to its
 *   struct_size (later fields take their defaults) and writes an output
 *   struct only up to its struct_size. Every struct has polymass_sizeof_*,
 *   polymass_*_init and POLYMASS_*_INIT.
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
   smaller than a vertex, unknown type, flag or mode, face sizes that do not
   add up, an option out of its range. */
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
   Compare its major part with the header's before use. Thread-safe.
   Since 2.0. */
POLYMASS_API uint32_t polymass_version(void);

/* "MAJOR.MINOR.PATCH" of the library loaded at run time. Static text.
   Since 2.0. */
POLYMASS_API const char* polymass_version_string(void);

/* Static text naming a status ("open surface", ...); unknown codes give
   "unknown status". Thread-safe. Since 2.0. */
POLYMASS_API const char* polymass_status_string(int32_t status);

/* ========================================================================== */
/* Constants                                                                  */
/* ========================================================================== */

/* Room in polymass_options.modes. */
#define POLYMASS_MAX_MODES 4
/* Default of polymass_options.planarity_tolerance. */
#define POLYMASS_DEFAULT_PLANARITY_TOLERANCE 1e-6
/* Largest polymass_options.weld_tolerance: a coarser weld would merge
   vertices of distinct features. */
#define POLYMASS_MAX_WELD_TOLERANCE 1e-3
/* Largest count of threads a context may be given. */
#define POLYMASS_MAX_THREADS 256
/* How many locations of each finding polymass_diagnostics and
   polymass_provenance list: the lowest face or vertex indices, the edges with
   the lowest vertex pairs. */
#define POLYMASS_DIAGNOSTIC_LOCATIONS 8
/* How many face pairs of a kind (crossing, touching) the intersection check
   counts: past that the count is a lower bound (the message says "at
   least"). The pairs listed are the lowest, but for one case: once this many
   pairs cross, the surface is refused whatever else it holds, and the search
   ends (a pile of parts crossing each other meets in a number of pairs that
   grows with the square of the parts). Both kinds' counts and pairs are then
   those of the part of the search done, the same on any number of threads:
   crossing pairs that are not the lowest may be listed, and fewer touching
   pairs than there are may be counted. */
#define POLYMASS_MAX_COUNTED_FACE_PAIRS 2048
/* No location: the value of the "first_*" entries past the count beside them
   (all of them when it is 0). */
#define POLYMASS_NONE UINT64_MAX
/* Length of polymass_batch_item.message, its terminating NUL included. */
#define POLYMASS_BATCH_MESSAGE_SIZE 256

/* ========================================================================== */
/* Types                                                                      */
/* ========================================================================== */

typedef struct polymass_context polymass_context;
typedef struct polymass_mesh polymass_mesh;

/* Memory for a context and everything made through it. allocate returns memory
   aligned to at least `alignment` (a power of two) or NULL on failure;
   deallocate accepts what allocate returned. A NULL allocator (or one whose
   functions are both NULL) means malloc. The functions and user_data must
   stay valid until the context and every mesh made through it are destroyed
   (a mesh frees itself through them). */
typedef struct polymass_allocator {
    uint32_t struct_size; /* sizeof(polymass_allocator) */
    uint32_t reserved;    /* must be 0 */
    void* (*allocate)(void* user_data, size_t size, size_t alignment);
    void (*deallocate)(void* user_data, void* pointer);
    void* user_data;
} polymass_allocator;

/* polymass_options.flags. Zero flags (the default) is every check. */
/* Trusted input (a game engine at load time): skip the open, non-manifold,
   orientation and planarity checks, and the intersection check with them.
   Index range and finiteness are always checked, so bad input still cannot
   crash the library. The answer carries POLYMASS_WARNING_UNCHECKED. */
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
   predicates decide every case. Skipping it saves most of the analysis's
   time (see the README for figures), but two overlapping parts exported as
   one surface then pass, their overlap counted twice, and a shell turned
   inside out is refused only when it lies outside every solid shell's
   bounding box. */
#define POLYMASS_OPTION_SKIP_INTERSECTION_CHECK (1u << 4)

/* polymass_options.modes: how a surface is turned into a body. */
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

/* What one analysis is asked to check and accept, and how to turn the
   surface into a body. Given per call; NULL means the defaults (every check,
   SOLID alone). */
typedef struct polymass_options {
    uint32_t struct_size; /* sizeof(polymass_options) */
    uint32_t flags;       /* POLYMASS_OPTION_* bits */
    /* Largest distance of a polygon face's vertex from the face's plane,
       relative to the face's diameter; 0 means
       POLYMASS_DEFAULT_PLANARITY_TOLERANCE. */
    double planarity_tolerance;
    /* With POLYMASS_OPTION_WELD_VERTICES: two vertices whose coordinates each
       differ by at most weld_tolerance times the largest extent of the used
       vertices' bounding box are one vertex (up to rounding), and so are
       chains of such vertices. 0 (the default) welds exactly equal positions
       only; CAD exports whose coordinates carry rounding noise want about
       1e-9. A non-zero value below 2^-50 acts as 2^-50. In
       [0, POLYMASS_MAX_WELD_TOLERANCE]. */
    double weld_tolerance;
    /* The modes to try, in order, up to the first POLYMASS_MODE_NONE: the
       first that gives an answer answers (say SOLID, REPAIR, HULL). All NONE
       (the default) means SOLID alone. A chain without SOLID still answers a
       valid solid exactly as SOLID does, but for SHELL and HULL, which
       describe another body. polymass_provenance says which mode answered and
       what it did. */
    uint32_t modes[POLYMASS_MAX_MODES];
    /* The wall thickness of POLYMASS_MODE_SHELL, > 0 and finite when the
       chain holds SHELL. */
    double shell_thickness;
} polymass_options;

/* polymass_mesh_desc.position_type */
#define POLYMASS_POSITION_FLOAT64 0
#define POLYMASS_POSITION_FLOAT32 1
/* polymass_mesh_desc.index_type */
#define POLYMASS_INDEX_UINT32 0
#define POLYMASS_INDEX_UINT16 1
/* polymass_packed_meshes only (a dataset's 64-bit indices, PyTorch's int64
   read as unsigned): each mesh's indices are narrowed to 32 bits in the
   context's scratch memory, one mesh at a time; an index that does not fit
   (a negative int64 included) is that mesh's POLYMASS_ERROR_INDEX_OUT_OF_RANGE.
   A single mesh's description takes 16 and 32 bits. */
#define POLYMASS_INDEX_UINT64 2

/* A surface as the caller's own arrays; nothing is copied, and nothing is
   kept once a call returns. */
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

/* How heavy a body is. NULL where one is taken means unit density. */
typedef struct polymass_mass_desc {
    uint32_t struct_size; /* sizeof(polymass_mass_desc) */
    uint32_t mass_mode;   /* POLYMASS_MASS_FROM_* */
    double density;       /* > 0, finite; read when mass_mode is FROM_DENSITY */
    double mass;          /* > 0, finite; read when mass_mode is FROM_TOTAL */
} polymass_mass_desc;

/* polymass_mass_properties.warnings */
#define POLYMASS_WARNING_INVERTED (1u << 0)         /* accepted and turned */
#define POLYMASS_WARNING_DEGENERATE_FACES (1u << 1) /* zero-area faces, harmless */
#define POLYMASS_WARNING_UNCHECKED (1u << 2)        /* topology checks skipped */
#define POLYMASS_WARNING_NON_MANIFOLD (1u << 3)     /* accepted non-manifold edges */
#define POLYMASS_WARNING_TOUCHING_FACES (1u << 4)   /* faces touch without crossing */
/* The mode that answered, when not SOLID (see polymass_provenance). */
#define POLYMASS_WARNING_REPAIRED (1u << 5) /* a repaired surface */
#define POLYMASS_WARNING_SHELL (1u << 6)    /* a thin wall */
#define POLYMASS_WARNING_HULL (1u << 7)     /* the convex hull */
/* The intersection check was skipped (by name, or with the topology checks). */
#define POLYMASS_WARNING_INTERSECTIONS_UNCHECKED (1u << 8)

typedef struct polymass_mass_properties {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_mass_properties) */
    uint32_t warnings;    /* POLYMASS_WARNING_* bits */
    double volume;
    double mass;
    double density;
    double surface_area; /* NaN from moments, which do not keep the surface */
    double center_of_mass[3];
    double inertia[9];           /* about the centre of mass */
    double inertia_origin[9];    /* about (0, 0, 0); any point: polymass_inertia_about */
    double principal_moments[3]; /* eigenvalues of `inertia`, ascending */
    /* Row-major rotation R (det R = +1) whose columns are the principal axes:
       inertia = R diag(principal_moments) R^T. Where moments coincide the axes
       are chosen deterministically (coordinate axes when all three do). */
    double principal_axes[9];
    /* Bounds on the errors of the results above: absolute, in their units.
       The rounding's share comes from sums of absolute terms carried through
       the integration, the move to the centre of mass and the principal-axes
       step (docs/error_bound.md), for the surface as given (its coordinates
       taken as exact); an approximation (a repair that is not exact, a hull)
       adds its own share (polymass_provenance.approximation_bound_*). The
       axes' bound, in radians, grows as the bound over the gap between the
       nearest moments, so as moments approach each other; it is pi/2 when
       moments are closer than their bounds can tell apart, and covers only
       axes the moments determine (where moments coincide the axes are chosen
       by convention). Infinite when rounding could be the whole mass. */
    double error_bound_volume;
    double error_bound_center_of_mass;    /* of each coordinate */
    double error_bound_inertia;           /* of each entry of `inertia` */
    double error_bound_principal_moments; /* of each */
    double error_bound_principal_axes;    /* angle of each axis, radians */
} polymass_mass_properties;

/* polymass_diagnostics.checks: which checks ran to their end. */
#define POLYMASS_CHECKED_TOPOLOGY (1u << 0) /* open, non-manifold, orientation, planarity */
#define POLYMASS_CHECKED_SHELLS (1u << 1)   /* the shells judged (volume, sense) */
#define POLYMASS_CHECKED_INTERSECTIONS (1u << 2)

/* What the analysis of a surface found, with every check the options did not
   skip run to its end (not stopping at the first finding): for each kind of
   finding its count and its first (lowest) min(count,
   POLYMASS_DIAGNOSTIC_LOCATIONS) locations, in ascending order, the rest
   POLYMASS_NONE. Vertex numbers are the caller's indices (after welding: the
   lowest index at that position); an edge is a vertex pair in the direction
   the faces traverse it (most often); a face pair is (lower face, higher
   face), lowest pairs first. Faces of fewer than 3 vertices, indices out of
   range and non-finite coordinates leave the faces unreadable: the report
   then holds only those findings and the counts. */
typedef struct polymass_diagnostics {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_diagnostics) */
    /* The surface's own verdict, as the SOLID mode judges it (whatever mode
       answered): POLYMASS_OK for a valid solid, else its first defect. */
    int32_t status;
    uint32_t checks;   /* POLYMASS_CHECKED_* bits */
    uint32_t reserved; /* 0 */
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
    uint64_t shell_count;     /* connected pieces (0 when the faces are unreadable) */
    uint64_t inverted_shells; /* inside out, inside no solid shell */
    uint64_t first_inverted_shells[POLYMASS_DIAGNOSTIC_LOCATIONS];
    uint64_t overlapping_shells; /* inside a solid of the same sense, or through another */
    uint64_t first_overlapping_shells[POLYMASS_DIAGNOSTIC_LOCATIONS];
    /* Counted up to POLYMASS_MAX_COUNTED_FACE_PAIRS of a kind; when that many
       cross, the search ended there (POLYMASS_MAX_COUNTED_FACE_PAIRS). */
    uint64_t intersecting_face_pairs; /* faces that cross, or coincide facing the same way */
    uint64_t first_intersecting_face_pairs[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
    uint64_t touching_face_pairs; /* faces that touch without crossing nor sharing a vertex */
    uint64_t first_touching_face_pairs[POLYMASS_DIAGNOSTIC_LOCATIONS][2];
} polymass_diagnostics;

/* polymass_shell.kind */
#define POLYMASS_SHELL_UNJUDGED 0    /* the surface failed a check before the shells */
#define POLYMASS_SHELL_SOLID 1       /* encloses positive volume, in no other solid */
#define POLYMASS_SHELL_CAVITY 2      /* negative volume, inside a solid */
#define POLYMASS_SHELL_INVERTED 3    /* negative volume, inside no solid: inside out */
#define POLYMASS_SHELL_OVERLAPPING 4 /* inside a solid of the same sense: counted twice */
#define POLYMASS_SHELL_NO_VOLUME 5   /* encloses no volume (to rounding) */

/* One shell of a surface: a connected piece, faces sharing a vertex (after
   welding, when the options weld) being in one shell. Shells are numbered
   from 0 in the order of their first faces. */
typedef struct polymass_shell {
    uint32_t struct_size; /* set by the caller: sizeof(polymass_shell) */
    int32_t kind;         /* POLYMASS_SHELL_* */
    uint64_t face_count;
    uint64_t first_face;
    /* Signed so that the whole surface's volume is positive (a surface
       accepted inside out as a whole counts turned); NaN when unjudged, or when
       the volume is beyond a double's range (a shell of no volume made of
       coordinates near overflow). */
    double signed_volume;
} polymass_shell;

/* What answered, and what it did. Locations, as in polymass_diagnostics, are
   the first (lowest) min(count, POLYMASS_DIAGNOSTIC_LOCATIONS) of each kind,
   the rest POLYMASS_NONE; faces are the caller's face numbers, vertices the
   caller's indices (after welding: the lowest index at that position). */
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
       (which add the rounding bound to it), in the same units at unit
       density: 0 for an exact answer (a valid solid, exact repairs, a
       shell). */
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
   polymass_moments_* functions; each may write its result over one of its
   operands. Combining re-expresses the second operand about the first's
   reference point with the parallel-axis identities (docs/moments.md): sums
   are deterministic given the order of the operands, and equal, to rounding,
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

/* One mesh of a batch: what polymass_mass_properties_compute takes, and what
   it gives. */
typedef struct polymass_batch_item {
    uint32_t struct_size;                 /* sizeof(polymass_batch_item) */
    int32_t status;                       /* out: the item's status */
    const polymass_mesh_desc* desc;       /* in */
    const polymass_options* options;      /* in; NULL: the defaults */
    const polymass_mass_desc* mass;       /* in; NULL: unit density */
    polymass_mass_properties* properties; /* out, written on success; its
                                             struct_size set by the caller */
    polymass_provenance* provenance;      /* out, may be NULL; as properties */
    /* out: the item's message ("" on success), NUL-terminated, truncated to
       fit. */
    char message[POLYMASS_BATCH_MESSAGE_SIZE];
} polymass_batch_item;

/* polymass_packed_meshes.index_base */
/* Mesh i's indices count from its first vertex, vertex_offsets[i]. */
#define POLYMASS_INDICES_LOCAL 0
/* Mesh i's indices count from the first vertex of the packed array, as in
   PyTorch3D's packed form (faces_packed); they must still fall in mesh i's
   own range of vertices. */
#define POLYMASS_INDICES_GLOBAL 1

/* Many triangle meshes packed into shared arrays, as datasets keep them:
   mesh i is vertices [vertex_offsets[i], vertex_offsets[i + 1]) of
   `positions` and indices [index_offsets[i], index_offsets[i + 1]) of
   `indices`, three per triangle. The arrays are read in place (global and
   64-bit indices are rebased one mesh at a time, in the context's scratch
   memory).
   Since 2.0. */
typedef struct polymass_packed_meshes {
    uint32_t struct_size;   /* sizeof(polymass_packed_meshes) */
    uint32_t position_type; /* POLYMASS_POSITION_* */
    const void* positions;  /* as in polymass_mesh_desc */
    uint64_t position_stride;
    uint32_t index_type; /* POLYMASS_INDEX_* */
    uint32_t index_base; /* POLYMASS_INDICES_* */
    const void* indices;
    uint64_t mesh_count;
    /* mesh_count + 1 ascending offsets each, from 0: the last is the number
       of vertices, and of indices (a multiple of 3 between each pair). */
    const uint64_t* vertex_offsets;
    const uint64_t* index_offsets;
    /* Per mesh, mesh_count values: the density (POLYMASS_MASS_FROM_DENSITY)
       or the mass (POLYMASS_MASS_FROM_TOTAL) of mesh i; NULL: unit density
       for every mesh. */
    uint32_t mass_mode; /* POLYMASS_MASS_FROM_* */
    uint32_t reserved;  /* must be 0 */
    const double* mass_values;
} polymass_packed_meshes;

/* Where polymass_packed_compute writes the results of mesh i: each array has
   room for mesh_count rows (status: mesh_count values; center_of_mass:
   3 * mesh_count, row i at 3 * i; inertia and principal_axes: 9 *
   mesh_count, row-major 3x3 at 9 * i; ...). Any array may be NULL: not
   wanted. A failed mesh's row holds its status and NaN numbers (warnings 0).
   Since 2.0. */
typedef struct polymass_packed_results {
    uint32_t struct_size; /* sizeof(polymass_packed_results) */
    uint32_t reserved;    /* must be 0 */
    int32_t* status;      /* POLYMASS_OK or the mesh's status */
    uint32_t* warnings;   /* POLYMASS_WARNING_* bits */
    double* volume;
    double* mass;
    double* surface_area;
    double* center_of_mass;    /* 3 per mesh */
    double* inertia;           /* 9 per mesh: about the centre of mass */
    double* principal_moments; /* 3 per mesh */
    double* principal_axes;    /* 9 per mesh */
    double* error_bound_volume;
    double* error_bound_center_of_mass;
    double* error_bound_inertia;
    /* mesh_count * POLYMASS_BATCH_MESSAGE_SIZE bytes: mesh i's message ("" on
       success), NUL-terminated, at i * POLYMASS_BATCH_MESSAGE_SIZE. */
    char* messages;
} polymass_packed_results;

/* ========================================================================== */
/* Struct sizes and initialisers                                              */
/* ========================================================================== */

/* Sizes of the public structs as this library was compiled: for bindings to
   check their layouts. Thread-safe. Since 2.0. */
POLYMASS_API uint32_t polymass_sizeof_allocator(void);
POLYMASS_API uint32_t polymass_sizeof_options(void);
POLYMASS_API uint32_t polymass_sizeof_mesh_desc(void);
POLYMASS_API uint32_t polymass_sizeof_mass_desc(void);
POLYMASS_API uint32_t polymass_sizeof_mass_properties(void);
POLYMASS_API uint32_t polymass_sizeof_diagnostics(void);
POLYMASS_API uint32_t polymass_sizeof_shell(void);
POLYMASS_API uint32_t polymass_sizeof_provenance(void);
POLYMASS_API uint32_t polymass_sizeof_moments(void);
POLYMASS_API uint32_t polymass_sizeof_polygon_properties(void);
POLYMASS_API uint32_t polymass_sizeof_batch_item(void);
POLYMASS_API uint32_t polymass_sizeof_packed_meshes(void);
POLYMASS_API uint32_t polymass_sizeof_packed_results(void);

/* Initialisers. Each writes a struct's defaults, struct_size included, up to
   the struct_size given, which must be the size of a version of the struct
   this library knows (sizeof the struct as the caller's header declares it):
     polymass_mesh_desc desc;
     polymass_mesh_desc_init(&desc, sizeof desc);
   The defaults are zeros, except polymass_mass_desc's (unit density:
   POLYMASS_MASS_FROM_DENSITY, density 1) and the POLYMASS_NONE of the
   locations of polymass_diagnostics and polymass_provenance. Options' zero
   tolerances mean the default tolerances. Thread-safe. Since 2.0.
   Returns POLYMASS_OK, or POLYMASS_ERROR_INVALID_ARGUMENT (writing nothing)
   for a NULL struct or an unknown size. */
POLYMASS_API int32_t polymass_allocator_init(polymass_allocator* allocator, uint32_t struct_size);
POLYMASS_API int32_t polymass_options_init(polymass_options* options, uint32_t struct_size);
POLYMASS_API int32_t polymass_mesh_desc_init(polymass_mesh_desc* desc, uint32_t struct_size);
POLYMASS_API int32_t polymass_mass_desc_init(polymass_mass_desc* mass, uint32_t struct_size);
POLYMASS_API int32_t polymass_mass_properties_init(polymass_mass_properties* properties,
                                                   uint32_t struct_size);
POLYMASS_API int32_t polymass_diagnostics_init(polymass_diagnostics* diagnostics,
                                               uint32_t struct_size);
POLYMASS_API int32_t polymass_shell_init(polymass_shell* shell, uint32_t struct_size);
POLYMASS_API int32_t polymass_provenance_init(polymass_provenance* provenance,
                                              uint32_t struct_size);
POLYMASS_API int32_t polymass_moments_init(polymass_moments* moments, uint32_t struct_size);
POLYMASS_API int32_t polymass_polygon_properties_init(polymass_polygon_properties* properties,
                                                      uint32_t struct_size);
POLYMASS_API int32_t polymass_batch_item_init(polymass_batch_item* item, uint32_t struct_size);
POLYMASS_API int32_t polymass_packed_meshes_init(polymass_packed_meshes* meshes,
                                                 uint32_t struct_size);
POLYMASS_API int32_t polymass_packed_results_init(polymass_packed_results* results,
                                                  uint32_t struct_size);

/* The same defaults as static initialisers, for C (designated initialisers
   are C99; C++ before C++20 has none: call the functions above there). The
   output structs' locations are written by the library, so their macros set
   only struct_size:
     polymass_mass_desc body = POLYMASS_MASS_DESC_INIT;
     body.density = 2700.0; */
#ifndef __cplusplus
#define POLYMASS_ALLOCATOR_INIT \
    { .struct_size = sizeof(polymass_allocator) }
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
#define POLYMASS_SHELL_INIT \
    { .struct_size = sizeof(polymass_shell) }
#define POLYMASS_PROVENANCE_INIT \
    { .struct_size = sizeof(polymass_provenance) }
#define POLYMASS_MOMENTS_INIT \
    { .struct_size = sizeof(polymass_moments) }
#define POLYMASS_POLYGON_PROPERTIES_INIT \
    { .struct_size = sizeof(polymass_polygon_properties) }
#define POLYMASS_BATCH_ITEM_INIT \
    { .struct_size = sizeof(polymass_batch_item) }
#define POLYMASS_PACKED_MESHES_INIT \
    { .struct_size = sizeof(polymass_packed_meshes) }
#define POLYMASS_PACKED_RESULTS_INIT \
    { .struct_size = sizeof(polymass_packed_results) }
#endif

/* ========================================================================== */
/* Context: what belongs to the caller                                        */
/* ========================================================================== */

/* Creates a context: the caller's allocator, worker threads (none until
   asked), scratch memory and last message. allocator may be NULL (malloc); it
   is copied. Thread-safe. Since 2.0.
   Returns POLYMASS_OK; *out_context is NULL on failure. */
POLYMASS_API int32_t polymass_context_create(polymass_context** out_context,
                                             const polymass_allocator* allocator);

/* Frees a context and joins its workers. NULL is accepted. Meshes made
   through it stay valid. Not while another thread uses the context.
   Since 2.0. */
POLYMASS_API void polymass_context_destroy(polymass_context* context);

/* How many threads one call through this context may use: the calling thread
   and threads - 1 workers (see THREADING), in [1, POLYMASS_MAX_THREADS]; 1
   (the default) starts no thread, so a host with its own scheduler can
   spread meshes or face ranges itself (polymass_moments_compute_faces).
   Followed by the passes over one mesh's faces and by polymass_batch_compute
   (items spread over the threads). Results are bit for bit the same for
   every value. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK. */
POLYMASS_API int32_t polymass_context_set_threads(polymass_context* context, uint32_t threads);

/* A context keeps the large scratch blocks of its calls (the topology
   check's edge lists, the shells' tables: up to about 16 bytes per
   triangle, from the context's allocator) for its next calls, so that a call
   on a large mesh does not map fresh memory from the system and fault on
   every page of it each time; polymass_context_destroy frees them. This
   bounds what it keeps between calls (and frees what is beyond now): 0 keeps
   nothing. The default, UINT64_MAX, keeps what the largest recent call used.
   Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK. */
POLYMASS_API int32_t polymass_context_set_scratch_limit(polymass_context* context,
                                                        uint64_t max_kept_bytes);

/* The detailed message of the last call through this context that failed
   ("" after a success). Valid until the next call through the context, from
   the thread that made that call. Never NULL. Since 2.0. */
POLYMASS_API const char* polymass_context_message(const polymass_context* context);

/* ========================================================================== */
/* Solids: one call                                                           */
/* ========================================================================== */

/* The mass properties of a surface as a body of the given density or mass
   (NULL: unit density), with the options given (NULL: every check, SOLID
   alone): the analysis polymass_mesh_create makes, stopping at the first
   defect, with no mesh left to free. out_provenance may be NULL; when given
   (its struct_size set) it says which mode answered and what it did. Both
   are written on success only. When no mode answers, the status is the
   first mode's (the solid's, most often), and the message says why each
   mode failed. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK, a surface status (POLYMASS_ERROR_NON_FINITE,
   _INDEX_OUT_OF_RANGE, _FACE_TOO_SMALL, _OPEN, _NON_MANIFOLD,
   _INCONSISTENT_ORIENTATION, _NON_PLANAR_FACE, _INTERSECTING, _INVERTED,
   _ZERO_VOLUME) or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_mass_properties_compute(polymass_mass_properties* out_properties,
                                                      polymass_provenance* out_provenance,
                                                      polymass_context* context,
                                                      const polymass_mesh_desc* desc,
                                                      const polymass_options* options,
                                                      const polymass_mass_desc* mass);

/* ========================================================================== */
/* Solids: one analysis, many questions                                       */
/* ========================================================================== */

/* Analyses a surface once with the options given (NULL: every check, SOLID
   alone): the arguments, indices and coordinates; unless skipped, the
   topology (closed, manifold, oriented, planar polygon faces), the shells and
   how they nest, and the intersection check, each run to its end (every
   finding counted, not only the first); then the options' chain of modes.
   The mesh keeps what the questions below need - the verdict and its
   message, the diagnostics, the shells, the provenance and the integrals -
   and not the caller's arrays: they may be freed once this returns.
   The return value is the mesh's status (polymass_mesh_status). *out_mesh is
   a mesh whenever the analysis ran, answered or not, so that a caller can
   ask what is wrong; it is NULL only for POLYMASS_ERROR_INVALID_ARGUMENT,
   _OUT_OF_MEMORY and _INTERNAL, the message then in the context.
   Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK, a surface status (as polymass_mass_properties_compute)
   or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_mesh_create(polymass_mesh** out_mesh, polymass_context* context,
                                          const polymass_mesh_desc* desc,
                                          const polymass_options* options);

/* Frees a mesh. NULL is accepted. Not while another thread reads the mesh.
   Since 2.0. */
POLYMASS_API void polymass_mesh_destroy(polymass_mesh* mesh);

/* The mesh's status: POLYMASS_OK when a mode of the chain answered, else the
   status polymass_mesh_create returned. Thread-safe. Since 2.0.
   Returns POLYMASS_OK, the status polymass_mesh_create returned (a surface
   status or POLYMASS_ERROR_OVERFLOW), or POLYMASS_ERROR_INVALID_ARGUMENT for
   a NULL mesh. */
POLYMASS_API int32_t polymass_mesh_status(const polymass_mesh* mesh);

/* What is wrong with the surface as given, in words: the message of
   polymass_diagnostics.status ("edge (4, 9) is used by 3 faces"), kept when
   a later mode of the chain answered; when no mode answered, each later
   mode's reason follows ("...; hull: ..."). "" for a valid solid, "mesh is
   NULL" for a NULL mesh. Valid as long as the mesh. Never NULL.
   Thread-safe. Since 2.0. */
POLYMASS_API const char* polymass_mesh_message(const polymass_mesh* mesh);

/* Everything on the mesh below may be read by several threads at once, each
   with its own context. */

/* What the analysis found (see polymass_diagnostics). Written for every mesh,
   answered or not. Since 2.0.
   Returns POLYMASS_OK. */
POLYMASS_API int32_t polymass_mesh_diagnostics(polymass_diagnostics* out_diagnostics,
                                               polymass_context* context,
                                               const polymass_mesh* mesh);

/* The mesh's shells: writes the first min(capacity, count) shells to
   out_shells, an array whose elements all have the same struct_size set (the
   first element's is read), and the count (diagnostics.shell_count) to
   *out_shell_count; out_shells may be NULL when capacity is 0, to ask for
   the count. A shell's kind is judged when the surface passed the checks
   before the shells (closed, manifold, oriented, planar): by how the shells
   nest, counted exactly - or with POLYMASS_OPTION_SKIP_INTERSECTION_CHECK by
   bounding boxes, which can show a shell to be inside out but take any
   negative shell within a solid's box for a cavity; otherwise every shell is
   POLYMASS_SHELL_UNJUDGED. Since 2.0.
   Returns POLYMASS_OK. */
POLYMASS_API int32_t polymass_mesh_shells(polymass_shell* out_shells, uint64_t capacity,
                                          uint64_t* out_shell_count, polymass_context* context,
                                          const polymass_mesh* mesh);

/* The shell of each face: writes shell numbers (as polymass_mesh_shells
   numbers them) for the first min(capacity, face count) faces to
   out_shell_of_face (face count: face_count, or index_count / 3 for
   triangles). A caller can then check or compute each shell on its own.
   Since 2.0.
   Returns POLYMASS_OK, or the mesh's status when its faces were unreadable
   (POLYMASS_ERROR_NON_FINITE, _INDEX_OUT_OF_RANGE, _FACE_TOO_SMALL). */
POLYMASS_API int32_t polymass_mesh_shell_of_face(uint32_t* out_shell_of_face, uint64_t capacity,
                                                 polymass_context* context,
                                                 const polymass_mesh* mesh);

/* Which mode answered and what it did. Since 2.0.
   Returns POLYMASS_OK, or the mesh's status (with its message) when no mode
   answered. */
POLYMASS_API int32_t polymass_mesh_provenance(polymass_provenance* out_provenance,
                                              polymass_context* context, const polymass_mesh* mesh);

/* The moments (unit density) of the body that answered. Cheap: no pass over
   the faces. Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_OVERFLOW (a moment beyond a double),
   or the mesh's status (with its message) when no mode answered. */
POLYMASS_API int32_t polymass_mesh_moments(polymass_moments* out_moments, polymass_context* context,
                                           const polymass_mesh* mesh);

/* The mass properties of the body that answered, of the given density or mass
   (NULL: unit density). Cheap: no pass over the faces. Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_OVERFLOW, or the mesh's status (with
   its message) when no mode answered. */
POLYMASS_API int32_t polymass_mesh_mass_properties(polymass_mass_properties* out_properties,
                                                   polymass_context* context,
                                                   const polymass_mesh* mesh,
                                                   const polymass_mass_desc* mass);

/* The inertia tensor of a body about any point, from its mass properties, by
   the parallel-axis theorem (see INERTIA SIGN CONVENTION). Thread-safe.
   Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_OVERFLOW (a moment beyond a double),
   or POLYMASS_ERROR_INVALID_ARGUMENT (a NULL pointer, a non-finite point). */
POLYMASS_API int32_t polymass_inertia_about(double out_inertia[9],
                                            const polymass_mass_properties* properties,
                                            const double point[3]);

/* ========================================================================== */
/* Many meshes in one call                                                    */
/* ========================================================================== */

/* polymass_mass_properties_compute for item_count meshes: items[i] is found
   items[0].struct_size bytes after items[i - 1] (every item has that
   struct_size). Each item gets its own status, message and, on success,
   properties (and provenance when asked), exactly (bit for bit) those of
   polymass_mass_properties_compute; an item's failure does not stop the
   others. *out_failed (may be NULL) counts the items that failed. Items are
   independent: with a context of more than one thread they are spread over
   its threads (each item on one thread, its own passes serial), without
   changing any result. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK once every item has its status, or what kept the batch
   from running (POLYMASS_ERROR_INVALID_ARGUMENT: items NULL with item_count
   > 0, an unknown struct_size), with the context's message. */
POLYMASS_API int32_t polymass_batch_compute(polymass_batch_item* items, uint64_t item_count,
                                            uint64_t* out_failed, polymass_context* context);

/* The mass properties of every mesh of a packed set, with the same options
   for all (NULL: the defaults), written in columns: mesh i's numbers are bit
   for bit those polymass_mass_properties_compute gives for it alone, with its
   density or mass; a mesh's failure does not stop the others. *out_failed
   (may be NULL) counts the meshes that failed. Meshes are spread over the
   context's threads (each mesh on one thread) without changing any result.
   For a dataset's many small meshes, with no per-mesh struct or pointer to
   prepare. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK once every mesh has its status, or what kept the set
   from running (POLYMASS_ERROR_INVALID_ARGUMENT: offsets that do not ascend
   from 0, a count of indices not a multiple of 3, an unknown type, index
   base or mass mode, a stride or NULL array the set cannot have, a reserved
   field not 0, more than 2^32 vertices with global or 64-bit indices), with the
   context's message. */
POLYMASS_API int32_t polymass_packed_compute(const polymass_packed_results* results,
                                             uint64_t* out_failed, polymass_context* context,
                                             const polymass_packed_meshes* meshes,
                                             const polymass_options* options);

/* ========================================================================== */
/* Moments: mass integrals that compose                                       */
/* ========================================================================== */

/* The moments of faces [first_face, first_face + face_count) of the surface,
   about `reference` (every range of one surface must use the same point; one
   near the surface keeps the digits), flagged POLYMASS_MOMENTS_PARTIAL. For a
   caller's own threads: each takes a range, and the ranges added up (in a
   fixed order for a deterministic result) are the surface's moments. Indices
   and coordinates are checked, and polygon faces' planarity unless the
   options (NULL: the defaults) skip the topology checks; whether the whole is
   closed is the whole's question. Face numbers in messages count from
   first_face. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_NON_FINITE, _INDEX_OUT_OF_RANGE,
   _FACE_TOO_SMALL, _NON_PLANAR_FACE or _OVERFLOW. */
POLYMASS_API int32_t polymass_moments_compute_faces(polymass_moments* out_moments,
                                                    polymass_context* context,
                                                    const polymass_mesh_desc* desc,
                                                    uint64_t first_face, uint64_t face_count,
                                                    const double reference[3],
                                                    const polymass_options* options);

/* a + b: two disjoint bodies as one, about a's reference point. Context: one
   thread at a time. Since 2.0.
   Returns POLYMASS_OK or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_moments_add(polymass_moments* out_moments, polymass_context* context,
                                          const polymass_moments* a, const polymass_moments* b);

/* a - b: b removed from a (a bore from a block: b inside a), about a's
   reference point. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_moments_subtract(polymass_moments* out_moments,
                                               polymass_context* context, const polymass_moments* a,
                                               const polymass_moments* b);

/* The body moved by r -> rotation r + translation: rotation is row-major,
   orthonormal to 1e-12 (a proper rotation, or of determinant -1: a mirror);
   translation may be NULL (none). A mirrored body is the mirror image solid,
   of the same positive volume and mass (its faces reversed, as a mirrored
   mesh must be to stay a valid solid). Context: one thread at a time.
   Since 2.0.
   Returns POLYMASS_OK or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_moments_transform(polymass_moments* out_moments,
                                                polymass_context* context,
                                                const polymass_moments* moments,
                                                const double rotation[9],
                                                const double translation[3]);

/* The body stretched by factors[i] along axis i, about the origin: uniform
   scale (three equal factors, e.g. a unit conversion), per-axis scale, or a
   mirror (negative factors; volume and mass stay positive). Density is kept:
   the mass scales with the volume. Factors must be finite and non-zero.
   Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_moments_scale(polymass_moments* out_moments,
                                            polymass_context* context,
                                            const polymass_moments* moments,
                                            const double factors[3]);

/* The body with a density or a total mass: its whole mass distribution
   rescaled so that its mean density is mass->density
   (POLYMASS_MASS_FROM_DENSITY) or its mass is mass->mass
   (POLYMASS_MASS_FROM_TOTAL). For a single part that is "made of this
   material"; parts weighted first and added keep their own densities.
   Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_ZERO_VOLUME (no positive volume to
   weigh) or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_moments_weight(polymass_moments* out_moments,
                                             polymass_context* context,
                                             const polymass_moments* moments,
                                             const polymass_mass_desc* mass);

/* The mass properties of the body: NULL mass takes the moments as weighted,
   otherwise weighted as by polymass_moments_weight. density is the mean
   density (mass / volume); surface_area is NaN (moments do not keep the
   surface); warnings are 0. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_ZERO_VOLUME (the volume or mass is not
   positive) or POLYMASS_ERROR_OVERFLOW. */
POLYMASS_API int32_t polymass_moments_mass_properties(polymass_mass_properties* out_properties,
                                                      polymass_context* context,
                                                      const polymass_moments* moments,
                                                      const polymass_mass_desc* mass);

/* ========================================================================== */
/* Planar polygons                                                            */
/* ========================================================================== */

/* Area, centroid and second moments of area of a simple polygon (convex or
   not, either orientation) given as point_count (x, y) pairs of doubles, each
   pair `stride` bytes after the previous (0: packed). The polygon closes
   itself: do not repeat the first point. A self-intersecting polygon is not
   detected: its result is the signed sum over its lobes.
   Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK, POLYMASS_ERROR_NON_FINITE, _FACE_TOO_SMALL (fewer than
   3 points), _ZERO_AREA or _OVERFLOW. */
POLYMASS_API int32_t polymass_polygon_compute(polymass_polygon_properties* out_properties,
                                              polymass_context* context, const double* points,
                                              uint64_t point_count, uint64_t stride);

/* ========================================================================== */
/* Welding on its own                                                         */
/* ========================================================================== */

/* The library's welding over positions alone, for a caller that numbers
   vertices before handing a mesh over (a triangle soup such as STL repeats a
   vertex once per face). Positions are vertex_count points of position_type
   (POLYMASS_POSITION_*), each position_stride bytes after the previous (0:
   packed), as in polymass_mesh_desc. Writes to out_vertex_of (room for
   vertex_count) the lowest vertex index welded to each vertex, and to
   *out_distinct_count how many vertices are their own lowest. weld_tolerance
   is polymass_options.weld_tolerance's, relative to the largest extent of
   the positions' bounding box: 0 welds exactly equal positions in one
   hashing pass (coordinates compared by their bits once -0 is +0 and a NaN
   is quiet: NaNs of one payload are one position); above 0
   chains of near positions are one, and then non-finite coordinates are an
   error. At most UINT32_MAX vertices. Context: one thread at a time. Since 2.0.
   Returns POLYMASS_OK or POLYMASS_ERROR_NON_FINITE. */
POLYMASS_API int32_t polymass_weld_positions(uint32_t* out_vertex_of, uint64_t* out_distinct_count,
                                             polymass_context* context, const void* positions,
                                             uint32_t position_type, uint64_t vertex_count,
                                             uint64_t position_stride, double weld_tolerance);

#ifdef __cplusplus
}
#endif

#endif /* POLYMASS_POLYMASS_H */
