// The winding numbers of how shells nest (shell_nesting.cpp), counted by
// probes over the indexed surface once no face crosses another: zero around
// parts apart or resting on each other, one around a cavity or a solid
// inside a solid, the sum of the enclosing shells' around a part in a
// hollow, and mixed for a shell that passes through another's face along its
// own edges (half inside, half out). Each case also far from the origin, and
// with the probes' tasks run in reverse order.
#include "core/shell_nesting.hpp"

#include "check.hpp"
#include "test_mesh.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <memory_resource>
#include <string>
#include <utility>
#include <vector>

#include "core/surface_contacts.hpp"
#include "core/worker_pool.hpp"
#include "reversed_task_runner.hpp"

namespace {

using polymass::core::kMixedWinding;
using polymass::core::kUnknownWinding;
using polymass_test::TestMesh;

// Appends the axis-aligned box [lo, hi] (triangles), inside out on request.
void add_box(TestMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
             bool inside_out) {
    const Eigen::Vector3d size = hi - lo;
    const TestMesh box = polymass_test::box_mesh(lo, Eigen::Vector3d(size.x(), 0, 0),
                                                 Eigen::Vector3d(0, size.y(), 0),
                                                 Eigen::Vector3d(0, 0, size.z()), true);
    const std::uint32_t base = std::uint32_t(mesh.vertex_count());
    for (std::size_t v = 0; v < box.vertex_count(); ++v) mesh.add_vertex(box.vertex(v));
    for (std::size_t f = 0; f < box.indices.size(); f += 3) {
        const std::uint32_t a = base + box.indices[f], b = base + box.indices[f + 1],
                            c = base + box.indices[f + 2];
        if (inside_out)
            mesh.add_face({a, c, b});
        else
            mesh.add_face({a, b, c});
    }
}

// A double pyramid whose square waist [0.25, 0.75]^2 lies at height 1 (on a
// unit cube's top face), apexes at heights 2 and `bottom_height` (0.5: inside
// the cube; 0: on its bottom face, so that every corner of its lower half
// lies on the cube's faces, and only starts inside its triangles see it).
void add_double_pyramid(TestMesh& mesh, double bottom_height = 0.5) {
    const std::uint32_t top = mesh.add_vertex({0.5, 0.5, 2}),
                        bottom = mesh.add_vertex({0.5, 0.5, bottom_height});
    std::uint32_t waist[4];
    const double corners[4][2] = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
    for (int k = 0; k < 4; ++k) waist[k] = mesh.add_vertex({corners[k][0], corners[k][1], 1});
    for (int k = 0; k < 4; ++k) {
        mesh.add_face({top, waist[k], waist[(k + 1) % 4]});
        mesh.add_face({bottom, waist[(k + 1) % 4], waist[k]});
    }
}

// An L-shaped prism, [0, 3] x [0, 1] and [0, 1] x [0, 3] across, z in [0,
// 1]: its box holds the notch [1, 3]^2 x [0, 1], which lies outside it.
void add_l_prism(TestMesh& mesh) {
    const double outline[6][2] = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    std::uint32_t bottom[6], top[6];
    for (int k = 0; k < 6; ++k) {
        bottom[k] = mesh.add_vertex({outline[k][0], outline[k][1], 0});
        top[k] = mesh.add_vertex({outline[k][0], outline[k][1], 1});
    }
    // The outline cut into triangles about its corner (0, 0), which sees all of it.
    for (int k = 1; k < 5; ++k) {
        mesh.add_face({top[0], top[k], top[k + 1]});
        mesh.add_face({bottom[0], bottom[k + 1], bottom[k]});
    }
    for (int k = 0; k < 6; ++k) {
        const int next = (k + 1) % 6;
        mesh.add_face({bottom[k], bottom[next], top[next]});
        mesh.add_face({bottom[k], top[next], top[k]});
    }
}

// A tetrahedron (its own four vertices, faces turned outward).
// Its faces turned outward, or inward (a cavity, or inside out) when `inward`.
void add_tetrahedron(TestMesh& mesh, const Eigen::Vector3d (&corner)[4], bool inward = false) {
    const bool positive =
        (corner[1] - corner[0]).dot((corner[2] - corner[0]).cross(corner[3] - corner[0])) > 0;
    std::uint32_t v[4];
    for (int k = 0; k < 4; ++k) v[k] = mesh.add_vertex(corner[k]);
    if (positive == inward) std::swap(v[1], v[2]);
    mesh.add_face({v[0], v[2], v[1]});
    mesh.add_face({v[0], v[1], v[3]});
    mesh.add_face({v[0], v[3], v[2]});
    mesh.add_face({v[1], v[2], v[3]});
}

// k thin tetrahedra whose apexes are one point, `apex`, pointing out along
// directions spread over the sphere (length 1, never meeting elsewhere):
// separate parts, each its own vertex there, all touching each other at it.
// With `nested`, needle 0 holds a second one, half as long and half as wide,
// from the same apex (its own vertex there): touching it at that point alone.
// All turned inward with `inward`.
void add_needles(TestMesh& mesh, const Eigen::Vector3d& apex, int k, bool nested = false,
                 bool inward = false) {
    const double pi = 3.14159265358979323846;
    for (int n = 0; n < k; ++n) {
        const double z = 1 - (2 * n + 1.0) / k, r = std::sqrt(1 - z * z);
        const double turn = n * pi * (3 - std::sqrt(5.0));
        const Eigen::Vector3d d(r * std::cos(turn), r * std::sin(turn), z);
        const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
        const double width = 0.2 * std::sqrt(4 * pi / k);
        for (const double scale : {1.0, 0.5}) {
            if (scale != 1 && !(nested && n == 0)) continue;
            Eigen::Vector3d corner[4] = {apex, apex, apex, apex};
            for (int c = 0; c < 3; ++c)
                corner[1 + c] +=
                    scale * (d + scale * width *
                                     (std::cos(2 * pi * c / 3) * u + std::sin(2 * pi * c / 3) * v));
            add_tetrahedron(mesh, corner, inward);
        }
    }
}

// k thin tetrahedra around one edge from `foot` up by 1 along z, as the
// pages of a book around its spine: touching each other along it.
// With `nested`, page 0 holds a second one from the same foot, its spine the
// lower half of the first's, its other corners inside the first: touching it
// along that half spine (off the first's faces elsewhere: a corner of the
// inner one in the plane of the outer's foot and far corners, and the two
// faces would coincide). All turned inward with `inward`.
void add_pages(TestMesh& mesh, const Eigen::Vector3d& foot, int k, bool nested = false,
               bool inward = false) {
    const double pi = 3.14159265358979323846;
    for (int n = 0; n < k; ++n) {
        const double angle = 2 * pi * n / k, width = pi / k;
        const Eigen::Vector3d corner[4] = {
            foot, foot + Eigen::Vector3d(0, 0, 1),
            foot + Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.5),
            foot + Eigen::Vector3d(std::cos(angle + width), std::sin(angle + width), 0.5)};
        add_tetrahedron(mesh, corner, inward);
        if (!nested || n != 0) continue;
        const Eigen::Vector3d inner[4] = {
            foot, foot + Eigen::Vector3d(0, 0, 0.5),
            0.4 * foot + 0.1 * corner[1] + 0.375 * corner[2] + 0.125 * corner[3],
            0.4 * foot + 0.1 * corner[1] + 0.125 * corner[2] + 0.375 * corner[3]};
        add_tetrahedron(mesh, inner, inward);
    }
}

// The mesh turned a quarter about z: exactly, no coordinate rounded.
TestMesh turned(TestMesh mesh) {
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        double* x = &mesh.coordinates[3 * v];
        const double x0 = x[0];
        x[0] = -x[1], x[1] = x0;
    }
    return mesh;
}

// The unit cube with each face cut into n x n squares of two triangles: one
// shell of 12 n^2 triangles, more than the nesting tests one by one at a
// point (kScannedTriangles) for n = 5 and more.
void add_fine_cube(TestMesh& mesh, int n) {
    const std::uint32_t base = std::uint32_t(mesh.vertex_count());
    auto at = [&](int i, int j, int k) {
        return base + std::uint32_t((i * (n + 1) + j) * (n + 1) + k);
    };
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            for (int k = 0; k <= n; ++k)
                mesh.add_vertex(Eigen::Vector3d(i, j, k) / n);  // inner ones unused
    // Each face as a grid over (u, v), turned outward or inward as `outward` says.
    auto face = [&](auto vertex, bool outward) {
        for (int u = 0; u < n; ++u)
            for (int v = 0; v < n; ++v) {
                const std::uint32_t a = vertex(u, v), b = vertex(u + 1, v),
                                    c = vertex(u + 1, v + 1), d = vertex(u, v + 1);
                if (outward) {
                    mesh.add_face({a, b, c});
                    mesh.add_face({a, c, d});
                } else {
                    mesh.add_face({a, c, b});
                    mesh.add_face({a, d, c});
                }
            }
    };
    face([&](int u, int v) { return at(u, v, 0); }, false);
    face([&](int u, int v) { return at(u, v, n); }, true);
    face([&](int u, int v) { return at(0, u, v); }, false);
    face([&](int u, int v) { return at(n, u, v); }, true);
    face([&](int u, int v) { return at(v, 0, u); }, false);
    face([&](int u, int v) { return at(v, n, u); }, true);
}

// The windings of the mesh's shells moved by `offset`.
std::vector<int> windings_of(TestMesh mesh, const Eigen::Vector3d& offset) {
    for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) mesh.coordinates[i] += offset[i % 3];
    const polymass::core::Shells shells = polymass_test::shells_of(mesh);
    const auto view = mesh.view();
    Eigen::AlignedBox3d box;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) box.extend(mesh.vertex(v));
    polymass::core::SerialTaskRunner serial;
    std::pmr::memory_resource* memory = std::pmr::get_default_resource();
    const polymass::core::IndexedSurface surface(view, nullptr, box.center(), box.diagonal().norm(),
                                                 &shells, serial, memory);
    const polymass::core::SurfaceContacts contacts =
        polymass::core::find_contacts(surface, serial, memory);
    CHECK(contacts.crossing.count == 0);
    const std::pmr::vector<int> windings =
        polymass::core::count_windings(surface, contacts, serial, memory);
    // Tasks finishing in any order, on any number of threads, give the same windings.
    polymass_test::ReversedTaskRunner reversed;
    CHECK(polymass::core::count_windings(surface, contacts, reversed, memory) == windings);
    static polymass::core::WorkerPool two_threads(2, memory);
    CHECK(polymass::core::count_windings(surface, contacts, two_threads, memory) == windings);
    return std::vector<int>(windings.begin(), windings.end());
}

void expect(const char* name, const TestMesh& mesh, const std::vector<int>& expected) {
    for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e6, -1e6, 1e6),
                                          Eigen::Vector3d(1e8, 1e8, -1e8)}) {
        const std::vector<int> found = windings_of(mesh, offset);
        const bool same = found == expected;
        if (!same) {
            std::fprintf(stderr, "%s at (%g, %g, %g): windings", name, offset.x(), offset.y(),
                         offset.z());
            for (const int w : found) std::fprintf(stderr, " %d", w);
            std::fprintf(stderr, "\n");
        }
        CHECK(same);
    }
}

}  // namespace

int main() {
    TestMesh apart;
    add_box(apart, {0, 0, 0}, {1, 1, 1}, false);
    add_box(apart, {2, 0, 0}, {3, 1, 1}, false);
    expect("two cubes apart", apart, {0, 0});

    TestMesh resting;
    add_box(resting, {0, 0, 0}, {1, 1, 1}, false);
    add_box(resting, {1, 0.25, 0.5}, {2, 1.25, 1.5}, false);
    expect("a cube resting against another, offset", resting, {0, 0});

    TestMesh cavity;
    add_box(cavity, {0, 0, 0}, {4, 4, 4}, false);
    add_box(cavity, {1, 1, 1}, {3, 3, 3}, true);
    expect("a cube with a cavity", cavity, {0, 1});

    TestMesh nested;
    add_box(nested, {0, 0, 0}, {4, 4, 4}, false);
    add_box(nested, {1, 1, 1}, {2, 2, 2}, false);
    expect("a solid inside a solid", nested, {0, 1});

    TestMesh hollow;
    add_box(hollow, {0, 0, 0}, {6, 6, 6}, false);
    add_box(hollow, {1, 1, 1}, {5, 5, 5}, true);
    add_box(hollow, {2, 2, 2}, {4, 4, 4}, false);
    expect("a part inside a hollow part", hollow, {0, 1, 0});

    TestMesh touching_inside;
    add_box(touching_inside, {0, 0, 0}, {6, 6, 6}, false);
    add_box(touching_inside, {1, 1, 1}, {5, 5, 5}, true);
    add_box(touching_inside, {1, 1, 1}, {2, 2, 2}, false);  // in the cavity's corner
    add_box(touching_inside, {2, 2, 1}, {3, 3, 2}, false);  // on its floor, by an edge
    expect("parts resting in a cavity, on its floor and walls", touching_inside, {0, 1, 0, 0});

    // The shells' boxes overlap or hold one another, the shells do not nest.
    TestMesh notch;
    add_l_prism(notch);
    add_box(notch, {1, 1, 0}, {2, 2, 1}, false);                    // against the inner walls
    add_box(notch, {2.25, 2.25, 0.25}, {2.75, 2.75, 0.75}, true);   // inside out
    add_box(notch, {0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}, false);  // in the L
    add_box(notch, {2.5, 0.5, 1}, {3.5, 1.5, 2}, false);            // on the L's end, overhanging
    expect("parts in the notch of an L, in it and on it", notch, {0, 0, 0, 1, 0});

    // A start whose segment leaves the box of the only shell around it (a
    // tall L) inside a part it does not count (whose box does not hold it).
    TestMesh tall_notch;
    add_l_prism(tall_notch);
    for (std::size_t v = 0; v < tall_notch.vertex_count(); ++v)
        tall_notch.coordinates[3 * v + 2] *= 3;
    add_box(tall_notch, {1.1, 1.1, 0.1}, {1.3, 1.3, 0.3}, false);
    add_box(tall_notch, {1.5, 1.5, 0.5}, {4, 4, 4}, false);
    expect("a part in a tall L's notch, beside one reaching out of it", tall_notch, {0, 0, 0});

    // More shells around the innermost starts than a probe lists
    // (kNearShells): hollows within hollows, each a solid around a cavity,
    // and solids within solids, each wound around by all outside it.
    TestMesh hollows, solids;
    std::vector<int> alternating, depth;
    for (int k = 0; k < 41; ++k) {
        const Eigen::Vector3d lo = Eigen::Vector3d::Constant(k),
                              hi = Eigen::Vector3d::Constant(100 - k);
        add_box(hollows, lo, hi, k % 2 != 0);
        alternating.push_back(k % 2);
        add_box(solids, lo, hi, false);
        depth.push_back(k);
    }
    expect("41 nested shells, solids and cavities in turn", hollows, alternating);
    expect("41 nested solids", solids, depth);

    // Many separate parts touching at one point, or along one edge: each
    // start there lies on the others' triangles, or next to them, and more
    // than kNearShells of their boxes hold it. Alone, and inside a solid.
    for (const bool inside : {false, true}) {
        TestMesh needles, pages;
        std::vector<int> expected(1, 0);
        expected.resize(41, inside ? 1 : 0);
        add_box(needles, {-2, -2, -2}, {2, 2, 2}, false);
        add_box(pages, {-2, -2, -2}, {2, 2, 2}, false);
        if (!inside) {  // the solid moved aside, its part of the count 0
            for (std::size_t v = 0; v < 8; ++v) needles.coordinates[3 * v] += 10;
            for (std::size_t v = 0; v < 8; ++v) pages.coordinates[3 * v] += 10;
        }
        add_needles(needles, {0.25, -0.5, 0.125}, 40);
        add_pages(pages, {0.25, -0.5, -0.375}, 40);
        expect(inside ? "40 needles at one point inside a solid" : "40 needles at one point",
               needles, expected);
        expect(inside ? "40 pages around one edge inside a solid" : "40 pages around one edge",
               pages, expected);
    }

    // A part inside another touching it only where the many parts meet (at
    // the needles' apex, along the lower half of the pages' spine), as a
    // solid or a cavity, and every part inside out; the solids also turned
    // (each case runs 6 analyses of 41 shells: the test's time is in them).
    // The inner part is shell 1, the one holding it shell 0.
    for (const bool cavity : {false, true})
        for (const bool inward : {false, true}) {
            if (cavity && inward) continue;
            TestMesh needles, pages;
            add_needles(needles, {0.25, -0.5, 0.125}, 40, true, inward);
            add_pages(pages, {0.25, -0.5, -0.375}, 40, true, inward);
            if (cavity)  // the inner part (shell 1's 4 faces) turned the other way
                for (TestMesh* mesh : {&needles, &pages})
                    for (std::size_t f = 4; f < 8; ++f)
                        std::swap(mesh->indices[3 * f + 1], mesh->indices[3 * f + 2]);
            // Around the inner part: the outer one, +1 or, inside out, -1.
            std::vector<int> expected(41, 0);
            expected[1] = inward ? -1 : 1;
            const char* what = cavity   ? "the inner one a cavity"
                               : inward ? "all inside out"
                                        : "solids";
            for (const bool quarter : {false, true}) {
                if (quarter && (cavity || inward)) continue;
                const std::string needle_name = std::string("40 needles, one inside another at ") +
                                                "the apex, " + what + (quarter ? ", turned" : "");
                const std::string page_name = std::string("40 pages, one inside another along ") +
                                              "the spine, " + what + (quarter ? ", turned" : "");
                expect(needle_name.c_str(), quarter ? turned(needles) : needles, expected);
                expect(page_name.c_str(), quarter ? turned(pages) : pages, expected);
            }
        }

    // A tetrahedron under a box, its top face flush with part of the box's
    // bottom, from a corner on the bottom's edge (x = 0): the start inside
    // that face next to the corner moves first to x > 0, onto the box's
    // bottom, then towards x < 0, which must not turn it away from the box
    // (probed upwards, it would seem inside the box).
    TestMesh under;
    add_box(under, {0, 0, 1}, {2, 2, 2}, false);
    const Eigen::Vector3d flush[4] = {{0, 1, 1}, {1, 0.5, 1}, {-0.5, 1.5, 1}, {0.25, 1, 0}};
    add_tetrahedron(under, flush);
    expect("a tetrahedron under a box, flush with part of its bottom", under, {0, 0});

    TestMesh through;
    add_box(through, {0, 0, 0}, {1, 1, 1}, false);
    add_double_pyramid(through);
    expect("a double pyramid through a cube's face along its edges", through, {0, kMixedWinding});
    TestMesh on_floor;
    add_box(on_floor, {0, 0, 0}, {1, 1, 1}, false);
    add_double_pyramid(on_floor, 0);
    expect("a double pyramid through a cube's face, its apex on the cube's floor", on_floor,
           {0, kMixedWinding});

    // The same through, and on, a cube cut into 768 triangles: its
    // triangles at a point are looked up along the tree, not one by one.
    // Cut finely, the cube's top face has triangles inside the pyramid's
    // waist, whose probes see the pyramid around them: the cube is mixed too.
    TestMesh fine_through, fine_resting;
    add_fine_cube(fine_through, 8);
    add_double_pyramid(fine_through);
    expect("a double pyramid through a finely cut cube's face along its edges", fine_through,
           {kMixedWinding, kMixedWinding});
    add_fine_cube(fine_resting, 8);
    add_box(fine_resting, {0.25, 0.25, 1}, {0.75, 0.75, 1.5}, false);
    add_box(fine_resting, {1, 0, 0}, {2, 1, 1}, false);
    expect("cubes resting on a finely cut cube", fine_resting, {0, 0, 0});

    // Nesting inside a touching assembly: a hollow part with another resting
    // flush on it and a third on its cavity's floor against a wall, and a
    // solid resting flush on the floor of another hollow, which rests flush
    // on the first (the starts on flush faces are turned away, the others
    // see the hollows around them).
    TestMesh hollow_stack;
    add_box(hollow_stack, {0, 0, 0}, {4, 4, 4}, false);
    add_box(hollow_stack, {1, 1, 1}, {3, 3, 3}, true);
    add_box(hollow_stack, {1, 1, 1}, {2, 2, 2}, false);            // in the cavity's corner
    add_box(hollow_stack, {0, 0, 4}, {4, 4, 8}, false);            // resting on the hollow part
    add_box(hollow_stack, {1, 1, 5}, {3, 3, 7}, true);             // its own cavity
    add_box(hollow_stack, {1.5, 1.5, 5}, {2.5, 2.5, 5.5}, false);  // on that cavity's floor
    expect("hollow parts resting on each other, parts in their cavities", hollow_stack,
           {0, 1, 0, 0, 1, 0});

    // A grid of cubes resting on each other, the middle one hollow, with a
    // cube in its cavity touching its wall (the hollow's probes all start on
    // its neighbours, its cavity's and the cube's see it around them):
    // the points where the cubes meet are held by eight shells, found among
    // the neighbours of one of them.
    TestMesh grid;
    std::vector<int> grid_windings;
    for (int k = 0; k < 27; ++k) {
        const Eigen::Vector3d corner(2 * (k % 3), 2 * (k / 3 % 3), 2 * (k / 9));
        add_box(grid, corner, corner + Eigen::Vector3d(2, 2, 2), false);
        // The middle cube lies on the others wherever it is probed: unknown.
        grid_windings.push_back(k == 13 ? kUnknownWinding : 0);
    }
    add_box(grid, {2.5, 2.5, 2.5}, {3.5, 3.5, 3.5}, true);  // the middle cube's cavity
    add_box(grid, {2.5, 2.5, 2.5}, {3, 3, 3}, false);       // in its corner
    grid_windings.push_back(1);
    grid_windings.push_back(0);
    expect("a grid of cubes, one hollow around a cube", grid, grid_windings);

    // The same grid solid: the middle cube lies on the others wherever it
    // is probed, but no cube's box reaches inside another's, so no cube is
    // wound around, and none is probed.
    TestMesh solid_grid;
    for (int k = 0; k < 27; ++k) {
        const Eigen::Vector3d corner(2 * (k % 3), 2 * (k / 3 % 3), 2 * (k / 9));
        add_box(solid_grid, corner, corner + Eigen::Vector3d(2, 2, 2), false);
    }
    expect("a grid of cubes resting on each other", solid_grid, std::vector<int>(27, 0));

    // A plate inside a solid with more parts resting on it than a point of
    // the plate lists as neighbours (kScannedNeighbours): the plate's points
    // look along the shells' tree for the solid around them.
    TestMesh plate;
    add_box(plate, {-1, -1, -1}, {13, 13, 3}, false);
    add_box(plate, {0, 0, 0}, {12, 12, 1}, false);
    std::vector<int> plate_windings{0, 1};
    for (int k = 0; k < 72; ++k) {
        const Eigen::Vector3d corner(1 + k % 9 * 1.25, 1 + k / 9 * 1.25, 1);
        add_box(plate, corner, corner + Eigen::Vector3d(1, 1, 1), false);
        plate_windings.push_back(1);
    }
    expect("72 parts resting on a plate inside a solid", plate, plate_windings);

    // More pairs of shells whose boxes meet than the neighbours are listed
    // for (kPairsPerShell a shell): 200 solids nested, each box in all the
    // others', and apart 20 cubes each inside a solid of its own. The walk
    // over the pairs stops before it has them all: no point may use its
    // shell's neighbours (a cube's, with its solid missing, would see none).
    TestMesh deep;
    std::vector<int> deep_depth;
    for (int k = 0; k < 200; ++k) {
        add_box(deep, Eigen::Vector3d::Constant(k), Eigen::Vector3d::Constant(400 - k), false);
        deep_depth.push_back(k);
    }
    for (int k = 0; k < 20; ++k) {
        const Eigen::Vector3d corner(-100 - 4 * k, 0, 0);
        add_box(deep, corner, corner + Eigen::Vector3d(3, 3, 3), false);
        add_box(deep, corner + Eigen::Vector3d(1, 1, 1), corner + Eigen::Vector3d(2, 2, 2), false);
        deep_depth.push_back(0);
        deep_depth.push_back(1);
    }
    expect("200 nested solids, and 20 cubes each in a solid apart", deep, deep_depth);

    // Enough shells and triangles for the probes to run as several tasks,
    // the mixed shell in the last: a layer of cubes resting side by side.
    TestMesh layer;
    const int rows = 8, columns = 9;
    for (int k = 0; k < rows * columns; ++k) {
        const Eigen::Vector3d corner(k % columns, k / columns, 0);
        add_box(layer, corner, corner + Eigen::Vector3d(1, 1, 1), false);
    }
    add_box(layer, {-2, 0, 0}, {-1, 1, 1}, false);
    add_double_pyramid(layer);  // through the last cube's top face (moved below)
    for (std::size_t v = layer.vertex_count() - 6; v < layer.vertex_count(); ++v)
        layer.coordinates[3 * v] -= 2;
    std::vector<int> windings(rows * columns + 1, 0);
    windings.push_back(kMixedWinding);
    expect("a layer of cubes, and a double pyramid through a cube beside it", layer, windings);
    return polymass_test::finish("test_shell_nesting");
}
