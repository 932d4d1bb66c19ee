#include "topology.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

#include "face_blocks.hpp"
#include "instruction_sets.hpp"
#include "scratch_buffer.hpp"
#include "smallest_index_sets.hpp"

namespace polymass::core {
namespace {

// Each directed edge is filed under its lower vertex as one Entry:
// (higher vertex << 1) | (1 when it runs from the higher vertex down to the
// lower). A counting sort by the lower vertex (one pass counting, one
// filing) replaces a sort of 64-bit keys: 4 bytes an edge instead of 16, and
// two passes instead of four. The buckets are short (a vertex is the lower
// end of about three edges, six entries). Most hold only edges traversed
// once each way, which a comparison of all their pairs shows without sorting
// them; any other is sorted, and walking the buckets in order visits the
// edges in ascending (lower, higher) order, which keeps the findings' "lowest
// first".
//
// Entry is 32 bits when every vertex number fits in 31 bits and the entries
// fit 32-bit offsets; 64 bits otherwise (meshes of billions of indices).
//
// On several threads each counts and files the edges whose lower vertex is
// in its own range of vertices, going through every face in order: no two
// threads touch one bucket, so no increment need be atomic (atomic ones made
// two threads slower than one), and every bucket is filed in face order, as
// on one thread. The walk runs in fixed blocks of lower vertices whose
// findings are joined in order.
constexpr std::size_t vertices_per_piece = std::size_t{1} << 15;

// The buckets hold about three entries: insertion beats a general sort.
template <class Entry>
void sort_bucket(Entry* first, Entry* last) {
    // Also the empty mesh's case, whose buckets may be null: null + 1 is undefined.
    if (last - first < 2) return;
    if (last - first > 16) {
        std::sort(first, last);
        return;
    }
    for (Entry* next = first + 1; next < last; ++next) {
        const Entry value = *next;
        Entry* at = next;
        for (; at > first && at[-1] > value; --at) *at = at[-1];
        *at = value;
    }
}

// Buckets of at most this many entries (most of a surface's: about six
// each) are tested for common edges before, and usually instead of, sorting.
constexpr std::size_t small_bucket = 8;
// The baseline's test pads a small bucket with 0, 4, ..., 4 * (small_bucket
// - 1): distinct, and neither equal nor a partner (one apart) to any entry of
// a lower vertex from here on, whose entries are at least 2 * (low + 1).
// (The AVX2 test's padding needs no such vertex; both are asked from here on.)
constexpr std::size_t padded_from_low = 2 * small_bucket - 2;

// Whether a small bucket, in any order, holds only common edges (each
// traversed once each way and by no other face): all its entries distinct,
// and n / 2 pairs of them partners (h << 1 and h << 1 | 1), so that every
// higher vertex is there once up and once down. Returns the slots of the ups
// (bit i for slot i: one entry an edge, whose ends the walk joins), or 0 when
// the bucket holds another kind of edge. Every pair is compared,
// four at a time and with no branch on the data, where a sort's branches
// would be mispredicted about once an entry. The padded bucket's eight slots
// against themselves turned by 1, 2 and 3 slots meet each pair of slots 1,
// 2, 3, 5, 6 or 7 apart once; its first four against its last four, the
// pairs 4 apart. (Turned in registers: loads straddling the stores of a
// copy would wait for them.) The eight slots from `first` are read whatever
// n is: the caller sees that they are all its piece's.
// 32-bit entries only (64-bit ones, for meshes of billions, are sorted).
__attribute__((always_inline)) inline unsigned small_bucket_of_common_edges(
    const std::uint32_t* first, std::size_t n) {
    using Four = std::uint32_t __attribute__((vector_size(16)));
    static_assert(small_bucket == 8, "two vectors of four");
    Four low, high;
    std::memcpy(&low, first, sizeof low);
    std::memcpy(&high, first + 4, sizeof high);
    // A comparison gives all bits set (-1) where it holds.
    const auto count = std::uint32_t(n);
    const Four low_in = Four(Four{0, 1, 2, 3} < count), high_in = Four(Four{4, 5, 6, 7} < count);
    low = (low & low_in) | (Four{0, 4, 8, 12} & ~low_in);
    high = (high & high_in) | (Four{16, 20, 24, 28} & ~high_in);
    Four partners{}, repeated{};
    auto compare = [&](const Four& a, const Four& b) {
        const Four difference = a ^ b;
        partners -= Four(difference == 1);
        repeated |= Four(difference == 0);
    };
    compare(low, high);
    compare(low, __builtin_shufflevector(low, high, 1, 2, 3, 4));
    compare(high, __builtin_shufflevector(low, high, 5, 6, 7, 0));
    compare(low, __builtin_shufflevector(low, high, 2, 3, 4, 5));
    compare(high, __builtin_shufflevector(low, high, 6, 7, 0, 1));
    compare(low, __builtin_shufflevector(low, high, 3, 4, 5, 6));
    compare(high, __builtin_shufflevector(low, high, 7, 0, 1, 2));
    const std::uint32_t pairs = partners[0] + partners[1] + partners[2] + partners[3];
    const std::uint32_t any_repeated = repeated[0] | repeated[1] | repeated[2] | repeated[3];
    if (any_repeated != 0 || 2 * std::size_t(pairs) != n) return 0;
    unsigned ups = 0;
    for (std::size_t i = 0; i < n; ++i) ups |= unsigned(~first[i] & 1) << i;
    return ups;
}

template <class Entry>
unsigned small_bucket_of_common_edges(const Entry*, std::size_t) {
    return 0;
}

#if defined(__x86_64__)
// The same test on AVX2, by sorting instead of comparing every pair: the
// eight slots in one vector, those past n set to all bits (sorted last, and
// not read after), sorted by a bitonic network (six rounds, each lane
// against the one whose number differs in bit 0, 1 or 2 of its own, keeping
// the smaller or the larger; every shuffle of a round takes an immediate).
// Sorted, the bucket holds only common edges when n is even and each pair of
// lanes (2i, 2i + 1) below n holds partners: the pair's first is then even
// (an up, h << 1) and its second the down (h << 1 | 1), and the next pair's
// first, even, differs from it: no entry repeated. A round is a shuffle, a
// minimum, a maximum and a blend; the test about 56 instructions where
// comparing every pair (turned by 1, 2, 3 and 4 slots) took about 63
// (callgrind: docs/integrals.md).
// Inlined only into the AVX2 walk, whose target it takes (a function with a
// target of its own would not be inlined into the walk's shared body).
__attribute__((always_inline)) inline unsigned small_bucket_of_common_edges_avx2(
    const std::uint32_t* first, std::size_t n) {
    using Eight = std::uint32_t __attribute__((vector_size(32)));
    static_assert(small_bucket == 8, "one vector of eight");
    // An odd bucket is never only common edges; and its last entry would be
    // paired with a pad, which the up of vertex 2^31 - 1 (all bits set but
    // bit 0) would pass for.
    if (n % 2 != 0) return 0;
    Eight slots;
    std::memcpy(&slots, first, sizeof slots);
    const auto count = std::uint32_t(n);
    const Eight in = Eight(Eight{0, 1, 2, 3, 4, 5, 6, 7} < count);
    Eight sorted = slots | ~in;
    // A round: each lane's smaller and larger of itself and its partner,
    // then from each lane (a blend) one or the other: lane i of `low`, or
    // of `high` numbered 8 + i.
    Eight low, high;
    auto order = [&](const Eight& partner) {
        low = sorted < partner ? sorted : partner;
        high = sorted < partner ? partner : sorted;
    };
    // Runs of 2, then 4, rising and falling in turn; then the 8 merged.
    order(__builtin_shufflevector(sorted, sorted, 1, 0, 3, 2, 5, 4, 7, 6));
    sorted = __builtin_shufflevector(low, high, 0, 9, 10, 3, 4, 13, 14, 7);
    order(__builtin_shufflevector(sorted, sorted, 2, 3, 0, 1, 6, 7, 4, 5));
    sorted = __builtin_shufflevector(low, high, 0, 1, 10, 11, 12, 13, 6, 7);
    order(__builtin_shufflevector(sorted, sorted, 1, 0, 3, 2, 5, 4, 7, 6));
    sorted = __builtin_shufflevector(low, high, 0, 9, 2, 11, 12, 5, 14, 7);
    order(__builtin_shufflevector(sorted, sorted, 4, 5, 6, 7, 0, 1, 2, 3));
    sorted = __builtin_shufflevector(low, high, 0, 1, 2, 3, 12, 13, 14, 15);
    order(__builtin_shufflevector(sorted, sorted, 2, 3, 0, 1, 6, 7, 4, 5));
    sorted = __builtin_shufflevector(low, high, 0, 1, 10, 11, 4, 5, 14, 15);
    order(__builtin_shufflevector(sorted, sorted, 1, 0, 3, 2, 5, 4, 7, 6));
    sorted = __builtin_shufflevector(low, high, 0, 9, 2, 11, 4, 13, 6, 15);
    const Eight partners =
        Eight((sorted ^ 1) == __builtin_shufflevector(sorted, sorted, 1, 0, 3, 2, 5, 4, 7, 6));
    // One word of flags a lane: bit i when slot i is an up in the bucket (in
    // its own order, whose entries join_lanes reads), and bit 8 when the
    // lane's pair is not one of partners; ORed across the lanes by folding
    // halves.
    Eight flags = ((~slots & 1) << Eight{0, 1, 2, 3, 4, 5, 6, 7} | (~partners & 0x100)) & in;
    flags |= __builtin_shufflevector(flags, flags, 4, 5, 6, 7, 0, 1, 2, 3);
    flags |= __builtin_shufflevector(flags, flags, 2, 3, 0, 1, 6, 7, 4, 5);
    flags |= __builtin_shufflevector(flags, flags, 1, 0, 3, 2, 5, 4, 7, 6);
    return (flags[0] & 0x100) != 0 ? 0 : flags[0];
}

template <class Entry>
unsigned small_bucket_of_common_edges_avx2(const Entry*, std::size_t) {
    return 0;
}
#endif

// Whether a sorted bucket holds only common edges, each traversed once each
// way and by no other face: pairs (h << 1, h << 1 | 1), with h rising. That
// every pair starts with an up (an even entry) also rules out a third
// traversal of the pair before it, which would sort between the two pairs.
// Tested for the whole bucket with no branch per edge: a surface is almost
// all such buckets.
template <class Entry>
bool only_common_edges(const Entry* first, const Entry* last) {
    if ((last - first) % 2 != 0) return false;
    Entry mismatch = 0;
    for (const Entry* at = first; at != last; at += 2)
        mismatch |= (at[0] & 1) | (at[1] ^ (at[0] + 1));
    return mismatch == 0;
}

// Hands each directed edge of the face of `size` corners from position
// `first` of the index array to file.edge(from, to), in the face's order (a
// triangle's loop unrolled: its three edges stay in registers).
template <class VertexId, class File>
__attribute__((always_inline)) inline void file_edges_of_face(std::size_t first, std::size_t size,
                                                              VertexId& id, File& file) {
    std::uint32_t from = id(first + size - 1);
#pragma GCC unroll 4
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t to = id(first + i);
        if (from != to) file.edge(from, to);
        from = to;
    }
}

// The two passes over the edges, each edge given as its ends (edge) or as
// its lower vertex and Entry (filed, by the passes eight triangles at a
// time): the count of each lower vertex's edges, then the edges filed in its
// bucket. (Copies of the arrays' addresses: read through the containers,
// they were loaded again after every store.)
template <class Entry>
struct Count {
    Entry* bucket_end;

    void edge(std::uint32_t from, std::uint32_t to) { ++bucket_end[std::min(from, to)]; }
    void filed(std::uint32_t lower, Entry) { ++bucket_end[lower]; }
};
template <class Entry>
struct File {
    Entry* bucket_end;
    Entry* slots;

    void edge(std::uint32_t from, std::uint32_t to) {
        const bool down = from > to;
        filed(down ? to : from, (Entry(down ? from : to) << 1) | Entry(down));
    }
    void filed(std::uint32_t lower, Entry entry) { slots[bucket_end[lower]++] = entry; }
};
// Passes on to `file` the edges whose lower vertex is in [low, high): one
// thread's share of the buckets.
template <class Pass>
struct FileInRange {
    Pass& pass;
    std::size_t low, high;

    bool ours(std::uint32_t lower) const { return lower >= low && lower < high; }
    void edge(std::uint32_t from, std::uint32_t to) {
        if (ours(std::min(from, to))) pass.edge(from, to);
    }
    template <class Entry>
    void filed(std::uint32_t lower, Entry entry) {
        if (ours(lower)) pass.filed(lower, entry);
    }
};

// file_edges_of_face for each face of one block, in face order.
template <class Scalar, class Index, class VertexId, class File>
void file_edges_of_block(const MeshView<Scalar, Index>& mesh, std::size_t block,
                         std::size_t first_index, VertexId& id, File file) {
    for_each_face_of_block(mesh, block, first_index,
                           [&](std::size_t, std::size_t first, std::size_t size) {
                               file_edges_of_face(first, size, id, file);
                           });
}

#if defined(__x86_64__)
// The lower vertices and entries of the 24 edges of eight triangles from
// `corners` (32-bit indices, each vertex its own identity), edge k from
// corner k to the next corner of its triangle; false when an edge runs from
// a vertex to itself (no edge: then the caller files them one by one). In
// vectors of eight, the shuffles giving each corner's next one: the
// counting and filing passes were 16 and 40 instructions a triangle one edge
// at a time, most of them choosing the ends and the entry of each edge; 13
// and 27 so (torus of 1e6 triangles, callgrind: docs/integrals.md).
__attribute__((always_inline)) inline bool edges_of_eight_triangles(const unsigned char* corners,
                                                                    std::uint32_t (&lower)[24],
                                                                    std::uint32_t (&entry)[24]) {
    using Eight = std::uint32_t __attribute__((vector_size(32)));
    // One load a vector: copied whole, the 96 bytes went through the stack
    // in 16-byte halves read back as 32-byte vectors, a stall each (store
    // forwarding fails) that made the passes slower than one edge at a time.
    Eight from[3];
#pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) std::memcpy(&from[k], corners + k * sizeof(Eight), sizeof(Eight));
    // Corners 0..23 in three vectors; the next corner of corner 3t + i is
    // 3t + i + 1, or 3t for i = 2.
    const Eight to[3] = {__builtin_shufflevector(from[0], from[1], 1, 2, 0, 4, 5, 3, 7, 8),
                         __builtin_shufflevector(
                             __builtin_shufflevector(from[0], from[1], 6, 10, 11, 9, 13, 14, 12, 8),
                             from[2], 0, 1, 2, 3, 4, 5, 6, 8),
                         __builtin_shufflevector(from[1], from[2], 9, 7, 11, 12, 10, 14, 15, 13)};
    Eight repeated{};
#pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) {
        const Eight down = Eight(from[k] > to[k]);  // all bits set where the edge runs down
        const Eight low = (to[k] & down) | (from[k] & ~down);
        const Eight high = from[k] ^ to[k] ^ low;
        const Eight filed = (high << 1) | (down & 1);
        repeated |= Eight(from[k] == to[k]);
        std::memcpy(lower + 8 * k, &low, sizeof low);
        std::memcpy(entry + 8 * k, &filed, sizeof filed);
    }
    std::uint32_t any_repeated = 0;
    for (int i = 0; i < 8; ++i) any_repeated |= repeated[i];
    return any_repeated == 0;
}

// file_edges_of_block for a block of triangles whose 32-bit indices are
// their vertices' identities, eight triangles at a time on AVX2 (32-bit
// entries). The same edges, each bucket's in another order, which neither
// the test of small buckets nor the sort of the others sees.
template <class Scalar, class File>
__attribute__((target("avx2"))) void file_triangle_edges_avx2(
    const MeshView<Scalar, std::uint32_t>& mesh, std::size_t block, File& file) {
    const std::size_t first_face = block * kFacesPerBlock;
    const std::size_t last_face = std::min(mesh.face_count, first_face + kFacesPerBlock);
    auto own_identity = [&mesh](std::size_t position) { return mesh.indices[position]; };
    std::size_t face = first_face;
    for (; face + 8 <= last_face; face += 8) {
        alignas(32) std::uint32_t lower[24], entry[24];
        if (edges_of_eight_triangles(mesh.indices.base + 3 * face * sizeof(std::uint32_t), lower,
                                     entry)) {
#pragma GCC unroll 24
            for (int k = 0; k < 24; ++k) file.filed(lower[k], entry[k]);
            continue;
        }
        for (std::size_t one = face; one < face + 8; ++one)
            file_edges_of_face(3 * one, 3, own_identity, file);
    }
    for (; face < last_face; ++face) file_edges_of_face(3 * face, 3, own_identity, file);
}
#endif

// Joins `low` with the higher end of the entries in the slots of `lanes`
// from `first`: a common edge's up alone (its down names the same vertex).
// Most ends hang straight below low's root already (joined through a lower
// vertex): one load each, and no search.
template <class Entry>
__attribute__((always_inline)) inline void join_lanes(ConcurrentSmallestIndexSets sets,
                                                      std::size_t low, const Entry* first,
                                                      unsigned lanes) {
    std::uint32_t root = sets.find(std::uint32_t(low));
    for (; lanes != 0; lanes &= lanes - 1)
        root = sets.join_to(root, std::uint32_t(first[__builtin_ctz(lanes)] >> 1));
}

template <bool avx2, class Entry>
__attribute__((always_inline)) inline unsigned small_bucket_test(const Entry* first,
                                                                 std::size_t n) {
#if defined(__x86_64__)
    if constexpr (avx2) return small_bucket_of_common_edges_avx2(first, n);
#endif
    return small_bucket_of_common_edges(first, n);
}

// Classifies the edges whose lower vertex is in [first_low, last_low), from
// their bucket entries starting at `entries`, and joins their ends in `sets`
// (taken by value, as by join_lanes: the parent array's address then stays in
// a register; through a reference it was loaded again at every join).
template <bool avx2, class Entry>
__attribute__((always_inline)) inline TopologyReport walk_buckets_as(
    Entry* entries, const Entry* end_of, std::size_t first_low, std::size_t last_low,
    ConcurrentSmallestIndexSets sets) {
    TopologyReport report;
    Entry begin = first_low == 0 ? 0 : end_of[first_low - 1];
    // Reading past a bucket stays within the piece: the next piece's buckets
    // may be being sorted on another thread.
    const Entry* const piece_end = entries + (last_low > first_low ? end_of[last_low - 1] : begin);
    for (std::size_t low = first_low; low < last_low; ++low) {
        Entry* const first = entries + begin;
        Entry* const last = entries + end_of[low];
        begin = end_of[low];
        const std::size_t size = std::size_t(last - first);
        // No edge: an unused or a welded-away vertex (most of a welded
        // soup's); those after it passed in a loop of their own, one load
        // and test each.
        if (size == 0) {
            while (low + 1 < last_low && end_of[low + 1] == begin) ++low;
            continue;
        }
        if (size <= small_bucket && low >= padded_from_low &&
            std::size_t(piece_end - first) >= small_bucket) {
            if (const unsigned ups = small_bucket_test<avx2>(first, size)) {
                join_lanes(sets, low, first, ups);
                report.edge_count += size / 2;
                continue;
            }
        }
        sort_bucket(first, last);  // by higher vertex, ups (bit 0) before downs
        // Each edge joins its ends once, however many faces traverse it.
        std::uint32_t root = sets.find(std::uint32_t(low));
        if (only_common_edges(first, last)) {
            for (const Entry* up = first; up != last; up += 2)
                root = sets.join_to(root, std::uint32_t(*up >> 1));
            report.edge_count += std::size_t(last - first) / 2;
            continue;
        }
        for (Entry* at = first; at != last;) {
            const Entry high = *at >> 1;
            root = sets.join_to(root, std::uint32_t(high));
            std::size_t ups = 0, downs = 0;
            for (; at != last && (*at >> 1) == high; ++at) (*at & 1 ? downs : ups) += 1;
            ++report.edge_count;
            // Name the edge in the direction it was (most often) traversed.
            const auto lower = std::uint32_t(low), higher = std::uint32_t(high);
            const std::uint32_t from = ups >= downs ? lower : higher;
            const std::uint32_t to = ups >= downs ? higher : lower;
            if (ups + downs == 1) {
                report.open.record(from, to, 1);
            } else if (ups + downs == 2) {
                if (ups != 1) report.misoriented.record(from, to, 2);
            } else {
                report.non_manifold.record(from, to, ups + downs);
                if (ups != downs) report.non_manifold_balanced = false;
            }
        }
    }
    return report;
}

// The walk built for each instruction set, chosen at run time (the shipped
// library is built for the baseline); both give the same report and sets.
template <class Entry>
TopologyReport walk_buckets_baseline(Entry* entries, const Entry* end_of, std::size_t first_low,
                                     std::size_t last_low,
                                     const ConcurrentSmallestIndexSets& sets) {
    return walk_buckets_as<false>(entries, end_of, first_low, last_low, sets);
}
#if defined(__x86_64__)
template <class Entry>
__attribute__((target("avx2"))) TopologyReport walk_buckets_avx2(
    Entry* entries, const Entry* end_of, std::size_t first_low, std::size_t last_low,
    const ConcurrentSmallestIndexSets& sets) {
    return walk_buckets_as<true>(entries, end_of, first_low, last_low, sets);
}
#endif

template <class Entry>
auto walk_buckets_for(InstructionSet set) {
#if defined(__x86_64__)
    if (set != InstructionSet::baseline) return walk_buckets_avx2<Entry>;
#endif
    return walk_buckets_baseline<Entry>;
}

// ids_are_indices: id(position) is the index at `position` (no weld).
template <class Entry, class Scalar, class Index, class VertexId>
TopologyReport match_edges(const MeshView<Scalar, Index>& mesh, std::size_t identity_count,
                           VertexId&& id, bool ids_are_indices, TaskRunner& tasks,
                           std::pmr::memory_resource* memory, std::uint32_t* vertex_sets,
                           InstructionSet set) {
    const std::pmr::vector<std::size_t> starts = face_block_starts(mesh, memory);
    // end_of[v]: first counts, then (after the prefix sum) where v's bucket
    // starts, then (after filing, each bucket filled from its start) where it
    // ends. (v: an identity, as every vertex below.)
    std::pmr::vector<Entry> end_of(identity_count, Entry{0}, memory);
    Entry* const bucket_end = end_of.data();
    // Eight triangles at a time when their indices are the identities.
    // Decided once here: asked in file_edges_of, block by block, the checked
    // call took 4.3 % more instructions (callgrind, torus of 1e5 triangles).
    const bool eight_at_a_time = [&] {
#if defined(__x86_64__)
        if constexpr (std::is_same_v<Index, std::uint32_t> && std::is_same_v<Entry, std::uint32_t>)
            return ids_are_indices && mesh.all_triangles() && set != InstructionSet::baseline;
#endif
        return false;
    }();
    auto file_edges_of = [&](std::size_t block, auto& file) {
#if defined(__x86_64__)
        if constexpr (std::is_same_v<Index, std::uint32_t> && std::is_same_v<Entry, std::uint32_t>)
            if (eight_at_a_time) return file_triangle_edges_avx2(mesh, block, file);
#endif
        file_edges_of_block(mesh, block, starts[block], id, file);
    };
    // Each edge of every face whose lower vertex is in range `range` of the
    // tasks' concurrency.
    const std::size_t ranges = std::max<std::size_t>(1, tasks.concurrency());
    const std::size_t per_range = (identity_count + ranges - 1) / ranges;
    auto file_edges_in_range = [&](std::size_t range, auto&& file) {
        if (ranges == 1) {  // every edge: no test per edge on one thread
            for (std::size_t block = 0; block < starts.size(); ++block) file_edges_of(block, file);
            return;
        }
        const std::size_t low = range * per_range;
        const std::size_t high = std::min(identity_count, low + per_range);
        FileInRange<std::remove_reference_t<decltype(file)>> ours{file, low, high};
        for (std::size_t block = 0; block < starts.size(); ++block) file_edges_of(block, ours);
    };
    tasks.run(ranges,
              [&](std::size_t range) { file_edges_in_range(range, Count<Entry>{bucket_end}); });
    Entry edge_total = 0;
    for (Entry& count : end_of) edge_total += std::exchange(count, edge_total);
    ScratchBuffer<Entry> entries(edge_total, memory);  // each slot filed once below
    tasks.run(ranges, [&](std::size_t range) {
        file_edges_in_range(range, File<Entry>{bucket_end, entries.data()});
    });

    const std::size_t pieces = (identity_count + vertices_per_piece - 1) / vertices_per_piece;
    std::pmr::vector<TopologyReport> parts(pieces, memory);
    const ConcurrentSmallestIndexSets sets(vertex_sets);
    const auto walk_buckets = walk_buckets_for<Entry>(set);
    tasks.run(pieces, [&](std::size_t piece) {
        parts[piece] =
            walk_buckets(entries.data(), end_of.data(), piece * vertices_per_piece,
                         std::min(identity_count, (piece + 1) * vertices_per_piece), sets);
    });
    TopologyReport report;
    for (const TopologyReport& part : parts) {
        report.edge_count += part.edge_count;
        report.open.append(part.open);
        report.misoriented.append(part.misoriented);
        report.non_manifold.append(part.non_manifold);
        report.non_manifold_balanced &= part.non_manifold_balanced;
    }
    return report;
}

// Findings name identities' vertices (a welded position by its lowest vertex).
void name_vertices(EdgeFinding& finding, const VertexIdentities& identities) {
    for (std::size_t i = 0; i < finding.kept(); ++i)
        for (std::uint32_t& end : finding.lowest[i]) end = identities.vertex(end);
}

}  // namespace

template <class Scalar, class Index>
TopologyReport analyse_topology(const MeshView<Scalar, Index>& mesh,
                                const VertexIdentities& identities, TaskRunner& tasks,
                                std::pmr::memory_resource* memory,
                                std::pmr::vector<std::uint32_t>& vertex_sets, InstructionSet set) {
    const std::size_t count = identities.count_among(mesh.vertex_count);
    vertex_sets.resize(count);
    std::iota(vertex_sets.begin(), vertex_sets.end(), 0u);
    const bool ids_are_indices = !identities.of_vertex;
    auto analyse = [&](auto&& id) {
        const bool narrow = count <= (std::size_t{1} << 31) &&
                            mesh.index_count <= std::numeric_limits<std::uint32_t>::max();
        return narrow ? match_edges<std::uint32_t>(mesh, count, id, ids_are_indices, tasks, memory,
                                                   vertex_sets.data(), set)
                      : match_edges<std::uint64_t>(mesh, count, id, ids_are_indices, tasks, memory,
                                                   vertex_sets.data(), set);
    };
    if (!identities.of_vertex)
        return analyse([&](std::size_t position) { return mesh.indices[position]; });
    TopologyReport report =
        analyse([&](std::size_t position) { return identities.of_vertex[mesh.indices[position]]; });
    name_vertices(report.open, identities);
    name_vertices(report.misoriented, identities);
    name_vertices(report.non_manifold, identities);
    return report;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                   \
    template TopologyReport analyse_topology<Scalar, Index>(                  \
        const MeshView<Scalar, Index>&, const VertexIdentities&, TaskRunner&, \
        std::pmr::memory_resource*, std::pmr::vector<std::uint32_t>&, InstructionSet);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
