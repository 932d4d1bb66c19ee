// A few doubles processed as one value (GCC/Clang vector extension).
//
// The triangle kernel keeps its running sums in two lane groups (WideLanes,
// eight lanes): triangle i of a batch adds to lane i mod 8, so the order of
// every addition is fixed by the lanes alone. Narrower hardware computes one
// group (Lanes, lane_count triangles) at a time and adds it to the sums'
// groups in turn, wider hardware both at once: every instruction set gives
// the same bits. Baseline x86-64 code runs a Lanes operation as two SSE2
// instructions, the AVX2 kernel as one, the AVX-512 kernel a WideLanes
// operation as one. The shipped library is built for the baseline: wider code
// is only ever chosen at run time (instruction_sets.hpp).
//
// Loops over the axes or vertices of arrays of Lanes carry `#pragma GCC
// unroll 3` (Clang honours it too): at -O2 GCC keeps such a loop and, with its
// counter, the arrays in memory; unrolled, their elements live in registers.
#pragma once

#include <cstddef>
#include <cstring>

namespace polymass::core {

constexpr int lane_count = 4;
using Lanes = double __attribute__((vector_size(lane_count * sizeof(double))));
// Two lane groups: what one AVX-512 register holds.
using WideLanes = double __attribute__((vector_size(2 * lane_count * sizeof(double))));

// How many doubles, and how many lane groups, a vector of doubles holds.
template <class Vector>
constexpr int width_of = int(sizeof(Vector) / sizeof(double));
template <class Vector>
constexpr int groups_of = width_of<Vector> / lane_count;

// Lanes are passed by reference, never by value: a function compiled for
// another instruction set than its caller would disagree on how a vector is
// passed (GCC's -Wpsabi warning), and at -O0 nothing is inlined.

// Adds lane group `group` of a wider vector (or the whole of Lanes) to `sum`.
template <class Vector>
__attribute__((always_inline)) inline void add_lane_group(Lanes& sum, const Vector& vector,
                                                          int group) {
    Lanes lanes;
    std::memcpy(&lanes, reinterpret_cast<const char*>(&vector) + group * sizeof(Lanes),
                sizeof lanes);
    sum += lanes;
}

// A comparison of vectors gives one of these: all bits set in the lanes where it holds.
template <class Vector>
using MaskOf = decltype(Vector{} < Vector{});
using LaneMask = MaskOf<Lanes>;

// Whether any lane of a mask is set: halves or'ed together in registers (a
// mask stored whole and read back a lane at a time waits for the store to
// forward, on every lane group).
__attribute__((always_inline)) inline bool any_lane(const LaneMask& mask) {
    const auto pair =
        __builtin_shufflevector(mask, mask, 0, 1) | __builtin_shufflevector(mask, mask, 2, 3);
    return (pair[0] | pair[1]) != 0;
}

__attribute__((always_inline)) inline bool any_lane(const MaskOf<WideLanes>& mask) {
    const LaneMask half = __builtin_shufflevector(mask, mask, 0, 1, 2, 3) |
                          __builtin_shufflevector(mask, mask, 4, 5, 6, 7);
    return any_lane(half);
}

__attribute__((always_inline)) inline double sum_lanes(const Lanes& lanes) {
    double sum = 0.0;
    for (int lane = 0; lane < lane_count; ++lane) sum += lanes[lane];
    return sum;
}

// Adds `groups` lane groups of `term` (Lanes or WideLanes) to the lane groups
// of `sum` from `first_group` on: the whole register at once when they are
// all of it, else group by group.
template <class Vector>
__attribute__((always_inline)) inline void add_lane_groups(WideLanes& sum, const Vector& term,
                                                           int first_group, int groups) {
    if constexpr (sizeof(Vector) == sizeof(WideLanes)) {
        if (groups == groups_of<WideLanes>) {
            sum += term;
            return;
        }
    }
    for (int group = 0; group < groups; ++group) {
        Lanes lanes;
        std::memcpy(&lanes,
                    reinterpret_cast<const char*>(&sum) + (first_group + group) * sizeof(Lanes),
                    sizeof lanes);
        add_lane_group(lanes, term, group);
        std::memcpy(reinterpret_cast<char*>(&sum) + (first_group + group) * sizeof(Lanes), &lanes,
                    sizeof lanes);
    }
}

// The sum of a WideLanes' lanes: its two groups added lane by lane, then
// those four lanes, lane 0 first.
__attribute__((always_inline)) inline double sum_lanes(const WideLanes& lanes) {
    return sum_lanes(Lanes(__builtin_shufflevector(lanes, lanes, 0, 1, 2, 3) +
                           __builtin_shufflevector(lanes, lanes, 4, 5, 6, 7)));
}

}  // namespace polymass::core
