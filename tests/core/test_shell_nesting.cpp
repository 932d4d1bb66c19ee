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
#include <cstdio>
#include <memory_resource>
#include <vector>

#include "core/surface_contacts.hpp"
#include "reversed_task_runner.hpp"

namespace {

using polymass::core::kMixedWinding;
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
// unit cube's top face), apexes at heights 2 and 0.5 (inside the cube).
void add_double_pyramid(TestMesh& mesh) {
    const std::uint32_t top = mesh.add_vertex({0.5, 0.5, 2}),
                        bottom = mesh.add_vertex({0.5, 0.5, 0.5});
    std::uint32_t waist[4];
    const double corners[4][2] = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
    for (int k = 0; k < 4; ++k) waist[k] = mesh.add_vertex({corners[k][0], corners[k][1], 1});
    for (int k = 0; k < 4; ++k) {
        mesh.add_face({top, waist[k], waist[(k + 1) % 4]});
        mesh.add_face({bottom, waist[(k + 1) % 4], waist[k]});
    }
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
                                                 serial, memory);
    const polymass::core::SurfaceContacts contacts =
        polymass::core::find_contacts(surface, &shells, serial, memory);
    CHECK(contacts.crossing.count == 0);
    const std::pmr::vector<int> windings = polymass::core::count_windings(
        surface, shells, contacts.touches_other_shell, serial, memory);
    // Tasks finishing in any order give the same windings.
    polymass_test::ReversedTaskRunner reversed;
    CHECK(polymass::core::count_windings(surface, shells, contacts.touches_other_shell, reversed,
                                         memory) == windings);
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

    TestMesh through;
    add_box(through, {0, 0, 0}, {1, 1, 1}, false);
    add_double_pyramid(through);
    expect("a double pyramid through a cube's face along its edges", through, {0, kMixedWinding});

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
