// A leaf of the surface's tree with its triangles side by side, and the test
// of two such leaves' pairs of neighbours all at once: the contact search's
// most frequent decision (surface_contacts.cpp), made for a leaf pair's
// sixteen pairs in a few vector operations.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "box_tree.hpp"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace polymass::core {

// The triangles of one of the tree's leaves side by side, lane i for the
// leaf's item i (BoxTree::leaf_item): their corners as welded vertices and
// their corner extremes (IndexedSurface::corner_extremes), and kHasCopies
// for a triangle with copies. The contact search tests a leaf pair's
// neighbours all at once from two of these (surface_contacts.cpp), a cache
// line each, where each pair read both triangles' corners and extremes
// through their indices. Lanes past the last item are zero, and never in a
// leaf pair's overlapping bits.
struct alignas(64) LeafCorners {
    static constexpr std::uint32_t kHasCopies = 1u << 31;
    std::uint32_t corner[3][BoxTree::kLeafSize];  // corner k of lane i
    std::uint32_t extremes[BoxTree::kLeafSize];
};

// Bit j set when lane j of `lanes` is (all bits set: a comparison's true).
__attribute__((always_inline)) inline unsigned lanes_set(std::uint32_t
                                                         __attribute__((vector_size(16))) lanes) {
#if defined(__SSE2__)
    // The lanes' sign bits in one instruction (movmskps). The eight-lane form
    // is an AVX intrinsic, which the walk's baseline body cannot call.
    return unsigned(_mm_movemask_ps(_mm_castsi128_ps(__m128i(lanes))));
#else
    unsigned bits = 0;
    for (int j = 0; j < 4; ++j) bits |= (lanes[j] & 1u) << j;
    return bits;
#endif
}

// The pairs (i, j) of lane i of leaf `first` and lane j of leaf `second` that
// share two corners, or one at which the two triangles lie on either side of
// an axis plane through it (apart_at_shared_corner in surface_contacts.cpp),
// neither with copies: bit BoxTree::kLeafSize i + j. They add nothing to the
// contact search (its add_nothing, the first two cases), and on a closed
// surface they are nearly all of a leaf pair's overlapping pairs. The four
// lanes of `second` against two lanes of `first` at once, on eight lanes
// (one AVX2 vector: inlined into the walk, which is built for AVX2 too; the
// baseline's walk takes them as two halves), with no branch on the data,
// where a pair at a time took about 130 instructions
// (docs/intersection-search.md, "Neighbours a leaf pair at a time"). A
// triangle's corners are distinct vertices (one with a repeated corner is
// degenerate, boxed empty, in no pair), so the corners shared are counted by
// the corners of `first`'s triangle that any of `second`'s matches.
__attribute__((always_inline)) inline unsigned neighbours_adding_nothing(
    const LeafCorners& first, const LeafCorners& second) {
    using Four = std::uint32_t __attribute__((vector_size(16)));
    using Eight = std::uint32_t __attribute__((vector_size(32)));
    static_assert(BoxTree::kLeafSize == 4, "a leaf's lanes are four words");
    // Per corner l of `second`'s four lanes, twice over (two lanes of
    // `first` at once: bits 4 i to 4 i + 7), and of `first`'s (k): the
    // vertex, and its 6 bits of extremes. Comparisons give all bits set
    // where they hold.
    Eight second_vertex[3], second_extremes[3];
    Four first_vertex[3], first_extremes[3];
    Four extremes, own;
    std::memcpy(&extremes, second.extremes, sizeof extremes);
    std::memcpy(&own, first.extremes, sizeof own);
    // Unrolled: GCC kept these loops, and the vectors on the stack.
#pragma GCC unroll 3
    for (int l = 0; l < 3; ++l) {
        Four vertex;
        std::memcpy(&vertex, second.corner[l], sizeof vertex);
        second_vertex[l] = __builtin_shufflevector(vertex, vertex, 0, 1, 2, 3, 0, 1, 2, 3);
        const Four bits = extremes >> (6 * l) & 63;
        second_extremes[l] = __builtin_shufflevector(bits, bits, 0, 1, 2, 3, 0, 1, 2, 3);
        std::memcpy(&first_vertex[l], first.corner[l], sizeof first_vertex[l]);
        first_extremes[l] = own >> (6 * l) & 63;
    }
    const Four copies = Four(extremes >= LeafCorners::kHasCopies);
    const Four own_copies = Four(own >= LeafCorners::kHasCopies);
    // Lanes i and i + 1 of `first` against the four of `second` (i a
    // constant: the lanes to spread are a shuffle's operands).
    auto two_rows = [&](auto lane) __attribute__((always_inline)) {
        constexpr int i = decltype(lane)::value;
        Eight matched_first[3], matched_second[3] = {};  // which corner is shared
        Eight a = {};  // the shared corner's extremes in `first`'s triangle
#pragma GCC unroll 3
        for (int k = 0; k < 3; ++k) {
            // (Shuffles written out: a function returning an eight-lane
            // vector changes the ABI where AVX is not enabled.)
            const Eight vertex = __builtin_shufflevector(first_vertex[k], first_vertex[k], i, i, i,
                                                         i, i + 1, i + 1, i + 1, i + 1);
            const Eight hit0 = Eight(second_vertex[0] == vertex);
            const Eight hit1 = Eight(second_vertex[1] == vertex);
            const Eight hit2 = Eight(second_vertex[2] == vertex);
            matched_first[k] = hit0 | hit1 | hit2;
            matched_second[0] |= hit0;
            matched_second[1] |= hit1;
            matched_second[2] |= hit2;
            a |= matched_first[k] & __builtin_shufflevector(first_extremes[k], first_extremes[k], i,
                                                            i, i, i, i + 1, i + 1, i + 1, i + 1);
        }
        const Eight shared = -(matched_first[0] + matched_first[1] + matched_first[2]);
        const Eight b = (matched_second[0] & second_extremes[0]) |
                        (matched_second[1] & second_extremes[1]) |
                        (matched_second[2] & second_extremes[2]);
        // apart_at_shared_corner, with one corner shared (a and b then
        // each that corner's bits).
        const Eight apart = Eight(((a & b >> 3) | (a >> 3 & b)) != 0);
        const Eight with_copies =
            __builtin_shufflevector(copies, copies, 0, 1, 2, 3, 0, 1, 2, 3) |
            __builtin_shufflevector(own_copies, own_copies, i, i, i, i, i + 1, i + 1, i + 1, i + 1);
        const Eight adds_nothing =
            (Eight(shared == 2) | (Eight(shared == 1) & apart)) & ~with_copies;
        const Four low = __builtin_shufflevector(adds_nothing, adds_nothing, 0, 1, 2, 3);
        const Four high = __builtin_shufflevector(adds_nothing, adds_nothing, 4, 5, 6, 7);
        return (lanes_set(low) | lanes_set(high) << BoxTree::kLeafSize) << (BoxTree::kLeafSize * i);
    };
    return two_rows(std::integral_constant<int, 0>()) | two_rows(std::integral_constant<int, 2>());
}

}  // namespace polymass::core
