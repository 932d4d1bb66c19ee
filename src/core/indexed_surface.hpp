// A surface's triangles indexed for the intersection check: each corner as
// the vertex it is welded to, copies of one triangle (the same three
// positions in the same order) linked together, and a box tree over one
// triangle of each shape. The search for meeting faces (surface_contacts.hpp)
// walks the tree's overlapping pairs; the count of how shells nest
// (shell_nesting.hpp) walks the triangles near its probing segments. With
// two shells or more, each shell's exact box, which both use, is taken in
// the same pass that boxes the triangles.
//
// Copies meet every other triangle alike, so the tree holds one triangle of
// each shape, and the copies of the two shapes of a pair it finds are paired
// without it: a pile of k copies is then one pair of shapes, not k^2 pairs
// of triangles each found through the tree.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory_resource>
#include <optional>
#include <vector>

#include "box_tree.hpp"
#include "leaf_corners.hpp"
#include "mesh_view.hpp"
#include "shells.hpp"
#include "surface_triangles.hpp"
#include "task_runner.hpp"
#include "triangle_contact.hpp"

namespace polymass::core {

// The end of a list of copies.
inline constexpr std::uint32_t kNoCopy = UINT32_MAX;

// A shell's box, exact: the least and greatest coordinates of its corners.
struct ShellBox {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;

    void extend(const Eigen::Vector3d& p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    void extend(const ShellBox& box) {
        lo = lo.cwiseMin(box.lo);
        hi = hi.cwiseMax(box.hi);
    }
};

template <class Scalar, class Index>
class IndexedSurface {
public:
    // vertex_ids: welding (see weld_vertices), null meaning the index itself.
    // reference, size: a point near the surface and its size (the scan's
    // bounding box centre and diagonal). shells: null, or the surface's
    // shells, kept by pointer. may_have_copies false: the caller has proved
    // that no two triangles lie at the same three positions in the same
    // order (copies_ruled_out, topology.hpp), and their search is skipped.
    // Indices must be in range, coordinates finite, faces fewer than 2^32.
    // Built in blocks on `tasks`; the same for every runner.
    IndexedSurface(const MeshView<Scalar, Index>& mesh, const std::uint32_t* vertex_ids,
                   const Eigen::Vector3d& reference, double size, const Shells* shells,
                   TaskRunner& tasks, std::pmr::memory_resource* memory,
                   bool may_have_copies = true);

    std::size_t size() const { return size_; }
    // Triangle t's corners as welded vertices, in the face's turn.
    std::array<std::uint32_t, 3> corners(std::size_t t) const {
        return {corners_[3 * t], corners_[3 * t + 1], corners_[3 * t + 2]};
    }
    std::uint32_t face(std::size_t t) const {
        return one_face_each_ ? std::uint32_t(t) : triangles_.face[t];
    }
    // Triangle t with corner `first` first, keeping its turn. A welded
    // vertex sits at the position of the vertex it was welded to, so that
    // corners the surface shares are one point, not two points 1e-17 apart
    // whose triangles would seem to cross.
    // Inlined: GCC left it out of line in the search once its pairs had
    // two searches (surface_contacts.cpp), 3 % of a clean torus's check.
    __attribute__((always_inline)) Triangle triangle(std::size_t t, int first = 0) const {
        const std::array<std::uint32_t, 3> ids = corners(t);
        const int second = first == 2 ? 0 : first + 1, third = second == 2 ? 0 : second + 1;
        return Triangle{mesh_.positions[ids[first]], mesh_.positions[ids[second]],
                        mesh_.positions[ids[third]]};
    }

    // The lowest copy of t's shape (t itself when it is alone), and the next
    // copy above t, or kNoCopy. A shape's copies ascend.
    __attribute__((always_inline)) std::uint32_t lowest_copy(std::size_t t) const {
        return has_copies(t) ? lowest_[copy_rank(t)] : std::uint32_t(t);
    }
    __attribute__((always_inline)) std::uint32_t next_copy(std::size_t t) const {
        return has_copies(t) ? next_[copy_rank(t)] : kNoCopy;
    }
    // Whether any triangle has copies.
    bool any_copies() const { return !next_.empty(); }
    // Degenerate triangles (three collinear corners) bound nothing and meet nothing.
    bool meets_nothing(std::size_t t) const { return corner_bits_[t] >> kDegenerateBit & 1; }
    // Per corner k of triangle t, bits 6 k + axis: the corner is the
    // triangle's highest on that axis (its two others at or below it), and
    // bits 6 k + 3 + axis: its lowest. Exact comparisons of the corners'
    // coordinates, taken in the pass that boxes the triangles, where a pass
    // of their own fetched every triangle again.
    std::uint32_t corner_extremes(std::size_t t) const {
        return corner_bits_[t] & ((1u << kDegenerateBit) - 1);
    }

    // The tree over the lowest copy of each shape, in units about the
    // reference: a power of two near the surface's size, so that single
    // precision holds the boxes for any size a double does. Built with its
    // leaves' LeafCorners by the first build_tree, on `tasks`, and only
    // then: the search by pairs of shells (parts resting on each other)
    // needs neither, and the tree was a tenth of its check. build_tree must
    // be called from the thread that runs `tasks`, before any task reads
    // the tree (a cache of a const index: the same tree whoever builds it).
    void build_tree(TaskRunner& tasks) const;
    const BoxTree& tree() const { return *tree_; }
    // The triangles of the tree's leaf `leaf` (LeafCorners).
    const LeafCorners& leaf_corners(std::size_t leaf) const { return leaf_corners_[leaf]; }
    Eigen::Vector3d in_units(const Eigen::Vector3d& p) const {
        return (p - reference_) * per_unit_;
    }
    // The largest extent of the boxes, in the mesh's units (once the tree is built).
    double span() const;

    // The shells given, or null.
    const Shells* shells() const { return shells_; }
    // With two shells or more, each shell's box (by Shells' numbering);
    // empty otherwise.
    const std::pmr::vector<ShellBox>& shell_boxes() const { return shell_boxes_; }
    // Those boxes in the tree's units, rounded outward: the items of a tree
    // over the shells, whose pairs hold every pair of shells whose exact
    // boxes meet.
    std::pmr::vector<FloatBox> rounded_shell_boxes(std::pmr::memory_resource* memory) const;

private:
    std::pmr::vector<FloatBox> boxes_with_copies(const std::uint32_t* vertex_ids,
                                                 bool may_have_copies, TaskRunner& tasks,
                                                 std::pmr::memory_resource* memory);
    // Triangles at the same three positions in the same order: copies of a
    // part stacked in place, or a surface exported twice. keys: per
    // triangle t, a hash of its coordinates (shape_hash) above t.
    void find_copies(std::pmr::vector<std::uint64_t> keys, std::pmr::memory_resource* memory);
    // The tree's leaves' LeafCorners, once the tree is built.
    std::pmr::vector<LeafCorners> corners_by_leaf(TaskRunner& tasks,
                                                  std::pmr::memory_resource* memory) const;

    // Inlined (the search asks for every candidate pair), but not the rank,
    // which only triangles with copies need. A surface without copies (most
    // of them) reads no bit: a branch always taken alike, where the bit's
    // word, shift and mask were two thirds of the cost of asking, twice per
    // candidate pair.
    __attribute__((always_inline)) bool has_copies(std::size_t t) const {
        return !next_.empty() && (with_copies_[t / 64] >> (t % 64) & 1);
    }
    // Where t's copies are in lowest_ and next_: how many triangles below t
    // have copies.
    std::size_t copy_rank(std::size_t t) const;

    const MeshView<Scalar, Index>& mesh_;
    // The caller's indices serve as the triangles' corners when nothing
    // would change them: every face a triangle, 32-bit indices aligned as
    // such, no weld. Else they are copied (triangulate_faces), 12 MB a
    // million triangles at the check's peak of memory.
    static bool uses_callers_corners(const MeshView<Scalar, Index>& mesh,
                                     const std::uint32_t* vertex_ids);
    bool callers_corners_;
    SurfaceTriangles triangles_;    // empty when the caller's corners serve
    const std::uint32_t* corners_;  // three a triangle, welded
    std::size_t size_;
    // Every face is one triangle (triangle t is face t), as in most meshes:
    // the faces' list is let go before the tree is built (4 MB a million
    // triangles at the check's peak).
    bool one_face_each_ = false;
    Eigen::Vector3d reference_;
    double per_unit_;
    const Shells* shells_;
    std::pmr::vector<ShellBox> shell_boxes_;
    // Per triangle, its corner extremes (corner_extremes), and above them
    // whether it is degenerate: one word, not a byte more for the flag.
    static constexpr int kDegenerateBit = 31;
    std::pmr::vector<std::uint32_t> corner_bits_;
    // Copies are rare, and a list of them per triangle took 8 MB a million
    // triangles at the check's peak: a bit per triangle says whether it has
    // copies (with_copies_, 64 to a word, and the count of those in the
    // words before each), and the lowest and next copy are kept for those
    // triangles only, in the order of their indices.
    std::pmr::vector<std::uint64_t> with_copies_;
    std::pmr::vector<std::uint32_t> copies_before_;
    std::pmr::vector<std::uint32_t> lowest_, next_;
    std::pmr::memory_resource* memory_;
    // The triangles' boxes until the tree takes them.
    mutable std::pmr::vector<FloatBox> boxes_;
    mutable std::optional<BoxTree> tree_;
    mutable std::pmr::vector<LeafCorners> leaf_corners_;
};

}  // namespace polymass::core
