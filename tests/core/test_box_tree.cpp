// BoxTree's search for overlapping pairs against a sweep along x, on more
// boxes than one block of its construction takes (so that the blocks' box
// of all, leaves and levels are joined across blocks), built on the calling
// thread and on a runner that runs its blocks last first: every overlapping
// pair once, none else, and the same tree for both; on trees of every small
// size, the items near segments too; and the walk built for each
// instruction set against the baseline's and against every pair.
#include "core/box_tree.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <memory_resource>
#include <random>
#include <vector>

#include "check.hpp"
#include "reversed_task_runner.hpp"

namespace {

using polymass::core::BoxTree;
using polymass::core::FloatBox;
using polymass::core::InstructionSet;
using Pair = std::array<std::uint32_t, 2>;

// Boxes along a slab `width` wide and high, long enough that a sweep along
// it tests few pairs; every 97th empty (it meets nothing), and some repeated.
// (A flat slab, or a line, has an axis of no extent: its cells are one.)
std::vector<FloatBox> random_boxes(std::size_t count, double width = 1.0, double high = 1.0) {
    std::mt19937 random(31);
    std::uniform_real_distribution<double> along(0.0, 300.0), across(0.0, width), up(0.0, high),
        size(0.0, 0.1);
    std::vector<FloatBox> boxes(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (i % 97 == 0) continue;
        if (i % 89 == 0) {
            boxes[i] = boxes[i - 1];
            continue;
        }
        const Eigen::Vector3d lo(along(random), across(random), up(random));
        const Eigen::Vector3d step(size(random), width > 0 ? size(random) : 0,
                                   high > 0 ? size(random) : 0);
        boxes[i] = FloatBox::spanning(lo, lo + step);
    }
    return boxes;
}

std::vector<Pair> pairs_of(const BoxTree& tree) {
    std::vector<Pair> pairs;
    for (const BoxTree::PairTask& piece : tree.pair_tasks())
        tree.for_each_overlapping_pair(piece, [&](std::uint32_t i, std::uint32_t j) {
            pairs.push_back({std::min(i, j), std::max(i, j)});
        });
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// Every overlapping pair, by testing every pair, in ascending order.
std::vector<Pair> every_pair(const std::vector<FloatBox>& boxes) {
    std::vector<Pair> pairs;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
            if (boxes[i].overlaps(boxes[j])) pairs.push_back({i, j});
    return pairs;
}

// Every overlapping pair, by a sweep of the boxes in order of their low x.
std::vector<Pair> sweep(const std::vector<FloatBox>& boxes) {
    std::vector<std::uint32_t> order;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].lo[0] <= boxes[i].hi[0]) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return boxes[a].lo[0] < boxes[b].lo[0]; });
    std::vector<Pair> pairs;
    for (std::size_t m = 0; m < order.size(); ++m)
        for (std::size_t n = m + 1; n < order.size(); ++n) {
            const FloatBox &a = boxes[order[m]], &b = boxes[order[n]];
            if (b.lo[0] > a.hi[0]) break;
            if (a.overlaps(b))
                pairs.push_back({std::min(order[m], order[n]), std::max(order[m], order[n])});
        }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

bool same_box(const FloatBox& a, const FloatBox& b) { return a.lo == b.lo && a.hi == b.hi; }

void check_pairs_across_blocks() {
    // Five blocks of items, two of leaves.
    const std::vector<FloatBox> boxes = random_boxes(270000);
    const std::vector<Pair> expected = sweep(boxes);
    std::pmr::memory_resource* memory = std::pmr::get_default_resource();
    polymass::core::SerialTaskRunner one_thread;
    const BoxTree serial(std::pmr::vector<FloatBox>(boxes.begin(), boxes.end(), memory), memory,
                         one_thread);
    polymass_test::ReversedTaskRunner reversed;
    const BoxTree blocks_reversed(std::pmr::vector<FloatBox>(boxes.begin(), boxes.end(), memory),
                                  memory, reversed);
    CHECK(expected.size() > boxes.size() / 4);  // many boxes meet another
    CHECK(pairs_of(serial) == expected);
    CHECK(pairs_of(blocks_reversed) == expected);
    FloatBox all;
    for (const FloatBox& box : boxes) all.extend(box);
    CHECK(same_box(serial.bounds(), all));
    CHECK(same_box(blocks_reversed.bounds(), all));
}

// The tree's Morton grid on boxes of every shape, against the sweep: a slab
// far thinner than long (cells far from cubic), a flat one and a line (an
// axis of no extent, whose places are NaN: cell 0), and boxes at one point
// (every code 0).
void check_pairs_of_shapes() {
    std::pmr::memory_resource* memory = std::pmr::get_default_resource();
    polymass::core::SerialTaskRunner one_thread;
    const std::vector<FloatBox> shapes[] = {
        random_boxes(20000, 0.01, 0.001), random_boxes(20000, 1.0, 0.0),
        random_boxes(20000, 0.0, 0.0),
        std::vector<FloatBox>(
            1000, FloatBox::spanning(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3)))};
    for (const std::vector<FloatBox>& boxes : shapes) {
        const BoxTree tree(std::pmr::vector<FloatBox>(boxes.begin(), boxes.end(), memory), memory,
                           one_thread);
        const std::vector<Pair> expected = sweep(boxes);
        CHECK(!expected.empty());
        CHECK(pairs_of(tree) == expected);
    }
}

// Trees of every size up to 100 items, so that levels of odd and even size
// come at every height (a level of odd size ends in an empty node): boxes
// crowded in a unit cube, every 7th empty and, for even sizes, the last five
// too (a leaf, or a node, of empty boxes only). Every overlapping pair
// against all pairs, and the items near segments against every item's test.
void check_every_small_size() {
    std::pmr::memory_resource* memory = std::pmr::get_default_resource();
    polymass::core::SerialTaskRunner one_thread;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> place(0.0, 1.0), size(0.0, 0.3);
    for (std::size_t count = 0; count <= 100; ++count) {
        std::vector<FloatBox> boxes(count);
        for (std::size_t i = 0; i < count; ++i) {
            if (i % 7 == 3 || (count % 2 == 0 && i + 5 >= count)) continue;
            const Eigen::Vector3d lo(place(random), place(random), place(random));
            boxes[i] = FloatBox::spanning(
                lo, lo + Eigen::Vector3d(size(random), size(random), size(random)));
        }
        const BoxTree tree(std::pmr::vector<FloatBox>(boxes.begin(), boxes.end(), memory), memory,
                           one_thread);
        const std::vector<Pair> expected = every_pair(boxes);
        CHECK(pairs_of(tree) == expected);
        for (int segment = 0; segment < 10; ++segment) {
            const Eigen::Vector3d a(place(random), place(random), place(random)),
                b(place(random), place(random), place(random));
            // The tree pads its boxes by a millionth of their extent (at
            // most 1.3 here): no more than a hundredth.
            const polymass::core::SegmentSlabs exact(a, b, 0.0), padded(a, b, 0.01);
            std::vector<std::uint32_t> near;
            tree.for_each_item_near_segment(a, b, [&](std::uint32_t i) {
                near.push_back(i);
                return true;
            });
            std::sort(near.begin(), near.end());
            CHECK(std::adjacent_find(near.begin(), near.end()) == near.end());
            for (std::uint32_t i = 0; i < count; ++i) {
                const bool found = std::binary_search(near.begin(), near.end(), i);
                CHECK(found || !exact.may_meet(boxes[i]));
                CHECK(!found || padded.may_meet(boxes[i]));
            }
        }
    }
}

// The visits of the walk built for `set`, in their order, until the
// `budget`-th (a visit then returns false: the walk must stop there).
std::vector<Pair> visits_of(const BoxTree& tree, InstructionSet set,
                            std::size_t budget = SIZE_MAX) {
    std::vector<Pair> visits;
    for (const BoxTree::PairTask& piece : tree.pair_tasks()) {
        const bool within_budget = tree.for_each_overlapping_pair(
            piece,
            [&](std::uint32_t i, std::uint32_t j) {
                visits.push_back({i, j});
                return visits.size() < budget;
            },
            set);
        if (!within_budget) break;
    }
    return visits;
}

// Every instruction set's walk visits the pairs the baseline's does, in its
// order (the nesting keeps its pairs in the order they come), and stops
// where it does; and those are every overlapping pair once, against the
// test of every pair. On boxes that make the leaves' masks hard: empty
// ones, boxes on a grid touching their neighbours at a face, an edge or a
// corner (equal bounds), leaves full of one box repeated (every lane meets
// every lane), and sizes that leave levels of odd size and part-full leaves.
void check_instruction_sets_alike() {
    std::pmr::memory_resource* memory = std::pmr::get_default_resource();
    polymass::core::SerialTaskRunner one_thread;
    std::mt19937 random(11);
    std::uniform_int_distribution<int> cell(0, 5), kind(0, 9);
    std::size_t checked = 0;
    for (std::size_t count : {1, 2, 3, 5, 8, 13, 31, 64, 97, 333, 1000, 4099}) {
        std::vector<FloatBox> boxes(count);
        for (std::size_t i = 0; i < count; ++i) {
            const int what = kind(random);
            if (what == 0) continue;  // empty
            if (what <= 3 && i > 0) {
                boxes[i] = boxes[i - 1];  // repeated
                continue;
            }
            // Unit cubes, or flat and thin ones, on a grid: neighbours
            // touch at equal bounds.
            const Eigen::Vector3d lo(cell(random), cell(random), cell(random));
            const Eigen::Vector3d size(what == 4 ? 0 : 1, what == 5 ? 0 : 1, 1);
            boxes[i] = FloatBox::spanning(lo, lo + size);
        }
        const BoxTree tree(std::pmr::vector<FloatBox>(boxes.begin(), boxes.end(), memory), memory,
                           one_thread);
        const std::vector<Pair> expected = every_pair(boxes);
        const std::vector<Pair> baseline = visits_of(tree, InstructionSet::baseline);
        std::vector<Pair> found;
        for (const Pair& pair : baseline)
            found.push_back({std::min(pair[0], pair[1]), std::max(pair[0], pair[1])});
        std::sort(found.begin(), found.end());
        CHECK(found == expected);
        for (InstructionSet set : {InstructionSet::avx2, InstructionSet::avx512}) {
            if (!polymass::core::runs_instruction_set(set)) continue;
            ++checked;
            CHECK(visits_of(tree, set) == baseline);
            const std::size_t budget = baseline.size() / 3 + 1;
            CHECK(visits_of(tree, set, budget) ==
                  visits_of(tree, InstructionSet::baseline, budget));
        }
    }
    std::printf("test_box_tree: %zu walks of other instruction sets compared\n", checked);
}

}  // namespace

int main() {
    check_pairs_across_blocks();
    check_pairs_of_shapes();
    check_every_small_size();
    check_instruction_sets_alike();
    return polymass_test::finish("test_box_tree");
}
