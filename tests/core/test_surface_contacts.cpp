// The search for meeting faces finds the face pairs of a test of every pair
// of triangles, however many copies of a triangle the surface holds: the box
// tree holds one triangle of each shape (same positions, same order) and the
// copies are paired from the shape pair's tests, each row of copies ending
// where no count can take its pairs (surface_contacts.cpp). Piles of cubes
// at one place, unwelded, sharing some corners with the first copy (in every
// corner position), or all of them, with turned cubes crossing the pile at
// a shared corner; past the count's stop (2048 pairs) and below it; with the
// search's pieces in order and in reverse, and a surface of many pieces; without shells and with
// them (coinciding copies on two shells cross, on one they touch, and copies on the same vertices
// in the same turn cross wherever they are); fans of triangles around one
// vertex, and two triangles folded over each other in one plane around a
// shared vertex (no pair: only crossing counts there); an assembly of touching cubes, past the
// count's stop, with a crossing cube and coinciding faces late; crossing boxes of quads among
// resting cubes, whose touching count is the tree's. The reference tests all pairs with
// the same exact predicate (test_triangle_contact checks that one).
#include "core/surface_contacts.hpp"

#include "check.hpp"
#include "reversed_task_runner.hpp"
#include "test_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory_resource>
#include <random>
#include <set>
#include <vector>

#include "core/triangle_contact.hpp"
#include "core/worker_pool.hpp"

namespace {

using polymass::core::Contact;
using polymass::core::PairFinding;
using polymass::core::Triangle;
using polymass_test::TestMesh;

constexpr std::size_t kMostCountedPairs = 2048;

// A triangulated cube [0, 1]^3 turned by `turn` about the origin, its vertex
// v taken as reuse[v] for v < reused, its triangles listing their corners
// from corner `first`.
void add_cube(TestMesh& mesh, const Eigen::Matrix3d& turn, const std::uint32_t* reuse,
              std::size_t reused, int first) {
    static const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::uint32_t ids[8];
    for (int v = 0; v < 8; ++v) {
        const Eigen::Vector3d corner(v & 1, (v >> 1) & 1, (v >> 2) & 1);
        ids[v] = std::size_t(v) < reused ? reuse[v] : mesh.add_vertex(turn * corner);
    }
    for (const auto& q : quads)
        for (const std::array<int, 3> t :
             {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}})
            mesh.add_face({ids[t[first]], ids[t[(first + 1) % 3]], ids[t[(first + 2) % 3]]});
}

// Every pair of triangles (each face is one) tested.
struct Reference {
    std::vector<std::array<std::uint64_t, 2>> crossing, touching;
};

Reference test_every_pair(const TestMesh& mesh, const polymass::core::Shells* shells) {
    Reference found;
    const std::size_t faces = mesh.indices.size() / 3;
    auto corner = [&](std::size_t f, int k) { return mesh.indices[3 * f + k]; };
    auto triangle = [&](std::size_t f, int first) {
        return Triangle{mesh.vertex(corner(f, first)), mesh.vertex(corner(f, (first + 1) % 3)),
                        mesh.vertex(corner(f, (first + 2) % 3))};
    };
    // Triangles whose boxes do not meet do not meet: not tested, so that
    // assemblies of a few thousand triangles stay quick in a debug build.
    std::vector<Eigen::AlignedBox3d> boxes(faces);
    for (std::size_t f = 0; f < faces; ++f)
        for (int k = 0; k < 3; ++k) boxes[f].extend(mesh.vertex(corner(f, k)));
    for (std::size_t f = 0; f < faces; ++f) {
        if (polymass::core::is_degenerate(triangle(f, 0))) continue;
        for (std::size_t g = f + 1; g < faces; ++g) {
            if (!boxes[f].intersects(boxes[g])) continue;
            if (polymass::core::is_degenerate(triangle(g, 0))) continue;
            int shared = 0, at_f = 0, at_g = 0;
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    if (corner(f, k) == corner(g, l)) ++shared, at_f = k, at_g = l;
            if (shared >= 2) {
                // Neighbours across an edge, or one triangle written twice:
                // in one turn that bounds its region twice, and crosses.
                if (shared == 3 && corner(f, (at_f + 1) % 3) == corner(g, (at_g + 1) % 3))
                    found.crossing.push_back({f, g});
                continue;
            }
            Contact contact =
                polymass::core::triangle_contact(triangle(f, at_f), triangle(g, at_g), shared == 1);
            if (contact == Contact::coinciding)
                contact = shells && shells->of_face[f] != shells->of_face[g] ? Contact::crossing
                                                                             : Contact::touching;
            if (contact == Contact::crossing) found.crossing.push_back({f, g});
            if (contact == Contact::touching) found.touching.push_back({f, g});
        }
    }
    return found;
}

// What the nesting needs marked: per shell, whether another shell's box
// reaches inside its own (on every axis each begins below where the other
// ends), every pair of shells compared; per triangle, whether it touches a
// triangle of another shell and its own shell is reached inside.
struct Marks {
    std::vector<std::uint8_t> reached_inside;
    std::vector<bool> touches_other_shell;
};

Marks expected_marks(const TestMesh& mesh, const polymass::core::Shells& shells,
                     const Reference& contacts) {
    std::vector<Eigen::AlignedBox3d> boxes(shells.count);
    for (std::size_t f = 0; f < mesh.indices.size() / 3; ++f)
        for (int k = 0; k < 3; ++k)
            boxes[shells.of_face[f]].extend(mesh.vertex(mesh.indices[3 * f + k]));
    Marks marks{std::vector<std::uint8_t>(shells.count, 0),
                std::vector<bool>(mesh.indices.size() / 3, false)};
    for (std::size_t r = 0; r < shells.count; ++r)
        for (std::size_t s = 0; s < shells.count; ++s)
            if (r != s && (boxes[r].min().array() < boxes[s].max().array()).all() &&
                (boxes[s].min().array() < boxes[r].max().array()).all())
                marks.reached_inside[r] = 1;
    for (const auto& [f, g] : contacts.touching) {
        const std::uint32_t shell_f = shells.of_face[f], shell_g = shells.of_face[g];
        if (shell_f == shell_g) continue;
        if (marks.reached_inside[shell_f]) marks.touches_other_shell[f] = true;
        if (marks.reached_inside[shell_g]) marks.touches_other_shell[g] = true;
    }
    return marks;
}

// The triangles whose mark differs from the expected one (and a shell's
// reached-inside flag that does, counted as one).
std::size_t wrong_marks(const polymass::core::SurfaceContacts& found, const Marks& expected) {
    std::size_t wrong = !std::equal(found.reached_inside.begin(), found.reached_inside.end(),
                                    expected.reached_inside.begin(), expected.reached_inside.end());
    for (std::size_t t = 0; t < expected.touches_other_shell.size(); ++t)
        wrong += expected.touches_other_shell[t] != (found.touches_other_shell[t].load() != 0);
    return wrong;
}

using Pairs = std::vector<std::array<std::uint64_t, 2>>;

// Whether a finding of a search that went to the end agrees with the sorted
// pairs of the test of every pair: counted to the stop, the lowest listed.
bool agrees(const PairFinding& found, const Pairs& pairs) {
    const bool stopped = pairs.size() >= kMostCountedPairs;
    if (found.complete == stopped) return false;
    if (found.count != (stopped ? kMostCountedPairs : pairs.size())) return false;
    for (std::size_t i = 0; i < found.kept(); ++i)
        if (found.lowest[i] != pairs[i]) return false;
    return true;
}

// Whether a finding of a search that ended at the crossing pairs' stop
// holds what such a search promises (POLYMASS_MAX_COUNTED_FACE_PAIRS): a
// lower bound, no more than the stop nor than there are, its listed pairs
// ascending and each one of `pairs` or of `also` (a face pair touching where
// the search went may cross where it did not).
bool agrees_in_part(const PairFinding& found, const Pairs& pairs, const Pairs& also) {
    if (found.complete || found.count > std::min(kMostCountedPairs, pairs.size() + also.size()))
        return false;
    for (std::size_t i = 0; i < found.kept(); ++i) {
        const auto& pair = found.lowest[i];
        if (i > 0 && !(found.lowest[i - 1] < pair)) return false;
        if (!std::binary_search(pairs.begin(), pairs.end(), pair) &&
            !std::binary_search(also.begin(), also.end(), pair))
            return false;
    }
    return true;
}

// Whether the search's findings agree with the test of every pair: as
// agrees, or past the crossing pairs' stop, where the search ends, as
// agrees_in_part for both kinds.
bool agrees(const polymass::core::SurfaceContacts& found, const Reference& expected) {
    if (expected.crossing.size() < kMostCountedPairs)
        return agrees(found.crossing, expected.crossing) &&
               agrees(found.touching, expected.touching);
    return found.crossing.count == kMostCountedPairs &&
           agrees_in_part(found.crossing, expected.crossing, {}) &&
           agrees_in_part(found.touching, expected.touching, expected.crossing);
}

// `run` given a runner of one thread, one taking the pieces in reverse, and
// one of two threads, in turn.
template <class Run>
void on_three_runners(const Run& run) {
    polymass::core::SerialTaskRunner serial;
    polymass_test::ReversedTaskRunner reversed;
    polymass::core::WorkerPool pool(2, std::pmr::get_default_resource());
    for (polymass::core::TaskRunner* runner : {static_cast<polymass::core::TaskRunner*>(&serial),
                                               static_cast<polymass::core::TaskRunner*>(&reversed),
                                               static_cast<polymass::core::TaskRunner*>(&pool)})
        run(*runner);
}

// Whether two triangles lie at the same three positions in one turn (copies).
bool has_copies(const TestMesh& mesh) {
    std::set<std::array<std::array<double, 3>, 3>> seen;
    for (std::size_t f = 0; f < mesh.indices.size(); f += 3) {
        std::array<std::array<double, 3>, 3> t;
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d p = mesh.vertex(mesh.indices[f + k]);
            t[k] = {p.x(), p.y(), p.z()};
        }
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        if (!seen.insert(t).second) return true;
    }
    return false;
}

// The search's contacts on `mesh`, with its pieces in order and in reverse,
// each given to `check`; on a mesh without copies, also indexed without
// their search (as a caller that has ruled them out indexes it).
template <class Check>
void on_each_runner(const TestMesh& mesh, const polymass::core::Shells* shells,
                    const Eigen::Vector3d& reference, double size, const Check& check) {
    const auto view = mesh.view();
    polymass::core::SerialTaskRunner serial;
    polymass_test::ReversedTaskRunner reversed;
    for (const bool may_have_copies : {true, false}) {
        if (!may_have_copies && has_copies(mesh)) continue;
        for (polymass::core::TaskRunner* runner :
             {static_cast<polymass::core::TaskRunner*>(&serial),
              static_cast<polymass::core::TaskRunner*>(&reversed)}) {
            const polymass::core::IndexedSurface surface(view, nullptr, reference, size, shells,
                                                         *runner, std::pmr::get_default_resource(),
                                                         may_have_copies);
            check(
                polymass::core::find_contacts(surface, *runner, std::pmr::get_default_resource()));
        }
    }
}

void check_pile(const char* name, const TestMesh& mesh, const polymass::core::Shells* shells) {
    const Reference expected = test_every_pair(mesh, shells);
    Eigen::AlignedBox3d box;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) box.extend(mesh.vertex(v));
    on_each_runner(mesh, shells, box.center(), box.diagonal().norm(), [&](const auto& found) {
        const bool agreed = agrees(found, expected);
        if (!agreed)
            std::fprintf(stderr,
                         "%s, %s: crossing %zu (expected %zu), touching %zu (expected %zu); the "
                         "findings differ\n",
                         name, shells ? "with shells" : "without shells", found.crossing.count,
                         expected.crossing.size(), found.touching.count, expected.touching.size());
        CHECK(agreed);
    });
}

// Pairs of crossing triangles, each pair in a cell of a grid with a third
// triangle apart, the first triangles of the pairs first: more pairs than
// the count keeps, over more triangles than one piece of the search holds
// (4096), none of which holds 2048 pairs, so that only the pieces' findings
// merged reach the stop. The count stops at 2048, and the search with it
// (the touching pairs, none, are then a lower bound); the pairs listed are
// crossing ones, whatever the runner.
// The corners of a cell of a grid of crossing pairs, added to `mesh` about
// the cell's corner `at`: a triangle flat in z = 0 and one upright across its
// inside, along y = 0.25, which cross; and a third apart from both. Their
// boxes are centred at z = 0, so that the curve orders the cells by x and y
// alone, and a piece of the search holds whole cells.
struct CrossingCell {
    std::array<std::uint32_t, 3> flat, upright, apart;
};

CrossingCell add_crossing_cell(TestMesh& mesh, const Eigen::Vector3d& at) {
    auto add = [&](double x, double y, double z) {
        return mesh.add_vertex(at + Eigen::Vector3d(x, y, z));
    };
    return {{add(0, 0, 0), add(1, 0, 0), add(0, 1, 0)},
            {add(0.1, 0.25, -0.5), add(0.6, 0.25, -0.5), add(0.35, 0.25, 0.5)},
            {add(1.8, 1.8, 0), add(2.3, 1.8, 0), add(1.8, 2.3, 0)}};
}

void check_many_pieces() {
    constexpr std::uint32_t cells = 3000, row = 60;
    TestMesh mesh;
    std::vector<std::array<std::uint32_t, 3>> flat, upright, apart;
    for (std::uint32_t k = 0; k < cells; ++k) {
        const CrossingCell cell = add_crossing_cell(mesh, {3.0 * (k % row), 3.0 * (k / row), 0.0});
        flat.push_back(cell.flat);
        upright.push_back(cell.upright);
        apart.push_back(cell.apart);
    }
    for (const auto& triangles : {flat, upright, apart})
        for (const auto& t : triangles) mesh.add_face({t[0], t[1], t[2]});
    on_each_runner(mesh, nullptr, Eigen::Vector3d(90, 75, 0), 300.0, [&](const auto& found) {
        CHECK(found.crossing.count == kMostCountedPairs);
        CHECK(!found.crossing.complete);
        for (std::uint64_t k = 0; k < found.crossing.kept(); ++k)
            CHECK(found.crossing.lowest[k][1] == found.crossing.lowest[k][0] + cells);
        CHECK(found.touching.count == 0 && !found.touching.complete);
    });
}

// Two clusters far apart, each a grid of cells of two crossing triangles
// (add_crossing_cell; the third's corners left unused), more than the
// count's stop in each, and over more triangles than a piece holds; their
// faces alternate between the clusters
// (cell k's triangles are faces 2k and 2 cells + 2k in the first, one more
// in the second), so that the lowest crossing pairs of all would alternate
// too. The search ends at the crossing pairs' stop, within the cluster the
// tree's pieces reach first: every pair listed is of one cluster, and the
// finding is the same on every runner, two threads included.
void check_search_ends_at_the_crossing_stop() {
    constexpr std::uint32_t cells = 3000, row = 60;
    TestMesh mesh;
    std::vector<std::array<std::uint32_t, 3>> flat, upright;
    for (std::uint32_t k = 0; k < cells; ++k) {
        for (const double offset : {0.0, 1e4}) {
            const CrossingCell cell =
                add_crossing_cell(mesh, {offset + 3.0 * (k % row), 3.0 * (k / row), 0.0});
            flat.push_back(cell.flat);
            upright.push_back(cell.upright);
        }
    }
    for (const auto& triangles : {flat, upright})
        for (const auto& t : triangles) mesh.add_face({t[0], t[1], t[2]});
    const auto view = mesh.view();
    std::vector<PairFinding> crossing, touching;
    on_three_runners([&](polymass::core::TaskRunner& tasks) {
        const polymass::core::IndexedSurface surface(view, nullptr, Eigen::Vector3d(5090, 75, 0),
                                                     2e4, nullptr, tasks,
                                                     std::pmr::get_default_resource());
        const auto found =
            polymass::core::find_contacts(surface, tasks, std::pmr::get_default_resource());
        CHECK(found.crossing.count == kMostCountedPairs && !found.crossing.complete);
        CHECK(found.touching.count == 0 && !found.touching.complete);
        const std::uint64_t cluster = found.crossing.lowest[0][0] % 2;
        for (std::size_t i = 0; i < found.crossing.kept(); ++i) {
            const auto& pair = found.crossing.lowest[i];
            CHECK(pair[0] % 2 == cluster && pair[1] == pair[0] + 2 * cells);
        }
        crossing.push_back(found.crossing);
        touching.push_back(found.touching);
    });
    for (std::size_t run = 1; run < crossing.size(); ++run) {
        CHECK(crossing[run].count == crossing[0].count);
        CHECK(crossing[run].lowest == crossing[0].lowest);
        CHECK(touching[run].count == touching[0].count);
    }
}

// Fans of triangles around one vertex, their other corners at random points
// of a small integer grid, the vertex at each corner position: most pairs
// share that vertex alone, many of them meet in its coordinate on an axis
// (decided from the triangles' corner extremes, surface_contacts.cpp), and
// many cross at it, some with the vertex the highest of one on an axis and
// the lowest of the other on another.
void check_fans() {
    std::mt19937 random(27);
    std::uniform_int_distribution<int> coordinate(-2, 2);
    auto point = [&] {
        return Eigen::Vector3d(coordinate(random), coordinate(random), 0.5 * coordinate(random));
    };
    std::size_t crossing = 0, pairs = 0;
    for (int fan = 0; fan < 24; ++fan) {
        TestMesh mesh;
        const std::uint32_t centre = mesh.add_vertex(Eigen::Vector3d::Zero());
        for (int t = 0; t < 40; ++t) {
            Eigen::Vector3d a, b;
            do {
                a = point();
                b = point();
            } while (a.cross(b).isZero());  // collinear with the centre
            const std::uint32_t corners[3] = {centre, mesh.add_vertex(a), mesh.add_vertex(b)};
            mesh.add_face({corners[t % 3], corners[(t + 1) % 3], corners[(t + 2) % 3]});
        }
        char name[32];
        std::snprintf(name, sizeof name, "fan %d", fan);
        check_pile(name, mesh, nullptr);
        crossing += test_every_pair(mesh, nullptr).crossing.size();
        pairs += 40 * 39 / 2;
    }
    // The fans must cross often, or the test proves little.
    CHECK(crossing > pairs / 20);
    std::printf("  24 fans of 40 triangles: %zu of %zu pairs cross\n", crossing, pairs);
}

// Two triangles in one plane around a vertex they share, overlapping over an
// area: met at a shared corner only crossing counts (triangle_contact), and
// a fold within a plane changes no point's winding number, so no pair is
// reported, in either turn. In an axis plane the search decides them from
// the corner extremes alone (the vertex is the highest and the lowest of
// both on that axis); in a tilted plane, by the predicates. The same two
// triangles on two vertices at one position coincide or touch there, and are
// reported: what drops the pair is the shared vertex, not where it lies.
void check_folds_at_a_shared_corner() {
    // The plane's two steps: along x and y, or across every axis (integers,
    // so that the corners lie exactly in one plane).
    const std::array<Eigen::Vector3d, 2> axis_plane{Eigen::Vector3d(1, 0, 0),
                                                    Eigen::Vector3d(0, 1, 0)};
    const std::array<Eigen::Vector3d, 2> tilted{Eigen::Vector3d(1, -1, 0),
                                                Eigen::Vector3d(1, 1, -2)};
    for (const auto& steps : {axis_plane, tilted}) {
        for (const bool same_turn : {true, false}) {
            for (const bool shared : {true, false}) {
                TestMesh mesh;
                auto add = [&](double x, double y) {
                    return mesh.add_vertex(Eigen::Vector3d(5, -3, 7) + x * steps[0] + y * steps[1]);
                };
                const std::uint32_t v = add(0, 0), a = add(2, 0), b = add(0, 2);
                const std::uint32_t w = shared ? v : add(0, 0), c = add(2, 1), d = add(1, 2);
                mesh.add_face({v, a, b});
                if (same_turn)
                    mesh.add_face({w, c, d});
                else
                    mesh.add_face({w, d, c});
                const Triangle first{mesh.vertex(v), mesh.vertex(a), mesh.vertex(b)};
                const Triangle second =
                    same_turn ? Triangle{mesh.vertex(w), mesh.vertex(c), mesh.vertex(d)}
                              : Triangle{mesh.vertex(w), mesh.vertex(d), mesh.vertex(c)};
                const Contact expected = shared      ? Contact::none
                                         : same_turn ? Contact::coinciding
                                                     : Contact::touching;
                CHECK(polymass::core::triangle_contact(first, second, shared) == expected);
                Eigen::AlignedBox3d box;
                for (std::size_t k = 0; k < mesh.vertex_count(); ++k) box.extend(mesh.vertex(k));
                polymass::core::SerialTaskRunner serial;
                const auto view = mesh.view();
                const polymass::core::IndexedSurface surface(view, nullptr, box.center(),
                                                             box.diagonal().norm(), nullptr, serial,
                                                             std::pmr::get_default_resource());
                const polymass::core::SurfaceContacts found = polymass::core::find_contacts(
                    surface, serial, std::pmr::get_default_resource());
                // Without shells, coinciding faces are taken as touching.
                CHECK(found.crossing.count == 0);
                CHECK(found.touching.count == (shared ? 0u : 1u));
                check_pile("a fold at a shared corner", mesh, nullptr);
            }
        }
    }
}

// Separate cubes stacked in a grid, each resting on its neighbours: far
// more touching pairs than the count keeps, so that past its stop a pair
// between two triangles already marked as touching another shell is asked
// only whether it crosses or coincides (crossing_or_coinciding). Among them,
// late in face order, a small cube crossing the top of the last one, a
// box around the first, twice its height, whose faces coincide with its
// faces in part (on two shells: crossing), and an inside-out cube resting
// against the last one, half beside it, their faces in the plane where their
// boxes meet coinciding in part in the same turn (crossing; most pairs of
// shells whose boxes meet in a plane are decided from those boxes, but not
// two faces flat in it). The findings must be those of a test of every
// pair, and the marks of triangles touching another shell those its
// touching pairs give.
void check_touching_assembly() {
    constexpr int side = 5;
    TestMesh mesh;
    const Eigen::Vector3d far(1e3, -2e3, 3e3), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    for (int k = 0; k < side * side * side; ++k) {
        const Eigen::Vector3d at(k % side, k / side % side, k / side / side);
        polymass_test::append(mesh, polymass_test::box_mesh(far + at, x, y, z, true));
    }
    const Eigen::Vector3d top = far + Eigen::Vector3d::Constant(side - 1);
    polymass_test::append(mesh, polymass_test::box_mesh(top + Eigen::Vector3d(0.25, 0.25, 0.5),
                                                        0.5 * x, 0.5 * y, 0.5 * z, true));
    polymass_test::append(mesh, polymass_test::box_mesh(far, x, 2 * y, 2 * z, true));
    polymass_test::append(mesh,
                          polymass_test::box_mesh(top + Eigen::Vector3d(1, 0.5, 0), y, x, z, true));
    const polymass::core::Shells shells = polymass_test::shells_of(mesh);
    const Reference expected = test_every_pair(mesh, &shells);
    const Marks marks = expected_marks(mesh, shells, expected);
    CHECK(expected.touching.size() > 8 * kMostCountedPairs);
    CHECK(!expected.crossing.empty());
    on_each_runner(mesh, &shells, top, 10.0, [&](const auto& found) {
        CHECK(agrees(found, expected));
        const std::size_t wrong = wrong_marks(found, marks);
        CHECK(wrong == 0);
        if (wrong) std::fprintf(stderr, "touching assembly: %zu marked wrongly\n", wrong);
    });
    std::printf(
        "  %d touching cubes, a crossing cube, a coinciding box and an inside-out cube: %zu pairs "
        "crossing, %zu touching\n",
        side * side * side, expected.crossing.size(), expected.touching.size());
}

// Parts resting on each other and nothing crossing, searched by pairs of
// shells (shell_pairs.hpp): 125 unit cubes in a grid, past the count's stop
// in one piece of the search, and a tetrahedron whose box overlaps a cube's
// in volume, touching it at one point of its edge. Then the same with a
// sheet resting on the last cube, coinciding with its top across the plane
// they meet in: crossing, found only by the pairs of faces flat in that
// plane once both are marked. And eight cubes, every touching pair
// counted. Counts,
// lowest pairs and marks as a test of every pair finds them, on one thread,
// in reverse and on two. (Marks only without crossing faces: with them the
// nesting, which reads them, does not run, and the tree's search then
// decides.)
void check_resting_parts() {
    constexpr int side = 5;
    const Eigen::Vector3d far(1e3, -2e3, 3e3), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    TestMesh resting;
    for (int k = 0; k < side * side * side; ++k) {
        const Eigen::Vector3d at(k % side, k / side % side, k / side / side);
        polymass_test::append(resting, polymass_test::box_mesh(far + at, x, y, z, true));
    }
    // Its edge from (s + 1/2, 1/2, t - 1/2) to (s - 1/2, 1/2, t + 1/2) meets
    // the cube's edge x = s, z = t at y = 1/2; the tetrahedron lies where
    // x + z >= s + t, the cube where x + z <= s + t.
    {
        const Eigen::Vector3d edge = far + Eigen::Vector3d(side, 0.5, side);
        TestMesh tetrahedron;
        const std::uint32_t a = tetrahedron.add_vertex(edge + Eigen::Vector3d(0.5, 0, -0.5));
        const std::uint32_t b = tetrahedron.add_vertex(edge + Eigen::Vector3d(-0.5, 0, 0.5));
        const std::uint32_t c = tetrahedron.add_vertex(edge + Eigen::Vector3d(0.5, -1, 0.5));
        const std::uint32_t d = tetrahedron.add_vertex(edge + Eigen::Vector3d(0.5, 1, 0.5));
        for (const auto& face : {std::array<std::uint32_t, 3>{a, c, b},
                                 {a, b, d},
                                 {a, d, c},
                                 std::array<std::uint32_t, 3>{b, c, d}})
            tetrahedron.add_face({face[0], face[1], face[2]});
        polymass_test::append(resting, tetrahedron);
    }
    // A sheet of one triangle on the last cube's top, facing up as it does
    // (coinciding: crossing), along the edge it shares with the cube
    // before it, whose side marks it first.
    TestMesh with_sheet = resting;
    {
        const Eigen::Vector3d corner = far + Eigen::Vector3d(side - 1, side - 1, side);
        TestMesh sheet;
        sheet.add_face({sheet.add_vertex(corner), sheet.add_vertex(corner + 0.5 * x),
                        sheet.add_vertex(corner + 0.5 * y)});
        polymass_test::append(with_sheet, sheet);
    }
    // Eight cubes, below the count's stop: every touching pair counted, those
    // of two cubes whose triangles others have marked too.
    TestMesh few;
    for (int k = 0; k < 8; ++k)
        polymass_test::append(
            few, polymass_test::box_mesh(far + Eigen::Vector3d(k & 1, k >> 1 & 1, k >> 2), x, y, z,
                                         true));
    for (const TestMesh* mesh : {&resting, &with_sheet, &few}) {
        const polymass::core::Shells shells = polymass_test::shells_of(*mesh);
        const Reference expected = test_every_pair(*mesh, &shells);
        const Marks marks = expected_marks(*mesh, shells, expected);
        CHECK((expected.touching.size() > kMostCountedPairs) == (mesh != &few));
        CHECK(expected.crossing.empty() == (mesh != &with_sheet));
        const auto view = mesh->view();
        on_three_runners([&](polymass::core::TaskRunner& tasks) {
            const polymass::core::IndexedSurface surface(view, nullptr, far, 10.0, &shells, tasks,
                                                         std::pmr::get_default_resource());
            const auto found =
                polymass::core::find_contacts(surface, tasks, std::pmr::get_default_resource());
            CHECK(agrees(found, expected));
            const std::size_t wrong = expected.crossing.empty() ? wrong_marks(found, marks) : 0;
            CHECK(wrong == 0);
            if (wrong) std::fprintf(stderr, "resting parts: %zu marked wrongly\n", wrong);
        });
        std::printf("  %s: %zu pairs crossing, %zu touching\n",
                    mesh == &few       ? "8 resting cubes"
                    : mesh == &resting ? "125 resting cubes and a tetrahedron"
                                       : "125 resting cubes, a tetrahedron and a sheet",
                    expected.crossing.size(), expected.touching.size());
    }
}

// A face pair that both crosses (through one pair of its triangles) and
// touches (through another) is listed as crossing only, so it leaves the
// touching count when the pairs counted before the count's stop held it;
// which pairs they held depends on the order the pairs come. The search by
// pairs of shells (shell_pairs.hpp) comes in the shells' order, the tree's in
// Morton order, and a surface on which the former finds a crossing pair is
// searched again along the tree, so that the answer is the tree's. Here 124
// resting cubes (triangles) pass the stop; in the place of the 125th, two
// boxes of quads, the last two shells, cross: a side quad of the small one
// crosses the large one's bottom quad through one of its triangles and
// touches the other at a point of the diagonal. The tree meets that pair
// before its stop, the shells' order after it (the hole, 87, is chosen so).
// Without shells only the tree searches, and finds the contacts it finds
// with them (no faces coincide in one turn).
void check_crossing_searched_along_the_tree() {
    constexpr int side = 5, hole = 87;
    const Eigen::Vector3d far(1e3, -2e3, 3e3), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    auto cell = [&](int k) -> Eigen::Vector3d {
        return far + Eigen::Vector3d(k % side, k / side % side, k / side / side);
    };
    TestMesh mesh;
    polymass::core::Shells shells(std::pmr::get_default_resource());
    auto add_part = [&](const TestMesh& part) {
        polymass_test::append(mesh, part);
        shells.of_face.resize(mesh.face_sizes.size(), std::uint32_t(shells.count++));
    };
    for (int k = 0; k < side * side * side; ++k)
        if (k != hole) add_part(polymass_test::box_mesh(cell(k), x, y, z, true));
    add_part(polymass_test::box_mesh(cell(hole) + Eigen::Vector3d::Constant(0.25), 0.5 * x, 0.5 * y,
                                     0.5 * z, false));
    add_part(polymass_test::box_mesh(cell(hole) + Eigen::Vector3d(0.375, 0.375, 0.125), 0.25 * x,
                                     0.25 * y, 0.375 * z, false));
    const auto view = mesh.view();
    auto same = [](const PairFinding& a, const PairFinding& b) {
        if (a.count != b.count || a.complete != b.complete) return false;
        for (std::size_t i = 0; i < a.kept(); ++i)
            if (a.lowest[i] != b.lowest[i]) return false;
        return true;
    };
    on_three_runners([&](polymass::core::TaskRunner& tasks) {
        auto contacts = [&](const polymass::core::Shells* of_faces) {
            const polymass::core::IndexedSurface surface(view, nullptr, far, 10.0, of_faces, tasks,
                                                         std::pmr::get_default_resource());
            return polymass::core::find_contacts(surface, tasks, std::pmr::get_default_resource());
        };
        const auto with_shells = contacts(&shells), along_the_tree = contacts(nullptr);
        CHECK(with_shells.crossing.count == 4);
        // The case this test is for: the tree counted face pairs that also
        // cross before its stop (should the tree's order change, choose
        // another hole where it does).
        CHECK(along_the_tree.touching.count < kMostCountedPairs);
        CHECK(same(with_shells.crossing, along_the_tree.crossing));
        CHECK(same(with_shells.touching, along_the_tree.touching));
        if (!same(with_shells.touching, along_the_tree.touching))
            std::fprintf(stderr,
                         "crossing boxes among resting cubes: %zu touching pairs, %zu "
                         "along the tree\n",
                         with_shells.touching.count, along_the_tree.touching.count);
    });
}

// The shells' boxes, taken in the pass that boxes the triangles, in blocks
// of 2^16 triangles joined in block order: the exact least and greatest
// coordinates of each shell's corners, degenerate triangles' too, on every
// runner. Over three blocks of random triangles far from the origin, whose
// faces go to the shells in runs of random length, so that runs of one
// shell cross blocks and a shell returns in many; one shell reaches farthest
// only through a degenerate triangle.
void check_shell_boxes() {
    constexpr std::size_t triangles = 3 * (std::size_t{1} << 16) + 123, shells = 41;
    std::mt19937_64 random(27);
    std::uniform_int_distribution<int> grid(-4096, 4096);
    auto random_point = [&] {
        return Eigen::Vector3d(-1e6 + 0x1p-10 * grid(random), 3e5 + 0x1p-7 * grid(random),
                               0x1p-12 * grid(random));
    };
    TestMesh mesh;
    polymass::core::Shells shells_of_faces(std::pmr::get_default_resource());
    shells_of_faces.count = shells;
    std::uniform_int_distribution<std::uint32_t> run_length(1, 700), shell(0, shells - 1);
    for (std::uint32_t run = 0, of_run = 0; mesh.face_sizes.size() < triangles; --run) {
        if (run == 0) {
            run = run_length(random);
            of_run = shell(random);
        }
        const std::uint32_t a = mesh.add_vertex(random_point());
        mesh.add_face({a, mesh.add_vertex(random_point()), mesh.add_vertex(random_point())});
        shells_of_faces.of_face.push_back(of_run);
    }
    const std::uint32_t far_out = mesh.add_vertex(Eigen::Vector3d(-2e6, 4e5, -1.5));
    mesh.add_face({far_out, far_out, 0});
    shells_of_faces.of_face.push_back(7);
    std::vector<polymass::core::ShellBox> expected(shells);
    for (std::size_t f = 0; f < mesh.face_sizes.size(); ++f)
        for (int k = 0; k < 3; ++k)
            expected[shells_of_faces.of_face[f]].extend(mesh.vertex(mesh.indices[3 * f + k]));
    const auto view = mesh.view();
    on_three_runners([&](polymass::core::TaskRunner& tasks) {
        const polymass::core::IndexedSurface surface(view, nullptr, Eigen::Vector3d(-1e6, 3e5, 0),
                                                     1e3, &shells_of_faces, tasks,
                                                     std::pmr::get_default_resource());
        const auto& found = surface.shell_boxes();
        CHECK(found.size() == shells);
        std::size_t wrong = 0;
        for (std::size_t k = 0; k < std::min(found.size(), expected.size()); ++k)
            wrong += found[k].lo != expected[k].lo || found[k].hi != expected[k].hi;
        CHECK(wrong == 0);
        if (wrong) std::fprintf(stderr, "shell boxes: %zu of %zu wrong\n", wrong, shells);
    });
    // One shell: nothing to nest, no boxes.
    polymass::core::SerialTaskRunner serial;
    shells_of_faces.count = 1;
    std::fill(shells_of_faces.of_face.begin(), shells_of_faces.of_face.end(), 0);
    CHECK(polymass::core::IndexedSurface(view, nullptr, Eigen::Vector3d(-1e6, 3e5, 0), 1e3,
                                         &shells_of_faces, serial, std::pmr::get_default_resource())
              .shell_boxes()
              .empty());
}

}  // namespace

int main() {
    check_shell_boxes();
    check_touching_assembly();
    check_resting_parts();
    check_crossing_searched_along_the_tree();
    check_folds_at_a_shared_corner();
    check_many_pieces();
    check_search_ends_at_the_crossing_stop();
    check_fans();
    const Eigen::Matrix3d none = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d turned =
        Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Matrix3d turned_more =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(-2, 1, 3).normalized()).toRotationMatrix();
    const std::uint32_t first_vertices[] = {0, 1, 2, 3, 4, 5, 6, 7};
    // 4 copies stay below the count's stop; 24 pass it for touching pairs,
    // and with shells for crossing ones too when the cubes share no vertex
    // (coinciding faces of two shells), which otherwise (the turned cubes)
    // stay below it.
    for (std::size_t copies : {4, 24}) {
        for (int first = 0; first < 2; ++first) {
            for (std::size_t shared_vertices : {0, 1, 8}) {
                TestMesh pile;
                for (std::size_t c = 0; c < copies; ++c)
                    add_cube(pile, none, first_vertices, c == 0 ? 0 : shared_vertices, first);
                add_cube(pile, turned, first_vertices, 1, 0);
                add_cube(pile, turned_more, first_vertices, 1, 2);
                char name[96];
                std::snprintf(name, sizeof name,
                              "%zu cubes from corner %d sharing %zu vertices, 2 turned", copies,
                              first, shared_vertices);
                const polymass::core::Shells shells = polymass_test::shells_of(pile);
                check_pile(name, pile, nullptr);
                check_pile(name, pile, &shells);
            }
        }
    }
    // A pile of subnormal size, whose boxes are in units of 2^-1022 (the
    // unit stops there: the inverse of a subnormal unit is infinite, which
    // made every box NaN and the search test every pair, slowly).
    for (int first = 0; first < 2; ++first) {
        const double tiny = 0x1p-1050;
        TestMesh pile;
        for (std::size_t c = 0; c < 4; ++c)
            add_cube(pile, tiny * none, first_vertices, c == 0 ? 0 : 1, first);
        add_cube(pile, tiny * turned, first_vertices, 1, 0);
        char name[96];
        std::snprintf(name, sizeof name, "4 cubes of side 2^-1050 from corner %d, 1 turned", first);
        const polymass::core::Shells shells = polymass_test::shells_of(pile);
        check_pile(name, pile, nullptr);
        check_pile(name, pile, &shells);
    }
    return polymass_test::finish("test_surface_contacts");
}
