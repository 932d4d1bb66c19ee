#include "indexed_surface.hpp"

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "face_blocks.hpp"
#include "position_hash.hpp"
#include "radix_sort.hpp"
#include "scratch_buffer.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {
namespace {

// A triangle's corner extremes (IndexedSurface::corner_extremes), and its
// lowest and highest coordinate on each axis: both from the six comparisons
// of its corners' coordinates per axis. (Each corner against its two others
// took twelve, and the box then compared each corner again: a third of the
// pass over the positions.)
struct CornerOrder {
    std::uint32_t extremes = 0;
    Eigen::Vector3d lowest, highest;
};

// Bit axis set where a's coordinate is at or below b's (finite coordinates).
// All three axes of one pair of corners at once (x and y in one comparison
// of two lanes where SSE2 is), so that each corner's bits land where
// corner_extremes wants them with one shift a pair: the axes one at a time,
// three shifts and an or a comparison, made order_corners 177 instructions
// a triangle (callgrind, clean 1e5 torus).
__attribute__((always_inline)) inline std::uint32_t at_or_below(const Eigen::Vector3d& a,
                                                                const Eigen::Vector3d& b) {
#if defined(__SSE2__)
    const std::uint32_t xy = std::uint32_t(
        _mm_movemask_pd(_mm_cmple_pd(_mm_loadu_pd(a.data()), _mm_loadu_pd(b.data()))));
    return xy | std::uint32_t(a[2] <= b[2]) << 2;
#else
    return std::uint32_t(a[0] <= b[0]) | std::uint32_t(a[1] <= b[1]) << 1 |
           std::uint32_t(a[2] <= b[2]) << 2;
#endif
}

CornerOrder order_corners(const Triangle& t) {
    // xy: x at or below y on each axis (finite coordinates: not y below x).
    const std::uint32_t ab = at_or_below(t[0], t[1]), ba = at_or_below(t[1], t[0]);
    const std::uint32_t bc = at_or_below(t[1], t[2]), cb = at_or_below(t[2], t[1]);
    const std::uint32_t ca = at_or_below(t[2], t[0]), ac = at_or_below(t[0], t[2]);
    // Corner k's highest on each axis at bits 6 k + axis, its lowest at 6 k + 3 + axis.
    CornerOrder order;
    order.extremes = (ba & ca) | (ab & ac) << 3 | (cb & ab) << 6 | (bc & ba) << 9 |
                     (ac & bc) << 12 | (ca & cb) << 15;
    for (int axis = 0; axis < 3; ++axis) {
        const double a = t[0][axis], b = t[1][axis], c = t[2][axis];
        order.lowest[axis] = std::min(std::min(a, b), c);
        order.highest[axis] = std::max(std::max(a, b), c);
    }
    return order;
}

// The nine coordinates' bits (position_hash.hpp: -0 as +0) mixed in order:
// copies of a shape hash alike.
std::uint64_t shape_hash(const Triangle& t) {
    std::uint64_t h = 0x9e3779b97f4a7c15u;
    for (const Eigen::Vector3d& corner : t)
        for (int c = 0; c < 3; ++c) {
            h = (h ^ position_bits(corner[c])) * 0xff51afd7ed558ccdu;
            h ^= h >> 32;
        }
    return h;
}

}  // namespace

template <class Scalar, class Index>
IndexedSurface<Scalar, Index>::IndexedSurface(const MeshView<Scalar, Index>& mesh,
                                              const std::uint32_t* vertex_ids,
                                              const Eigen::Vector3d& reference, double size,
                                              const Shells* shells, TaskRunner& tasks,
                                              std::pmr::memory_resource* memory,
                                              bool may_have_copies)
    : mesh_(mesh),
      callers_corners_(uses_callers_corners(mesh, vertex_ids)),
      triangles_(callers_corners_ ? SurfaceTriangles(memory) : triangulate_faces(mesh, memory)),
      corners_(callers_corners_ ? reinterpret_cast<const std::uint32_t*>(mesh.indices.base)
                                : triangles_.corners.data()),
      size_(callers_corners_ ? mesh.face_count : triangles_.size()),
      reference_(reference),
      per_unit_(1.0 / unit_length_near(size)),
      shells_(shells),
      shell_boxes_(memory),
      corner_bits_(memory),
      with_copies_(memory),
      copies_before_(memory),
      lowest_(memory),
      next_(memory),
      memory_(memory),
      boxes_(boxes_with_copies(vertex_ids, may_have_copies, tasks, memory)),
      leaf_corners_(memory) {}

template <class Scalar, class Index>
void IndexedSurface<Scalar, Index>::build_tree(TaskRunner& tasks) const {
    if (tree_) return;
    tree_.emplace(std::move(boxes_), memory_, tasks);
    leaf_corners_ = corners_by_leaf(tasks, memory_);
}

template <class Scalar, class Index>
bool IndexedSurface<Scalar, Index>::uses_callers_corners(const MeshView<Scalar, Index>& mesh,
                                                         const std::uint32_t* vertex_ids) {
    return std::is_same_v<Index, std::uint32_t> && mesh.all_triangles() && !vertex_ids &&
           reinterpret_cast<std::uintptr_t>(mesh.indices.base) % alignof(std::uint32_t) == 0;
}

// Welds the corners, boxes the triangles, and links the copies, whose boxes
// above the lowest are then emptied: met through it. (Copies are found after
// the boxes, so that the tree's scratch reuses their search's: 8 MB less at
// the peak of a million triangles.) The tree takes the boxes.
template <class Scalar, class Index>
std::pmr::vector<FloatBox> IndexedSurface<Scalar, Index>::boxes_with_copies(
    const std::uint32_t* vertex_ids, bool may_have_copies, TaskRunner& tasks,
    std::pmr::memory_resource* memory) {
    // Each corner as the vertex it is welded to, in place: the test of
    // shared corners reads nothing else for most candidate pairs.
    if (vertex_ids)
        for (std::uint32_t& vertex : triangles_.corners) vertex = vertex_ids[vertex];
    // Faces of one triangle each need no list of faces (none was made when
    // the caller's corners serve).
    std::uint32_t next = 0;
    one_face_each_ = std::all_of(triangles_.face.begin(), triangles_.face.end(),
                                 [&](std::uint32_t face) { return face == next++; });
    if (one_face_each_) let_go(triangles_.face);
    // One pass over the triangles' positions for all that needs them: their
    // copies' hash, corner extremes, degeneracy, boxes and shells' boxes. Degenerate
    // triangles keep an empty box. (The boxes are allocated first: with the
    // hash keys first, the tool's peak memory on a million triangles was
    // 8 MB higher. A call's freed blocks are kept for its later requests,
    // capi/scratch_memory.hpp, and which block serves which depends on
    // their order.)
    std::pmr::vector<FloatBox> boxes(size(), memory);
    corner_bits_.resize(size());
    std::pmr::vector<std::uint64_t> shape_keys(may_have_copies ? size() : 0, memory);
    // Each block's shells' boxes, per run of its triangles on one shell
    // (numbered in the order of their first faces, a shell's faces mostly
    // come together), joined in block order: the same boxes whatever the
    // runner; at worst (shells' faces interleaved one by one) a run a
    // triangle, 56 bytes, let go before the tree is built. The run being
    // extended is the block's own, kept out of the list until it ends:
    // extended in place in the list, it cost as much as the serial pass it
    // replaced.
    struct ShellRun {
        std::uint32_t shell;
        ShellBox box;
    };
    constexpr std::uint32_t kNoShell = UINT32_MAX;  // shells are fewer than faces
    const bool boxes_shells = shells_ && shells_->count >= 2;
    std::pmr::vector<std::pmr::vector<ShellRun>> runs_of_block(
        boxes_shells ? block_count(size(), kFacesPerBlock) : 0, memory);
    for_each_block(
        size(), kFacesPerBlock, tasks, [&](std::size_t block, std::size_t begin, std::size_t end) {
            ShellRun run{kNoShell, ShellBox()};
            for (std::size_t t = begin; t < end; ++t) {
                const Triangle corners = triangle(t);
                if (may_have_copies)
                    shape_keys[t] = (shape_hash(corners) & 0xffffffff00000000u) | t;
                const bool degenerate = is_degenerate(corners);
                const CornerOrder order = order_corners(corners);
                corner_bits_[t] = order.extremes | std::uint32_t(degenerate) << kDegenerateBit;
                // in_units is monotone (a positive scale), so it keeps the lowest
                // and the highest: rounded outward, they bound the three corners.
                if (!degenerate)
                    boxes[t] = FloatBox::spanning(in_units(order.lowest), in_units(order.highest));
                if (!boxes_shells) continue;
                const std::uint32_t shell = shells_->of_face[face(t)];
                if (shell != run.shell) {
                    if (run.shell != kNoShell) runs_of_block[block].push_back(run);
                    run = {shell, ShellBox()};
                }
                run.box.extend(order.lowest);
                run.box.extend(order.highest);
            }
            if (run.shell != kNoShell) runs_of_block[block].push_back(run);
        });
    if (boxes_shells) {
        shell_boxes_.resize(shells_->count);
        for (const std::pmr::vector<ShellRun>& runs : runs_of_block)
            for (const ShellRun& run : runs) shell_boxes_[run.shell].extend(run.box);
        let_go(runs_of_block);
    }
    if (!may_have_copies) return boxes;
    find_copies(std::move(shape_keys), memory);
    for_each_in_blocks(size(), kFacesPerBlock, tasks, [&](std::size_t t) {
        if (lowest_copy(t) != t) boxes[t] = FloatBox();
    });
    return boxes;
}

template <class Scalar, class Index>
std::pmr::vector<LeafCorners> IndexedSurface<Scalar, Index>::corners_by_leaf(
    TaskRunner& tasks, std::pmr::memory_resource* memory) const {
    std::pmr::vector<LeafCorners> leaves(tree_->leaf_count(), memory);
    for_each_in_blocks(
        leaves.size(), kFacesPerBlock / BoxTree::kLeafSize, tasks, [&](std::size_t leaf) {
            LeafCorners& lanes = leaves[leaf];
            for (std::size_t lane = 0; lane < BoxTree::kLeafSize; ++lane) {
                if (BoxTree::kLeafSize * leaf + lane >= tree_->item_count()) break;
                const std::uint32_t t = tree_->leaf_item(leaf, lane);
                for (int k = 0; k < 3; ++k) lanes.corner[k][lane] = corners_[3 * t + k];
                lanes.extremes[lane] =
                    corner_extremes(t) | (has_copies(t) ? LeafCorners::kHasCopies : 0);
            }
        });
    return leaves;
}

template <class Scalar, class Index>
std::size_t IndexedSurface<Scalar, Index>::copy_rank(std::size_t t) const {
    const std::uint64_t below = with_copies_[t / 64] & ((std::uint64_t{1} << (t % 64)) - 1);
    return copies_before_[t / 64] + std::size_t(__builtin_popcountll(below));
}

template <class Scalar, class Index>
std::pmr::vector<FloatBox> IndexedSurface<Scalar, Index>::rounded_shell_boxes(
    std::pmr::memory_resource* memory) const {
    std::pmr::vector<FloatBox> boxes(memory);
    boxes.reserve(shell_boxes_.size());
    for (const ShellBox& box : shell_boxes_)
        boxes.push_back(FloatBox::spanning(in_units(box.lo), in_units(box.hi)));
    return boxes;
}

template <class Scalar, class Index>
double IndexedSurface<Scalar, Index>::span() const {
    const FloatBox everything = tree_->bounds();
    double span = 0;
    for (int k = 0; k < 3; ++k)
        span = std::max(span, double(everything.hi[k]) - double(everything.lo[k]));
    return span / per_unit_;
}

// Triangles are first sorted by a hash of their nine coordinates and then by
// index (one 64-bit key each, sorted in linear time): copies hash alike, so
// only triangles of one hash, nearly always alone, are compared coordinate by
// coordinate. Sorting every triangle by its coordinates took 40 % of the
// intersection check of a million-triangle sphere.
template <class Scalar, class Index>
void IndexedSurface<Scalar, Index>::find_copies(std::pmr::vector<std::uint64_t> keys,
                                                std::pmr::memory_resource* memory) {
    const std::size_t count = size();
    auto coordinates = [&](std::uint32_t t) {
        const Triangle corners = triangle(t);
        std::array<double, 9> flat;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) flat[3 * k + c] = corners[k][c];
        return flat;
    };
    radix_sort_high_half(keys.data(), keys.data() + keys.size(), memory);
    auto triangle_of = [&](std::size_t k) { return std::uint32_t(keys[k]); };
    // Each triangle with copies, with its lowest and next copy, in the order
    // the groups come; then marked, and filed in the order of the indices.
    struct Copy {
        std::uint32_t triangle, lowest, next;
    };
    std::pmr::vector<Copy> copies(memory);
    std::pmr::vector<std::pair<std::array<double, 9>, std::uint32_t>> group(memory);
    for (std::size_t k = 0; k < count;) {
        std::size_t end = k + 1;
        while (end < count && keys[end] >> 32 == keys[k] >> 32) ++end;
        if (end - k == 1) {
            k = end;
            continue;
        }
        // Triangles of one hash, in ascending index: nearly always copies
        // of one shape, whose list is then that order. Otherwise (hashes
        // that collide) by coordinates, then index.
        group.clear();
        for (std::size_t m = k; m < end; ++m)
            group.push_back({coordinates(triangle_of(m)), triangle_of(m)});
        const bool one_shape = std::all_of(group.begin(), group.end(), [&](const auto& member) {
            return member.first == group.front().first;
        });
        if (!one_shape) std::sort(group.begin(), group.end());
        for (std::size_t first = 0; first < group.size();) {
            std::size_t last = first + 1;
            while (last < group.size() && group[last].first == group[first].first) ++last;
            for (std::size_t m = first; last - first > 1 && m < last; ++m)
                copies.push_back({group[m].second, group[first].second,
                                  m + 1 < last ? group[m + 1].second : kNoCopy});
            first = last;
        }
        k = end;
    }
    with_copies_.assign((count + 63) / 64, 0);
    for (const Copy& copy : copies)
        with_copies_[copy.triangle / 64] |= std::uint64_t{1} << (copy.triangle % 64);
    copies_before_.resize(with_copies_.size());
    std::uint32_t before = 0;
    for (std::size_t word = 0; word < with_copies_.size(); ++word) {
        copies_before_[word] = before;
        before += std::uint32_t(__builtin_popcountll(with_copies_[word]));
    }
    lowest_.resize(copies.size());
    next_.resize(copies.size());
    for (const Copy& copy : copies) {
        lowest_[copy_rank(copy.triangle)] = copy.lowest;
        next_[copy_rank(copy.triangle)] = copy.next;
    }
}

#define POLYMASS_INSTANTIATE(Scalar, Index) template class IndexedSurface<Scalar, Index>;
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
