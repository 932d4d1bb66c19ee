#include "test_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A public struct as a caller compiled with this header makes it: zeroed,
   struct_size set. */
#define PM_INIT_STRUCT(s) (memset(&(s), 0, sizeof(s)), (s).struct_size = sizeof(s))

/* ------------------------------------------------------------------------ */
/* Mesh builder                                                             */
/* ------------------------------------------------------------------------ */

static void* pm_grow(void* p, size_t* capacity, size_t needed, size_t element) {
    size_t cap = *capacity;
    if (needed <= cap) {
        return p;
    }
    while (cap < needed) {
        cap = cap ? cap * 2 : 16;
    }
    p = realloc(p, cap * element);
    if (p == NULL) {
        print_error("test_support: out of memory\n");
        abort();
    }
    *capacity = cap;
    return p;
}

void pm_mesh_init(pm_mesh* m) { memset(m, 0, sizeof *m); }

void pm_mesh_free(pm_mesh* m) {
    free(m->positions);
    free(m->indices);
    free(m->face_sizes);
    memset(m, 0, sizeof *m);
}

uint32_t pm_mesh_add_vertex(pm_mesh* m, double x, double y, double z) {
    m->positions =
        pm_grow(m->positions, &m->vertex_capacity, m->vertex_count + 1, 3 * sizeof(double));
    m->positions[3 * m->vertex_count + 0] = x;
    m->positions[3 * m->vertex_count + 1] = y;
    m->positions[3 * m->vertex_count + 2] = z;
    return (uint32_t)m->vertex_count++;
}

void pm_mesh_add_face(pm_mesh* m, size_t n, const uint32_t* indices) {
    m->indices = pm_grow(m->indices, &m->index_capacity, m->index_count + n, sizeof(uint32_t));
    memcpy(m->indices + m->index_count, indices, n * sizeof(uint32_t));
    m->index_count += n;
    m->face_sizes = pm_grow(m->face_sizes, &m->face_capacity, m->face_count + 1, sizeof(uint32_t));
    m->face_sizes[m->face_count++] = (uint32_t)n;
}

void pm_mesh_add_tri(pm_mesh* m, uint32_t a, uint32_t b, uint32_t c) {
    const uint32_t f[3] = {a, b, c};
    pm_mesh_add_face(m, 3, f);
}

void pm_mesh_add_quad(pm_mesh* m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const uint32_t f[4] = {a, b, c, d};
    pm_mesh_add_face(m, 4, f);
}

void pm_mesh_copy(pm_mesh* dst, const pm_mesh* src) {
    pm_mesh_init(dst);
    pm_mesh_append(dst, src);
}

void pm_mesh_append(pm_mesh* dst, const pm_mesh* src) {
    const uint32_t base = (uint32_t)dst->vertex_count;
    size_t v, f, offset = 0;
    for (v = 0; v < src->vertex_count; ++v) {
        pm_mesh_add_vertex(dst, src->positions[3 * v], src->positions[3 * v + 1],
                           src->positions[3 * v + 2]);
    }
    for (f = 0; f < src->face_count; ++f) {
        uint32_t face[64];
        size_t k, n = src->face_sizes[f];
        assert_true(n <= 64);
        for (k = 0; k < n; ++k) {
            face[k] = base + src->indices[offset + k];
        }
        pm_mesh_add_face(dst, n, face);
        offset += n;
    }
}

void pm_mesh_add_box(pm_mesh* m, const double lo[3], const double hi[3], int triangulate) {
    /* Vertex k: bit 0 -> x, bit 1 -> y, bit 2 -> z (same layout as the
       reference generator). */
    static const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const uint32_t base = (uint32_t)m->vertex_count;
    int k;
    for (k = 0; k < 8; ++k) {
        pm_mesh_add_vertex(m, (k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1],
                           (k & 4) ? hi[2] : lo[2]);
    }
    for (k = 0; k < 6; ++k) {
        const uint32_t a = base + quads[k][0], b = base + quads[k][1];
        const uint32_t c = base + quads[k][2], d = base + quads[k][3];
        if (!triangulate) {
            pm_mesh_add_quad(m, a, b, c, d);
        } else if (k % 2 == 0) {
            pm_mesh_add_tri(m, a, b, c);
            pm_mesh_add_tri(m, a, c, d);
        } else {
            pm_mesh_add_tri(m, b, c, d);
            pm_mesh_add_tri(m, b, d, a);
        }
    }
}

void pm_mesh_box(pm_mesh* m, const double lo[3], const double hi[3], int triangulate) {
    pm_mesh_init(m);
    pm_mesh_add_box(m, lo, hi, triangulate);
}

void pm_mesh_unit_cube(pm_mesh* m, int triangulate) {
    static const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    pm_mesh_box(m, lo, hi, triangulate);
}

void pm_mesh_add_prism(pm_mesh* m, const double* xy, size_t n, double z0, double z1) {
    const uint32_t base = (uint32_t)m->vertex_count;
    uint32_t cap[64];
    size_t k;
    assert_true(n >= 3 && n <= 64);
    for (k = 0; k < n; ++k) {
        pm_mesh_add_vertex(m, xy[2 * k], xy[2 * k + 1], z0);
    }
    for (k = 0; k < n; ++k) {
        pm_mesh_add_vertex(m, xy[2 * k], xy[2 * k + 1], z1);
    }
    for (k = 0; k < n; ++k) {
        cap[k] = base + (uint32_t)(n - 1 - k); /* bottom: reversed, normal -z */
    }
    pm_mesh_add_face(m, n, cap);
    for (k = 0; k < n; ++k) {
        cap[k] = base + (uint32_t)(n + k);
    }
    pm_mesh_add_face(m, n, cap);
    for (k = 0; k < n; ++k) {
        const uint32_t j = (uint32_t)((k + 1) % n);
        pm_mesh_add_quad(m, base + (uint32_t)k, base + j, base + (uint32_t)n + j,
                         base + (uint32_t)(n + k));
    }
}

void pm_mesh_add_torus(pm_mesh* m, uint32_t rings, uint32_t segments, double major, double minor,
                       const double centre[3]) {
    const double pi = 3.14159265358979323846;
    const uint32_t base = (uint32_t)m->vertex_count;
    uint32_t i, j;
    for (i = 0; i < rings; ++i) {
        for (j = 0; j < segments; ++j) {
            const double u = 2 * pi * i / rings, v = 2 * pi * j / segments;
            pm_mesh_add_vertex(m, centre[0] + (major + minor * cos(v)) * cos(u),
                               centre[1] + (major + minor * cos(v)) * sin(u),
                               centre[2] + minor * sin(v));
        }
    }
    for (i = 0; i < rings; ++i) {
        for (j = 0; j < segments; ++j) {
            const uint32_t a = base + i * segments + j;
            const uint32_t b = base + ((i + 1) % rings) * segments + j;
            const uint32_t c = base + ((i + 1) % rings) * segments + (j + 1) % segments;
            const uint32_t d = base + i * segments + (j + 1) % segments;
            pm_mesh_add_tri(m, a, b, c);
            pm_mesh_add_tri(m, a, c, d);
        }
    }
}

void pm_mesh_from_reference(pm_mesh* m, const pm_reference_solid* ref) {
    size_t v, f, offset = 0;
    pm_mesh_init(m);
    for (v = 0; v < ref->vertex_count; ++v) {
        pm_mesh_add_vertex(m, ref->positions[3 * v], ref->positions[3 * v + 1],
                           ref->positions[3 * v + 2]);
    }
    for (f = 0; f < ref->face_count; ++f) {
        const size_t n = ref->face_sizes ? ref->face_sizes[f] : 3;
        pm_mesh_add_face(m, n, ref->indices + offset);
        offset += n;
    }
    assert_int_equal(offset, ref->index_count);
}

size_t pm_mesh_face_offset(const pm_mesh* m, size_t face) {
    size_t f, offset = 0;
    assert_true(face < m->face_count);
    for (f = 0; f < face; ++f) {
        offset += m->face_sizes[f];
    }
    return offset;
}

void pm_mesh_reverse_face(pm_mesh* m, size_t face) {
    uint32_t* idx = m->indices + pm_mesh_face_offset(m, face);
    size_t i = 0, j = m->face_sizes[face] - 1;
    while (i < j) {
        const uint32_t t = idx[i];
        idx[i++] = idx[j];
        idx[j--] = t;
    }
}

void pm_mesh_reverse_all(pm_mesh* m) {
    size_t f;
    for (f = 0; f < m->face_count; ++f) {
        pm_mesh_reverse_face(m, f);
    }
}

void pm_mesh_remove_face(pm_mesh* m, size_t face) {
    const size_t offset = pm_mesh_face_offset(m, face);
    const size_t n = m->face_sizes[face];
    memmove(m->indices + offset, m->indices + offset + n,
            (m->index_count - offset - n) * sizeof(uint32_t));
    m->index_count -= n;
    memmove(m->face_sizes + face, m->face_sizes + face + 1,
            (m->face_count - face - 1) * sizeof(uint32_t));
    m->face_count -= 1;
}

void pm_mesh_triangulate_fan(pm_mesh* m) {
    pm_mesh out;
    size_t f, k, offset = 0;
    pm_mesh_init(&out);
    for (k = 0; k < m->vertex_count; ++k) {
        pm_mesh_add_vertex(&out, m->positions[3 * k], m->positions[3 * k + 1],
                           m->positions[3 * k + 2]);
    }
    for (f = 0; f < m->face_count; ++f) {
        const uint32_t* idx = m->indices + offset;
        for (k = 1; k + 1 < m->face_sizes[f]; ++k) {
            pm_mesh_add_tri(&out, idx[0], idx[k], idx[k + 1]);
        }
        offset += m->face_sizes[f];
    }
    pm_mesh_free(m);
    *m = out;
}

void pm_mesh_to_soup(pm_mesh* m) {
    pm_mesh out;
    size_t f, k, offset = 0;
    pm_mesh_init(&out);
    for (f = 0; f < m->face_count; ++f) {
        uint32_t face[64];
        assert_true(m->face_sizes[f] <= 64);
        for (k = 0; k < m->face_sizes[f]; ++k) {
            const double* p = m->positions + 3 * (size_t)m->indices[offset + k];
            face[k] = pm_mesh_add_vertex(&out, p[0], p[1], p[2]);
        }
        pm_mesh_add_face(&out, m->face_sizes[f], face);
        offset += m->face_sizes[f];
    }
    pm_mesh_free(m);
    *m = out;
}

void pm_mesh_transform(pm_mesh* m, const double rotation[9], double scale,
                       const double translation[3]) {
    size_t v;
    int i, j;
    for (v = 0; v < m->vertex_count; ++v) {
        double* p = m->positions + 3 * v;
        long double q[3];
        for (i = 0; i < 3; ++i) {
            long double s = 0;
            for (j = 0; j < 3; ++j) {
                const long double r = rotation ? rotation[3 * i + j] : (i == j);
                s += r * p[j];
            }
            q[i] = (long double)scale * s + (translation ? translation[i] : 0.0);
        }
        for (i = 0; i < 3; ++i) {
            p[i] = (double)q[i];
        }
    }
}

void pm_mesh_placed(pm_mesh* dst, const pm_mesh* src, const pm_placement* at) {
    pm_mesh_init(dst);
    pm_mesh_copy(dst, src);
    pm_mesh_transform(dst, NULL, at->scale, at->translation);
}

int pm_mesh_all_triangles(const pm_mesh* m) {
    size_t f;
    for (f = 0; f < m->face_count; ++f) {
        if (m->face_sizes[f] != 3) {
            return 0;
        }
    }
    return 1;
}

static double pm_bbox_diagonal(const double* positions, size_t count) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t v;
    int i;
    for (v = 0; v < count; ++v) {
        for (i = 0; i < 3; ++i) {
            lo[i] = fmin(lo[i], positions[3 * v + i]);
            hi[i] = fmax(hi[i], positions[3 * v + i]);
        }
    }
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

double pm_mesh_size(const pm_mesh* m) { return pm_bbox_diagonal(m->positions, m->vertex_count); }

/* Packed doubles and uint32 indices; face_sizes may be NULL (triangles). */
static polymass_mesh_desc pm_packed_desc(const double* positions, uint64_t vertex_count,
                                         const uint32_t* indices, uint64_t index_count,
                                         const uint32_t* face_sizes, uint64_t face_count) {
    polymass_mesh_desc d;
    PM_INIT_STRUCT(d);
    d.position_type = POLYMASS_POSITION_FLOAT64;
    d.positions = positions;
    d.vertex_count = vertex_count;
    d.position_stride = 0;
    d.index_type = POLYMASS_INDEX_UINT32;
    d.indices = indices;
    d.index_count = index_count;
    if (face_sizes) {
        d.face_sizes = face_sizes;
        d.face_count = face_count;
    }
    return d;
}

polymass_mesh_desc pm_mesh_desc_ex(const pm_mesh* m, int force_face_sizes) {
    const int give_sizes = force_face_sizes || !pm_mesh_all_triangles(m);
    return pm_packed_desc(m->positions, m->vertex_count, m->indices, m->index_count,
                          give_sizes ? m->face_sizes : NULL, m->face_count);
}

polymass_mesh_desc pm_mesh_desc(const pm_mesh* m) { return pm_mesh_desc_ex(m, 0); }

int pm_reference_touches_itself(const pm_reference_solid* ref) {
    return strcmp(ref->name, "ring_of_boxes") == 0 || strcmp(ref->name, "prism_star_fan") == 0;
}

uint32_t pm_reference_rounded_rotation_flags(const pm_reference_solid* ref) {
    return pm_reference_touches_itself(ref) ? POLYMASS_OPTION_SKIP_INTERSECTION_CHECK : 0;
}

polymass_mesh_desc pm_reference_desc(const pm_reference_solid* ref) {
    return pm_packed_desc(ref->positions, ref->vertex_count, ref->indices, ref->index_count,
                          ref->face_sizes, ref->face_count);
}

/* Writes x as a float or a double at dst, asserting it converts exactly. */
static void pm_store_coordinate(unsigned char* dst, uint32_t position_type, double x) {
    if (position_type == POLYMASS_POSITION_FLOAT32) {
        const float f = (float)x;
        assert_true((double)f == x || (isnan(f) && isnan(x)));
        memcpy(dst, &f, sizeof f);
    } else {
        memcpy(dst, &x, sizeof x);
    }
}

void pm_lay_out(pm_laid_out_mesh* out, const pm_mesh* m, const pm_layout* layout) {
    const size_t element =
        layout->position_type == POLYMASS_POSITION_FLOAT32 ? sizeof(float) : sizeof(double);
    const size_t record = layout->stride ? layout->stride : 3 * element;
    const size_t bytes = record * m->vertex_count + layout->misalign + 16;
    unsigned char* base;
    size_t v, k;
    int i;
    out->block = malloc(bytes);
    assert_non_null(out->block);
    memset(out->block, 0x7F, bytes); /* junk */
    base = out->block + layout->misalign;
    for (v = 0; v < m->vertex_count; ++v) {
        unsigned char* r = base + v * record;
        for (i = 0; i < 3; ++i) {
            pm_store_coordinate(r + (size_t)i * element, layout->position_type,
                                m->positions[3 * v + (size_t)i]);
        }
        /* a "normal" after the position, where the record has room */
        for (i = 3; i < 6 && record >= 6 * element; ++i) {
            const double not_a_position = layout->position_type == POLYMASS_POSITION_FLOAT32
                                              ? (double)(-1.0f / (float)i)
                                              : NAN;
            pm_store_coordinate(r + (size_t)i * element, layout->position_type, not_a_position);
        }
    }
    out->indices16 = NULL;
    out->desc = pm_mesh_desc(m);
    out->desc.position_type = layout->position_type;
    out->desc.positions = base;
    out->desc.position_stride = layout->stride;
    out->desc.index_type = layout->index_type;
    if (layout->index_type == POLYMASS_INDEX_UINT16) {
        out->indices16 = malloc(m->index_count * sizeof *out->indices16 + 1);
        assert_non_null(out->indices16);
        for (k = 0; k < m->index_count; ++k) {
            assert_true(m->indices[k] <= 0xFFFF);
            out->indices16[k] = (uint16_t)m->indices[k];
        }
        out->desc.indices = out->indices16;
    }
}

void pm_laid_out_free(pm_laid_out_mesh* out) {
    free(out->block);
    free(out->indices16);
    memset(out, 0, sizeof *out);
}

/* ------------------------------------------------------------------------ */
/* Expected values                                                          */
/* ------------------------------------------------------------------------ */

pm_expected pm_expected_from_reference(const pm_reference_solid* ref) {
    pm_expected e;
    e.volume = ref->volume;
    memcpy(e.center_of_mass, ref->center_of_mass, sizeof e.center_of_mass);
    memcpy(e.inertia, ref->inertia, sizeof e.inertia);
    memcpy(e.inertia_origin, ref->inertia_origin, sizeof e.inertia_origin);
    e.surface_area = ref->surface_area;
    e.size = pm_bbox_diagonal(ref->positions, ref->vertex_count);
    return e;
}

pm_expected pm_expected_box(const double lo[3], const double hi[3]) {
    static const double origin[3] = {0, 0, 0};
    const double a = hi[0] - lo[0], b = hi[1] - lo[1], c = hi[2] - lo[2];
    pm_expected e;
    int i;
    memset(&e, 0, sizeof e);
    e.volume = a * b * c;
    for (i = 0; i < 3; ++i) {
        e.center_of_mass[i] = 0.5 * (lo[i] + hi[i]);
    }
    e.inertia[0] = e.volume * (b * b + c * c) / 12;
    e.inertia[4] = e.volume * (a * a + c * c) / 12;
    e.inertia[8] = e.volume * (a * a + b * b) / 12;
    pm_parallel_axis(e.inertia_origin, e.inertia, e.volume, e.center_of_mass, origin);
    e.surface_area = 2 * (a * b + b * c + c * a);
    e.size = sqrt(a * a + b * b + c * c);
    return e;
}

void pm_parallel_axis(double out[9], const double inertia_com[9], double mass, const double com[3],
                      const double point[3]) {
    long double d[3];
    int i, j;
    for (i = 0; i < 3; ++i) {
        d[i] = (long double)com[i] - point[i];
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            /* The diagonal as the sum of the other two squares, not |d|^2 - d_i^2:
               far from the origin that difference cancels even in long double. */
            const long double term =
                i == j ? d[(i + 1) % 3] * d[(i + 1) % 3] + d[(i + 2) % 3] * d[(i + 2) % 3]
                       : -d[i] * d[j];
            out[3 * i + j] = (double)(inertia_com[3 * i + j] + (long double)mass * term);
        }
    }
}

pm_expected pm_expected_transform(const pm_expected* e, const double rotation[9], double scale,
                                  const double translation[3]) {
    static const double origin[3] = {0, 0, 0};
    pm_expected out;
    long double r[9], ri[9], s2;
    int i, j, k;
    for (i = 0; i < 9; ++i) {
        r[i] = rotation ? rotation[i] : (i % 4 == 0);
    }
    s2 = (long double)scale * scale;
    out.volume = (double)(e->volume * s2 * scale);
    for (i = 0; i < 3; ++i) {
        long double s = 0;
        for (j = 0; j < 3; ++j) {
            s += r[3 * i + j] * e->center_of_mass[j];
        }
        out.center_of_mass[i] = (double)(scale * s + (translation ? translation[i] : 0.0));
    }
    /* I' = s^5 R I R^T */
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            long double s = 0;
            for (k = 0; k < 3; ++k) {
                s += r[3 * i + k] * e->inertia[3 * k + j];
            }
            ri[3 * i + j] = s;
        }
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            long double s = 0;
            for (k = 0; k < 3; ++k) {
                s += ri[3 * i + k] * r[3 * j + k];
            }
            out.inertia[3 * i + j] = (double)(s * s2 * s2 * scale);
        }
    }
    pm_parallel_axis(out.inertia_origin, out.inertia, out.volume, out.center_of_mass, origin);
    out.surface_area = (double)(e->surface_area * s2);
    out.size = e->size * scale;
    return out;
}

pm_expected pm_expected_sum(const pm_expected* a, const pm_expected* b) {
    static const double origin[3] = {0, 0, 0};
    pm_expected e;
    double origin_sum[9];
    int i;
    e.volume = a->volume + b->volume;
    for (i = 0; i < 3; ++i) {
        e.center_of_mass[i] =
            (a->volume * a->center_of_mass[i] + b->volume * b->center_of_mass[i]) / e.volume;
    }
    for (i = 0; i < 9; ++i) {
        origin_sum[i] = a->inertia_origin[i] + b->inertia_origin[i];
        e.inertia_origin[i] = origin_sum[i];
    }
    /* I_C = I_O - m (|c|^2 Id - c c^T): the parallel-axis theorem backwards. */
    {
        double correction[9];
        static const double zero[9] = {0};
        pm_parallel_axis(correction, zero, e.volume, e.center_of_mass, origin);
        for (i = 0; i < 9; ++i) {
            e.inertia[i] = origin_sum[i] - correction[i];
        }
    }
    e.surface_area = a->surface_area + b->surface_area;
    e.size = a->size + b->size;
    return e;
}

/* ------------------------------------------------------------------------ */
/* Library calls                                                            */
/* ------------------------------------------------------------------------ */

const int32_t pm_all_statuses[] = {
    POLYMASS_OK,
    POLYMASS_ERROR_INVALID_ARGUMENT,
    POLYMASS_ERROR_OUT_OF_MEMORY,
    POLYMASS_ERROR_INTERNAL,
    POLYMASS_ERROR_NON_FINITE,
    POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
    POLYMASS_ERROR_FACE_TOO_SMALL,
    POLYMASS_ERROR_OPEN,
    POLYMASS_ERROR_NON_MANIFOLD,
    POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
    POLYMASS_ERROR_NON_PLANAR_FACE,
    POLYMASS_ERROR_INTERSECTING,
    POLYMASS_ERROR_INVERTED,
    POLYMASS_ERROR_ZERO_VOLUME,
    POLYMASS_ERROR_ZERO_AREA,
    POLYMASS_ERROR_OVERFLOW,
};
const size_t pm_status_count = sizeof pm_all_statuses / sizeof pm_all_statuses[0];

int pm_is_documented_status(int32_t status) {
    size_t i;
    for (i = 0; i < pm_status_count; ++i) {
        if (pm_all_statuses[i] == status) {
            return 1;
        }
    }
    return 0;
}

polymass_context* pm_context_new(void) {
    polymass_context* ctx = NULL;
    assert_int_equal(polymass_context_create(&ctx, NULL), POLYMASS_OK);
    assert_non_null(ctx);
    return ctx;
}

polymass_options pm_options(uint32_t flags, double planarity_tolerance) {
    polymass_options o;
    PM_INIT_STRUCT(o);
    o.flags = flags;
    o.planarity_tolerance = planarity_tolerance;
    return o;
}

void pm_props_init(polymass_mass_properties* p) { PM_INIT_STRUCT(*p); }

void pm_diagnostics_init(polymass_diagnostics* d) { PM_INIT_STRUCT(*d); }

void pm_polygon_props_init(polymass_polygon_properties* p) { PM_INIT_STRUCT(*p); }

/* The field the mode does not read stays 0. */
static polymass_mass_desc pm_mass_desc_of(uint32_t mode, double density, double mass) {
    polymass_mass_desc d;
    PM_INIT_STRUCT(d);
    d.mass_mode = mode;
    d.density = density;
    d.mass = mass;
    return d;
}

polymass_mass_desc pm_mass_density(double density) {
    return pm_mass_desc_of(POLYMASS_MASS_FROM_DENSITY, density, 0.0);
}

polymass_mass_desc pm_mass_total(double mass) {
    return pm_mass_desc_of(POLYMASS_MASS_FROM_TOTAL, 0.0, mass);
}

int32_t pm_compute(polymass_mass_properties* out, polymass_context* ctx, const pm_mesh* m,
                   const polymass_mass_desc* mass) {
    return pm_compute_flags(out, ctx, m, 0, mass);
}

int32_t pm_compute_flags(polymass_mass_properties* out, polymass_context* ctx, const pm_mesh* m,
                         uint32_t flags, const polymass_mass_desc* mass) {
    const polymass_mesh_desc d = pm_mesh_desc(m);
    const polymass_options o = pm_options(flags, 0.0);
    pm_props_init(out);
    return polymass_mass_properties_compute(out, NULL, ctx, &d, &o, mass);
}

int32_t pm_diagnose(polymass_diagnostics* out, polymass_context* ctx,
                    const polymass_mesh_desc* desc, const polymass_options* options) {
    polymass_mesh* mesh = NULL;
    const int32_t status = polymass_mesh_create(&mesh, ctx, desc, options);
    char message[512];
    pm_diagnostics_init(out);
    if (mesh == NULL) {
        return status; /* the arguments: no analysis ran */
    }
    assert_int_equal(status, polymass_mesh_status(mesh));
    snprintf(message, sizeof message, "%s", polymass_mesh_message(mesh));
    assert_string_equal(message, polymass_context_message(ctx));
    PM_ASSERT_OK(ctx, polymass_mesh_diagnostics(out, ctx, mesh));
    if (status != POLYMASS_OK) {
        /* A refused mesh refuses its mass properties with its status and
           message, which are then the context's again (for the message
           assertions). */
        polymass_mass_properties p;
        pm_props_init(&p);
        assert_int_equal(polymass_mesh_mass_properties(&p, ctx, mesh, NULL), status);
        assert_string_equal(message, polymass_context_message(ctx));
    }
    polymass_mesh_destroy(mesh);
    return out->status;
}

int32_t pm_moments(polymass_moments* out, polymass_context* ctx, const polymass_mesh_desc* desc,
                   const polymass_options* options) {
    polymass_mesh* mesh = NULL;
    int32_t status = polymass_mesh_create(&mesh, ctx, desc, options);
    if (status == POLYMASS_OK) {
        status = polymass_mesh_moments(out, ctx, mesh);
    }
    polymass_mesh_destroy(mesh);
    return status;
}

int32_t pm_check(polymass_diagnostics* out, polymass_context* ctx, const pm_mesh* m) {
    return pm_check_flags(out, ctx, m, 0);
}

int32_t pm_check_flags(polymass_diagnostics* out, polymass_context* ctx, const pm_mesh* m,
                       uint32_t flags) {
    const polymass_mesh_desc d = pm_mesh_desc(m);
    const polymass_options o = pm_options(flags, 0.0);
    return pm_diagnose(out, ctx, &d, &o);
}

int32_t pm_compute_reference(polymass_mass_properties* out, polymass_context* ctx,
                             const pm_reference_solid* ref) {
    const polymass_mesh_desc d = pm_reference_desc(ref);
    pm_props_init(out);
    return polymass_mass_properties_compute(out, NULL, ctx, &d, NULL, NULL);
}

void pm_check_reference_compute(const char* file, int line, polymass_context* ctx,
                                const pm_reference_solid* ref, polymass_mass_properties* out) {
    const pm_expected e = pm_expected_from_reference(ref);
    pm_check_status(file, line, ref->name, POLYMASS_OK, pm_compute_reference(out, ctx, ref), ctx);
    pm_check_properties(file, line, ref->name, &e, out, PM_TOL);
}

/* ------------------------------------------------------------------------ */
/* Assertions                                                               */
/* ------------------------------------------------------------------------ */

void pm_check_abs(const char* file, int line, const char* what, double expected, double got,
                  double allowed) {
    const double err = fabs(got - expected);
    if (!(err <= allowed)) { /* also catches NaN */
        const double rel = expected != 0 ? err / fabs(expected) : err;
        print_error(
            "%s:%d: %s\n    expected %.17g\n    got      %.17g\n"
            "    error    %.3g (relative %.3g), allowed %.3g\n",
            file, line, what, expected, got, err, rel, allowed);
        _fail(file, line);
    }
}

void pm_check_close(const char* file, int line, const char* what, double expected, double got,
                    double tol, double scale) {
    pm_check_abs(file, line, what, expected, got, tol * fmax(fabs(expected), scale));
}

void pm_check_same(const char* file, int line, const char* what, double expected, double got) {
    if (memcmp(&expected, &got, sizeof got) != 0 && !(isnan(expected) && isnan(got))) {
        print_error(
            "%s:%d: %s: not bitwise equal\n    expected %.17g (%a)\n    got      %.17g (%a)\n",
            file, line, what, expected, expected, got, got);
        _fail(file, line);
    }
}

void pm_check_vec(const char* file, int line, const char* what, const double* expected,
                  const double* got, size_t n, double tol, double scale) {
    size_t i;
    for (i = 0; i < n; ++i) {
        char label[160];
        snprintf(label, sizeof label, "%s[%u]", what, (unsigned)i);
        pm_check_close(file, line, label, expected[i], got[i], tol, scale);
    }
}

void pm_check_tensor(const char* file, int line, const char* what, const double expected[9],
                     const double got[9], double tol) {
    double max_norm = 0;
    int i, j;
    for (i = 0; i < 9; ++i) {
        max_norm = fmax(max_norm, fabs(expected[i]));
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            char label[160];
            const int k = 3 * i + j;
            snprintf(label, sizeof label, "%s[%d][%d]%s", what, i, j,
                     i == j ? "" : " (relative to the tensor's largest entry)");
            if (i == j) {
                pm_check_close(file, line, label, expected[k], got[k], tol, 0.0);
            } else {
                pm_check_abs(file, line, label, expected[k], got[k], tol * max_norm);
            }
        }
    }
}

void pm_check_properties(const char* file, int line, const char* what, const pm_expected* e,
                         const polymass_mass_properties* got, double tol) {
    char label[200];
    int i;
    snprintf(label, sizeof label, "%s: volume", what);
    pm_check_close(file, line, label, e->volume, got->volume, tol, 0.0);
    snprintf(label, sizeof label, "%s: mass (unit density)", what);
    pm_check_close(file, line, label, e->volume, got->mass, tol, 0.0);
    snprintf(label, sizeof label, "%s: density", what);
    pm_check_close(file, line, label, 1.0, got->density, tol, 0.0);
    for (i = 0; i < 3; ++i) {
        snprintf(label, sizeof label, "%s: center_of_mass[%d] (relative to the mesh size %g)", what,
                 i, e->size);
        pm_check_abs(file, line, label, e->center_of_mass[i], got->center_of_mass[i],
                     tol * e->size + 4 * DBL_EPSILON * fabs(e->center_of_mass[i]));
    }
    snprintf(label, sizeof label, "%s: inertia", what);
    pm_check_tensor(file, line, label, e->inertia, got->inertia, tol);
    snprintf(label, sizeof label, "%s: inertia_origin", what);
    pm_check_tensor(file, line, label, e->inertia_origin, got->inertia_origin, tol);
    if (!isnan(e->surface_area)) {
        snprintf(label, sizeof label, "%s: surface_area", what);
        pm_check_close(file, line, label, e->surface_area, got->surface_area, tol, 0.0);
    }
}

void pm_check_same_properties(const char* file, int line, const char* what,
                              const polymass_mass_properties* a,
                              const polymass_mass_properties* b) {
    char label[200];
    int i;
#define PM_SAME_FIELD(field)                                  \
    do {                                                      \
        snprintf(label, sizeof label, "%s: " #field, what);   \
        pm_check_same(file, line, label, a->field, b->field); \
    } while (0)
#define PM_SAME_ARRAY(field, n)                                       \
    for (i = 0; i < (n); ++i) {                                       \
        snprintf(label, sizeof label, "%s: " #field "[%d]", what, i); \
        pm_check_same(file, line, label, a->field[i], b->field[i]);   \
    }
    if (a->warnings != b->warnings) {
        print_error("%s:%d: %s: warnings 0x%x != 0x%x\n", file, line, what, a->warnings,
                    b->warnings);
        _fail(file, line);
    }
    PM_SAME_FIELD(volume);
    PM_SAME_FIELD(mass);
    PM_SAME_FIELD(density);
    PM_SAME_FIELD(surface_area);
    PM_SAME_ARRAY(center_of_mass, 3);
    PM_SAME_ARRAY(inertia, 9);
    PM_SAME_ARRAY(inertia_origin, 9);
    PM_SAME_ARRAY(principal_moments, 3);
    PM_SAME_ARRAY(principal_axes, 9);
#undef PM_SAME_FIELD
#undef PM_SAME_ARRAY
}

void pm_check_status(const char* file, int line, const char* what, int32_t expected, int32_t got,
                     const polymass_context* ctx) {
    if (expected != got) {
        print_error(
            "%s:%d: %s\n    expected status %d (%s)\n    got      status %d (%s)\n"
            "    message: \"%s\"\n",
            file, line, what, (int)expected, polymass_status_string(expected), (int)got,
            polymass_status_string(got), ctx ? polymass_context_message(ctx) : "(no context)");
        _fail(file, line);
    }
}

void pm_check_message_mentions(const char* file, int line, const polymass_context* ctx,
                               const char* word, uint64_t number) {
    char needle[96];
    const char* msg = polymass_context_message(ctx);
    snprintf(needle, sizeof needle, "%s %llu", word, (unsigned long long)number);
    if (msg == NULL || strstr(msg, needle) == NULL) {
        print_error("%s:%d: the message \"%s\" does not mention \"%s\"\n", file, line,
                    msg ? msg : "(null)", needle);
        _fail(file, line);
    } else {
        /* "face 1" must not be the start of "face 17". */
        const char* p = strstr(msg, needle);
        int found = 0;
        while (p) {
            const char next = p[strlen(needle)];
            if (next < '0' || next > '9') {
                found = 1;
                break;
            }
            p = strstr(p + 1, needle);
        }
        if (!found) {
            print_error(
                "%s:%d: the message \"%s\" mentions \"%s\" only as part of a longer number\n", file,
                line, msg, needle);
            _fail(file, line);
        }
    }
}

static int pm_has_number_token(const char* msg, uint64_t number) {
    const char* p = msg;
    while (*p) {
        if (*p >= '0' && *p <= '9' && (p == msg || p[-1] < '0' || p[-1] > '9')) {
            char* end = NULL;
            const unsigned long long v = strtoull(p, &end, 10);
            if (v == number) {
                return 1;
            }
            p = end;
        } else {
            ++p;
        }
    }
    return 0;
}

void pm_check_message_tokens(const char* file, int line, const polymass_context* ctx,
                             const char* word, const uint64_t* numbers, size_t count) {
    const char* msg = polymass_context_message(ctx);
    size_t i;
    int ok = msg != NULL && strstr(msg, word) != NULL;
    for (i = 0; ok && i < count; ++i) {
        ok = pm_has_number_token(msg, numbers[i]);
    }
    if (!ok) {
        print_error("%s:%d: the message \"%s\" does not mention \"%s\" with", file, line,
                    msg ? msg : "(null)", word);
        for (i = 0; i < count; ++i) {
            print_error(" %llu", (unsigned long long)numbers[i]);
        }
        print_error("\n");
        _fail(file, line);
    }
}

/* ------------------------------------------------------------------------ */
/* Linear algebra                                                           */
/* ------------------------------------------------------------------------ */

void pm_mat3_mul(double out[9], const double a[9], const double b[9]) {
    double r[9];
    int i, j, k;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            long double s = 0;
            for (k = 0; k < 3; ++k) {
                s += (long double)a[3 * i + k] * b[3 * k + j];
            }
            r[3 * i + j] = (double)s;
        }
    }
    memcpy(out, r, sizeof r);
}

void pm_mat3_transpose(double out[9], const double a[9]) {
    double r[9];
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            r[3 * i + j] = a[3 * j + i];
        }
    }
    memcpy(out, r, sizeof r);
}

double pm_mat3_det(const double a[9]) {
    const long double d =
        (long double)a[0] * ((long double)a[4] * a[8] - (long double)a[5] * a[7]) -
        (long double)a[1] * ((long double)a[3] * a[8] - (long double)a[5] * a[6]) +
        (long double)a[2] * ((long double)a[3] * a[7] - (long double)a[4] * a[6]);
    return (double)d;
}

void pm_rotation_from_quaternion(double out[9], double w, double x, double y, double z) {
    const long double n =
        sqrtl((long double)w * w + (long double)x * x + (long double)y * y + (long double)z * z);
    const long double a = w / n, b = x / n, c = y / n, d = z / n;
    out[0] = (double)(1 - 2 * (c * c + d * d));
    out[1] = (double)(2 * (b * c - a * d));
    out[2] = (double)(2 * (b * d + a * c));
    out[3] = (double)(2 * (b * c + a * d));
    out[4] = (double)(1 - 2 * (b * b + d * d));
    out[5] = (double)(2 * (c * d - a * b));
    out[6] = (double)(2 * (b * d - a * c));
    out[7] = (double)(2 * (c * d + a * b));
    out[8] = (double)(1 - 2 * (b * b + c * c));
}
