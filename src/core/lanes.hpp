// A few doubles processed as one value (GCC/Clang vector extension).
//
// Baseline x86-64 code runs a Lanes operation as two SSE2 instructions; the
// x86-64-v3 clone of a function (see mesh_integration.cpp) as one AVX
// instruction. The shipped library is built for the baseline: wider code is
// only ever chosen at run time.
//
// Loops over the axes or vertices of arrays of Lanes carry `#pragma GCC
// unroll 3` (Clang honours it too): at -O2 GCC keeps such a loop and, with its
// counter, the arrays in memory; unrolled, their elements live in registers.
#pragma once

#include <cstring>

namespace polymass::core {

constexpr int lane_count = 4;
using Lanes = double __attribute__((vector_size(lane_count * sizeof(double))));

// Lanes are passed by reference, never by value: a function compiled for
// another instruction set than its caller would disagree on how a vector is
// passed (GCC's -Wpsabi warning), and at -O0 nothing is inlined.
__attribute__((always_inline)) inline void load_lanes(Lanes& lanes, const double* values) {
    std::memcpy(&lanes, values, sizeof lanes);
}

// A comparison of Lanes gives one of these: all bits set in the lanes where it holds.
using LaneMask = decltype(Lanes{} < Lanes{});

__attribute__((always_inline)) inline bool any_lane(const LaneMask& mask) {
    auto any = mask[0];
    for (int lane = 1; lane < lane_count; ++lane) any |= mask[lane];
    return any != 0;
}

__attribute__((always_inline)) inline double sum_lanes(const Lanes& lanes) {
    double sum = 0.0;
    for (int lane = 0; lane < lane_count; ++lane) sum += lanes[lane];
    return sum;
}

}  // namespace polymass::core
