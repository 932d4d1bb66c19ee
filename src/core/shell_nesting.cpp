#include "shell_nesting.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "box_tree.hpp"
#include "exact_predicates.hpp"
#include "position_hash.hpp"
#include "scratch_buffer.hpp"

namespace polymass::core {
namespace {

// Where a nesting probe starts: a vertex p of a shell, or inside a triangle
// p, a, b of it, at p + e (a - p) + e^2 (b - p) for e -> 0+, a point of the
// open triangle next to p. Every predicate of a probe is affine in its start
// point, so its sign there is the first nonzero of its signs at p, a and b.
struct ProbeStart {
    Eigen::Vector3d p, a, b;
    bool inside;
};

template <class Predicate>
int sign_at(const ProbeStart& start, const Predicate& predicate) {
    int sign = predicate(start.p);
    if (sign != 0 || !start.inside) return sign;
    sign = predicate(start.a);
    return sign != 0 ? sign : predicate(start.b);
}

// The sign of orient2d(from, to, x) in the coordinates u, v, exact. Where
// parts rest flush on each other the starts are mostly corners of the
// triangles tested (the determinant is zero) and the triangles' edges mostly
// run along an axis (the determinant is a product of two differences, whose
// signs compare exactly): both decided without the predicate's call.
int edge_side(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& x,
              int u, int v) {
    const auto sign = [](double a, double b) { return (a > b) - (a < b); };
    if ((x[u] == from[u] && x[v] == from[v]) || (x[u] == to[u] && x[v] == to[v])) return 0;
    if (to[u] == from[u]) return -sign(to[v], from[v]) * sign(x[u], from[u]);
    if (to[v] == from[v]) return sign(to[u], from[u]) * sign(x[v], from[v]);
    return orient2d({from[u], from[v]}, {to[u], to[v]}, {x[u], x[v]});
}

// Whether the start, on the plane of t, lies on the closed triangle t:
// exact, in the coordinate plane that drops the axis `drop`, where t turns
// `turn` (drop_axis, projected_turn).
bool lies_on(const Triangle& t, int drop, int turn, const ProbeStart& start) {
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    for (int k = 0; k < 3; ++k) {
        const int side = sign_at(start, [&](const Eigen::Vector3d& x) {
            return edge_side(t[k], t[(k + 1) % 3], x, u, v);
        });
        if (side == -turn) return false;
    }
    return true;
}

// The axis whose coordinate plane t projects onto best: that of its
// normal's largest component (rounded; the first of equal ones).
int drop_axis(const Triangle& t) {
    int drop = 0;
    (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs().maxCoeff(&drop);
    return drop;
}

// The turn of t projected along `drop` (0 for a triangle degenerate there).
int projected_turn(const Triangle& t, int drop) {
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    return orient2d({t[0][u], t[0][v]}, {t[1][u], t[1][v]}, {t[2][u], t[2][v]});
}

// Whether the start lies in the closed box of a shell: compared coordinate
// by coordinate, exactly, the start inside a triangle as its limit.
bool holds(const ShellBox& box, const ProbeStart& start) {
    for (int k = 0; k < 3; ++k) {
        const auto above_lo = [&](const Eigen::Vector3d& x) {
            return (x[k] > box.lo[k]) - (x[k] < box.lo[k]);
        };
        const auto below_hi = [&](const Eigen::Vector3d& x) {
            return (x[k] < box.hi[k]) - (x[k] > box.hi[k]);
        };
        if (sign_at(start, above_lo) < 0 || sign_at(start, below_hi) < 0) return false;
    }
    return true;
}

// Directions of the probing segments: far from every coordinate plane and
// from each other, so that the next one avoids what grazed the last.
const Eigen::Vector3d kProbeDirections[] = {
    {0.4353, 0.5209, 0.7342}, {-0.6016, 0.3187, 0.7326}, {0.2679, -0.8535, 0.4472}};
// Vertices of a shell tried as probes before its nesting is left unknown.
constexpr std::size_t kProbeVertices = 4;
// Other shells whose boxes may hold a start before its probes stop looking
// for more and walk their whole segments (a start deep in many boxes).
constexpr std::size_t kNearShells = 32;
// Triangles of the shells whose boxes hold a point tested one by one before
// the point is looked up along the triangles' tree instead.
constexpr std::size_t kScannedTriangles = 256;
// Pairs of shells whose boxes meet, a shell on average, past which the
// shells' neighbours are not listed; and the neighbours of a shell past
// which a point of it looks along the shells' tree instead of at them. Parts
// resting on each other in a grid have 26 neighbours each.
constexpr std::size_t kPairsPerShell = 64;
constexpr std::size_t kScannedNeighbours = 64;
// Shells, and triangles, probed by one task.
constexpr std::size_t kShellsPerTask = 64;
constexpr std::size_t kTrianglesPerTask = 256;

// Joins the windings of two probes of one shell: an unknown one says
// nothing, two that differ are mixed. In any order, the same join.
int join_windings(int first, int second) {
    if (first == kUnknownWinding) return second;
    if (second == kUnknownWinding) return first;
    return first == second ? first : kMixedWinding;
}

}  // namespace

template <class Scalar, class Index>
std::pmr::vector<int> count_windings(const IndexedSurface<Scalar, Index>& surface,
                                     const SurfaceContacts& contacts, TaskRunner& tasks,
                                     std::pmr::memory_resource* memory) {
    const Shells& shells = *surface.shells();
    const auto& touches_other_shell = contacts.touches_other_shell;
    const auto shell_of = [&](std::size_t t) { return shells.of_face[surface.face(t)]; };
    std::pmr::vector<int> winding_of_shell(shells.count, kUnknownWinding, memory);
    // Only a shell another's box reaches inside may be wound around
    // (shells_reached_inside, docs/validity.md, "Only the shells whose boxes
    // reach inside"): the others' winding is 0, exact, without a probe, and
    // their triangles are not marked touching.
    const std::pmr::vector<std::uint8_t>& reached_inside = contacts.reached_inside;
    bool any_reached = false;
    for (std::size_t shell = 0; shell < shells.count; ++shell) {
        if (!reached_inside[shell]) winding_of_shell[shell] = 0;
        any_reached = any_reached || reached_inside[shell];
    }
    if (!any_reached) return winding_of_shell;
    // The probes walk the triangles' tree; their far ends lie outside every box.
    surface.build_tree(tasks);
    const double span = surface.span();
    if (!(span > 0) || !std::isfinite(4 * span)) return winding_of_shell;

    // A few triangles of each shell that may be wound around, in order,
    // whose first corners are the probes; and a tree over the shells' boxes.
    std::pmr::vector<std::array<std::uint32_t, kProbeVertices>> probes(shells.count, memory);
    std::pmr::vector<std::uint8_t> probe_count(shells.count, 0, memory);
    const std::pmr::vector<ShellBox>& shell_boxes = surface.shell_boxes();
    for (std::size_t t = 0; t < surface.size(); ++t) {
        const std::uint32_t shell = shell_of(t);
        if (reached_inside[shell] && !surface.meets_nothing(t) &&
            probe_count[shell] < kProbeVertices)
            probes[shell][probe_count[shell]++] = std::uint32_t(t);
    }
    const BoxTree shell_tree(surface.rounded_shell_boxes(memory), memory, tasks);

    // Where the other shells can wind around a start: the box around those
    // whose boxes hold it (each winds 0 around points outside its box), and
    // how many they are, counted up to kNearShells + 1 (then the box is
    // everything's).
    struct Near {
        std::size_t count = 0;
        ShellBox box;
    };

    // The winding number of every shell but `shell` at a start that lies on
    // no other shell, or kUnknownWinding when the segment from it to
    // q = p + 4 span direction grazes an edge, a vertex or a plane of a
    // shell whose box holds the start. Only those shells wind around the
    // start, and q lies outside their boxes, so their faces' signed
    // crossings count it; the walk along the segment ends where it leaves
    // `near.box` (docs/validity.md).
    auto winding_at = [&](const ProbeStart& start, const Eigen::Vector3d& direction,
                          std::uint32_t shell, const Near& near) {
        const Eigen::Vector3d& p = start.p;
        const Eigen::Vector3d q = p + 4 * span * direction.normalized();
        // The part of the segment in near.box: it leaves the box at the
        // first of its slabs it leaves (p lies in the closed box), found
        // with rounding far below the margin of 1 % and the tree's pad.
        double leave = 1;
        if (near.count <= kNearShells) {
            for (int k = 0; k < 3; ++k) {
                const double step = q[k] - p[k];
                const double bound = step > 0 ? near.box.hi[k] : near.box.lo[k];
                if (step != 0) leave = std::min(leave, std::max(0.0, (bound - p[k]) / step));
            }
            leave = std::min(1.0, 1.01 * leave);
        }
        const Eigen::Vector3d end = leave < 1 ? Eigen::Vector3d(p + leave * (q - p)) : q;
        int winding = 0;
        bool counted = true;
        surface.tree().for_each_item_near_segment(
            surface.in_units(p), surface.in_units(end), [&](std::uint32_t t) {
                // t and its copies, of the other shells whose boxes hold the
                // start. The first graze ends the walk: a pile of k shells at
                // one place then costs each probe a triangle, not k.
                int others = 0;
                for (std::uint32_t copy = t; copy != kNoCopy; copy = surface.next_copy(copy)) {
                    const std::uint32_t other = shell_of(copy);
                    others += other != shell && holds(shell_boxes[other], start);
                }
                if (others == 0) return true;
                const Triangle c = surface.triangle(t);
                const int to = orient3d(c[0], c[1], c[2], q);
                const int from = sign_at(
                    start, [&](const Eigen::Vector3d& x) { return orient3d(c[0], c[1], c[2], x); });
                // A start on c was turned away before (on_another_shell): from
                // = 0 is a start in c's plane beside it. q lies outside the
                // box of c's shell, so off c: a segment meeting c's plane at
                // q alone passes beside c, one lying in it grazes.
                if (from == 0 && to == 0) {
                    counted = false;
                    return false;
                }
                if (from == 0 || to == 0 || from == to) return true;
                auto edge_sign = [&](int k) {
                    return sign_at(start, [&](const Eigen::Vector3d& x) {
                        return orient3d(x, q, c[k], c[(k + 1) % 3]);
                    });
                };
                const int e0 = edge_sign(0), e1 = edge_sign(1), e2 = edge_sign(2);
                const bool some_positive = e0 > 0 || e1 > 0 || e2 > 0;
                const bool some_negative = e0 < 0 || e1 < 0 || e2 < 0;
                if (some_positive && some_negative) return true;  // passes beside the triangle
                if (e0 == 0 || e1 == 0 || e2 == 0) {
                    counted = false;  // through an edge or a corner
                    return false;
                }
                winding += from < 0 ? others : -others;  // leaving through the faces' outer side
                return true;
            });
        return counted ? winding : kUnknownWinding;
    };

    // Whether a start lies on another shell's triangle, asked before long
    // probes that would only graze there: the vertices of parts resting on
    // each other often do, and the starts next to the corners of faces
    // resting flush always do. A start next to the vertex p lies on a
    // triangle only if p does, and so only in a triangle whose closed box
    // holds p (each of the start's signs is first p's). The triangles whose
    // boxes hold p are therefore listed once per point, by one look along
    // the tree, and each start at p is tested against those of other shells
    // alone: a corner where parts rest on each other starts several probes
    // (five or so for each of the cubes stacked there), which each looked
    // along the tree before (docs/validity.md).
    auto triangle_box = [&](std::uint32_t t) {
        ShellBox box;
        for (const Eigen::Vector3d& corner : surface.triangle(t)) box.extend(corner);
        return box;
    };
    // A start next to p lies in the closed box of a triangle listed at p
    // (whose box holds p) unless, on some axis, p lies on the box's low side
    // and the start moves below it, or on its high side and moves above:
    // six bits each, those of the box (SideBits::of_box, kept in the list)
    // and those of the start (SideBits::of_start), which must not share one.
    struct SideBits {
        static std::uint8_t of_box(const ShellBox& box, const Eigen::Vector3d& p) {
            std::uint8_t bits = 0;
            for (int k = 0; k < 3; ++k)
                bits |= std::uint8_t((p[k] == box.lo[k]) << (2 * k) | (p[k] == box.hi[k])
                                                                          << (2 * k + 1));
            return bits;
        }
        // Where x(e) moves off p on each axis: the first nonzero of its steps to a and b.
        static std::uint8_t of_start(const ProbeStart& start) {
            std::uint8_t bits = 0;
            if (!start.inside) return bits;
            for (int k = 0; k < 3; ++k) {
                const double to = start.a[k] != start.p[k] ? start.a[k] : start.b[k];
                bits |=
                    std::uint8_t((to < start.p[k]) << (2 * k) | (to > start.p[k]) << (2 * k + 1));
            }
            return bits;
        }
    };
    // Each triangle's projection for lies_on (drop_axis, and projected_turn
    // + 2 above it; kNoProjection until one is needed), taken once: a
    // triangle where parts rest flush on each other is tested against the
    // starts at each of its corners, about five times, where the rounded
    // cross product and the orient2d were a quarter of a test. Set by any
    // task that needs it, as the same value whoever sets it.
    constexpr std::uint8_t kNoProjection = 0;
    std::pmr::vector<std::atomic<std::uint8_t>> projection(surface.size(), memory);
    // Whether the start lies on triangle t, whose box holds it. A triangle
    // lying flat on an axis (most of those where parts rest flush on each
    // other) has the plane x = c of its corners' coordinate there: the start
    // lies in it when its points do, compared exactly, without three orient3d.
    auto lies_on_triangle = [&](const ProbeStart& start, std::uint32_t t) {
        const Triangle c = surface.triangle(t);
        const std::uint32_t flat = flat_axes(surface.corner_extremes(t));
        if (flat != 0 && !surface.meets_nothing(t)) {
            const int axis = flat & 1 ? 0 : flat & 2 ? 1 : 2;
            const auto on = [&](const Eigen::Vector3d& x) { return x[axis] == c[0][axis]; };
            if (!on(start.p) || (start.inside && !(on(start.a) && on(start.b)))) return false;
        } else if (sign_at(start, [&](const Eigen::Vector3d& x) {
                       return orient3d(c[0], c[1], c[2], x);
                   }) != 0) {
            return false;
        }
        std::uint8_t projected = projection[t].load(std::memory_order_relaxed);
        if (projected == kNoProjection) {
            const int drop = drop_axis(c);
            projected = std::uint8_t(4 * (projected_turn(c, drop) + 2) + drop);
            projection[t].store(projected, std::memory_order_relaxed);
        }
        return lies_on(c, projected % 4, projected / 4 - 2, start);
    };
    // The vertices where probes start, numbered in the order of their ids:
    // the probe vertices, and the corners of triangles touching another shell.
    constexpr std::uint32_t kNoStart = UINT32_MAX;
    std::uint32_t vertex_end = 0;
    for (std::size_t t = 0; t < surface.size(); ++t)
        for (const std::uint32_t vertex : surface.corners(t))
            vertex_end = std::max(vertex_end, vertex + 1);
    std::pmr::vector<std::uint32_t> start_of_vertex(vertex_end, kNoStart, memory);
    for (std::size_t shell = 0; shell < shells.count; ++shell)
        for (std::size_t k = 0; k < probe_count[shell]; ++k)
            start_of_vertex[surface.corners(probes[shell][k])[0]] = 0;
    for (std::size_t t = 0; t < surface.size(); ++t)
        if (touches_other_shell[t].load(std::memory_order_relaxed))
            for (const std::uint32_t vertex : surface.corners(t)) start_of_vertex[vertex] = 0;
    std::uint32_t start_count = 0;
    for (std::uint32_t& start : start_of_vertex)
        if (start != kNoStart) start = start_count++;
    // A corner (3 t + k) at each start vertex, for its position.
    std::pmr::vector<std::uint32_t> corner_of_start(start_count, 0, memory);
    for (std::uint32_t t = 0; t < surface.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t start = start_of_vertex[surface.corners(t)[k]];
            if (start != kNoStart) corner_of_start[start] = 3 * t + std::uint32_t(k);
        }
    auto position_of_start = [&](std::uint32_t s) {
        return surface.triangle(corner_of_start[s] / 3, int(corner_of_start[s] % 3))[0];
    };
    // Start vertices at one point (separate parts touching there, each with
    // its own vertex) share one list: k parts meeting at a point would
    // otherwise list each other's triangles k times over, k^2 in all. The
    // starts sorted by their position's hash (position_hash.hpp), then by
    // position (the starts at one point, of one hash, are neighbours), the
    // points numbered in that order, which only orders the lists. Each
    // start's position is fetched once, beside it: fetched at each
    // comparison, the sort cost more than all the rest of the numbering;
    // sorted by position first, three coordinates compared at each step, it
    // still cost a sixth of the count on cubes resting on each other
    // (docs/validity.md).
    struct PlacedStart {
        std::uint64_t hash;
        std::array<double, 3> at;
        std::uint32_t start;
    };
    std::pmr::vector<PlacedStart> by_position(start_count, memory);
    for (std::uint32_t s = 0; s < start_count; ++s) {
        const Eigen::Vector3d p = position_of_start(s);
        const std::uint64_t hash =
            position_hash({position_bits(p[0]), position_bits(p[1]), position_bits(p[2])});
        by_position[s] = {hash, {p[0], p[1], p[2]}, s};
    }
    std::sort(by_position.begin(), by_position.end(),
              [](const PlacedStart& a, const PlacedStart& b) {
                  return a.hash != b.hash ? a.hash < b.hash : a.at < b.at;
              });
    std::pmr::vector<std::uint32_t> point_of_start(start_count, 0, memory);
    std::pmr::vector<std::uint32_t> start_of_point(memory);  // one start at each point
    for (std::uint32_t k = 0; k < start_count; ++k) {
        const std::uint32_t s = by_position[k].start;
        if (k == 0 || by_position[k - 1].at != by_position[k].at) start_of_point.push_back(s);
        point_of_start[s] = std::uint32_t(start_of_point.size() - 1);
    }
    let_go(by_position);
    const std::size_t point_count = start_of_point.size();
    // The tree's triangles of each shell (lowest copies, not degenerate), in
    // order, with their boxes: those of shell s are
    // shell_triangles[shell_begin[s], shell_begin[s + 1]). The boxes are
    // taken once here: taken at each point, from the triangles' corners,
    // they were half the cost of the points' lists on cubes resting on each
    // other, whose triangles are listed at every one of their corners.
    struct BoxedTriangle {
        std::uint32_t triangle;
        ShellBox box;
    };
    std::pmr::vector<std::uint32_t> shell_begin(shells.count + 1, 0, memory);
    const auto in_tree = [&](std::uint32_t t) {
        return surface.lowest_copy(t) == t && !surface.meets_nothing(t);
    };
    for (std::uint32_t t = 0; t < surface.size(); ++t)
        if (in_tree(t)) ++shell_begin[shell_of(t) + 1];
    for (std::size_t shell = 0; shell < shells.count; ++shell)
        shell_begin[shell + 1] += shell_begin[shell];
    std::pmr::vector<BoxedTriangle> shell_triangles(shell_begin.back(), memory);
    {
        std::pmr::vector<std::uint32_t> next(shell_begin.begin(), shell_begin.end() - 1, memory);
        for (std::uint32_t t = 0; t < surface.size(); ++t)
            if (in_tree(t)) shell_triangles[next[shell_of(t)]++] = {t, triangle_box(t)};
    }
    // The shells whose boxes may meet each shell's: those of shell s are
    // neighbours[neighbours_begin[s], neighbours_begin[s + 1]), from one walk
    // over the pairs of the shells' tree, whose boxes are rounded outward
    // (every shell whose exact box meets s's is among them). A shell whose
    // box holds a point meets the box of every shell with a vertex there, so
    // a point's shells are found among the neighbours of one of those, where
    // a look along the shells' tree, whose boxes all touch a point where
    // parts rest on each other, opened hundreds of nodes (docs/validity.md).
    // Past kPairsPerShell pairs a shell (parts in each other's boxes, as at a
    // point many parts touch) the walk stops and none are kept: each point
    // looks along the tree, as does one whose shell has more than
    // kScannedNeighbours.
    std::pmr::vector<std::array<std::uint32_t, 2>> meeting(memory);
    bool paired = true;
    for (const BoxTree::PairTask& piece : shell_tree.pair_tasks()) {
        paired = shell_tree.for_each_overlapping_pair(piece, [&](std::uint32_t r, std::uint32_t s) {
            meeting.push_back({r, s});
            return meeting.size() <= kPairsPerShell * shells.count;
        });
        if (!paired) break;
    }
    std::pmr::vector<std::uint32_t> neighbours_begin(paired ? shells.count + 1 : 0, 0, memory);
    std::pmr::vector<std::uint32_t> neighbours(paired ? 2 * meeting.size() : 0, memory);
    if (paired) {
        for (const auto& [r, s] : meeting) {
            ++neighbours_begin[r + 1];
            ++neighbours_begin[s + 1];
        }
        for (std::size_t shell = 0; shell < shells.count; ++shell)
            neighbours_begin[shell + 1] += neighbours_begin[shell];
        std::pmr::vector<std::uint32_t> next(neighbours_begin.begin(), neighbours_begin.end() - 1,
                                             memory);
        for (const auto& [r, s] : meeting) {
            neighbours[next[r]++] = s;
            neighbours[next[s]++] = r;
        }
    }
    let_go(meeting);
    // The triangles whose boxes hold each point, of every shell (a start
    // skips its own shell's), with their boxes' side bits, looked up in
    // blocks as tasks, then gathered in order: those of point i are
    // near_triangles[near_begin[i], near_begin[i + 1]). A triangle's box
    // holds the point only if its shell's does: where those shells are
    // small (parts of an assembly: a corner where eight cubes meet has 96
    // triangles) their triangles are tested one by one, which costs a
    // third of a look along the triangles' tree, whose boxes there all
    // touch the point; otherwise the tree is asked. The same triangles
    // either way (the tree holds the lowest copies of shapes not
    // degenerate), in another order, which on_another_shell does not use.
    // With them, the shells whose boxes hold each point, kNearShells + 1 at
    // most (more: the list is left empty and marked kManyShells), for the
    // starts' shells_near: a start next to p lies in a box only if p does,
    // and the shells' tree, whose boxes all touch such a point, was looked
    // along again at each start there (five or so a cube of a stack).
    struct NearTriangle {
        std::uint32_t triangle;
        std::uint8_t box_sides;
    };
    constexpr std::uint32_t kManyShells = UINT32_MAX;
    const std::size_t point_blocks = (point_count + kTrianglesPerTask - 1) / kTrianglesPerTask;
    std::pmr::vector<std::pmr::vector<NearTriangle>> block_near(point_blocks, memory);
    std::pmr::vector<std::pmr::vector<std::uint32_t>> block_shells(point_blocks, memory);
    std::pmr::vector<std::uint32_t> near_count(point_count, 0, memory);
    std::pmr::vector<std::uint32_t> shell_count(point_count, 0, memory);
    tasks.run(point_blocks, [&](std::size_t block) {
        const std::size_t end = std::min<std::size_t>(point_count, (block + 1) * kTrianglesPerTask);
        std::array<std::uint32_t, kNearShells + 1> holding;
        for (std::size_t i = block * kTrianglesPerTask; i < end; ++i) {
            const Eigen::Vector3d p = position_of_start(start_of_point[i]);
            const ProbeStart start{p, p, p, false};
            const auto list_if_near = [&](std::uint32_t t, const ShellBox& box) {
                if ((box.lo.array() <= p.array()).all() && (p.array() <= box.hi.array()).all()) {
                    block_near[block].push_back({t, SideBits::of_box(box, p)});
                    ++near_count[i];
                }
                return true;
            };
            const auto list_along_tree = [&] {
                const Eigen::Vector3d p_in_units = surface.in_units(p);
                surface.tree().for_each_item_near_segment(
                    p_in_units, p_in_units,
                    [&](std::uint32_t t) { return list_if_near(t, triangle_box(t)); });
            };
            std::size_t holding_count = 0, triangle_count = 0;
            const auto hold_if_holding = [&](std::uint32_t shell) {
                if (!holds(shell_boxes[shell], start)) return true;
                if (holding_count == holding.size()) {
                    holding_count = kManyShells;
                    return false;
                }
                triangle_count += shell_begin[shell + 1] - shell_begin[shell];
                holding[holding_count++] = shell;
                return true;
            };
            const std::uint32_t own = shell_of(corner_of_start[start_of_point[i]] / 3);
            if (paired && neighbours_begin[own + 1] - neighbours_begin[own] <= kScannedNeighbours) {
                if (hold_if_holding(own))
                    for (std::uint32_t n = neighbours_begin[own]; n < neighbours_begin[own + 1];
                         ++n)
                        if (!hold_if_holding(neighbours[n])) break;
            } else {
                const Eigen::Vector3d p_in_units = surface.in_units(p);
                shell_tree.for_each_item_near_segment(p_in_units, p_in_units, hold_if_holding);
            }
            shell_count[i] = std::uint32_t(holding_count);
            if (holding_count == kManyShells) {
                list_along_tree();
                continue;
            }
            block_shells[block].insert(block_shells[block].end(), holding.begin(),
                                       holding.begin() + holding_count);
            if (triangle_count > kScannedTriangles) {
                list_along_tree();
                continue;
            }
            for (std::size_t k = 0; k < holding_count; ++k)
                for (std::uint32_t n = shell_begin[holding[k]]; n < shell_begin[holding[k] + 1];
                     ++n)
                    list_if_near(shell_triangles[n].triangle, shell_triangles[n].box);
        }
    });
    std::pmr::vector<std::size_t> near_begin(point_count + 1, 0, memory);
    for (std::size_t i = 0; i < point_count; ++i) near_begin[i + 1] = near_begin[i] + near_count[i];
    // The listed triangles, and apart their side bits, read eight at a time
    // by on_another_shell (a word past the last: kSidesPadding).
    constexpr std::size_t kSidesPadding = 8;
    std::pmr::vector<std::uint32_t> near_triangles(memory);
    std::pmr::vector<std::uint8_t> near_sides(memory);
    near_triangles.reserve(near_begin.back());
    near_sides.reserve(near_begin.back() + kSidesPadding);
    for (const auto& found : block_near)
        for (const NearTriangle& near : found) {
            near_triangles.push_back(near.triangle);
            near_sides.push_back(near.box_sides);
        }
    near_sides.resize(near_begin.back() + kSidesPadding, 0);
    let_go(block_near);
    std::pmr::vector<std::size_t> shells_begin(point_count + 1, 0, memory);
    for (std::size_t i = 0; i < point_count; ++i)
        shells_begin[i + 1] =
            shells_begin[i] + (shell_count[i] == kManyShells ? 0 : shell_count[i]);
    std::pmr::vector<std::uint32_t> near_shells(memory);
    near_shells.reserve(shells_begin.back());
    for (const auto& found : block_shells)
        near_shells.insert(near_shells.end(), found.begin(), found.end());
    let_go(block_shells);
    // The other shells whose boxes hold a start at vertex `vertex` of `shell`:
    // from its point's list, or, past kNearShells + 1 there, along the tree.
    auto shells_near = [&](const ProbeStart& start, std::uint32_t shell, std::uint32_t vertex) {
        Near near;
        const auto count_if_holding = [&](std::uint32_t other) {
            if (other == shell || !holds(shell_boxes[other], start)) return true;
            near.box.extend(shell_boxes[other]);
            return ++near.count <= kNearShells;
        };
        const std::uint32_t point = point_of_start[start_of_vertex[vertex]];
        if (shell_count[point] != kManyShells) {
            for (std::size_t k = shells_begin[point]; k < shells_begin[point + 1]; ++k)
                if (!count_if_holding(near_shells[k])) break;
            return near;
        }
        const Eigen::Vector3d p = surface.in_units(start.p);
        shell_tree.for_each_item_near_segment(p, p, count_if_holding);
        return near;
    };
    auto on_another_shell = [&](const ProbeStart& start, std::uint32_t shell,
                                std::uint32_t vertex) {
        const std::uint32_t point = point_of_start[start_of_vertex[vertex]];
        const std::uint8_t start_sides = SideBits::of_start(start);
        // A start off the triangle's box is off the triangle: of the many
        // triangles around a corner where parts rest on each other, this
        // leaves those on the start's side, a few of a hundred. Their bits
        // are tested eight at a time, as the bytes of a word (whether one of
        // them is zero, exactly), and one by one only in a word that has
        // one: tested one by one, they were a quarter of the probes' cost.
        const std::uint64_t start_word = start_sides * std::uint64_t{0x0101010101010101u};
        const std::size_t end = near_begin[point + 1];
        for (std::size_t first = near_begin[point]; first < end; first += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, &near_sides[first], sizeof word);
            word &= start_word;
            const std::uint64_t low_bits = 0x0101010101010101u, high_bits = 0x8080808080808080u;
            if (((word - low_bits) & ~word & high_bits) == 0) continue;  // no zero byte
            for (std::size_t k = first; k < std::min(end, first + 8); ++k)
                if ((start_sides & near_sides[k]) == 0 && shell_of(near_triangles[k]) != shell &&
                    lies_on_triangle(start, near_triangles[k]))
                    return true;
        }
        return false;
    };
    // The winding at the start: kUnknownWinding when it lies on another
    // shell (asked first: the starts where parts rest flush on each other,
    // most of a touching assembly's, then need no look at the shells'
    // boxes) or every direction grazes, 0 when no other shell's box holds it
    // (no segment needed).
    auto probe = [&](const ProbeStart& start, std::uint32_t shell, std::uint32_t vertex) {
        int winding = kUnknownWinding;
        if (on_another_shell(start, shell, vertex)) return winding;
        const Near near = shells_near(start, shell, vertex);
        if (near.count == 0) return 0;
        for (const Eigen::Vector3d& direction : kProbeDirections) {
            winding = winding_at(start, direction, shell, near);
            if (winding != kUnknownWinding) break;
        }
        return winding;
    };
    // Each task probes its own shells, and below its own triangles.
    tasks.run((shells.count + kShellsPerTask - 1) / kShellsPerTask, [&](std::size_t task) {
        const std::size_t end = std::min<std::size_t>(shells.count, (task + 1) * kShellsPerTask);
        for (std::uint32_t shell = std::uint32_t(task * kShellsPerTask); shell < end; ++shell) {
            int& winding = winding_of_shell[shell];
            for (std::size_t k = 0; k < probe_count[shell] && winding == kUnknownWinding; ++k) {
                const Eigen::Vector3d p = surface.triangle(probes[shell][k])[0];
                winding = probe({p, p, p, false}, shell, surface.corners(probes[shell][k])[0]);
            }
        }
    });
    // Where a shell touches another, the rest of the surface may wind around
    // its pieces differently: a surface passing through another's face
    // exactly along its own edges crosses no face, yet lies partly inside
    // the other part, and all its vertices may lie on that part or outside
    // it. So each triangle touching another shell is probed from inside,
    // next to each of its corners, unless the start there lies on another
    // shell (what touches it from one side, along a segment or at a point,
    // leaves the winding alike on both sides; a face lying flush on part of
    // it cuts its inside into pieces, which these probes reach unless flush
    // faces cover every corner); a shell whose probes disagree bounds some
    // region twice (or less than once), whatever its sense. Each triangle's
    // probes are joined apart, then into its shell's, in triangle order.
    std::pmr::vector<int> winding_inside(surface.size(), kUnknownWinding, memory);
    tasks.run((surface.size() + kTrianglesPerTask - 1) / kTrianglesPerTask, [&](std::size_t task) {
        const std::size_t end = std::min(surface.size(), (task + 1) * kTrianglesPerTask);
        for (std::uint32_t t = std::uint32_t(task * kTrianglesPerTask); t < end; ++t) {
            if (!touches_other_shell[t].load(std::memory_order_relaxed)) continue;
            int& winding = winding_inside[t];
            for (int k = 0; k < 3 && winding != kMixedWinding; ++k) {
                const Triangle corners = surface.triangle(t, k);
                winding = join_windings(winding, probe({corners[0], corners[1], corners[2], true},
                                                       shell_of(t), surface.corners(t)[k]));
            }
        }
    });
    for (std::uint32_t t = 0; t < surface.size(); ++t) {
        int& winding = winding_of_shell[shell_of(t)];
        winding = join_windings(winding, winding_inside[t]);
    }
    return winding_of_shell;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                        \
    template std::pmr::vector<int> count_windings<Scalar, Index>(                  \
        const IndexedSurface<Scalar, Index>&, const SurfaceContacts&, TaskRunner&, \
        std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
