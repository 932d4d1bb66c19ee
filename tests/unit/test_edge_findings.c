/* The topology check's edge findings - how many edges are open, non-manifold
 * and misoriented, the first eight of each (lowest vertex pair first) and the
 * direction each is named in - against a plain count of every directed edge,
 * on tori large enough for every way the check classifies the edges of a
 * vertex (few or many edges to higher vertices, low and high vertex numbers,
 * more than one piece of vertices): faces removed (open edges), reversed
 * (misoriented), repeated as they are (non-manifold, more often one way) and
 * repeated both ways (non-manifold, balanced), with the vertices numbered
 * along the rings and shuffled. */
#include "test_support.h"

#include <stdlib.h>
#include <string.h>

enum { OPEN, NON_MANIFOLD, MISORIENTED, KINDS };

typedef struct directed_edge {
    uint32_t low, high;
    int down; /* traversed from high to low */
} directed_edge;

typedef struct edge_findings {
    uint64_t edges;
    uint64_t count[KINDS];
    uint64_t first[KINDS][POLYMASS_DIAGNOSTIC_LOCATIONS][2];
} edge_findings;

static int by_vertex_pair(const void* a, const void* b) {
    const directed_edge *x = a, *y = b;
    if (x->low != y->low) return x->low < y->low ? -1 : 1;
    if (x->high != y->high) return x->high < y->high ? -1 : 1;
    return 0;
}

static void record(edge_findings* found, int kind, uint32_t from, uint32_t to) {
    const uint64_t k = found->count[kind]++;
    if (k < POLYMASS_DIAGNOSTIC_LOCATIONS) {
        found->first[kind][k][0] = from;
        found->first[kind][k][1] = to;
    }
}

/* Every directed edge of every face (none from a vertex to itself), sorted by
   vertex pair, and each pair classified by how often it is traversed each way. */
static edge_findings count_edges(const pm_mesh* m) {
    directed_edge* edges = malloc(m->index_count * sizeof *edges);
    edge_findings found;
    size_t face, offset = 0, count = 0, at = 0;
    memset(&found, 0, sizeof found);
    assert_non_null(edges);
    for (face = 0; face < m->face_count; ++face) {
        const size_t n = m->face_sizes[face];
        size_t i;
        for (i = 0; i < n; ++i) {
            const uint32_t from = m->indices[offset + i], to = m->indices[offset + (i + 1) % n];
            if (from == to) continue;
            edges[count].low = from < to ? from : to;
            edges[count].high = from < to ? to : from;
            edges[count].down = from > to;
            ++count;
        }
        offset += n;
    }
    qsort(edges, count, sizeof *edges, by_vertex_pair);
    while (at < count) {
        size_t ups = 0, downs = 0, end = at;
        for (; end < count && by_vertex_pair(&edges[at], &edges[end]) == 0; ++end) {
            if (edges[end].down)
                ++downs;
            else
                ++ups;
        }
        {
            /* Named in the direction most of its traversals take (up on a tie). */
            const uint32_t from = ups >= downs ? edges[at].low : edges[at].high;
            const uint32_t to = ups >= downs ? edges[at].high : edges[at].low;
            ++found.edges;
            if (ups + downs == 1) record(&found, OPEN, from, to);
            if (ups + downs == 2 && ups != 1) record(&found, MISORIENTED, from, to);
            if (ups + downs > 2) record(&found, NON_MANIFOLD, from, to);
        }
        at = end;
    }
    free(edges);
    return found;
}

static void expect_kind(uint64_t count, const uint64_t (*first)[2], const edge_findings* e,
                        int kind) {
    uint64_t k;
    assert_int_equal(count, e->count[kind]);
    for (k = 0; k < count && k < POLYMASS_DIAGNOSTIC_LOCATIONS; ++k) {
        assert_int_equal(first[k][0], e->first[kind][k][0]);
        assert_int_equal(first[k][1], e->first[kind][k][1]);
    }
}

static void expect_findings_of_plain_count(polymass_context* ctx, const pm_mesh* m,
                                           uint32_t flags) {
    const edge_findings e = count_edges(m);
    polymass_diagnostics d;
    int force_face_sizes;
    for (force_face_sizes = 0; force_face_sizes < 2; ++force_face_sizes) {
        const polymass_mesh_desc desc = pm_mesh_desc_ex(m, force_face_sizes);
        const polymass_options options = pm_options(flags, 0.0);
        (void)pm_diagnose(&d, ctx, &desc, &options);
        assert_int_equal(d.edge_count, e.edges);
        expect_kind(d.open_edges, d.first_open_edges, &e, OPEN);
        expect_kind(d.non_manifold_edges, d.first_non_manifold_edges, &e, NON_MANIFOLD);
        expect_kind(d.misoriented_edges, d.first_misoriented_edges, &e, MISORIENTED);
    }
}

static void append_face_of(pm_mesh* m, size_t face, int reversed) {
    const size_t offset = pm_mesh_face_offset(m, face), n = m->face_sizes[face];
    uint32_t copy[8];
    size_t i;
    assert_true(n <= 8);
    for (i = 0; i < n; ++i) copy[i] = m->indices[offset + (reversed ? n - 1 - i : i)];
    pm_mesh_add_face(m, n, copy);
}

/* Vertex v becomes number[v] (a fixed pseudo-random permutation). */
static void shuffle_vertices(pm_mesh* m) {
    uint32_t* number = malloc(m->vertex_count * sizeof *number);
    double* positions = malloc(3 * m->vertex_count * sizeof *positions);
    uint64_t state = 12345;
    size_t v, i;
    assert_non_null(number);
    assert_non_null(positions);
    for (v = 0; v < m->vertex_count; ++v) number[v] = (uint32_t)v;
    for (v = m->vertex_count - 1; v > 0; --v) {
        size_t other;
        uint32_t t;
        state = state * 6364136223846793005u + 1442695040888963407u;
        other = (size_t)((state >> 33) % (v + 1));
        t = number[v], number[v] = number[other], number[other] = t;
    }
    for (v = 0; v < m->vertex_count; ++v)
        memcpy(positions + 3 * number[v], m->positions + 3 * v, 3 * sizeof *positions);
    memcpy(m->positions, positions, 3 * m->vertex_count * sizeof *positions);
    for (i = 0; i < m->index_count; ++i) m->indices[i] = number[m->indices[i]];
    free(positions);
    free(number);
}

/* A torus of 36,000 vertices (two pieces of the check's vertex blocks) with
   defects of every kind spread over it, numbered along its rings and shuffled. */
static void test_findings_equal_a_plain_count(void** state) {
    static const double centre[3] = {0, 0, 0};
    /* The edges' findings are under test, twelve checks of 72,000 triangles:
       the intersection check is skipped. */
    const uint32_t flags = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    size_t face, numbering;
    (void)state;
    for (numbering = 0; numbering < 2; ++numbering) {
        pm_mesh_init(&m);
        pm_mesh_add_torus(&m, 300, 120, 10.0, 3.0, centre);
        if (numbering == 1) shuffle_vertices(&m);
        expect_findings_of_plain_count(ctx, &m, flags); /* closed: no findings */
        for (face = 5; face < m.face_count; face += 1499) pm_mesh_reverse_face(&m, face);
        for (face = 11; face < m.face_count; face += 2999) append_face_of(&m, face, 0);
        for (face = 17; face < m.face_count; face += 4999) {
            append_face_of(&m, face, 0);
            append_face_of(&m, face, 1);
        }
        expect_findings_of_plain_count(ctx, &m, flags);
        for (face = m.face_count - 3; face > 997; face -= 997) pm_mesh_remove_face(&m, face);
        expect_findings_of_plain_count(ctx, &m, flags);
        pm_mesh_free(&m);
    }
    polymass_context_destroy(ctx);
}

/* A face whose corners repeat a vertex has no edge there, and one that
   repeats it on both sides of another vertex traverses that edge both ways. */
static void test_repeated_corners(void** state) {
    static const double centre[3] = {0, 0, 0};
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 40, 30, 10.0, 3.0, centre);
    pm_mesh_add_tri(&m, 100, 100, 900); /* a new edge, once each way */
    pm_mesh_add_tri(&m, 31, 31, 32);    /* an edge of the torus, twice each way */
    pm_mesh_add_tri(&m, 500, 500, 500); /* no edge */
    expect_findings_of_plain_count(ctx, &m, 0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

/* Vertex 100 of a torus numbered along its rings has edges to three higher
   vertices, each traversed once each way. A triangle (100, 101, new vertex)
   traverses (100, 101) a second time upwards (non-manifold: twice up, once
   down) and leaves (new vertex, 100) open: as many pairs of opposite
   traversals as edges then, but not each edge once each way. */
static void test_open_and_non_manifold_edges_of_one_vertex(void** state) {
    static const double centre[3] = {0, 0, 0};
    polymass_context* ctx = pm_context_new();
    pm_mesh m;
    uint32_t extra;
    (void)state;
    pm_mesh_init(&m);
    pm_mesh_add_torus(&m, 40, 30, 10.0, 3.0, centre);
    extra = pm_mesh_add_vertex(&m, 20, 20, 20);
    pm_mesh_add_tri(&m, 100, 101, extra);
    expect_findings_of_plain_count(ctx, &m, 0);
    pm_mesh_free(&m);
    polymass_context_destroy(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_findings_equal_a_plain_count),
        cmocka_unit_test(test_repeated_corners),
        cmocka_unit_test(test_open_and_non_manifold_edges_of_one_vertex),
    };
    return cmocka_run_group_tests_name("edge_findings", tests, NULL, NULL);
}
