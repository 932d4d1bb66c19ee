/* Every status a surface and its options can give, as a table of cases
 * {description, input, options, expected status, message fragment}. Each
 * case goes through polymass_mass_properties_compute and polymass_mesh_create:
 * the same status and message from both; a mesh unless the arguments are
 * refused, whose status and message are the call's, whose mass properties
 * are refused with its status and whose diagnostics hold the same verdict.
 * After the table: what the diagnostics report of each kind of finding
 * (counts, first locations), what the options that relax the checks accept
 * (skip, accept inverted, accept non-manifold, weld, planarity tolerance),
 * and the other arguments of the calls (NULL pointers, struct sizes, mass). */
#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double unit_lo[3] = {0, 0, 0}, unit_hi[3] = {1, 1, 1};

/* ------------------------------------------------------------------------ */
/* What every case must satisfy                                             */
/* ------------------------------------------------------------------------ */

/* The description with the options (NULL: the defaults) gives `status`
   through polymass_mass_properties_compute and polymass_mesh_create, with a
   message that contains `fragment` ("" on success) and is the same from
   both. The mesh is NULL only when the arguments are refused; otherwise its
   status and message are the call's, its mass properties are refused with
   its status, and its diagnostics' status is the verdict when the topology
   was checked. The context then holds the message. */
static void expect_status_at(const char* file, int line, const char* what, polymass_context* ctx,
                             const polymass_mesh_desc* desc, const polymass_options* options,
                             int32_t status, const char* fragment) {
    polymass_mesh* mesh = (polymass_mesh*)&mesh; /* garbage: must be overwritten */
    polymass_mass_properties p;
    char message[1024];
    pm_props_init(&p);
    pm_check_status(file, line, what, status,
                    polymass_mass_properties_compute(&p, NULL, ctx, desc, options, NULL), ctx);
    snprintf(message, sizeof message, "%s", polymass_context_message(ctx));
    if ((status == POLYMASS_OK) != (message[0] == '\0') || !strstr(message, fragment)) {
        print_error("%s:%d: %s: the message \"%s\" does not say \"%s\"\n", file, line, what,
                    message, fragment);
        _fail(file, line);
    }
    pm_check_status(file, line, what, status, polymass_mesh_create(&mesh, ctx, desc, options), ctx);
    if (strcmp(message, polymass_context_message(ctx)) != 0) {
        print_error(
            "%s:%d: %s: polymass_mesh_create's message \"%s\" is not the one call's \"%s\"\n", file,
            line, what, polymass_context_message(ctx), message);
        _fail(file, line);
    }
    if ((mesh == NULL) != (status == POLYMASS_ERROR_INVALID_ARGUMENT)) {
        print_error("%s:%d: %s: a mesh %s\n", file, line, what,
                    mesh ? "after refused arguments" : "missing after an analysis");
        _fail(file, line);
    }
    if (mesh != NULL) {
        polymass_diagnostics d;
        pm_check_status(file, line, "polymass_mesh_status", status, polymass_mesh_status(mesh),
                        ctx);
        assert_string_equal(polymass_mesh_message(mesh), message);
        pm_diagnostics_init(&d);
        PM_ASSERT_OK(ctx, polymass_mesh_diagnostics(&d, ctx, mesh));
        if (d.checks & POLYMASS_CHECKED_TOPOLOGY) {
            pm_check_status(file, line, "polymass_diagnostics.status", status, d.status, ctx);
        }
        pm_check_status(file, line, "polymass_mesh_mass_properties", status,
                        polymass_mesh_mass_properties(&p, ctx, mesh, NULL), ctx);
        polymass_mesh_destroy(mesh);
    }
    /* The message back in the context. */
    pm_check_status(file, line, what, status,
                    polymass_mass_properties_compute(&p, NULL, ctx, desc, options, NULL), ctx);
}

/* ------------------------------------------------------------------------ */
/* The inputs of the cases                                                  */
/* ------------------------------------------------------------------------ */

typedef struct case_input {
    pm_mesh mesh;
    polymass_mesh_desc desc;
    uint32_t sizes[8];
    pm_laid_out_mesh laid_out; /* when laid_out.block is not NULL */
} case_input;

/* Builds case `variant` of a row into `in` (which starts zeroed). */
typedef void (*make_input)(case_input* in, int variant);

static void describe(case_input* in) { in->desc = pm_mesh_desc(&in->mesh); }

static void lay_out(case_input* in, const pm_layout* layout) {
    pm_lay_out(&in->laid_out, &in->mesh, layout);
    in->desc = in->laid_out.desc;
}

/* Vertices at exactly equal positions become one (the first). */
static void weld_exact(pm_mesh* m) {
    size_t i, k;
    for (k = 0; k < m->index_count; ++k) {
        const size_t v = m->indices[k];
        for (i = 0; i < v; ++i) {
            if (memcmp(m->positions + 3 * i, m->positions + 3 * v, 3 * sizeof(double)) == 0) {
                m->indices[k] = (uint32_t)i;
                break;
            }
        }
    }
}

/* A triangle soup of a cube: every triangle has its own three vertices, at
   exactly the positions of its neighbours'. */
static void make_cube_soup(pm_mesh* m) {
    pm_mesh_unit_cube(m, 1);
    pm_mesh_to_soup(m);
    assert_int_equal(m->vertex_count, 36);
}

/* Two unit cubes sharing one edge (x = 1, y = 1): the edge is used by four
   faces, twice in each direction. */
static void make_two_cubes_sharing_an_edge(pm_mesh* m, int share_indices) {
    static const double lo2[3] = {1, 1, 0}, hi2[3] = {2, 2, 1};
    pm_mesh_unit_cube(m, 0);
    pm_mesh_add_box(m, lo2, hi2, 1);
    if (share_indices) {
        weld_exact(m);
    }
}

/* The unit cube with vertex 4 (0, 0, 1) lifted along z: it stays in the
   planes x = 0 and y = 0, so only the top face (face 1) bends. */
static void make_lifted_cube(pm_mesh* m, double lift) {
    pm_mesh_unit_cube(m, 0);
    m->positions[3 * 4 + 2] += lift;
}

/* The unit cube whose front face (y = 0) is split at x = 0.5 by vertices
   8 (0.5, 0, 0) and 9 (0.5, 0, 1): T-junctions on the bottom and top edges,
   closed by zero-area sliver triangles (collinear distinct vertices), faces 7
   and 8. */
static void make_t_junction_cube(pm_mesh* m) {
    pm_mesh_init(m);
    {
        int k;
        for (k = 0; k < 8; ++k) {
            pm_mesh_add_vertex(m, k & 1, (k >> 1) & 1, (k >> 2) & 1);
        }
    }
    pm_mesh_add_vertex(m, 0.5, 0, 0); /* 8 */
    pm_mesh_add_vertex(m, 0.5, 0, 1); /* 9 */
    pm_mesh_add_quad(m, 0, 2, 3, 1);  /* 0: bottom */
    pm_mesh_add_quad(m, 4, 5, 7, 6);  /* 1: top */
    pm_mesh_add_quad(m, 0, 8, 9, 4);  /* 2: front, left half */
    pm_mesh_add_quad(m, 8, 1, 5, 9);  /* 3: front, right half */
    pm_mesh_add_quad(m, 2, 6, 7, 3);  /* 4: back */
    pm_mesh_add_quad(m, 0, 4, 6, 2);  /* 5: x = 0 */
    pm_mesh_add_quad(m, 1, 3, 7, 5);  /* 6: x = 1 */
    pm_mesh_add_tri(m, 0, 1, 8);      /* 7: sliver on the bottom edge */
    pm_mesh_add_tri(m, 5, 4, 9);      /* 8: sliver on the top edge */
}

/* A flat double-sided square: two coincident quads of opposite orientation;
   closed, manifold, consistent, planar, and empty. */
static void make_flat_square(pm_mesh* m) {
    pm_mesh_init(m);
    pm_mesh_add_vertex(m, 0, 0, 0);
    pm_mesh_add_vertex(m, 1, 0, 0);
    pm_mesh_add_vertex(m, 1, 1, 0);
    pm_mesh_add_vertex(m, 0, 1, 0);
    pm_mesh_add_quad(m, 0, 1, 2, 3);
    pm_mesh_add_quad(m, 3, 2, 1, 0);
}

/* --- the arguments --- */

static void unit_quads(case_input* in, int variant) {
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 0);
    describe(in);
}

static void unit_triangles(case_input* in, int variant) {
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 1);
    describe(in);
}

static void positions_null(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.positions = NULL;
}

static void indices_null(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.indices = NULL;
}

static void face_sizes_null(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.face_sizes = NULL; /* face_count stays 6 */
}

static void bad_struct_size(case_input* in, int variant) {
    static const uint32_t sizes[] = {0,
                                     1,
                                     8,
                                     sizeof(polymass_mesh_desc) - 1,
                                     sizeof(polymass_mesh_desc) + 4096,
                                     0x7FFFFFFFu,
                                     0xFFFFFFFFu};
    unit_quads(in, variant);
    in->desc.struct_size = sizes[variant];
}

static void small_double_stride(case_input* in, int variant) {
    static const uint64_t strides[] = {1, 8, 16, 23};
    unit_quads(in, variant);
    in->desc.position_stride = strides[variant];
}

static void small_float_stride(case_input* in, int variant) {
    static const uint64_t strides[] = {4, 8, 11};
    unit_quads(in, variant);
    in->desc.position_type = POLYMASS_POSITION_FLOAT32;
    in->desc.position_stride = strides[variant];
}

static const uint32_t bad_types[] = {2, 0xFFFFFFFFu, 0x80000000u};

static void bad_position_type(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.position_type = bad_types[variant];
}

static void bad_index_type(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.index_type = bad_types[variant];
}

static void bad_reserved(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.reserved = variant ? 0x80000000u : 1u;
}

/* Face sizes adding up to more, and to less, than index_count; fewer faces;
   face_sizes given with face_count 0 while there are indices. */
static void sizes_not_adding_up(case_input* in, int variant) {
    unit_quads(in, variant);
    memcpy(in->sizes, in->mesh.face_sizes, 6 * sizeof in->sizes[0]);
    in->desc.face_sizes = in->sizes;
    if (variant < 2) {
        in->sizes[5] = variant == 0 ? 5 : 3;
    } else {
        in->desc.face_count = variant == 2 ? 5 : 0;
    }
}

static void triangle_count_not_whole(case_input* in, int variant) {
    static const uint64_t counts[] = {35, 34};
    unit_triangles(in, variant);
    in->desc.index_count = counts[variant];
}

/* Counts whose byte sizes overflow 64 bits are refused before anything is
   read (ASan would catch a read past the small arrays given). */
static void vertices_past_any_array(case_input* in, int variant) {
    unit_triangles(in, variant);
    in->desc.vertex_count = variant < 2 ? UINT64_MAX / 8 : 8; /* * 24 bytes overflows */
    in->desc.position_stride = variant == 0 ? 24 : variant == 1 ? 0 : UINT64_MAX / 4;
}

static void indices_past_any_array(case_input* in, int variant) {
    unit_triangles(in, variant);
    /* whose 4 bytes each overflow, whether a multiple of 3 or not */
    static const uint64_t counts[] = {UINT64_MAX / 2 - 1, UINT64_MAX, UINT64_MAX / 2};
    in->desc.index_count = counts[variant];
}

static void faces_past_any_array(case_input* in, int variant) {
    unit_triangles(in, variant);
    in->sizes[0] = in->sizes[1] = 3;
    in->desc.face_sizes = in->sizes;
    in->desc.face_count = variant == 0 ? UINT64_MAX / 2 : UINT64_MAX; /* * 4 bytes overflows */
}

static void no_faces(case_input* in, int variant) {
    unit_triangles(in, variant);
    in->desc.index_count = 0;
}

/* --- the coordinates, the indices, the face sizes --- */

static void non_finite_vertex(case_input* in, int variant) {
    static const double bad[] = {NAN, INFINITY, -INFINITY};
    pm_mesh_unit_cube(&in->mesh, 0);
    in->mesh.positions[3 * 5 + variant % 3] = bad[variant / 3];
    describe(in);
}

static void two_non_finite_vertices(case_input* in, int variant) {
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 1);
    in->mesh.positions[3 * 6] = NAN;
    in->mesh.positions[3 * 2 + 1] = INFINITY;
    describe(in);
}

static void float32_nan(case_input* in, int variant) {
    static const pm_layout float32 = {POLYMASS_POSITION_FLOAT32, 0, 0, POLYMASS_INDEX_UINT32};
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 0);
    in->mesh.positions[3 * 7 + 2] = NAN;
    lay_out(in, &float32);
}

static void index_out_of_range(case_input* in, int variant) {
    pm_mesh_unit_cube(&in->mesh, 0);
    in->mesh.indices[pm_mesh_face_offset(&in->mesh, 3) + 2] = variant ? UINT32_MAX : 8;
    describe(in);
}

static void two_faces_out_of_range(case_input* in, int variant) {
    index_out_of_range(in, variant);
    in->mesh.indices[pm_mesh_face_offset(&in->mesh, 5)] = 1000;
}

static void uint16_out_of_range(case_input* in, int variant) {
    static const pm_layout uint16 = {POLYMASS_POSITION_FLOAT64, 0, 0, POLYMASS_INDEX_UINT16};
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 1);
    in->mesh.indices[3 * 7 + 1] = 0xFFFF;
    lay_out(in, &uint16);
}

/* Faces 4 and 5 of 2 vertices each instead of one quad; a face of 0
   vertices; faces of 0 vertices only, so no indices at all. */
static void faces_too_small(case_input* in, int variant) {
    unit_quads(in, variant);
    in->desc.face_sizes = in->sizes;
    in->desc.face_count = 7;
    in->sizes[0] = in->sizes[1] = in->sizes[2] = in->sizes[3] = 4;
    in->sizes[4] = variant == 0 ? 2 : 4;
    in->sizes[5] = variant == 0 ? 2 : 0;
    in->sizes[6] = 4;
    if (variant == 2) {
        in->sizes[0] = in->sizes[1] = 0;
        in->desc.face_count = 2;
        in->desc.index_count = 0;
        in->desc.indices = NULL;
    }
}

static void face_of_no_vertices(case_input* in, int variant) {
    (void)variant;
    faces_too_small(in, 1);
}

static void faces_only_of_no_vertices(case_input* in, int variant) {
    (void)variant;
    faces_too_small(in, 2);
}

/* --- topology --- */

static void cube_without_a_face(case_input* in, int variant) {
    pm_mesh_unit_cube(&in->mesh, 0);
    pm_mesh_remove_face(&in->mesh, (size_t)variant);
    describe(in);
}

static void one_triangle(case_input* in, int variant) {
    (void)variant;
    pm_mesh_init(&in->mesh);
    pm_mesh_add_vertex(&in->mesh, 0, 0, 0);
    pm_mesh_add_vertex(&in->mesh, 1, 0, 0);
    pm_mesh_add_vertex(&in->mesh, 0, 1, 0);
    pm_mesh_add_tri(&in->mesh, 0, 1, 2);
    describe(in);
}

static void cube_soup(case_input* in, int variant) {
    (void)variant;
    make_cube_soup(&in->mesh);
    describe(in);
}

/* Only exactly equal positions weld: one ulp apart stays open. */
static void soup_one_ulp_apart(case_input* in, int variant) {
    cube_soup(in, variant);
    in->mesh.positions[3 * 20] = nextafter(in->mesh.positions[3 * 20], 2.0);
}

static void t_junctions_without_slivers(case_input* in, int variant) {
    (void)variant;
    make_t_junction_cube(&in->mesh);
    pm_mesh_remove_face(&in->mesh, 8);
    pm_mesh_remove_face(&in->mesh, 7);
    describe(in);
}

/* variant 1: of separate vertices, for welding to join. */
static void cubes_sharing_an_edge(case_input* in, int variant) {
    make_two_cubes_sharing_an_edge(&in->mesh, variant == 0);
    describe(in);
}

static void cubes_sharing_an_edge_welded(case_input* in, int variant) {
    (void)variant;
    cubes_sharing_an_edge(in, 1);
}

/* A tetrahedron with one face listed twice: its edges are used three times,
   twice one way: never accepted. */
static void face_listed_twice(case_input* in, int variant) {
    (void)variant;
    pm_mesh_from_reference(&in->mesh, &pm_reference_solids[PM_REF_TETRA_IRREGULAR]);
    pm_mesh_add_tri(&in->mesh, in->mesh.indices[0], in->mesh.indices[1], in->mesh.indices[2]);
    describe(in);
}

static void cube_with_a_face_reversed(case_input* in, int variant) {
    pm_mesh_unit_cube(&in->mesh, 0);
    pm_mesh_reverse_face(&in->mesh, (size_t)variant);
    describe(in);
}

static void torus_with_a_triangle_reversed(case_input* in, int variant) {
    (void)variant;
    pm_mesh_from_reference(&in->mesh, &pm_reference_solids[PM_REF_TORUS_TRIS]);
    pm_mesh_reverse_face(&in->mesh, 17);
    describe(in);
}

static void soup_with_a_triangle_reversed(case_input* in, int variant) {
    cube_soup(in, variant);
    pm_mesh_reverse_face(&in->mesh, 4);
}

/* The top bent by 1e-3, at the size of the unit cube or scaled by 2^30
   (the tolerance is relative to the face's size). */
static void cube_bent(case_input* in, int variant) {
    make_lifted_cube(&in->mesh, 1e-3);
    if (variant) {
        pm_mesh_transform(&in->mesh, NULL, 1073741824.0, NULL);
    }
    describe(in);
}

static void cube_bent_slightly(case_input* in, int variant) {
    make_lifted_cube(&in->mesh, 1e-9);
    if (variant) {
        pm_mesh_transform(&in->mesh, NULL, 1.0 / 1073741824.0, NULL);
    }
    describe(in);
}

/* --- volume --- */

static void house_reversed(case_input* in, int variant) {
    (void)variant;
    pm_mesh_from_reference(&in->mesh, &pm_reference_solids[PM_REF_HOUSE]);
    pm_mesh_reverse_all(&in->mesh);
    describe(in);
}

/* A cube, and beside it a smaller box inside out: inside no solid shell. */
static void shell_inside_out(case_input* in, int variant) {
    static const double lo[3] = {3, 0, 0}, hi[3] = {3.5, 0.5, 0.5};
    pm_mesh inside_out;
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 0);
    pm_mesh_box(&inside_out, lo, hi, 0);
    pm_mesh_reverse_all(&inside_out);
    pm_mesh_append(&in->mesh, &inside_out);
    pm_mesh_free(&inside_out);
    describe(in);
}

/* An octahedron about the vertical line through (0.5, 0.5): its square
   equator, of half-diagonal 0.25, in the plane z = 1, its apexes at z = 0.5
   and 1.5; inside out when asked. */
static void add_octahedron_at_z1(pm_mesh* m, int inside_out) {
    uint32_t bottom = pm_mesh_add_vertex(m, 0.5, 0.5, 0.5);
    uint32_t top = pm_mesh_add_vertex(m, 0.5, 0.5, 1.5);
    uint32_t equator[4];
    int i;
    equator[0] = pm_mesh_add_vertex(m, 0.75, 0.5, 1);
    equator[1] = pm_mesh_add_vertex(m, 0.5, 0.75, 1);
    equator[2] = pm_mesh_add_vertex(m, 0.25, 0.5, 1);
    equator[3] = pm_mesh_add_vertex(m, 0.5, 0.25, 1);
    for (i = 0; i < 4; ++i) {
        uint32_t a = equator[i], b = equator[(i + 1) % 4];
        if (inside_out) {
            pm_mesh_add_tri(m, b, a, top);
            pm_mesh_add_tri(m, a, b, bottom);
        } else {
            pm_mesh_add_tri(m, a, b, top);
            pm_mesh_add_tri(m, b, a, bottom);
        }
    }
}

/* The unit cube and an octahedron inside out, half in it and half above it,
   its equator on the cube's top: no faces cross, but the shell passes
   through the cube's surface. Its box is in no solid's box, and the analysis
   that stops at the first problem must not stop there: the windings say how
   it fails. */
static void inside_out_half_in_a_cube(case_input* in, int variant) {
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 1);
    add_octahedron_at_z1(&in->mesh, 1);
    describe(in);
}

/* The same octahedron inside out as a cavity across two boxes resting on
   each other: wholly inside the solid they make, though in neither box, so
   a valid solid of volume 2 - 1/24. */
static void cavity_across_two_boxes(case_input* in, int variant) {
    static const double lo[3] = {0, 0, 1}, hi[3] = {1, 1, 2};
    (void)variant;
    pm_mesh_unit_cube(&in->mesh, 1);
    pm_mesh_add_box(&in->mesh, lo, hi, 1);
    add_octahedron_at_z1(&in->mesh, 1);
    describe(in);
}

static void flat_square(case_input* in, int variant) {
    (void)variant;
    make_flat_square(&in->mesh);
    describe(in);
}

/* A tetrahedron flattened into the plane z = 0.5 (variant 1: moved far). */
static void flat_tetrahedron(case_input* in, int variant) {
    static const double t[3] = {1e6, -1e6, 0};
    pm_mesh* m = &in->mesh;
    pm_mesh_init(m);
    pm_mesh_add_vertex(m, 0, 0, 0.5);
    pm_mesh_add_vertex(m, 2, 0, 0.5);
    pm_mesh_add_vertex(m, 0, 1, 0.5);
    pm_mesh_add_vertex(m, 2, 3, 0.5);
    pm_mesh_add_tri(m, 0, 2, 1);
    pm_mesh_add_tri(m, 0, 1, 3);
    pm_mesh_add_tri(m, 0, 3, 2);
    pm_mesh_add_tri(m, 1, 2, 3);
    if (variant) {
        pm_mesh_transform(m, NULL, 1.0, t);
    }
    describe(in);
}

/* The unit cube and a box from (0.25, 0.25, 0.25) to `far`. */
static void cube_and_box_to(case_input* in, double far) {
    const double lo[3] = {0.25, 0.25, 0.25}, hi[3] = {far, far, far};
    pm_mesh_unit_cube(&in->mesh, 1);
    pm_mesh_add_box(&in->mesh, lo, hi, 1);
    describe(in);
}

static void cubes_overlapping(case_input* in, int variant) {
    (void)variant;
    cube_and_box_to(in, 1.5); /* the faces cross */
}

static void cube_inside_a_cube(case_input* in, int variant) {
    (void)variant;
    cube_and_box_to(in, 0.75);
}

static void tiny_box(case_input* in, int variant) {
    static const double lo[3] = {0, 0, 0}, hi[3] = {1e-110, 2e-110, 3e-110};
    (void)variant;
    pm_mesh_box(&in->mesh, lo, hi, 1);
    describe(in);
}

static void huge_box(case_input* in, int variant) {
    static const double lo[3] = {-1e308, 0, 0}, hi[3] = {1e308, 1, 1};
    (void)variant;
    pm_mesh_box(&in->mesh, lo, hi, 1);
    describe(in);
}

/* ------------------------------------------------------------------------ */
/* The table                                                                */
/* ------------------------------------------------------------------------ */

#define OPTIONS(...) \
    { .struct_size = sizeof(polymass_options), __VA_ARGS__ }

static const polymass_options skip_topology =
    OPTIONS(.flags = POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
static const polymass_options weld = OPTIONS(.flags = POLYMASS_OPTION_WELD_VERTICES);
static const polymass_options accept_inverted = OPTIONS(.flags = POLYMASS_OPTION_ACCEPT_INVERTED);
static const polymass_options accept_non_manifold =
    OPTIONS(.flags = POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
static const polymass_options weld_and_accept_non_manifold =
    OPTIONS(.flags = POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
/* Every flag that relaxes a check: none relaxes the input's own. */
static const polymass_options every_relaxing_flag =
    OPTIONS(.flags = POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_ACCEPT_INVERTED |
                     POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD);
static const polymass_options planarity_1e_2 = OPTIONS(.planarity_tolerance = 1e-2);
static const polymass_options planarity_1e_12 = OPTIONS(.planarity_tolerance = 1e-12);
static const polymass_options unknown_flag = OPTIONS(.flags = 1u << 31);
static const polymass_options negative_planarity = OPTIONS(.planarity_tolerance = -1e-3);
static const polymass_options weld_too_coarse =
    OPTIONS(.flags = POLYMASS_OPTION_WELD_VERTICES, .weld_tolerance = 1.0);
static const polymass_options unknown_mode = OPTIONS(.modes = {7});
static const polymass_options shell_without_thickness = OPTIONS(.modes = {POLYMASS_MODE_SHELL});
static const polymass_options unknown_size = {.struct_size = 8};

typedef struct error_case {
    const char* description;
    make_input make;
    int variants;                    /* the input's variants, each a case */
    const polymass_options* options; /* NULL: the defaults */
    int32_t status;
    const char* message; /* a fragment of it; "" on success */
} error_case;

static const error_case cases[] = {
    /* The arguments: refused before any analysis, no mesh. */
    {"positions NULL with 8 vertices", positions_null, 1, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "positions is NULL but vertex_count is 8"},
    {"indices NULL", indices_null, 1, NULL, POLYMASS_ERROR_INVALID_ARGUMENT, "indices is NULL"},
    {"face_count without face_sizes", face_sizes_null, 1, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "face_count is 6 but face_sizes is NULL"},
    {"desc->struct_size of no 2.0 struct", bad_struct_size, 7, NULL,
     POLYMASS_ERROR_INVALID_ARGUMENT, "desc->struct_size is"},
    {"position_stride below 3 doubles", small_double_stride, 4, NULL,
     POLYMASS_ERROR_INVALID_ARGUMENT, "is smaller than a vertex (24 bytes)"},
    {"position_stride below 3 floats", small_float_stride, 3, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "is smaller than a vertex (12 bytes)"},
    {"unknown position_type", bad_position_type, 3, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "is not POLYMASS_POSITION_FLOAT64"},
    {"unknown index_type", bad_index_type, 3, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "is not POLYMASS_INDEX_UINT32"},
    {"reserved not 0", bad_reserved, 2, NULL, POLYMASS_ERROR_INVALID_ARGUMENT, "; it must be 0"},
    {"face sizes not adding up to index_count", sizes_not_adding_up, 4, NULL,
     POLYMASS_ERROR_INVALID_ARGUMENT, "face_sizes add up to"},
    {"triangles: index_count not a multiple of 3", triangle_count_not_whole, 2, NULL,
     POLYMASS_ERROR_INVALID_ARGUMENT, "is not a multiple of 3"},
    {"vertices past any array", vertices_past_any_array, 3, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "is larger than any array can be"},
    {"indices past any array", indices_past_any_array, 3, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "is larger than any array can be"},
    {"face sizes past any array", faces_past_any_array, 2, NULL, POLYMASS_ERROR_INVALID_ARGUMENT,
     "is larger than any array can be"},
    {"no faces", no_faces, 1, NULL, POLYMASS_ERROR_INVALID_ARGUMENT, "the mesh has no faces"},
    {"an unknown option flag", unit_quads, 1, &unknown_flag, POLYMASS_ERROR_INVALID_ARGUMENT,
     "options->flags has unknown bits 0x80000000"},
    {"a negative planarity tolerance", unit_quads, 1, &negative_planarity,
     POLYMASS_ERROR_INVALID_ARGUMENT, "options->planarity_tolerance is"},
    {"a weld tolerance above the largest", unit_quads, 1, &weld_too_coarse,
     POLYMASS_ERROR_INVALID_ARGUMENT, "options->weld_tolerance is 1"},
    {"an unknown mode", unit_quads, 1, &unknown_mode, POLYMASS_ERROR_INVALID_ARGUMENT,
     "options->modes[0] is 7"},
    {"SHELL without a thickness", unit_quads, 1, &shell_without_thickness,
     POLYMASS_ERROR_INVALID_ARGUMENT, "options->shell_thickness is 0"},
    {"options of no 2.0 size", unit_quads, 1, &unknown_size, POLYMASS_ERROR_INVALID_ARGUMENT,
     "options->struct_size is 8"},

    /* Coordinates, indices and face sizes: never skipped. */
    {"a NaN or infinite coordinate of a used vertex", non_finite_vertex, 9, NULL,
     POLYMASS_ERROR_NON_FINITE, "vertex 5, used by a face, has a NaN or infinite coordinate"},
    {"the same with every check relaxed", non_finite_vertex, 9, &every_relaxing_flag,
     POLYMASS_ERROR_NON_FINITE, "vertex 5, used by a face"},
    {"two vertices not finite: the first named, both counted", two_non_finite_vertices, 1, NULL,
     POLYMASS_ERROR_NON_FINITE, "vertex 2, used by a face, has a NaN or infinite coordinate (2 "},
    {"a float32 NaN", float32_nan, 1, NULL, POLYMASS_ERROR_NON_FINITE, "vertex 7, used by a face"},
    {"an index past the vertices", index_out_of_range, 2, NULL, POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
     "face 3 refers to vertex"},
    {"the same with the topology skipped", index_out_of_range, 1, &skip_topology,
     POLYMASS_ERROR_INDEX_OUT_OF_RANGE, "face 3 refers to vertex 8"},
    {"the same, welding", index_out_of_range, 1, &weld, POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
     "face 3 refers to vertex 8"},
    {"two faces out of range: the first named, both counted", two_faces_out_of_range, 1, NULL,
     POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
     "face 3 refers to vertex 8, but there are only 8 vertices (2 indices out of range, in 2 "
     "faces)"},
    {"a uint16 index past the vertices", uint16_out_of_range, 1, NULL,
     POLYMASS_ERROR_INDEX_OUT_OF_RANGE, "face 7 refers to vertex 65535"},
    {"faces of 2 vertices", faces_too_small, 1, NULL, POLYMASS_ERROR_FACE_TOO_SMALL,
     "face 4 has 2 vertices; a face needs at least 3 (2 such faces)"},
    {"the same with the topology skipped", faces_too_small, 1, &skip_topology,
     POLYMASS_ERROR_FACE_TOO_SMALL, "face 4 has 2 vertices"},
    {"a face of no vertices", face_of_no_vertices, 1, NULL, POLYMASS_ERROR_FACE_TOO_SMALL,
     "face 5 has 0 vertices"},
    {"faces of no vertices only, no indices", faces_only_of_no_vertices, 1, NULL,
     POLYMASS_ERROR_FACE_TOO_SMALL, "face 0 has 0 vertices"},

    /* Topology. */
    {"the cube without one face", cube_without_a_face, 6, NULL, POLYMASS_ERROR_OPEN,
     "is used by one face only: the surface is open (4 such edges)"},
    {"one triangle", one_triangle, 1, NULL, POLYMASS_ERROR_OPEN,
     "is used by one face only: the surface is open (3 such edges)"},
    {"a triangle soup of a cube, not welded", cube_soup, 1, NULL, POLYMASS_ERROR_OPEN,
     "(36 such edges)"},
    {"a soup welded, one coordinate an ulp off", soup_one_ulp_apart, 1, &weld, POLYMASS_ERROR_OPEN,
     "is used by one face only"},
    {"T-junctions without their slivers", t_junctions_without_slivers, 1, NULL, POLYMASS_ERROR_OPEN,
     "is used by one face only"},
    {"two cubes sharing an edge", cubes_sharing_an_edge, 1, NULL, POLYMASS_ERROR_NON_MANIFOLD,
     "is used by 4 faces; an edge of a solid's surface has two (1 such edges)"},
    {"two cubes sharing an edge, welded", cubes_sharing_an_edge_welded, 1, &weld,
     POLYMASS_ERROR_NON_MANIFOLD, "is used by 4 faces"},
    {"a face listed twice", face_listed_twice, 1, NULL, POLYMASS_ERROR_NON_MANIFOLD,
     "is used by 3 faces"},
    {"a face listed twice: unbalanced, never accepted", face_listed_twice, 1, &accept_non_manifold,
     POLYMASS_ERROR_NON_MANIFOLD, "is used by 3 faces"},
    {"a face of the cube reversed", cube_with_a_face_reversed, 6, NULL,
     POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
     "traversed in the same direction by both its faces: one of them is reversed (4 such "
     "edges)"},
    {"a triangle of the torus reversed", torus_with_a_triangle_reversed, 1, NULL,
     POLYMASS_ERROR_INCONSISTENT_ORIENTATION, "(3 such edges)"},
    {"a triangle of a welded soup reversed", soup_with_a_triangle_reversed, 1, &weld,
     POLYMASS_ERROR_INCONSISTENT_ORIENTATION, "traversed in the same direction"},
    {"the cube's top bent by 1e-3 of its size", cube_bent, 2, NULL, POLYMASS_ERROR_NON_PLANAR_FACE,
     "face 1 is not planar"},
    {"bent by 1e-9, with a tolerance of 1e-12", cube_bent_slightly, 1, &planarity_1e_12,
     POLYMASS_ERROR_NON_PLANAR_FACE, "more than the tolerance 1e-12"},

    /* Volume. */
    {"every face reversed", house_reversed, 1, NULL, POLYMASS_ERROR_INVERTED,
     "every face is reversed"},
    {"a shell inside out, in no solid", shell_inside_out, 1, NULL, POLYMASS_ERROR_INVERTED,
     "shell 1 (6 faces, the first face 6, signed volume -0.125) is inside out"},
    {"a shell inside out, half in a solid", inside_out_half_in_a_cube, 1, NULL,
     POLYMASS_ERROR_INTERSECTING,
     "shell 1 (8 faces, the first face 12, signed volume -0.041666666666666664) lies inside "
     "another shell that already bounds the same side, or passes through its surface"},
    {"a cavity across two solids resting on each other", cavity_across_two_boxes, 1, NULL,
     POLYMASS_OK, ""},
    {"a flat double-sided square", flat_square, 1, NULL, POLYMASS_ERROR_ZERO_VOLUME,
     "the surface encloses no volume"},
    {"the same, inverted accepted", flat_square, 1, &accept_inverted, POLYMASS_ERROR_ZERO_VOLUME,
     "the surface encloses no volume"},
    {"a flat tetrahedron, near and far", flat_tetrahedron, 2, NULL, POLYMASS_ERROR_ZERO_VOLUME,
     "the surface encloses no volume"},
    {"two cubes whose faces cross", cubes_overlapping, 1, NULL, POLYMASS_ERROR_INTERSECTING,
     "cross each other: the region inside both would be counted twice"},
    {"a cube inside a cube", cube_inside_a_cube, 1, NULL, POLYMASS_ERROR_INTERSECTING,
     "lies inside another shell that already bounds the same side"},
    {"a box whose volume underflows", tiny_box, 1, NULL, POLYMASS_ERROR_OVERFLOW,
     "is too small for a double"},
    {"a box whose extent overflows", huge_box, 1, NULL, POLYMASS_ERROR_OVERFLOW,
     "the mesh spans more than a double can hold"},

    /* What the options accept. */
    {"the unit cube", unit_quads, 1, NULL, POLYMASS_OK, ""},
    {"two cubes sharing an edge, accepted", cubes_sharing_an_edge, 1, &accept_non_manifold,
     POLYMASS_OK, ""},
    {"the same welded, accepted", cubes_sharing_an_edge_welded, 1, &weld_and_accept_non_manifold,
     POLYMASS_OK, ""},
    {"two cubes touching along an edge, not welded", cubes_sharing_an_edge_welded, 1, NULL,
     POLYMASS_OK, ""},
    {"a triangle soup of a cube, welded", cube_soup, 1, &weld, POLYMASS_OK, ""},
    {"a triangle soup of a cube, topology skipped", cube_soup, 1, &skip_topology, POLYMASS_OK, ""},
    {"bent by 1e-3 with a tolerance of 1e-2", cube_bent, 1, &planarity_1e_2, POLYMASS_OK, ""},
    {"bent by 1e-3, topology skipped", cube_bent, 1, &skip_topology, POLYMASS_OK, ""},
    {"bent by 1e-9: within the default tolerance, at any scale", cube_bent_slightly, 2, NULL,
     POLYMASS_OK, ""},
    {"every face reversed, accepted", house_reversed, 1, &accept_inverted, POLYMASS_OK, ""},
};
#define CASE_COUNT (sizeof cases / sizeof cases[0])

static void test_case(void** state) {
    const error_case* c = *state;
    polymass_context* ctx = pm_context_new();
    int variant;
    for (variant = 0; variant < c->variants; ++variant) {
        case_input in;
        char what[256];
        memset(&in, 0, sizeof in);
        c->make(&in, variant);
        snprintf(what, sizeof what, "%s (variant %d)", c->description, variant);
        expect_status_at(__FILE__, __LINE__, what, ctx, &in.desc, c->options, c->status,
                         c->message);
        if (in.laid_out.block) {
            pm_laid_out_free(&in.laid_out);
        }
        pm_mesh_free(&in.mesh);
    }
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* The diagnostics of each kind of finding                                  */
/* ------------------------------------------------------------------------ */

static int is_edge(const uint64_t e[2], uint64_t a, uint64_t b) {
    return (e[0] == a && e[1] == b) || (e[0] == b && e[1] == a);
}

/* The edge e is one of the face's edges. */
static int edge_of_face(const pm_mesh* m, size_t face, const uint64_t e[2]) {
    const size_t offset = pm_mesh_face_offset(m, face), n = m->face_sizes[face];
    size_t k;
    for (k = 0; k < n; ++k) {
        if (is_edge(e, m->indices[offset + k], m->indices[offset + (k + 1) % n])) {
            return 1;
        }
    }
    return 0;
}

/* The three kinds of bad edge the diagnostics count. */
typedef enum edge_defect { OPEN_EDGE, NON_MANIFOLD_EDGE, MISORIENTED_EDGE } edge_defect;

static uint64_t defect_count(const polymass_diagnostics* d, edge_defect kind) {
    switch (kind) {
        case OPEN_EDGE:
            return d->open_edges;
        case NON_MANIFOLD_EDGE:
            return d->non_manifold_edges;
        default:
            return d->misoriented_edges;
    }
}

static const uint64_t* first_defect(const polymass_diagnostics* d, edge_defect kind) {
    switch (kind) {
        case OPEN_EDGE:
            return d->first_open_edges[0];
        case NON_MANIFOLD_EDGE:
            return d->first_non_manifold_edges[0];
        default:
            return d->first_misoriented_edges[0];
    }
}

/* The diagnostics of the mesh (default options), left in *diag, have
   `status` and count `count` edges of `kind`. */
static void expect_edge_defect_at(const char* file, int line, polymass_context* ctx,
                                  const pm_mesh* m, int32_t status, edge_defect kind,
                                  uint64_t count, polymass_diagnostics* diag) {
    pm_check_status(file, line, "polymass_mesh_diagnostics", status, pm_check(diag, ctx, m), ctx);
    if (defect_count(diag, kind) != count) {
        print_error("%s:%d: %llu bad edges of kind %d reported, expected %llu\n", file, line,
                    (unsigned long long)defect_count(diag, kind), (int)kind,
                    (unsigned long long)count);
        _fail(file, line);
    }
}
#define EXPECT_EDGE_DEFECT(ctx, m, status, kind, count, diag) \
    expect_edge_defect_at(__FILE__, __LINE__, (ctx), (m), (status), (kind), (count), (diag))

/* For each face f of the unit cube (quads), the cube with only face f changed
   by change_face (removed, reversed): EXPECT_EDGE_DEFECT with `bad_edges`
   edges of `kind`, the first of them an edge of face f and named in the
   message; no bad edge of another kind; face_count faces on the cube's 8
   vertices and 12 edges. */
static void expect_defect_on_each_cube_face(void (*change_face)(pm_mesh*, size_t), int32_t status,
                                            edge_defect kind, uint64_t bad_edges,
                                            uint64_t face_count) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    pm_mesh cube, m;
    size_t f;
    int other;
    pm_mesh_unit_cube(&cube, 0);
    for (f = 0; f < cube.face_count; ++f) {
        const uint64_t* first;
        pm_mesh_copy(&m, &cube);
        change_face(&m, f);
        EXPECT_EDGE_DEFECT(ctx, &m, status, kind, bad_edges, &diag);
        assert_int_equal(diag.face_count, face_count);
        assert_int_equal(diag.used_vertex_count, 8);
        assert_int_equal(diag.edge_count, 12);
        first = first_defect(&diag, kind);
        assert_true(edge_of_face(&cube, f, first));
        PM_ASSERT_EDGE_MENTIONED(ctx, first[0], first[1]);
        for (other = OPEN_EDGE; other <= MISORIENTED_EDGE; ++other) {
            if (other != (int)kind) {
                assert_int_equal(defect_count(&diag, (edge_defect)other), 0);
                assert_true(first_defect(&diag, (edge_defect)other)[0] == POLYMASS_NONE);
            }
        }
        pm_mesh_free(&m);
    }
    pm_mesh_free(&cube);
    polymass_context_destroy(ctx);
}

/* Coordinates, indices and face sizes that cannot be read: their findings
   and counts only, nothing integrated, no shells. */
static void expect_unreadable(const polymass_diagnostics* diag, uint64_t face_count) {
    assert_int_equal(diag->face_count, face_count);
    assert_int_equal(diag->checks, 0);
    assert_int_equal(diag->shell_count, 0);
    assert_int_equal(diag->edge_count, 0);
    assert_true(isnan(diag->signed_volume));
}

static void test_non_finite_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    m.positions[3 * 5 + 1] = NAN;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_finite_vertices, 1);
    assert_int_equal(diag.first_non_finite_vertices[0], 5);
    expect_unreadable(&diag, 6);
    pm_mesh_free(&m);
    /* Two bad vertices: both counted, the first reported. */
    pm_mesh_unit_cube(&m, 1);
    m.positions[3 * 6] = NAN;
    m.positions[3 * 2 + 1] = INFINITY;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_finite_vertices, 2);
    assert_int_equal(diag.first_non_finite_vertices[0], 2);
    pm_mesh_free(&m);

    /* An unused NaN vertex is fine. */
    pm_mesh_unit_cube(&m, 0);
    pm_mesh_add_vertex(&m, NAN, INFINITY, -INFINITY);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_REL("volume with an unused NaN vertex", 1.0, p.volume, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_finite_vertices, 0);
    assert_true(diag.first_non_finite_vertices[0] == POLYMASS_NONE);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_index_out_of_range_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    pm_mesh m;
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    m.indices[pm_mesh_face_offset(&m, 3) + 2] = 8; /* vertex_count is 8 */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.out_of_range_indices, 1);
    assert_int_equal(diag.first_out_of_range_faces[0], 3);
    expect_unreadable(&diag, 6);
    /* two bad faces: both counted, the first reported */
    m.indices[pm_mesh_face_offset(&m, 5)] = 1000;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INDEX_OUT_OF_RANGE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.out_of_range_indices, 2);
    assert_int_equal(diag.first_out_of_range_faces[0], 3);
    assert_int_equal(diag.first_out_of_range_faces[1], 5);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_face_too_small_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    case_input in;
    (void)state;
    memset(&in, 0, sizeof in);
    faces_too_small(&in, 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_FACE_TOO_SMALL, pm_diagnose(&diag, ctx, &in.desc, NULL));
    assert_int_equal(diag.small_faces, 2);
    assert_int_equal(diag.first_small_faces[0], 4);
    assert_int_equal(diag.first_small_faces[1], 5);
    assert_true(diag.first_small_faces[2] == POLYMASS_NONE);
    expect_unreadable(&diag, 7);
    pm_mesh_free(&in.mesh);
    polymass_context_destroy(ctx);
}

/* Each finding lists its first POLYMASS_DIAGNOSTIC_LOCATIONS locations:
   the lowest face or vertex indices, the edges with the lowest vertex pairs,
   ascending; POLYMASS_NONE after them. */
static void test_report_lists_the_first_locations(void** state) {
    enum { N = 4, SIDE = N + 1 }; /* a flat N x N grid of squares, two triangles each */
    static const uint32_t nan_vertices[] = {24, 3, 22, 5, 20, 18, 12, 21, 7, 9}; /* any order */
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    pm_mesh grid;
    uint32_t i, j, k;
    (void)state;
    pm_mesh_init(&grid);
    for (i = 0; i < SIDE; ++i) {
        for (j = 0; j < SIDE; ++j) {
            pm_mesh_add_vertex(&grid, j, i, 0);
        }
    }
    for (i = 0; i < N; ++i) {
        for (j = 0; j < N; ++j) {
            const uint32_t a = i * SIDE + j;
            pm_mesh_add_tri(&grid, a, a + 1, a + SIDE + 1);
            pm_mesh_add_tri(&grid, a, a + SIDE + 1, a + SIDE);
        }
    }
    /* The rim: 4 N open edges; the lowest pairs are on the row y = 0 and the
       column x = 0: (0,1) (0,5) (1,2) (2,3) (3,4) (4,9) (5,10) (9,14). */
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, pm_check(&diag, ctx, &grid));
    assert_int_equal(diag.open_edges, 4 * N);
    {
        static const uint64_t lowest[8][2] = {{0, 1}, {0, 5}, {1, 2},  {2, 3},
                                              {3, 4}, {4, 9}, {5, 10}, {9, 14}};
        for (k = 0; k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
            const uint64_t* e = diag.first_open_edges[k];
            assert_true((e[0] == lowest[k][0] && e[1] == lowest[k][1]) ||
                        (e[0] == lowest[k][1] && e[1] == lowest[k][0]));
        }
    }
    /* Ten NaN vertices: the eight lowest, sorted. */
    for (k = 0; k < sizeof nan_vertices / sizeof nan_vertices[0]; ++k) {
        grid.positions[3 * nan_vertices[k] + 2] = NAN;
    }
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &grid));
    assert_int_equal(diag.non_finite_vertices, 10);
    {
        static const uint64_t lowest[8] = {3, 5, 7, 9, 12, 18, 20, 21};
        for (k = 0; k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
            assert_int_equal(diag.first_non_finite_vertices[k], lowest[k]);
        }
    }
    /* Fewer findings than places: POLYMASS_NONE after them. */
    for (k = 0; k < 8; ++k) {
        grid.positions[3 * nan_vertices[k] + 2] = 0.0;
    }
    pm_diagnostics_init(&diag);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_FINITE, pm_check(&diag, ctx, &grid));
    assert_int_equal(diag.non_finite_vertices, 2);
    assert_int_equal(diag.first_non_finite_vertices[0], 7);
    assert_int_equal(diag.first_non_finite_vertices[1], 9);
    for (k = 2; k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
        assert_true(diag.first_non_finite_vertices[k] == POLYMASS_NONE);
    }
    pm_mesh_free(&grid);
    polymass_context_destroy(ctx);
}

static void test_open_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    case_input in;
    (void)state;
    expect_defect_on_each_cube_face(pm_mesh_remove_face, POLYMASS_ERROR_OPEN, OPEN_EDGE, 4, 5);
    memset(&in, 0, sizeof in);
    one_triangle(&in, 0);
    EXPECT_EDGE_DEFECT(ctx, &in.mesh, POLYMASS_ERROR_OPEN, OPEN_EDGE, 3, &diag);
    pm_mesh_free(&in.mesh);
    polymass_context_destroy(ctx);
}

static void test_non_manifold_findings(void** state) {
    static const double lo2[3] = {1, 1, 0}, hi2[3] = {2, 2, 1};
    const uint32_t accept = POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
    const uint32_t weld_flag = POLYMASS_OPTION_WELD_VERTICES;
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    const pm_expected a = pm_expected_box(unit_lo, unit_hi), b = pm_expected_box(lo2, hi2);
    pm_expected both = pm_expected_sum(&a, &b);
    (void)state;
    both.size = 3.0; /* [0, 2] x [0, 2] x [0, 1] */
    make_two_cubes_sharing_an_edge(&m, 1);
    EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_NON_MANIFOLD, NON_MANIFOLD_EDGE, 1, &diag);
    /* the shared edge joins vertices 3 (1, 1, 0) and 7 (1, 1, 1) */
    PM_ASSERT_EDGE_MENTIONED(ctx, 3, 7);
    assert_true(is_edge(diag.first_non_manifold_edges[0], 3, 7));
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.used_vertex_count, 14);

    /* balanced: accepted with the option, and the solid is the two cubes */
    PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, accept, NULL));
    assert_int_equal(p.warnings, POLYMASS_WARNING_NON_MANIFOLD);
    PM_ASSERT_PROPERTIES("two cubes sharing an edge", &both, &p, PM_TOL);
    pm_mesh_free(&m);

    /* the same made of separate vertices, joined by welding */
    make_two_cubes_sharing_an_edge(&m, 0);
    PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, weld_flag | accept, NULL));
    assert_true(p.warnings & POLYMASS_WARNING_NON_MANIFOLD);
    PM_ASSERT_PROPERTIES("two welded cubes sharing an edge", &both, &p, PM_TOL);
    /* unwelded they are two separate closed shells touching along the edge:
       fine, with a warning */
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, POLYMASS_WARNING_TOUCHING_FACES);
    PM_ASSERT_PROPERTIES("two cubes touching at an edge", &both, &p, PM_TOL);
    pm_mesh_free(&m);

    /* unbalanced: a tetrahedron with one face listed twice */
    {
        case_input in;
        memset(&in, 0, sizeof in);
        face_listed_twice(&in, 0);
        EXPECT_EDGE_DEFECT(ctx, &in.mesh, POLYMASS_ERROR_NON_MANIFOLD, NON_MANIFOLD_EDGE, 3, &diag);
        pm_mesh_free(&in.mesh);
    }
    polymass_context_destroy(ctx);
}

static void test_inconsistent_orientation_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    case_input in;
    (void)state;
    expect_defect_on_each_cube_face(pm_mesh_reverse_face, POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                                    MISORIENTED_EDGE, 4, 6);
    memset(&in, 0, sizeof in);
    torus_with_a_triangle_reversed(&in, 0);
    EXPECT_EDGE_DEFECT(ctx, &in.mesh, POLYMASS_ERROR_INCONSISTENT_ORIENTATION, MISORIENTED_EDGE, 3,
                       &diag);
    pm_mesh_free(&in.mesh);
    polymass_context_destroy(ctx);
}

static void test_non_planar_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    make_lifted_cube(&m, 1e-3);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_NON_PLANAR_FACE, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_planar_faces, 1);
    assert_int_equal(diag.first_non_planar_faces[0], 1);
    assert_true(diag.max_non_planarity > 1e-5 && diag.max_non_planarity < 1e-2);
    assert_int_equal(diag.open_edges + diag.misoriented_edges + diag.non_manifold_edges, 0);
    /* a looser tolerance accepts it, to its size */
    {
        const polymass_options loose = pm_options(0, 1e-2);
        const polymass_mesh_desc d = pm_mesh_desc(&m);
        pm_props_init(&p);
        PM_ASSERT_OK(ctx, polymass_mass_properties_compute(&p, NULL, ctx, &d, &loose, NULL));
        PM_ASSERT_CLOSE("volume of the slightly bent cube", 1.0, p.volume, 1e-3, 0.0);
    }
    /* skipping the checks accepts it too, and says so */
    PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS, NULL));
    assert_true(p.warnings & POLYMASS_WARNING_UNCHECKED);
    pm_mesh_free(&m);

    /* 1e-9 relative is well within the default 1e-6 */
    make_lifted_cube(&m, 1e-9);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    PM_ASSERT_CLOSE("volume of the cube bent by 1e-9", 1.0, p.volume, 1e-8, 0.0);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.non_planar_faces, 0);
    assert_true(diag.max_non_planarity > 0 && diag.max_non_planarity < 1e-6);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Every reference solid turned inside out: refused, its signed volume the
   negated volume; accepted, the solid turned the right way. */
static void test_inverted_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    int k;
    (void)state;
    for (k = 0; k < PM_REF_COUNT; ++k) {
        const pm_reference_solid* ref = &pm_reference_solids[k];
        const pm_expected e = pm_expected_from_reference(ref);
        pm_mesh m;
        pm_mesh_from_reference(&m, ref);
        pm_mesh_reverse_all(&m);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVERTED, pm_check(&diag, ctx, &m));
        PM_ASSERT_REL("signed volume of the inverted solid", -ref->volume, diag.signed_volume,
                      PM_TOL);
        PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, POLYMASS_OPTION_ACCEPT_INVERTED, NULL));
        assert_int_equal(
            p.warnings,
            POLYMASS_WARNING_INVERTED |
                (pm_reference_touches_itself(ref) ? POLYMASS_WARNING_TOUCHING_FACES : 0));
        PM_ASSERT_PROPERTIES(ref->name, &e, &p, PM_TOL);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* The cavity across two boxes resting on each other (the table's case):
   its volume is subtracted, the touching faces are warned of, and no shell
   is called inside out. */
static void test_cavity_across_two_solids(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    case_input in;
    (void)state;
    memset(&in, 0, sizeof in);
    cavity_across_two_boxes(&in, 0);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &in.mesh, NULL));
    PM_ASSERT_REL("volume of two unit cubes less the octahedron", 2.0 - 1.0 / 24.0, p.volume,
                  PM_TOL);
    assert_int_equal(p.warnings, POLYMASS_WARNING_TOUCHING_FACES);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &in.mesh));
    assert_int_equal(diag.shell_count, 3);
    assert_int_equal(diag.inverted_shells, 0);
    pm_mesh_free(&in.mesh);
    polymass_context_destroy(ctx);
}

static void test_zero_volume_findings(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    make_flat_square(&m);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_ZERO_VOLUME, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.open_edges + diag.non_manifold_edges + diag.misoriented_edges, 0);
    PM_ASSERT_ABS("signed volume", 0.0, diag.signed_volume, 1e-15);
    pm_mesh_free(&m);
    /* nothing at all: a vertex and no face */
    pm_mesh_init(&m);
    pm_mesh_add_vertex(&m, 0, 0, 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, pm_compute(&p, ctx, &m, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Skip, degenerate faces, welding                                          */
/* ------------------------------------------------------------------------ */

static void test_skip_topology_checks(void** state) {
    const pm_expected e = pm_expected_box(unit_lo, unit_hi);
    const uint32_t skip = POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    /* topologically open (nothing shared), geometrically the closed cube */
    make_cube_soup(&m);
    PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, skip, NULL));
    assert_int_equal(p.warnings,
                     POLYMASS_WARNING_UNCHECKED | POLYMASS_WARNING_INTERSECTIONS_UNCHECKED);
    PM_ASSERT_PROPERTIES("unchecked soup cube", &e, &p, PM_TOL);
    /* the mesh of a trusting caller: nothing checked, its verdict OK, its
       shells (one per triangle) listed unjudged */
    PM_ASSERT_OK(ctx, pm_check_flags(&diag, ctx, &m, skip));
    assert_int_equal(diag.checks, 0);
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.edge_count, 0);
    assert_int_equal(diag.shell_count, 12);
    PM_ASSERT_REL("signed_volume", 1.0, diag.signed_volume, PM_TOL);
    /* the same checked: every edge open */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.checks, POLYMASS_CHECKED_TOPOLOGY | POLYMASS_CHECKED_INTERSECTIONS);
    assert_int_equal(diag.open_edges, 36);
    assert_int_equal(diag.edge_count, 36);
    assert_int_equal(diag.used_vertex_count, 36);
    pm_mesh_free(&m);

    /* a valid solid through the unchecked path: same numbers, flagged */
    {
        const pm_reference_solid* ref = &pm_reference_solids[PM_REF_SQUARE_RING];
        const pm_expected r = pm_expected_from_reference(ref);
        pm_mesh_from_reference(&m, ref);
        PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, skip, NULL));
        assert_true(p.warnings & POLYMASS_WARNING_UNCHECKED);
        PM_ASSERT_PROPERTIES(ref->name, &r, &p, PM_TOL);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* Faces whose area squared underflows are tiny, not degenerate: a shell of
   size 1e-150 beside one of size 2 has faces of area ~1e-300, whose square is
   0 in double. (A SIMD area test once reported such triangles as degenerate,
   and the polygon path such quads.) The tiny shell sits at the integration's
   reference point, the centre of the bounding box: anywhere else its
   coordinates would round to one point when moved into that frame. */
static void test_tiny_faces_are_not_degenerate(void** state) {
    const double s = 1e-150;
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    /* a regular tetrahedron of volume 8/3 */
    pm_mesh_add_vertex(&m, 1, 1, 1);
    pm_mesh_add_vertex(&m, 1, -1, -1);
    pm_mesh_add_vertex(&m, -1, 1, -1);
    pm_mesh_add_vertex(&m, -1, -1, 1);
    pm_mesh_add_tri(&m, 0, 1, 2);
    pm_mesh_add_tri(&m, 0, 2, 3);
    pm_mesh_add_tri(&m, 0, 3, 1);
    pm_mesh_add_tri(&m, 2, 1, 3);
    /* and a corner tetrahedron of edge 1e-150 at the origin */
    pm_mesh_add_vertex(&m, 0, 0, 0);
    pm_mesh_add_vertex(&m, s, 0, 0);
    pm_mesh_add_vertex(&m, 0, s, 0);
    pm_mesh_add_vertex(&m, 0, 0, s);
    pm_mesh_add_tri(&m, 4, 6, 5);
    pm_mesh_add_tri(&m, 4, 5, 7);
    pm_mesh_add_tri(&m, 4, 7, 6);
    pm_mesh_add_tri(&m, 5, 6, 7);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_int_equal(p.warnings, 0);
    PM_ASSERT_REL("volume", 8.0 / 3.0, p.volume, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.degenerate_faces, 0);
    pm_mesh_free(&m);

    /* the same with quads: a cube [-1, 1]^3 and one [0, 1e-150]^3 */
    {
        static const double big_lo[3] = {-1, -1, -1}, big_hi[3] = {1, 1, 1};
        static const double tiny_lo[3] = {0, 0, 0};
        const double tiny_hi[3] = {s, s, s};
        pm_mesh_box(&m, big_lo, big_hi, 0);
        pm_mesh_add_box(&m, tiny_lo, tiny_hi, 0);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_int_equal(p.warnings, 0);
        PM_ASSERT_REL("volume", 8.0, p.volume, PM_TOL);
        PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
        assert_int_equal(diag.degenerate_faces, 0);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* The other arguments                                                      */
/* ------------------------------------------------------------------------ */

static void test_null_pointers(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    polymass_mesh_desc d;
    polymass_mass_properties p;
    polymass_diagnostics diag;
    polymass_polygon_properties pp;
    polymass_mesh* mesh = NULL;
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);
    pm_props_init(&p);
    pm_diagnostics_init(&diag);
    pm_polygon_props_init(&pp);

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_create(NULL, ctx, &d, NULL));
    mesh = (polymass_mesh*)&mesh; /* garbage: must become NULL */
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_create(&mesh, NULL, &d, NULL));
    assert_null(mesh);
    mesh = (polymass_mesh*)&mesh;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_create(&mesh, ctx, NULL, NULL));
    assert_null(mesh);
    assert_true(strlen(polymass_context_message(ctx)) > 0);

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(NULL, NULL, ctx, &d, NULL, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, NULL, &d, NULL, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, NULL, NULL, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);

    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_diagnostics(NULL, ctx, mesh));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_diagnostics(&diag, NULL, mesh));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_diagnostics(&diag, ctx, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_provenance(NULL, ctx, mesh));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT, polymass_mesh_moments(NULL, ctx, mesh));
    assert_int_equal(polymass_mesh_status(NULL), POLYMASS_ERROR_INVALID_ARGUMENT);
    assert_true(strlen(polymass_mesh_message(NULL)) > 0);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(NULL, ctx, mesh, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, NULL, mesh, NULL));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, NULL, NULL));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    polymass_mesh_destroy(mesh);
    mesh = NULL;

    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(NULL, ctx, square, 4, 0));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, NULL, square, 4, 0));
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, ctx, NULL, 4, 0));

    /* A later success clears the message. */
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    assert_string_equal(polymass_context_message(ctx), "");

    /* Destroy functions accept NULL. */
    polymass_mesh_destroy(NULL);
    polymass_context_destroy(NULL);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_struct_sizes_checked(void** state) {
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    polymass_mesh_desc d;
    polymass_mass_properties p;
    polymass_diagnostics diag;
    polymass_mass_desc md = pm_mass_density(1.0);
    polymass_polygon_properties pp;
    polymass_mesh* mesh = NULL;
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    (void)state;
    pm_mesh_unit_cube(&m, 0);
    d = pm_mesh_desc(&m);

    pm_props_init(&p);
    p.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));
    p.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, NULL));

    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d, NULL));
    pm_diagnostics_init(&diag);
    diag.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_diagnostics(&diag, ctx, mesh));
    diag.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_diagnostics(&diag, ctx, mesh));
    pm_props_init(&p);
    md.struct_size = 0;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    md.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    polymass_mesh_destroy(mesh);

    memset(&pp, 0, sizeof pp);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, ctx, square, 4, 0));
    pp.struct_size = 0x7FFFFFFFu;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_polygon_compute(&pp, ctx, square, 4, 0));
    assert_true(strlen(polymass_context_message(ctx)) > 0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_invalid_mass_desc(void** state) {
    const pm_reference_solid* ref = &pm_reference_solids[PM_REF_BOX];
    const polymass_mesh_desc d = pm_reference_desc(ref);
    static const double bad_values[] = {0.0, -0.0, -1.0, NAN, INFINITY, -INFINITY};
    polymass_context* ctx = pm_context_new();
    polymass_mesh* mesh = NULL;
    polymass_mass_properties p;
    polymass_mass_desc md;
    size_t k;
    (void)state;
    PM_ASSERT_OK(ctx, polymass_mesh_create(&mesh, ctx, &d, NULL));
    for (k = 0; k < sizeof bad_values / sizeof bad_values[0]; ++k) {
        md = pm_mass_density(bad_values[k]);
        pm_props_init(&p);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mesh_mass_properties(&p, ctx, mesh, &md));
        assert_true(strlen(polymass_context_message(ctx)) > 0);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, &md));
        md = pm_mass_total(bad_values[k]);
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mesh_mass_properties(&p, ctx, mesh, &md));
        PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                         polymass_mass_properties_compute(&p, NULL, ctx, &d, NULL, &md));
    }
    md = pm_mass_density(1.0);
    md.mass_mode = 2;
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INVALID_ARGUMENT,
                     polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    /* The field the mode does not read is not checked. */
    md = pm_mass_density(2.0);
    md.mass = NAN;
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    PM_ASSERT_REL("mass = density * volume", 2.0 * ref->volume, p.mass, PM_TOL);
    md = pm_mass_total(3.0);
    md.density = -INFINITY;
    PM_ASSERT_OK(ctx, polymass_mesh_mass_properties(&p, ctx, mesh, &md));
    PM_ASSERT_REL("mass as given", 3.0, p.mass, PM_TOL);
    polymass_mesh_destroy(mesh);
    polymass_context_destroy(ctx);
}

static void test_degenerate_faces(void** state) {
    const pm_expected e = pm_expected_box(unit_lo, unit_hi);
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    make_t_junction_cube(&m);
    PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
    /* The slivers lie along the faces they close without sharing all their
       vertices: touching, for the intersection check. */
    assert_int_equal(p.warnings,
                     POLYMASS_WARNING_DEGENERATE_FACES | POLYMASS_WARNING_TOUCHING_FACES);
    PM_ASSERT_PROPERTIES("cube with T-junctions closed by slivers", &e, &p, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.degenerate_faces, 2);
    assert_int_equal(diag.first_degenerate_faces[0], 7);
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.used_vertex_count, 10);
    pm_mesh_free(&m);

    /* the same translated far away: still exactly degenerate, still exact */
    {
        static const double t[3] = {1e8, 1e8, 1e8};
        const pm_expected et = pm_expected_transform(&e, NULL, 1.0, t);
        make_t_junction_cube(&m);
        pm_mesh_transform(&m, NULL, 1.0, t);
        PM_ASSERT_OK(ctx, pm_compute(&p, ctx, &m, NULL));
        assert_true(p.warnings & POLYMASS_WARNING_DEGENERATE_FACES);
        PM_ASSERT_PROPERTIES("T-junction cube at 1e8", &et, &p, PM_TOL);
        pm_mesh_free(&m);
    }
    /* the slivers removed: open */
    make_t_junction_cube(&m);
    pm_mesh_remove_face(&m, 8);
    pm_mesh_remove_face(&m, 7);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.open_edges, 6); /* (0, 1), (0, 8), (8, 1) at the bottom, at the top */
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

static void test_welding(void** state) {
    const pm_expected e = pm_expected_box(unit_lo, unit_hi);
    const uint32_t weld_flag = POLYMASS_OPTION_WELD_VERTICES;
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    polymass_mass_properties p;
    pm_mesh m;
    (void)state;
    make_cube_soup(&m);
    EXPECT_EDGE_DEFECT(ctx, &m, POLYMASS_ERROR_OPEN, OPEN_EDGE, 36, &diag);

    PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, weld_flag, NULL));
    assert_int_equal(p.warnings, 0);
    PM_ASSERT_PROPERTIES("welded soup cube", &e, &p, PM_TOL);
    PM_ASSERT_OK(ctx, pm_check_flags(&diag, ctx, &m, weld_flag));
    assert_int_equal(diag.used_vertex_count, 8);
    assert_int_equal(diag.edge_count, 18);
    assert_int_equal(diag.open_edges, 0);
    assert_int_equal(diag.face_count, 12);

    /* welded vertex numbers are the lowest index at the position: flip a
       triangle and the misoriented edge is named by such indices */
    pm_mesh_reverse_face(&m, 4);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                     pm_check_flags(&diag, ctx, &m, weld_flag));
    {
        size_t i, k;
        for (k = 0; k < 2; ++k) {
            const uint64_t v = diag.first_misoriented_edges[0][k];
            assert_true(v < m.vertex_count);
            for (i = 0; i < v; ++i) { /* no lower index at the same position */
                assert_true(memcmp(m.positions + 3 * i, m.positions + 3 * v, 3 * sizeof(double)) !=
                            0);
            }
        }
    }
    pm_mesh_free(&m);

    /* a soup of the reference torus welds into the torus */
    {
        const pm_reference_solid* ref = &pm_reference_solids[PM_REF_TORUS_TRIS];
        const pm_expected t = pm_expected_from_reference(ref);
        pm_mesh_from_reference(&m, ref);
        pm_mesh_to_soup(&m);
        PM_ASSERT_OK(ctx, pm_compute_flags(&p, ctx, &m, weld_flag, NULL));
        PM_ASSERT_PROPERTIES("welded torus soup", &t, &p, PM_TOL);
        PM_ASSERT_OK(ctx, pm_check_flags(&diag, ctx, &m, weld_flag));
        assert_int_equal(diag.used_vertex_count, ref->vertex_count);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* The mesh of a refused surface answers what is wrong: its status and
   message, its diagnostics, its shells (connected pieces, unjudged), the
   shell of each face; its provenance, moments and mass properties are
   refused with its status. */
static void test_mesh_of_a_refused_surface(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_mesh* mesh = NULL;
    polymass_diagnostics diag;
    polymass_shell shells[2];
    polymass_provenance provenance;
    polymass_moments moments;
    polymass_mass_properties p;
    uint32_t shell_of_face[5];
    uint64_t count = 0;
    case_input in;
    (void)state;
    memset(&in, 0, sizeof in);
    cube_without_a_face(&in, 2);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, polymass_mesh_create(&mesh, ctx, &in.desc, NULL));
    assert_non_null(mesh);
    assert_int_equal(polymass_mesh_status(mesh), POLYMASS_ERROR_OPEN);
    assert_non_null(strstr(polymass_mesh_message(mesh), "used by one face only"));
    pm_diagnostics_init(&diag);
    PM_ASSERT_OK(ctx, polymass_mesh_diagnostics(&diag, ctx, mesh));
    assert_int_equal(diag.status, POLYMASS_ERROR_OPEN);
    assert_int_equal(diag.open_edges, 4);
    assert_int_equal(diag.shell_count, 1);
    assert_int_equal(polymass_shell_init(&shells[0], sizeof shells[0]), POLYMASS_OK);
    assert_int_equal(polymass_shell_init(&shells[1], sizeof shells[1]), POLYMASS_OK);
    PM_ASSERT_OK(ctx, polymass_mesh_shells(shells, 2, &count, ctx, mesh));
    assert_int_equal(count, 1);
    assert_int_equal(shells[0].kind, POLYMASS_SHELL_UNJUDGED);
    assert_int_equal(shells[0].face_count, 5);
    assert_int_equal(shells[0].first_face, 0);
    assert_true(isnan(shells[0].signed_volume));
    assert_int_equal(shells[1].face_count, 0); /* past the count: not written */
    PM_ASSERT_OK(ctx, polymass_mesh_shell_of_face(shell_of_face, 5, ctx, mesh));
    assert_int_equal(shell_of_face[4], 0);
    assert_int_equal(polymass_provenance_init(&provenance, sizeof provenance), POLYMASS_OK);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, polymass_mesh_provenance(&provenance, ctx, mesh));
    assert_int_equal(provenance.mode, POLYMASS_MODE_NONE); /* not written */
    assert_non_null(strstr(polymass_context_message(ctx), "used by one face only"));
    assert_int_equal(polymass_moments_init(&moments, sizeof moments), POLYMASS_OK);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, polymass_mesh_moments(&moments, ctx, mesh));
    pm_props_init(&p);
    PM_ASSERT_STATUS(ctx, POLYMASS_ERROR_OPEN, polymass_mesh_mass_properties(&p, ctx, mesh, NULL));
    assert_true(p.volume == 0.0); /* not written */
    polymass_mesh_destroy(mesh);
    pm_mesh_free(&in.mesh);
    polymass_context_destroy(ctx);
}

/* ------------------------------------------------------------------------ */
/* Every check to its end                                                   */
/* ------------------------------------------------------------------------ */

static void test_check_reports_everything(void** state) {
    polymass_context* ctx = pm_context_new();
    polymass_diagnostics diag;
    pm_mesh m;
    (void)state;
    /* A clean cube: counts, NONE locations, signed volume */
    pm_mesh_unit_cube(&m, 0);
    PM_ASSERT_OK(ctx, pm_check(&diag, ctx, &m));
    assert_int_equal(diag.status, POLYMASS_OK);
    assert_int_equal(diag.checks, POLYMASS_CHECKED_TOPOLOGY | POLYMASS_CHECKED_SHELLS |
                                      POLYMASS_CHECKED_INTERSECTIONS);
    assert_int_equal(diag.shell_count, 1);
    assert_string_equal(polymass_context_message(ctx), "");
    assert_int_equal(diag.face_count, 6);
    assert_int_equal(diag.used_vertex_count, 8);
    assert_int_equal(diag.edge_count, 12);
    assert_int_equal(diag.non_finite_vertices, 0);
    assert_true(diag.first_non_finite_vertices[0] == POLYMASS_NONE);
    assert_int_equal(diag.out_of_range_indices, 0);
    assert_true(diag.first_out_of_range_faces[0] == POLYMASS_NONE);
    assert_int_equal(diag.small_faces, 0);
    assert_true(diag.first_small_faces[0] == POLYMASS_NONE);
    assert_int_equal(diag.degenerate_faces, 0);
    assert_true(diag.first_degenerate_faces[0] == POLYMASS_NONE);
    assert_int_equal(diag.open_edges, 0);
    assert_true(diag.first_open_edges[0][0] == POLYMASS_NONE &&
                diag.first_open_edges[0][1] == POLYMASS_NONE);
    assert_int_equal(diag.non_manifold_edges, 0);
    assert_true(diag.first_non_manifold_edges[0][0] == POLYMASS_NONE &&
                diag.first_non_manifold_edges[0][1] == POLYMASS_NONE);
    assert_int_equal(diag.misoriented_edges, 0);
    assert_true(diag.first_misoriented_edges[0][0] == POLYMASS_NONE &&
                diag.first_misoriented_edges[0][1] == POLYMASS_NONE);
    assert_int_equal(diag.non_planar_faces, 0);
    assert_true(diag.first_non_planar_faces[0] == POLYMASS_NONE);
    assert_true(diag.max_non_planarity >= 0 && diag.max_non_planarity < 1e-15);
    PM_ASSERT_REL("signed_volume", 1.0, diag.signed_volume, PM_TOL);
    pm_mesh_free(&m);

    /* Several problems at once: a missing face (open), a flipped face and a
       bent face: every one counted, without stopping at the first. */
    make_lifted_cube(&m, 1e-2);  /* bends face 1 */
    pm_mesh_remove_face(&m, 5);  /* opens the x = 1 side */
    pm_mesh_reverse_face(&m, 4); /* flips x = 0 */
    pm_check(&diag, ctx, &m);
    assert_int_not_equal(diag.status, POLYMASS_OK);
    assert_int_equal(diag.non_planar_faces, 1);
    assert_int_equal(diag.first_non_planar_faces[0], 1);
    assert_true(diag.open_edges >= 4);
    assert_true(diag.misoriented_edges >= 1);
    pm_mesh_free(&m);

    /* an out-of-range index and a NaN: both counted */
    pm_mesh_unit_cube(&m, 0);
    m.indices[5] = 99;
    m.positions[3 * 3 + 1] = NAN;
    pm_check(&diag, ctx, &m);
    assert_true(diag.status == POLYMASS_ERROR_NON_FINITE ||
                diag.status == POLYMASS_ERROR_INDEX_OUT_OF_RANGE);
    assert_int_equal(diag.out_of_range_indices, 1);
    assert_int_equal(diag.first_out_of_range_faces[0], 1);
    assert_int_equal(diag.non_finite_vertices, 1);
    assert_int_equal(diag.first_non_finite_vertices[0], 3);
    assert_true(isnan(diag.signed_volume));
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* A test of the table: its name is the case's. */
static struct CMUnitTest case_test(const error_case* c) {
    struct CMUnitTest t;
    memset(&t, 0, sizeof t);
    t.name = c->description;
    t.test_func = test_case;
    t.initial_state = (void*)c;
    return t;
}

int main(void) {
    static const struct CMUnitTest findings[] = {
        cmocka_unit_test(test_null_pointers),
        cmocka_unit_test(test_struct_sizes_checked),
        cmocka_unit_test(test_invalid_mass_desc),
        cmocka_unit_test(test_non_finite_findings),
        cmocka_unit_test(test_index_out_of_range_findings),
        cmocka_unit_test(test_face_too_small_findings),
        cmocka_unit_test(test_report_lists_the_first_locations),
        cmocka_unit_test(test_open_findings),
        cmocka_unit_test(test_non_manifold_findings),
        cmocka_unit_test(test_inconsistent_orientation_findings),
        cmocka_unit_test(test_non_planar_findings),
        cmocka_unit_test(test_inverted_findings),
        cmocka_unit_test(test_cavity_across_two_solids),
        cmocka_unit_test(test_zero_volume_findings),
        cmocka_unit_test(test_skip_topology_checks),
        cmocka_unit_test(test_degenerate_faces),
        cmocka_unit_test(test_tiny_faces_are_not_degenerate),
        cmocka_unit_test(test_welding),
        cmocka_unit_test(test_mesh_of_a_refused_surface),
        cmocka_unit_test(test_check_reports_everything),
    };
    enum { FINDINGS = sizeof findings / sizeof findings[0] };
    struct CMUnitTest tests[CASE_COUNT + FINDINGS];
    size_t n = 0, k;
    for (k = 0; k < CASE_COUNT; ++k) tests[n++] = case_test(&cases[k]);
    for (k = 0; k < FINDINGS; ++k) tests[n++] = findings[k];
    return _cmocka_run_group_tests("errors", tests, n, NULL, NULL);
}
