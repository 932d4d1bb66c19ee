// Which faces of a surface meet: those that cross each other, and those that
// only touch.
//
// Candidate pairs come from the box tree of the indexed surface
// (indexed_surface.hpp), so a closed surface costs about as many triangle
// tests as each triangle has neighbours. Each candidate is decided with exact
// predicates (triangle_contact.hpp). Faces that share an edge meet there by
// construction and are not compared; faces that share one vertex are
// compared for crossing only. Past the stop of the touching count, a pair
// whose touching would neither be kept nor mark a triangle (touches_other_shell
// already set for both, or one shell) is asked only whether it crosses or
// coincides, which faces resting on each other answer from their extents,
// and faces of two shells whose boxes meet only in a plane (parts resting on
// each other) from those boxes and whether the faces lie flat in it.
//
// A surface of several shells without copies, whose shells' pairs are few
// enough (shell_pairs.hpp), is searched by pairs of shells instead of along
// the tree: the triangles of two shells resting on each other are then not
// paired at all once the touching count is full, except those not yet
// marked and those flat in the plane the shells meet in. Whatever it finds
// is the tree's answer; a surface with crossing faces is searched again
// along the tree, whose order then decides which pairs are counted.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "findings.hpp"
#include "indexed_surface.hpp"
#include "shells.hpp"
#include "task_runner.hpp"

namespace polymass::core {

// The axes on which a triangle lies flat, from its corner extremes
// (IndexedSurface::corner_extremes): its first corner is both its highest
// and its lowest there. Bit `axis`.
inline std::uint32_t flat_axes(std::uint32_t corner_extremes) {
    return corner_extremes & corner_extremes >> 3 & 7u;
}

struct SurfaceContacts {
    PairFinding crossing;  // face pairs (low, high) that cross
    PairFinding touching;  // face pairs that meet without crossing (and share no vertex)
    // With two shells or more, per shell: whether another shell's box
    // reaches inside its own (shells_reached_inside, shell_pairs.hpp), so
    // that another shell may wind around it. Empty otherwise.
    std::pmr::vector<std::uint8_t> reached_inside;
    // With two shells or more, per shape (its lowest copy) of a shell
    // reached inside: whether it touches a triangle of another shell. Only
    // there can the rest of the surface wind around a shell otherwise than
    // at one vertex of it (shell_nesting.hpp). Empty otherwise; never set on
    // a shell not reached inside, which nothing winds around.
    std::pmr::vector<std::atomic<std::uint8_t>> touches_other_shell;

    SurfaceContacts(std::size_t triangles, std::pmr::memory_resource* memory)
        : reached_inside(memory), touches_other_shell(triangles, memory) {}
};

// With the surface's shells (IndexedSurface::shells), coinciding faces of
// two shells cross and touching between shells is marked. The search runs as tasks of
// `tasks`; the result is the same for every runner. Each kind counts its
// pairs up to a limit and keeps the lowest exactly (PairFinding), until
// the crossing pairs reach the limit: the search ends there (SearchEnd in
// surface_contacts.cpp), and neither kind is then complete.
template <class Scalar, class Index>
SurfaceContacts find_contacts(const IndexedSurface<Scalar, Index>& surface, TaskRunner& tasks,
                              std::pmr::memory_resource* memory);

}  // namespace polymass::core
