#include "shell_pairs.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace polymass::core {
namespace {

// Whether two exact boxes meet (closed: in a plane, a line or a point too).
bool boxes_meet(const ShellBox& first, const ShellBox& second) {
    return (first.lo.array() <= second.hi.array()).all() &&
           (second.lo.array() <= first.hi.array()).all();
}

// Whether two exact boxes overlap inside: on every axis each begins below
// where the other ends.
bool insides_meet(const ShellBox& first, const ShellBox& second) {
    return (first.lo.array() < second.hi.array()).all() &&
           (second.lo.array() < first.hi.array()).all();
}

}  // namespace

template <class Scalar, class Index>
std::pmr::vector<std::uint8_t> shells_reached_inside(const IndexedSurface<Scalar, Index>& surface,
                                                     TaskRunner& tasks,
                                                     std::pmr::memory_resource* memory) {
    const std::pmr::vector<ShellBox>& shell_boxes = surface.shell_boxes();
    const std::size_t shell_count = shell_boxes.size();
    // Copies on two shells coincide, which crosses, and the nesting is not
    // asked; a pile of copies would only cost the walk's budget.
    std::pmr::vector<std::uint8_t> reached(shell_count, surface.any_copies(), memory);
    if (surface.any_copies()) return reached;
    const BoxTree tree(surface.rounded_shell_boxes(memory), memory, tasks);
    std::size_t pairs = 0;
    for (const BoxTree::PairTask& piece : tree.pair_tasks()) {
        const bool within_budget =
            tree.for_each_overlapping_pair(piece, [&](std::uint32_t r, std::uint32_t s) {
                if (insides_meet(shell_boxes[r], shell_boxes[s])) reached[r] = reached[s] = 1;
                return ++pairs <= kShellPairsCompared * shell_count;
            });
        if (!within_budget) {
            std::fill(reached.begin(), reached.end(), 1);
            break;
        }
    }
    return reached;
}

template <class Scalar, class Index>
std::optional<ShellPairs> pair_shells(const IndexedSurface<Scalar, Index>& surface,
                                      TaskRunner& tasks, std::pmr::memory_resource* memory) {
    const Shells* shells = surface.shells();
    if (!shells || shells->count < 2 || surface.any_copies()) return std::nullopt;
    const std::size_t shell_count = shells->count;
    const auto shell_of = [&](std::size_t t) { return shells->of_face[surface.face(t)]; };

    ShellPairs paired(memory);
    paired.first_triangle.assign(shell_count + 1, 0);
    for (std::uint32_t t = 0; t < surface.size(); ++t)
        if (!surface.meets_nothing(t)) ++paired.first_triangle[shell_of(t) + 1];
    // The pairs within each shell, then those between shells as they are
    // found: past the budget, the tree of triangles serves.
    const std::size_t budget = kPairsPerTriangle * surface.size();
    std::size_t pairs = 0;
    for (std::size_t s = 0; s < shell_count; ++s) {
        const std::size_t size = paired.first_triangle[s + 1];
        pairs += size * (size - 1) / 2;  // 0 when size is 0, wrapping or not
    }
    if (pairs > budget) return std::nullopt;

    const std::pmr::vector<ShellBox>& shell_boxes = surface.shell_boxes();
    paired.shell_boxes = surface.rounded_shell_boxes(memory);
    const BoxTree tree(std::pmr::vector<FloatBox>(paired.shell_boxes, memory), memory, tasks);
    std::pmr::vector<std::array<std::uint32_t, 2>> meeting(memory);
    for (const BoxTree::PairTask& piece : tree.pair_tasks()) {
        const bool within_budget =
            tree.for_each_overlapping_pair(piece, [&](std::uint32_t r, std::uint32_t s) {
                if (!boxes_meet(shell_boxes[r], shell_boxes[s])) return true;
                meeting.push_back({std::min(r, s), std::max(r, s)});
                pairs += std::size_t(paired.first_triangle[r + 1]) * paired.first_triangle[s + 1];
                return pairs <= budget;
            });
        if (!within_budget) return std::nullopt;
    }
    // The partners grouped by shell, then each shell's few sorted: a sort
    // of all the pairs cost nine tenths of this pairing on 1,000 cubes.
    paired.first_partner.assign(shell_count + 1, 0);
    for (const auto& [r, s] : meeting) ++paired.first_partner[r + 1];
    for (std::size_t s = 0; s < shell_count; ++s) {
        paired.first_partner[s + 1] += paired.first_partner[s];
        paired.first_triangle[s + 1] += paired.first_triangle[s];
    }
    paired.partners.resize(meeting.size());
    {
        std::pmr::vector<std::uint32_t> next(paired.first_partner.begin(),
                                             paired.first_partner.end() - 1, memory);
        for (const auto& [r, s] : meeting) paired.partners[next[r]++] = s;
    }
    for (std::size_t s = 0; s < shell_count; ++s)
        std::sort(paired.partners.begin() + paired.first_partner[s],
                  paired.partners.begin() + paired.first_partner[s + 1]);

    // Each shell's triangles in ascending order, with their boxes as the
    // tree of triangles has them.
    paired.triangles.resize(paired.first_triangle[shell_count]);
    paired.boxes.resize(paired.triangles.size());
    std::pmr::vector<std::uint32_t> next(paired.first_triangle.begin(),
                                         paired.first_triangle.end() - 1, memory);
    for (std::uint32_t t = 0; t < surface.size(); ++t) {
        if (surface.meets_nothing(t)) continue;
        const std::uint32_t at = next[shell_of(t)]++;
        const Triangle corners = surface.triangle(t);
        const Eigen::Vector3d lo = corners[0].cwiseMin(corners[1]).cwiseMin(corners[2]);
        const Eigen::Vector3d hi = corners[0].cwiseMax(corners[1]).cwiseMax(corners[2]);
        paired.triangles[at] = t;
        paired.boxes[at] = FloatBox::spanning(surface.in_units(lo), surface.in_units(hi));
    }
    return paired;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                             \
    template std::optional<ShellPairs> pair_shells<Scalar, Index>(                      \
        const IndexedSurface<Scalar, Index>&, TaskRunner&, std::pmr::memory_resource*); \
    template std::pmr::vector<std::uint8_t> shells_reached_inside<Scalar, Index>(       \
        const IndexedSurface<Scalar, Index>&, TaskRunner&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
