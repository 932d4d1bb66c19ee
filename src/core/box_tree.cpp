#include "box_tree.hpp"

#include "radix_sort.hpp"
#include "scratch_buffer.hpp"

namespace polymass::core {
namespace {

// Spreads the low 10 bits of v so that two zero bits follow each one.
std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

}  // namespace

SegmentSlabs::SegmentSlabs(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double pad)
    : from_(a), step_(b - a), reciprocal_(step_.cwiseInverse()), pad_(pad) {}

bool SegmentSlabs::may_meet(const FloatBox& box) const {
    // An empty box meets nothing; its infinite bounds would pass every slab.
    if (!(box.lo[0] <= box.hi[0])) return false;
    double enter = 0.0, leave = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double low = double(box.lo[k]) - pad_, high = double(box.hi[k]) + pad_;
        if (step_[k] == 0) {
            if (from_[k] < low || from_[k] > high) return false;
            continue;
        }
        // Times a rounded reciprocal rather than divided: two roundings, a
        // few ulps of the segment's length, far below the pad.
        double t0 = (low - from_[k]) * reciprocal_[k], t1 = (high - from_[k]) * reciprocal_[k];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (!(enter <= leave)) return false;
    }
    return true;
}

BoxTree::BoxTree(std::pmr::vector<FloatBox> boxes, std::pmr::memory_resource* memory,
                 TaskRunner& tasks)
    : order_(memory), leaf_boxes_(memory), nodes_(memory), level_begin_(memory), memory_(memory) {
    // Every pass but the radix sort runs in blocks: on one thread the tree
    // was about a tenth of a million-triangle check, and on two threads,
    // run alone, it held the check to 1.65 times one thread's rate.
    const std::size_t items = boxes.size();
    auto in_blocks = [&](std::size_t count, const auto& visit) {
        for_each_in_blocks(count, kItemsPerBlock, tasks, visit);
    };
    // The box of all: each block's, then theirs in block order.
    std::pmr::vector<FloatBox> block_bounds(block_count(items, kItemsPerBlock), memory);
    for_each_in_numbered_blocks(
        items, kItemsPerBlock, tasks,
        [&](std::size_t block, std::size_t item) { block_bounds[block].extend(boxes[item]); });
    FloatBox all;
    for (const FloatBox& box : block_bounds) all.extend(box);
    // Morton codes of the centres on a 1024^3 grid over all boxes, each with
    // its item below it, sorted together.
    std::pmr::vector<std::uint64_t> keys(items, memory);  // let go below
    double width[3], extent = 0;
    for (int k = 0; k < 3; ++k) {
        width[k] = double(all.hi[k]) - double(all.lo[k]);
        extent = std::max(extent, width[k]);
    }
    in_blocks(items, [&](std::size_t item) {
        const FloatBox& box = boxes[item];
        std::uint32_t code = 0;
        if (box.lo[0] <= box.hi[0]) {  // empty boxes anywhere: they meet nothing
            for (int k = 0; k < 3; ++k) {
                // The centre's place across the width, divided rather than
                // scaled (1023 / width overflows for a subnormal width); a
                // NaN from an infinite width goes to cell 0, not into a cast.
                const double centre = 0.5 * (double(box.lo[k]) + double(box.hi[k]));
                const double across = (centre - double(all.lo[k])) / width[k];
                const double cell = across > 0 ? std::min(1023.0 * across, 1023.0) : 0.0;
                code |= spread_bits(std::uint32_t(cell)) << k;
            }
        }
        keys[item] = std::uint64_t{code} << 32 | item;
    });
    radix_sort_high_half(keys.data(), keys.data() + keys.size(), memory);
    order_.resize(items);
    in_blocks(items, [&](std::size_t at) { order_[at] = std::uint32_t(keys[at]); });
    let_go(keys);

    // Leaves, then each level from the one below, up to a single root.
    std::size_t count = (items + kLeafSize - 1) / kLeafSize;
    leaf_boxes_.resize(count);
    in_blocks(count, [&](std::size_t leaf) {
        for (std::size_t lane = 0; lane < kLeafSize; ++lane) {
            const std::size_t at = kLeafSize * leaf + lane;
            const FloatBox item = at < items ? boxes[order_[at]] : FloatBox();
            for (int k = 0; k < 3; ++k) {
                leaf_boxes_[leaf].lo[k][lane] = item.lo[k];
                leaf_boxes_[leaf].hi[k][lane] = item.hi[k];
            }
        }
    });
    let_go(boxes);
    // Exactly the nodes of every level: 2 count + 1 falls short when levels
    // of odd size round up, and the vector then doubled (12 MB more at the
    // check's peak for a million triangles). A level of odd size below the
    // root ends in an empty node (meeting nothing), so that every node above
    // the leaves has two children.
    level_begin_.push_back(0);
    for (std::size_t level = count;; level /= 2) {
        if (level > 1) level += level % 2;
        level_begin_.push_back(level_begin_.back() + level);
        if (level <= 1) break;
    }
    nodes_.resize(level_begin_.back());
    in_blocks(count, [&](std::size_t leaf) {
        FloatBox& box = nodes_[leaf];
        for (std::size_t lane = 0; lane < kLeafSize; ++lane)
            box.extend(item_box(kLeafSize * leaf + lane));
    });
    for (std::size_t level = 1; level + 1 < level_begin_.size(); ++level) {
        const std::size_t below = level_begin_[level - 1], at = level_begin_[level];
        in_blocks((at - below) / 2, [&](std::size_t i) {
            FloatBox& box = nodes_[at + i];
            box = nodes_[below + 2 * i];
            box.extend(nodes_[below + 2 * i + 1]);
        });
    }
    // Segment tests in double against float boxes: a margin far above the
    // rounding of either, far below any feature the boxes separate.
    pad_ = std::isfinite(extent) ? 1e-6 * extent : 0.0;
}

std::pmr::vector<BoxTree::PairTask> BoxTree::pair_tasks() const {
    std::pmr::vector<PairTask> pieces(memory_);
    if (order_.empty()) return pieces;
    std::pmr::vector<PairTask> pending(memory_);
    pending.push_back({root(), root()});
    while (!pending.empty()) {
        const PairTask task = pending.back();
        pending.pop_back();
        if (std::max(task.first.level, task.second.level) <= kPieceLevel) {
            pieces.push_back(task);
        } else {
            split(task, [&](const PairTask& part) { pending.push_back(part); });
        }
    }
    return pieces;
}

}  // namespace polymass::core
