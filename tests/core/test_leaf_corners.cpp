// neighbours_adding_nothing, the contact search's test of a leaf pair's
// sixteen pairs at once, against the pair-at-a-time rule it replaces (the
// corners two triangles share, and for one shared corner whether the two
// lie on either side of an axis plane through it), on random leaves whose
// triangles share none, one, two or three corners in every lane and turn,
// some with copies; built for the baseline and, where the processor runs
// it, for AVX2 (as the walk that inlines it is).
#include "core/leaf_corners.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <random>

#include "check.hpp"
#include "core/instruction_sets.hpp"

namespace {

using polymass::core::BoxTree;
using polymass::core::InstructionSet;
using polymass::core::LeafCorners;

constexpr std::size_t kLanes = BoxTree::kLeafSize;

// The rule a pair at a time: lanes i of `first` and j of `second`.
bool adds_nothing(const LeafCorners& first, std::size_t i, const LeafCorners& second,
                  std::size_t j) {
    if ((first.extremes[i] | second.extremes[j]) & LeafCorners::kHasCopies) return false;
    int shared = 0, at_first = 0, at_second = 0;
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            if (first.corner[k][i] == second.corner[l][j]) {
                ++shared;
                at_first = k;
                at_second = l;
            }
    if (shared == 2) return true;
    if (shared != 1) return false;
    // Corner k's bits: 6 k + axis, highest on that axis; 6 k + 3 + axis, lowest.
    const std::uint32_t a = first.extremes[i] >> 6 * at_first & 63;
    const std::uint32_t b = second.extremes[j] >> 6 * at_second & 63;
    for (int axis = 0; axis < 3; ++axis) {
        const bool a_highest = a >> axis & 1, a_lowest = a >> (3 + axis) & 1;
        const bool b_highest = b >> axis & 1, b_lowest = b >> (3 + axis) & 1;
        if ((a_highest && b_lowest) || (a_lowest && b_highest)) return true;
    }
    return false;
}

unsigned expected(const LeafCorners& first, const LeafCorners& second) {
    unsigned bits = 0;
    for (std::size_t i = 0; i < kLanes; ++i)
        for (std::size_t j = 0; j < kLanes; ++j)
            bits |= unsigned(adds_nothing(first, i, second, j)) << (kLanes * i + j);
    return bits;
}

#if defined(__x86_64__)
__attribute__((target("avx2"))) unsigned neighbours_on_avx2(const LeafCorners& first,
                                                            const LeafCorners& second) {
    return polymass::core::neighbours_adding_nothing(first, second);
}
#endif

// Three distinct vertices from a pool of `pool` (small: pairs share corners
// often), in a random turn; random extremes; copies now and then.
LeafCorners random_leaf(std::mt19937& random, std::uint32_t pool) {
    std::uniform_int_distribution<std::uint32_t> vertex(0, pool - 1), bits(0, (1u << 18) - 1);
    std::bernoulli_distribution copies(0.08);
    LeafCorners leaf{};
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
        std::uint32_t v[3];
        v[0] = vertex(random);
        do v[1] = vertex(random);
        while (v[1] == v[0]);
        do v[2] = vertex(random);
        while (v[2] == v[0] || v[2] == v[1]);
        for (int k = 0; k < 3; ++k) leaf.corner[k][lane] = v[k];
        leaf.extremes[lane] = bits(random) | (copies(random) ? LeafCorners::kHasCopies : 0);
    }
    return leaf;
}

void random_leaves() {
    std::mt19937 random(45);
    long pairs = 0, wrong = 0, wrong_avx2 = 0, decided = 0;
    long shared_count[4] = {};
    const bool avx2 = polymass::core::runs_instruction_set(InstructionSet::avx2);
    for (int n = 0; n < 20000; ++n) {
        const std::uint32_t pool = n % 2 == 0 ? 5 : 12;
        const LeafCorners first = random_leaf(random, pool);
        const LeafCorners second = n % 50 == 0 ? first : random_leaf(random, pool);
        const unsigned want = expected(first, second);
        const unsigned got = polymass::core::neighbours_adding_nothing(first, second);
        wrong += got != want;
        if (got != want && wrong <= 3)
            std::fprintf(stderr, "  leaf pair %d: got %04x, expected %04x\n", n, got, want);
#if defined(__x86_64__)
        if (avx2) wrong_avx2 += neighbours_on_avx2(first, second) != want;
#endif
        for (std::size_t i = 0; i < kLanes; ++i)
            for (std::size_t j = 0; j < kLanes; ++j) {
                int shared = 0;
                for (int k = 0; k < 3; ++k)
                    for (int l = 0; l < 3; ++l) shared += first.corner[k][i] == second.corner[l][j];
                ++shared_count[shared];
                ++pairs;
            }
        decided += __builtin_popcount(want);
    }
    CHECK(wrong == 0);
    CHECK(wrong_avx2 == 0);
    // Every case met, and both answers, or the comparison proves little.
    CHECK(shared_count[0] > 0 && shared_count[1] > 0 && shared_count[2] > 0 && shared_count[3] > 0);
    CHECK(decided > pairs / 20 && decided < pairs - pairs / 20);
    std::printf(
        "  %ld pairs of random leaves (sharing 0/1/2/3 corners: %ld/%ld/%ld/%ld; %ld add "
        "nothing): %ld leaf pairs differ on the baseline, %ld on AVX2%s\n",
        pairs, shared_count[0], shared_count[1], shared_count[2], shared_count[3], decided, wrong,
        wrong_avx2, avx2 ? "" : " (not run here)");
}

}  // namespace

int main() {
    std::printf("leaf corners:\n");
    random_leaves();
    return polymass_test::finish("test_leaf_corners");
}
