// The pairs of a surface's shells whose boxes meet, found once as pairs of
// shells rather than as the pairs of their triangles: an assembly of parts
// resting on each other meets in about 10,500 pairs of parts where its
// 12,000 triangles meet in 612,000 pairs of two parts (1,000 cubes,
// docs/intersection-search.md), and most of those pairs of parts have
// nothing left to tell once their triangles are marked and the touching
// count is full (surface_contacts.cpp decides which).
//
// Each shell's triangles are listed together with their boxes, so that the
// triangles of two shells are paired by comparing their boxes one by one:
// cheap for small parts, quadratic for large ones. The pairs are therefore
// only made when the triangle pairs they would compare are at most
// kPairsPerTriangle a triangle (shells nesting in each other's boxes, or one
// large shell touching many, are left to the triangles' tree).
#pragma once

#include <cstdint>
#include <memory_resource>
#include <optional>
#include <vector>

#include "box_tree.hpp"
#include "indexed_surface.hpp"
#include "task_runner.hpp"

namespace polymass::core {

struct ShellPairs {
    // Shell s's triangles (none degenerate), by index, and their boxes (the
    // tree's, in its units): triangles[first_triangle[s], first_triangle[s + 1]).
    std::pmr::vector<std::uint32_t> first_triangle, triangles;
    std::pmr::vector<FloatBox> boxes;
    // Each shell's box in the tree's units, rounded outward.
    std::pmr::vector<FloatBox> shell_boxes;
    // The shells t > s whose exact boxes meet shell s's (closed: a box
    // meeting another in a plane, a line or a point meets it), ascending:
    // partners[first_partner[s], first_partner[s + 1]).
    std::pmr::vector<std::uint32_t> first_partner, partners;

    explicit ShellPairs(std::pmr::memory_resource* memory)
        : first_triangle(memory),
          triangles(memory),
          boxes(memory),
          shell_boxes(memory),
          first_partner(memory),
          partners(memory) {}
};

// The triangle pairs that comparing box with box may cost, per triangle:
// 1,000 cubes on a grid compare about 130 (5.5 within their cube).
inline constexpr std::size_t kPairsPerTriangle = 256;

// The surface's shells paired, when it has two shells or more, no copies
// (a pile of copies is met through its lowest copy, by the tree), and the
// pairs within each shell and between the shells paired are at most
// kPairsPerTriangle a triangle; nothing otherwise. The same for every
// runner.
template <class Scalar, class Index>
std::optional<ShellPairs> pair_shells(const IndexedSurface<Scalar, Index>& surface,
                                      TaskRunner& tasks, std::pmr::memory_resource* memory);

// Per shell: whether another shell's box reaches inside its own (on every
// axis, each box begins below where the other ends; so too for a flat box,
// whose inside is empty). Only such a shell may have another shell wind
// around it (shell_nesting.hpp): another shell winds 0 around every point
// off it outside its open box. Parts resting on each other, whose boxes
// meet in a plane, a line or a point, are reached inside by none. Exact,
// from the shells' exact boxes; past kShellPairsCompared pairs of boxes a
// shell (boxes inside boxes, a pile of parts), and on a surface with copies
// (a pile of copies), every shell is taken as reached. The same for every
// runner.
template <class Scalar, class Index>
std::pmr::vector<std::uint8_t> shells_reached_inside(const IndexedSurface<Scalar, Index>& surface,
                                                     TaskRunner& tasks,
                                                     std::pmr::memory_resource* memory);

// The pairs of boxes meeting, a shell on average, that shells_reached_inside
// compares before it takes every shell as reached: parts resting on each
// other in a grid meet 26 neighbours each, 13 pairs a shell.
inline constexpr std::size_t kShellPairsCompared = 64;

}  // namespace polymass::core
