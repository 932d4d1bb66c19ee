// A bounding-volume hierarchy over boxes, for finding which of many items
// (a surface's triangles) can touch each other, or a segment, without
// comparing every pair.
//
// Items are ordered along a Morton (Z-order) curve of their boxes' centres,
// grouped by four into leaves, and the tree above them is implicit: node i of
// a level holds nodes 2i and 2i + 1 of the level below (a level of odd size
// but the root's ends in an empty node, so that every node has two
// children). Building it is a radix sort and one pass per level; no
// pointers, no per-node allocation.
//
// Boxes are single precision, taken about a point near the items (a surface
// far from the origin keeps small relative coordinates) and rounded outward,
// so a box always contains its item: the tree may report a pair that does not
// touch, never miss one that does.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory_resource>
#include <type_traits>
#include <vector>

#include "instruction_sets.hpp"
#include "task_runner.hpp"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace polymass::core {

struct FloatBox {
    std::array<float, 3> lo{INFINITY, INFINITY, INFINITY};
    std::array<float, 3> hi{-INFINITY, -INFINITY, -INFINITY};  // empty: meets nothing

    // The box from lo to hi (about the tree's reference point), rounded outward.
    static FloatBox spanning(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
        FloatBox box;
        for (int k = 0; k < 3; ++k) {
            box.lo[k] = below(lo[k]);
            box.hi[k] = above(hi[k]);
        }
        return box;
    }
    // Grows to contain p (given about the tree's reference point).
    void extend(const Eigen::Vector3d& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], below(p[k]));
            hi[k] = std::max(hi[k], above(p[k]));
        }
    }
    void extend(const FloatBox& box) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], box.lo[k]);
            hi[k] = std::max(hi[k], box.hi[k]);
        }
    }
    bool overlaps(const FloatBox& other) const {
        return lo[0] <= other.hi[0] && other.lo[0] <= hi[0] && lo[1] <= other.hi[1] &&
               other.lo[1] <= hi[1] && lo[2] <= other.hi[2] && other.lo[2] <= hi[2];
    }

private:
    // x rounded down (up) to a float. Rounding to nearest is off by at most
    // half a step, so one step of relative size 2^-23, or the smallest
    // subnormal near zero, always covers it; cheaper than nextafter.
    static float below(double x) {
        const float f = float(x);
        return double(f) > x ? f - std::max(std::abs(f) * 0x1p-23f, 0x1p-149f) : f;
    }
    static float above(double x) {
        const float f = float(x);
        return double(f) < x ? f + std::max(std::abs(f) * 0x1p-23f, 0x1p-149f) : f;
    }
};

// A segment from a to b (about the tree's reference point), tested against
// many boxes by the slab method, each box grown by `pad` against rounding:
// the reciprocals of its steps are taken once, not divided by at every box.
class SegmentSlabs {
public:
    SegmentSlabs(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double pad);
    // Whether the segment may meet the box.
    bool may_meet(const FloatBox& box) const;

private:
    Eigen::Vector3d from_, step_, reciprocal_;
    double pad_;
};

class BoxTree {
public:
    // The items are the boxes' indices. The tree keeps the boxes in its
    // order along the curve and side by side by leaf (LeafBoxes): the search
    // reads a leaf's boxes one after another, where reading them through
    // their indices missed the cache about once a box on a large surface.
    // It takes the boxes and lets them go once they are in its leaves, before
    // its nodes are built: the boxes, their leaves and the nodes together
    // were the intersection check's peak of memory. Its passes over the
    // items run in fixed blocks on `tasks` (the same tree for every
    // runner).
    BoxTree(std::pmr::vector<FloatBox> boxes, std::pmr::memory_resource* memory, TaskRunner& tasks);

    // The box of every item (empty when there are none).
    FloatBox bounds() const { return order_.empty() ? FloatBox() : box(root()); }

    // A piece of the search for overlapping pairs: the pairs inside one node
    // (first == second), or between two nodes whose boxes overlap.
    struct Node {
        std::uint32_t level, index;
    };
    struct PairTask {
        Node first, second;
    };

    // The search for overlapping pairs cut into pieces by the tree alone,
    // never by the number of threads, so that pieces run on any number of
    // threads and combined in their order give the same result. Together
    // they visit each overlapping pair once; a tree of at most
    // kLeafSize * 2^kPieceLevel items is one piece.
    std::pmr::vector<PairTask> pair_tasks() const;

    // visit(i, j) once for each pair of distinct items of `task` whose boxes
    // overlap; a visit returning bool ends the walk when it returns false
    // (a caller with a budget of pairs). False when a visit ended it. The
    // walk is built for each instruction set and `set` chooses it; every
    // one visits the same pairs in the same order.
    template <class Visit>
    bool for_each_overlapping_pair(PairTask task, Visit&& visit,
                                   InstructionSet set = widest_instruction_set()) const;

    // The same search a leaf pair at a time: visit_leaves(first, second,
    // overlapping) for each pair of leaves (first == second: a leaf with
    // itself) with an overlapping pair of items, bit kLeafSize i + j of
    // `overlapping` set when item leaf_item(first, i) overlaps
    // leaf_item(second, j) (within one leaf, only j > i). For a caller that
    // decides many of a leaf pair's items at once (the contact search's
    // neighbours). The walk ends when a visit returns false; false then.
    template <class VisitLeaves>
    bool for_each_overlapping_leaf_pair(PairTask task, VisitLeaves&& visit_leaves,
                                        InstructionSet set = widest_instruction_set()) const;

    // visit(i, j) for each pair of items that the bits of `overlapping` name
    // (a mask as for_each_overlapping_leaf_pair gives), lowest bit first; a
    // visit returning bool ends it when it returns false, and false then.
    template <class Visit>
    bool for_each_pair_of(std::uint32_t first, std::uint32_t second, unsigned overlapping,
                          Visit&& visit) const;

    // Items a leaf holds, and the item in lane `lane` of `leaf` (along the
    // curve: leaf l holds items kLeafSize l to kLeafSize (l + 1) - 1 of it;
    // the last leaf's lanes past the last item are empty).
    static constexpr std::size_t kLeafSize = 4;
    std::size_t leaf_count() const { return leaf_boxes_.size(); }
    std::size_t item_count() const { return order_.size(); }
    std::uint32_t leaf_item(std::size_t leaf, std::size_t lane) const {
        return order_[kLeafSize * leaf + lane];
    }

    // visit(i) for each item whose box may meet the segment from a to b,
    // until a visit returns false.
    template <class Visit>
    void for_each_item_near_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    Visit&& visit) const;

private:
    // Pieces of pair_tasks() reach no higher than this level (4096 items):
    // a million triangles give a few hundred pieces, enough to share among
    // threads; the pieces of a small surface are one.
    static constexpr std::uint32_t kPieceLevel = 10;

    // The boxes of a leaf, one lane each, so that one box is tested against
    // the four of another leaf at once (overlap_masks): tested one pair at
    // a time, the leaf tests' branches, taken at random, were a third of a
    // clean surface's search. Lanes past the last item hold empty boxes,
    // which meet nothing.
    struct LeafBoxes {
        alignas(sizeof(float) * kLeafSize) float lo[3][kLeafSize];
        alignas(sizeof(float) * kLeafSize) float hi[3][kLeafSize];
    };
    // Bit kLeafSize i + j set when lane i of `first` overlaps lane j of
    // `second` (the test of FloatBox::overlaps): each lane of `first`
    // broadcast against the lanes of `second`, all of them before any pair
    // is visited, so that the lanes stay in registers (a visit is a call,
    // after which they were loaded again, and the broadcast box recomputed
    // from its index: 60 instructions a box, now under 30). With
    // `eight_lanes` (only where the walk is built for AVX2), two lanes of
    // `first` at once, each against the four of `second`: the same bits in
    // half the vector operations.
    template <bool eight_lanes>
    __attribute__((always_inline)) static inline unsigned overlap_masks(const LeafBoxes& first,
                                                                        const LeafBoxes& second);
    // The bits of overlap_masks for the pairs (i, j) with j > i: inside one
    // leaf, each pair once.
    static constexpr unsigned later_lanes() {
        unsigned bits = 0;
        for (std::size_t i = 0; i < kLeafSize; ++i)
            for (std::size_t j = i + 1; j < kLeafSize; ++j) bits |= 1u << (kLeafSize * i + j);
        return bits;
    }
    // The box of the item at `at` along the curve.
    FloatBox item_box(std::size_t at) const;

    static bool same(const PairTask& task) {
        return task.first.level == task.second.level && task.first.index == task.second.index;
    }
    // Calls push(t) for the tasks that together do `task`, which must not be
    // two leaves: the children of a node with themselves and with each
    // other, or each child of one node with each of the other's, where
    // their boxes overlap (an empty child, ending a level, meets nothing:
    // not even itself). Inlined: called once per task of the search, as a
    // call it added 2 % to the instructions of a sphere's intersection check.
    template <class Push>
    __attribute__((always_inline)) inline void split(const PairTask& task, Push&& push) const;

    // for_each_overlapping_leaf_pair's walk, its leaf pairs' masks taken on
    // eight lanes or four; one body, built for the baseline inline in
    // for_each_overlapping_leaf_pair and for AVX2 in walk_avx2 (into which
    // the visit is inlined, built for AVX2 with it).
    template <bool eight_lanes, class VisitLeaves>
    __attribute__((always_inline)) inline bool walk(PairTask task, VisitLeaves& visit_leaves) const;
#if defined(__x86_64__)
    template <class VisitLeaves>
    __attribute__((target("avx2"))) bool walk_avx2(PairTask task, VisitLeaves& visit_leaves) const;
#endif

    const FloatBox& box(Node node) const { return nodes_[level_begin_[node.level] + node.index]; }
    static bool empty(const FloatBox& box) { return !(box.lo[0] <= box.hi[0]); }
    Node child(Node node, std::size_t which) const {
        return {node.level - 1, std::uint32_t(2 * node.index + which)};
    }
    // The items of a leaf: order_[first, last).
    std::size_t leaf_first(Node leaf) const { return kLeafSize * leaf.index; }
    std::size_t leaf_last(Node leaf) const {
        return std::min(order_.size(), kLeafSize * (leaf.index + 1));
    }
    Node root() const { return {std::uint32_t(level_begin_.size() - 2), 0}; }

    std::pmr::vector<std::uint32_t> order_;      // items along the curve
    std::pmr::vector<LeafBoxes> leaf_boxes_;     // their boxes, in that order
    std::pmr::vector<FloatBox> nodes_;           // every level, leaves first
    std::pmr::vector<std::size_t> level_begin_;  // level k is nodes_[begin[k], begin[k + 1])
    double pad_ = 0;                             // slack of segment tests
    std::pmr::memory_resource* memory_;
};

template <class Push>
void BoxTree::split(const PairTask& task, Push&& push) const {
    const auto [a, b] = task;
    if (same(task)) {
        push(PairTask{child(a, 0), child(a, 0)});
        if (!empty(box(child(a, 1)))) {
            push(PairTask{child(a, 1), child(a, 1)});
            if (box(child(a, 0)).overlaps(box(child(a, 1))))
                push(PairTask{child(a, 0), child(a, 1)});
        }
        return;
    }
    // Two nodes of one level (all leaves are at level 0, so a task's nodes
    // always are): each child of one with each of the other, one task a
    // level rather than two (the children of one with the other node, then
    // of that node), which cut the search's tasks by half. Two children
    // each, always: counting them (the last node of a level of odd size had
    // one) took a sixth of the instructions of the walk's node tasks.
    for (std::size_t i = 0; i < 2; ++i) {
        const FloatBox& child_of_a = box(child(a, i));
        for (std::size_t j = 0; j < 2; ++j)
            if (child_of_a.overlaps(box(child(b, j)))) push(PairTask{child(a, i), child(b, j)});
    }
}

template <bool eight_lanes>
inline unsigned BoxTree::overlap_masks(const LeafBoxes& first, const LeafBoxes& second) {
    static_assert(kLeafSize == 4, "a leaf's lanes are four floats");
    using Lanes = float __attribute__((vector_size(sizeof(float) * kLeafSize)));
    using Mask = std::int32_t __attribute__((vector_size(sizeof(float) * kLeafSize)));
    Lanes lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        std::memcpy(&lo[k], second.lo[k], sizeof lo[k]);
        std::memcpy(&hi[k], second.hi[k], sizeof hi[k]);
    }
#if defined(__x86_64__)
    if constexpr (eight_lanes) {
        // Lanes i and i + 1 of `first`, each in four lanes, against `second`
        // twice: the eight lanes' results are bits 4 i to 4 i + 7.
        using Wide = float __attribute__((vector_size(2 * sizeof(float) * kLeafSize)));
        using WideMask = std::int32_t __attribute__((vector_size(2 * sizeof(float) * kLeafSize)));
        Wide wide_lo[3], wide_hi[3];
        // Unrolled: GCC kept these loops, and the vectors on the stack.
#pragma GCC unroll 3
        for (int k = 0; k < 3; ++k) {
            wide_lo[k] = __builtin_shufflevector(lo[k], lo[k], 0, 1, 2, 3, 0, 1, 2, 3);
            wide_hi[k] = __builtin_shufflevector(hi[k], hi[k], 0, 1, 2, 3, 0, 1, 2, 3);
        }
        // Lanes i and i + 1 of `first` (i a constant: the lanes to spread
        // are a shuffle's operands) against `second`.
        auto two_lanes = [&](auto first_lane) {
            constexpr int i = decltype(first_lane)::value;
            WideMask overlapping = WideMask{} - 1;
#pragma GCC unroll 3
            for (int k = 0; k < 3; ++k) {
                Lanes box_lo, box_hi;
                std::memcpy(&box_lo, first.lo[k], sizeof box_lo);
                std::memcpy(&box_hi, first.hi[k], sizeof box_hi);
                const Wide two_lo =
                    __builtin_shufflevector(box_lo, box_lo, i, i, i, i, i + 1, i + 1, i + 1, i + 1);
                const Wide two_hi =
                    __builtin_shufflevector(box_hi, box_hi, i, i, i, i, i + 1, i + 1, i + 1, i + 1);
                overlapping &= (wide_lo[k] <= two_hi) & (two_lo <= wide_hi[k]);
            }
            // Each half's sign bits (movmskps): the eight-lane form is an
            // AVX intrinsic, which the walk's one body cannot call.
            const Mask low = __builtin_shufflevector(overlapping, overlapping, 0, 1, 2, 3);
            const Mask high = __builtin_shufflevector(overlapping, overlapping, 4, 5, 6, 7);
            return (unsigned(_mm_movemask_ps(_mm_castsi128_ps(__m128i(low)))) |
                    unsigned(_mm_movemask_ps(_mm_castsi128_ps(__m128i(high)))) << kLeafSize)
                   << kLeafSize * i;
        };
        return two_lanes(std::integral_constant<int, 0>()) |
               two_lanes(std::integral_constant<int, 2>());
    }
#endif
    unsigned bits = 0;
    for (std::size_t lane = 0; lane < kLeafSize; ++lane) {
        Mask overlapping = Mask{} - 1;
        for (int k = 0; k < 3; ++k) {
            const float box_lo = first.lo[k][lane], box_hi = first.hi[k][lane];
            overlapping &= (lo[k] <= Lanes{box_hi, box_hi, box_hi, box_hi}) &
                           (Lanes{box_lo, box_lo, box_lo, box_lo} <= hi[k]);
        }
#if defined(__SSE2__)
        // The lanes' sign bits in one instruction, where the loop below
        // took fourteen.
        bits |= unsigned(_mm_movemask_ps(_mm_castsi128_ps(__m128i(overlapping))))
                << (kLeafSize * lane);
#else
        for (std::size_t j = 0; j < kLeafSize; ++j)
            bits |= (unsigned(overlapping[j]) & 1u) << (kLeafSize * lane + j);
#endif
    }
    return bits;
}

inline FloatBox BoxTree::item_box(std::size_t at) const {
    const LeafBoxes& leaf = leaf_boxes_[at / kLeafSize];
    FloatBox box;
    for (int k = 0; k < 3; ++k) {
        box.lo[k] = leaf.lo[k][at % kLeafSize];
        box.hi[k] = leaf.hi[k][at % kLeafSize];
    }
    return box;
}

template <class Visit>
bool BoxTree::for_each_overlapping_pair(PairTask task, Visit&& visit, InstructionSet set) const {
    auto each_pair = [&](std::uint32_t first, std::uint32_t second, unsigned overlapping)
        __attribute__((always_inline)) {
        return for_each_pair_of(first, second, overlapping, visit);
    };
    return for_each_overlapping_leaf_pair(task, each_pair, set);
}

template <class Visit>
__attribute__((always_inline)) inline bool BoxTree::for_each_pair_of(std::uint32_t first,
                                                                     std::uint32_t second,
                                                                     unsigned overlapping,
                                                                     Visit&& visit) const {
    constexpr bool may_stop =
        std::is_same_v<std::invoke_result_t<Visit&, std::uint32_t, std::uint32_t>, bool>;
    for (; overlapping != 0; overlapping &= overlapping - 1) {
        const unsigned bit = unsigned(__builtin_ctz(overlapping));
        const std::uint32_t i = leaf_item(first, bit / kLeafSize);
        const std::uint32_t j = leaf_item(second, bit % kLeafSize);
        if constexpr (may_stop) {
            if (!visit(i, j)) return false;
        } else {
            visit(i, j);
        }
    }
    return true;
}

template <class VisitLeaves>
bool BoxTree::for_each_overlapping_leaf_pair(PairTask task, VisitLeaves&& visit_leaves,
                                             InstructionSet set) const {
#if defined(__x86_64__)
    if (set != InstructionSet::baseline) return walk_avx2(task, visit_leaves);
#endif
    return walk<false>(task, visit_leaves);
}

#if defined(__x86_64__)
template <class VisitLeaves>
bool BoxTree::walk_avx2(PairTask task, VisitLeaves& visit_leaves) const {
    return walk<true>(task, visit_leaves);
}
#endif

template <bool eight_lanes, class VisitLeaves>
bool BoxTree::walk(PairTask task, VisitLeaves& visit_leaves) const {
    // Depth first: a task adds at most four, each one level lower, so the
    // stack holds fewer than four per level.
    constexpr std::size_t kMaxTasks = 4 * 64;
    std::array<PairTask, kMaxTasks> tasks;
    std::size_t pending = 0;
    tasks[pending++] = task;
    while (pending > 0) {
        const PairTask next = tasks[--pending];
        const auto [a, b] = next;
        if (a.level > 0 || b.level > 0) {
            split(next, [&](const PairTask& part) { tasks[pending++] = part; });
            continue;
        }
        unsigned overlapping =
            overlap_masks<eight_lanes>(leaf_boxes_[a.index], leaf_boxes_[b.index]);
        if (same(next)) overlapping &= later_lanes();
        if (overlapping != 0 && !visit_leaves(a.index, b.index, overlapping)) return false;
    }
    return true;
}

template <class Visit>
void BoxTree::for_each_item_near_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                         Visit&& visit) const {
    if (order_.empty()) return;
    const SegmentSlabs segment(a, b, pad_);
    // Depth first: one node pending per level at most, besides the one opened.
    std::array<Node, 2 * 64> nodes;
    std::size_t pending = 0;
    nodes[pending++] = root();
    while (pending > 0) {
        const Node node = nodes[--pending];
        if (!segment.may_meet(box(node))) continue;  // the empty end of a level too
        if (node.level == 0) {
            for (std::size_t i = leaf_first(node); i < leaf_last(node); ++i)
                if (segment.may_meet(item_box(i)) && !visit(order_[i])) return;
        } else {
            for (std::size_t i = 0; i < 2; ++i) nodes[pending++] = child(node, i);
        }
    }
}

}  // namespace polymass::core
