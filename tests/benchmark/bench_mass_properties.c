/* Throughput of libpolymass on large closed triangle meshes (torus grids far
   from the origin) at 1e5, 1e6 and 1e7 triangles: trusted
   (POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS: the topology and intersection checks
   skipped) with float64 and with float32 positions, the topology checks
   without the intersection check (POLYMASS_OPTION_SKIP_INTERSECTION_CHECK),
   and every check (the default options), each on one thread and on two
   (polymass_context_set_threads); each against a
   read-bandwidth probe that sums the very arrays the library reads, on one
   thread and on two (the fastest of a few passes: see the probe below), a
   two-thread figure also against its one-thread one,
   and the checked paths against the trusted one. Runs are interleaved (every path once per round,
   each after an untimed read of its arrays, so that all start alike)
   and the median of the rounds is printed, as M triangles/s and as a fraction
   of the one-thread read bound. Prints figures; asserts nothing about speed.
   Usage: bench_mass_properties [rounds] [largest triangle count] */
#include <polymass/polymass.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_common.h"

/* The read probe, the goal's denominator: how fast one thread (or two) can
   read what the trusted path must read at least once - the position array
   and the index array, every byte - and nothing else. Each thread takes a
   share of both and adds up their 32-bit words as integers: no conversion and
   no chain of floating-point additions to wait on, so that it is bound by
   the reads (with the widest vectors the processor runs: target_clones), not
   by the sums, at every size - in the cache (1e5 triangles, 2.4 MB) as well
   as from memory. A pass is timed from a barrier that the threads leave
   together to the last one's end, so starting threads is not in it, and a
   measure is the fastest of probe_passes passes in a row: a bound is the best
   case, and the fastest pass is the figure least moved by other processes on
   a shared machine (the first pass also warms the caches as far as the
   arrays fit). A round takes one such measure; the rounds, interleaved with
   the library's calls, give the median printed. */
enum { probe_passes = 5 };

typedef struct probe_share {
    const polymass_mesh_desc* desc;
    int part, parts;
    pthread_barrier_t* barrier; /* NULL on one thread */
    double fastest;             /* seconds: the fastest pass */
    uint32_t sum;
} probe_share;

#if defined(__x86_64__)
#define WIDEST_VECTORS __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define WIDEST_VECTORS
#endif

WIDEST_VECTORS static uint32_t sum_words(const uint32_t* words, size_t begin, size_t end) {
    uint32_t sum = 0;
    for (size_t i = begin; i < end; ++i) sum += words[i];
    return sum;
}

/* The words of this thread's share of an array of `bytes` bytes (a multiple
   of four: coordinates and indices are 4 or 8 bytes). */
static uint32_t sum_share_of(const probe_share* share, const void* array, size_t bytes) {
    const size_t words = bytes / 4;
    return sum_words(array, words * share->part / share->parts,
                     words * (share->part + 1) / share->parts);
}

/* One pass over this thread's share of the position and index arrays. */
static uint32_t sum_share(const probe_share* share) {
    const polymass_mesh_desc* desc = share->desc;
    const size_t coordinate_bytes =
        desc->position_type == POLYMASS_POSITION_FLOAT32 ? sizeof(float) : sizeof(double);
    return sum_share_of(share, desc->positions, 3 * (size_t)desc->vertex_count * coordinate_bytes) +
           sum_share_of(share, desc->indices, (size_t)desc->index_count * sizeof(uint32_t));
}

static void wait_for_all(pthread_barrier_t* barrier) {
    if (barrier) pthread_barrier_wait(barrier);
}

/* probe_passes timed passes over a thread's share, in step with the others. */
static void* probe_passes_of(void* argument) {
    probe_share* share = argument;
    share->fastest = INFINITY;
    for (int pass = 0; pass < probe_passes; ++pass) {
        wait_for_all(share->barrier);
        const double start = now_seconds();
        share->sum += sum_share(share);
        wait_for_all(share->barrier);
        const double elapsed = now_seconds() - start;
        if (elapsed < share->fastest) share->fastest = elapsed;
    }
    return NULL;
}

/* Reads the arrays once, untimed, before every measure of the library, so
   that each starts with as much of them in the cache as it holds. Without it
   the first measure of a round read what the previous round's checks had
   evicted while the ones after it found the arrays warm. */
static void warm_up(const polymass_mesh_desc* desc) {
    const probe_share share = {desc, 0, 1, NULL, 0, 0};
    volatile uint32_t keep = sum_share(&share);
    (void)keep;
}

static double probe_seconds(const polymass_mesh_desc* desc, int threads, double* checksum) {
    pthread_t workers[2];
    probe_share shares[2];
    pthread_barrier_t barrier;
    if (threads > 1) pthread_barrier_init(&barrier, NULL, (unsigned)threads);
    for (int t = 0; t < threads; ++t) {
        shares[t] = (probe_share){desc, t, threads, threads > 1 ? &barrier : NULL, 0, 0};
        if (t > 0) pthread_create(&workers[t], NULL, probe_passes_of, &shares[t]);
    }
    probe_passes_of(&shares[0]);
    for (int t = 1; t < threads; ++t) pthread_join(workers[t], NULL);
    if (threads > 1) pthread_barrier_destroy(&barrier);
    for (int t = 0; t < threads; ++t) *checksum += shares[t].sum;
    return shares[0].fastest;
}

static double compute_seconds(polymass_context* context, const polymass_mesh_desc* desc,
                              uint32_t flags, uint32_t threads, double* checksum) {
    polymass_options options = POLYMASS_OPTIONS_INIT;
    options.flags = flags;
    polymass_mass_properties out = POLYMASS_MASS_PROPERTIES_INIT;
    if (polymass_context_set_threads(context, threads) != POLYMASS_OK) {
        fprintf(stderr, "error: %s\n", polymass_context_message(context));
        exit(1);
    }
    warm_up(desc);
    const double start = now_seconds();
    const int32_t status =
        polymass_mass_properties_compute(&out, NULL, context, desc, &options, NULL);
    const double elapsed = now_seconds() - start;
    if (status != POLYMASS_OK) {
        fprintf(stderr, "error: %s\n", polymass_context_message(context));
        exit(1);
    }
    *checksum += out.volume;
    return elapsed;
}

enum {
    read_1_f64,
    read_2_f64,
    read_1_f32,
    trusted_f64,
    trusted_f64_2,
    trusted_f32,
    trusted_f32_2,
    topology,
    topology_2,
    checked,
    checked_2,
    measures
};
static const char* const names[measures] = {
    "read probe, 1 thread",          "read probe, 2 threads",
    "read probe, 1 thread, float32", "trusted, float64",
    "trusted, float64, 2 threads",   "trusted, float32",
    "trusted, float32, 2 threads",   "topology checks, float64",
    "topology checks, 2 threads",    "every check (default), float64",
    "every check, 2 threads"};
/* What each measure is compared with: the 1-thread read bound of its arrays,
   and for a library path on two threads, the same path on one. */
static int read_bound_of(int m) {
    return m == trusted_f32 || m == trusted_f32_2 || m == read_1_f32 ? read_1_f32 : read_1_f64;
}
static int one_thread_of(int m) {
    return m == read_2_f64      ? read_1_f64
           : m == trusted_f64_2 ? trusted_f64
           : m == trusted_f32_2 ? trusted_f32
           : m == topology_2    ? topology
           : m == checked_2     ? checked
                                : -1;
}

static void run(size_t wanted, int rounds, polymass_context* context) {
    torus_meshes meshes = make_torus_meshes(wanted);
    const size_t triangles = meshes.triangles;
    const polymass_mesh_desc desc = meshes.float64, float_desc = meshes.float32;
    double* seconds = checked_malloc((size_t)measures * (size_t)rounds * sizeof *seconds);

    double checksum = 0;
    for (int r = 0; r < rounds; ++r) {
        double* s = seconds + (size_t)r * measures;
        const uint32_t trusted = POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
        const uint32_t no_overlaps = POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
        /* Each one-thread trusted path right after the read probe of its own
           arrays, float32 as float64: after the probe's passes a call finds
           more of its arrays in the caches than after warm_up's one pass.
           With float32 measured after the 2-thread float64 call instead, it
           ran 8-10 % slower than float64 at 1e6 triangles; so, alike. */
        s[read_1_f64] = probe_seconds(&desc, 1, &checksum);
        s[trusted_f64] = compute_seconds(context, &desc, trusted, 1, &checksum);
        s[read_2_f64] = probe_seconds(&desc, 2, &checksum);
        s[trusted_f64_2] = compute_seconds(context, &desc, trusted, 2, &checksum);
        s[read_1_f32] = probe_seconds(&float_desc, 1, &checksum);
        s[trusted_f32] = compute_seconds(context, &float_desc, trusted, 1, &checksum);
        s[trusted_f32_2] = compute_seconds(context, &float_desc, trusted, 2, &checksum);
        s[topology] = compute_seconds(context, &desc, no_overlaps, 1, &checksum);
        s[topology_2] = compute_seconds(context, &desc, no_overlaps, 2, &checksum);
        s[checked] = compute_seconds(context, &desc, 0, 1, &checksum);
        s[checked_2] = compute_seconds(context, &desc, 0, 2, &checksum);
    }
    double medians[measures];
    medians_of(seconds, rounds, measures, medians);
    printf("%zu triangles (median of %d interleaved rounds; checksum %.6g)\n", triangles, rounds,
           checksum);
    for (int m = 0; m < measures; ++m) {
        printf("  %-32s %9.3f ms %8.1f M triangles/s  %5.2f of the 1-thread read bound", names[m],
               1e3 * medians[m], (double)triangles / medians[m] / 1e6,
               medians[read_bound_of(m)] / medians[m]);
        if (one_thread_of(m) >= 0)
            printf("  %4.2fx one thread", medians[one_thread_of(m)] / medians[m]);
        if (m == topology || m == topology_2 || m == checked || m == checked_2)
            printf(
                "  %4.2f of trusted",
                medians[m == topology || m == checked ? trusted_f64 : trusted_f64_2] / medians[m]);
        printf("\n");
    }
    free(seconds);
    free_torus_meshes(&meshes);
}

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? atoi(argv[1]) : 7;
    const double largest = argc > 2 ? atof(argv[2]) : 1e7;
    polymass_context* context = NULL;
    if (rounds < 1 || polymass_context_create(&context, NULL) != POLYMASS_OK) return 1;
    printf("libpolymass %s\n", polymass_version_string());
    for (double wanted = 1e5; wanted <= largest * 1.0001; wanted *= 10)
        run((size_t)wanted, rounds, context);
    polymass_context_destroy(context);
    return 0;
}
