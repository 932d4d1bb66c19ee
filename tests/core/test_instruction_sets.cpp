// The integration pass gives the same bits on every instruction set this
// processor runs (baseline x86-64, AVX2, AVX-512; elsewhere the baseline
// alone) and whatever order its blocks of faces run in: random triangle
// soups with partial batches, degenerate triangles and slivers, far from the
// origin; polygon meshes with planar and non-planar faces; float positions
// and 16-bit indices; a reference point a subnormal step off the origin; a
// mesh of more than one block of faces; and a vertex
// array that ends where an unreadable page begins. With used marks (the
// trusted path's), the same bits, the same marks, and a pass that stops at
// an index out of range wherever it is.
#include "core/mesh_integration.hpp"

#include "check.hpp"
#include "reversed_task_runner.hpp"
#include "test_mesh.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory_resource>
#include <random>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace {

using polymass::core::InstructionSet;
using polymass::core::IntegrationResult;
using polymass::core::IntegrationSettings;
using polymass_test::TestMesh;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_finding(const polymass::core::Finding& a, const polymass::core::Finding& b) {
    return a.count == b.count && a.lowest == b.lowest;
}

bool same_result(const IntegrationResult& a, const IntegrationResult& b) {
    const auto& p = a.integrals;
    const auto& q = b.integrals;
    bool same = same_bits(p.volume, q.volume) && same_bits(a.surface_area, b.surface_area) &&
                same_bits(a.bounds.volume, b.bounds.volume) &&
                same_bits(a.bounds.first, b.bounds.first) &&
                same_bits(a.bounds.second, b.bounds.second) &&
                same_bits(a.max_non_planarity, b.max_non_planarity) &&
                a.encloses_no_volume == b.encloses_no_volume &&
                same_finding(a.degenerate_faces, b.degenerate_faces) &&
                same_finding(a.non_planar_faces, b.non_planar_faces);
    for (int axis = 0; axis < 3; ++axis)
        same = same && same_bits(p.first[axis], q.first[axis]) &&
               same_bits(p.second[axis], q.second[axis]) &&
               same_bits(p.products[axis], q.products[axis]);
    return same;
}

template <class Scalar, class Index>
struct TypedMesh {
    std::vector<Scalar> coordinates;
    std::vector<Index> indices;
    polymass::core::MeshView<Scalar, Index> view;

    explicit TypedMesh(const TestMesh& mesh)
        : coordinates(mesh.coordinates.begin(), mesh.coordinates.end()),
          indices(mesh.indices.begin(), mesh.indices.end()) {
        view.positions.base = reinterpret_cast<const unsigned char*>(coordinates.data());
        view.positions.stride = 3 * sizeof(Scalar);
        view.vertex_count = mesh.vertex_count();
        view.indices.base = reinterpret_cast<const unsigned char*>(indices.data());
        view.index_count = indices.size();
        view.face_sizes = mesh.polygons ? mesh.face_sizes.data() : nullptr;
        view.face_count = mesh.face_sizes.size();
    }
};

// Every wider instruction set this processor runs, and the widest with its
// blocks run in reverse, against the baseline run in order.
template <class Scalar, class Index>
void check_all_sets(const char* name, const TestMesh& mesh, const Eigen::Vector3d& reference,
                    double size) {
    const TypedMesh<Scalar, Index> typed(mesh);
    IntegrationSettings settings;
    settings.reference = reference;
    settings.size = size;
    settings.instruction_set = InstructionSet::baseline;
    polymass::core::SerialTaskRunner serial;
    const IntegrationResult expected = integrate_mesh(typed.view, settings, serial);
    for (InstructionSet set : {InstructionSet::avx2, InstructionSet::avx512}) {
        if (!polymass::core::runs_instruction_set(set)) continue;
        settings.instruction_set = set;
        const bool same = same_result(integrate_mesh(typed.view, settings, serial), expected);
        if (!same) std::fprintf(stderr, "%s: instruction set %d differs\n", name, int(set));
        CHECK(same);
    }
    settings.instruction_set = polymass::core::widest_instruction_set();
    polymass_test::ReversedTaskRunner reversed;
    const bool same = same_result(integrate_mesh(typed.view, settings, reversed), expected);
    if (!same) std::fprintf(stderr, "%s: blocks run in reverse differ\n", name);
    CHECK(same);
}

// The mesh's vertices at even positions, an unused vertex at each odd one.
TestMesh with_unused_vertices(const TestMesh& mesh) {
    TestMesh spread = mesh;
    spread.coordinates.clear();
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        spread.add_vertex(mesh.vertex(v));
        spread.add_vertex(Eigen::Vector3d(1e30, -7.0, 0.5));
    }
    for (std::uint32_t& index : spread.indices) index *= 2;
    return spread;
}

// An all-triangle mesh integrated with used marks on every set this
// processor runs (the widest also with its blocks in reverse): the bits of
// the pass without marks, every used vertex marked and no other. Then an
// index out of range, first, in the middle and last: every set stops without
// reading a vertex there (the sanitizers would see it read).
template <class Scalar, class Index>
void check_marks(const char* name, const TestMesh& unspread, const Eigen::Vector3d& reference,
                 double size) {
    const TestMesh mesh = with_unused_vertices(unspread);
    TypedMesh<Scalar, Index> typed(mesh);
    IntegrationSettings settings;
    settings.reference = reference;
    settings.size = size;
    settings.instruction_set = InstructionSet::baseline;
    polymass::core::SerialTaskRunner serial;
    polymass_test::ReversedTaskRunner reversed;
    const IntegrationResult expected = integrate_mesh(typed.view, settings, serial);
    std::vector<unsigned char> used(mesh.vertex_count(), 0);
    for (std::uint32_t index : mesh.indices) used[index] = 1;
    auto run = [&](InstructionSet set, polymass::core::TaskRunner& runner,
                   std::pmr::vector<unsigned char>& marks) {
        settings.instruction_set = set;
        settings.used_marks = &marks;
        const IntegrationResult result = integrate_mesh(typed.view, settings, runner);
        settings.used_marks = nullptr;
        return result;
    };
    for (InstructionSet set :
         {InstructionSet::baseline, InstructionSet::avx2, InstructionSet::avx512}) {
        if (!polymass::core::runs_instruction_set(set)) continue;
        for (polymass::core::TaskRunner* runner :
             {static_cast<polymass::core::TaskRunner*>(&serial),
              static_cast<polymass::core::TaskRunner*>(&reversed)}) {
            std::pmr::vector<unsigned char> marks(mesh.vertex_count(), 0);
            const IntegrationResult marked = run(set, *runner, marks);
            const bool same = marked.indices_in_range && same_result(marked, expected) &&
                              std::equal(marks.begin(), marks.end(), used.begin());
            if (!same) std::fprintf(stderr, "%s: marking with set %d differs\n", name, int(set));
            CHECK(same);
        }
        for (std::size_t position :
             {std::size_t{0}, typed.indices.size() / 2, typed.indices.size() - 1}) {
            const Index kept = typed.indices[position];
            typed.indices[position] = Index(mesh.vertex_count());
            std::pmr::vector<unsigned char> marks(mesh.vertex_count(), 0);
            const bool stopped = !run(set, serial, marks).indices_in_range;
            if (!stopped)
                std::fprintf(stderr, "%s: set %d reads past index %zu out of range\n", name,
                             int(set), position);
            CHECK(stopped);
            typed.indices[position] = kept;
        }
    }
}

// Random triangles around `centre` (some degenerate: a repeated vertex, three
// collinear points, a sliver of 1e-200 of its length).
TestMesh triangle_soup(std::size_t triangles, const Eigen::Vector3d& centre,
                       std::mt19937_64& random) {
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    TestMesh mesh;
    for (std::size_t t = 0; t < triangles; ++t) {
        Eigen::Vector3d p[3];
        for (auto& q : p)
            q = centre +
                Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
        if (t % 97 == 5) p[2] = p[1];
        if (t % 89 == 7) p[2] = p[0] + 0.5 * (p[1] - p[0]);
        if (t % 83 == 11) p[2] = p[0] + 1e-200 * (p[1] - p[0]) + Eigen::Vector3d(0, 0, 1e-200);
        const std::uint32_t a = mesh.add_vertex(p[0]), b = mesh.add_vertex(p[1]),
                            c = mesh.add_vertex(p[2]);
        mesh.add_face({a, b, c});
    }
    return mesh;
}

// Triangles, planar quads and a bent pentagon now and then, in random order.
TestMesh polygon_soup(std::size_t faces, std::mt19937_64& random) {
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    TestMesh mesh;
    for (std::size_t f = 0; f < faces; ++f) {
        const Eigen::Vector3d o(coordinate(random), coordinate(random), coordinate(random));
        const Eigen::Vector3d u(coordinate(random), coordinate(random), coordinate(random));
        const Eigen::Vector3d v(coordinate(random), coordinate(random), coordinate(random));
        const std::size_t kind = random() % 3;
        if (kind == 0) {
            mesh.add_face({mesh.add_vertex(o), mesh.add_vertex(o + u), mesh.add_vertex(o + v)});
        } else if (kind == 1) {
            mesh.add_face({mesh.add_vertex(o), mesh.add_vertex(o + u), mesh.add_vertex(o + u + v),
                           mesh.add_vertex(o + v)});
        } else {
            const Eigen::Vector3d bend = 1e-3 * u.cross(v);
            mesh.add_face({mesh.add_vertex(o), mesh.add_vertex(o + u),
                           mesh.add_vertex(o + 1.2 * u + 0.7 * v + bend), mesh.add_vertex(o + v),
                           mesh.add_vertex(o - 0.3 * u + 0.5 * v)});
        }
    }
    return mesh;
}

#if defined(__unix__) || defined(__APPLE__)
// A mesh whose vertex array ends where an unreadable page begins, its last
// vertex used in a whole lane group: the wider sets load a vertex with a
// masked load of four lanes, which must neither read past z nor fault.
template <class Scalar>
void check_last_vertex_before_unreadable_page(const TestMesh& mesh) {
    const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
    const std::size_t bytes = mesh.coordinates.size() * sizeof(Scalar);
    const std::size_t pages = (bytes + page - 1) / page;
    void* const mapped = mmap(nullptr, (pages + 1) * page, PROT_READ | PROT_WRITE,
                              MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    CHECK(mapped != MAP_FAILED);
    if (mapped == MAP_FAILED) return;
    unsigned char* const unreadable = static_cast<unsigned char*>(mapped) + pages * page;
    CHECK(mprotect(unreadable, page, PROT_NONE) == 0);
    unsigned char* const base = unreadable - bytes;
    for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) {
        const Scalar c = Scalar(mesh.coordinates[i]);
        std::memcpy(base + i * sizeof(Scalar), &c, sizeof c);
    }
    TypedMesh<Scalar, std::uint32_t> typed(mesh);
    typed.view.positions.base = base;
    IntegrationSettings settings;
    settings.size = 4.0;
    polymass::core::SerialTaskRunner serial;
    settings.instruction_set = InstructionSet::baseline;
    const IntegrationResult expected = integrate_mesh(typed.view, settings, serial);
    for (InstructionSet set : {InstructionSet::avx2, InstructionSet::avx512}) {
        if (!polymass::core::runs_instruction_set(set)) continue;
        settings.instruction_set = set;
        CHECK(same_result(integrate_mesh(typed.view, settings, serial), expected));
    }
    munmap(mapped, (pages + 1) * page);
}
#endif

}  // namespace

int main() {
    const char* const set_names[] = {"baseline", "AVX2", "AVX-512"};
    for (InstructionSet set :
         {InstructionSet::baseline, InstructionSet::avx2, InstructionSet::avx512})
        std::printf(
            "%s: %s\n", set_names[int(set)],
            polymass::core::runs_instruction_set(set) ? "compared" : "not run on this processor");
    std::mt19937_64 random(12);
    const Eigen::Vector3d far(1e6, -2e6, 3e6);
    // Sizes around a batch (64) and a lane group (4, 8), and a few batches.
    for (std::size_t triangles : {1, 3, 7, 9, 63, 64, 65, 1000, 1031}) {
        const TestMesh soup = triangle_soup(triangles, far, random);
        check_all_sets<double, std::uint32_t>("triangles", soup, far, 4.0);
        check_marks<double, std::uint32_t>("triangles, marked", soup, far, 4.0);
        check_marks<float, std::uint16_t>("triangles, float, 16-bit indices, marked",
                                          triangle_soup(triangles, Eigen::Vector3d::Zero(), random),
                                          Eigen::Vector3d::Zero(), 4.0);
        check_all_sets<double, std::uint16_t>("triangles, 16-bit indices", soup, far, 4.0);
        const TestMesh near = triangle_soup(triangles, Eigen::Vector3d::Zero(), random);
        check_all_sets<float, std::uint32_t>("triangles, float", near, Eigen::Vector3d::Zero(),
                                             4.0);
        check_all_sets<float, std::uint16_t>("triangles, float, 16-bit indices", near,
                                             Eigen::Vector3d::Zero(), 4.0);
    }
    // A reference point off the origin by less than 2^-1021 units: the
    // AVX-512 kernel's fused move into the frame could round otherwise than
    // the baseline's there, so the frame is integrated unfused.
    check_all_sets<double, std::uint32_t>("triangles about a subnormal reference",
                                          triangle_soup(100, Eigen::Vector3d::Zero(), random),
                                          Eigen::Vector3d(1e-310, -3e-320, 0.0), 4.0);
    for (std::size_t faces : {5, 70, 700}) {
        const TestMesh polygons = polygon_soup(faces, random);
        check_all_sets<double, std::uint32_t>("polygons", polygons, Eigen::Vector3d::Zero(), 6.0);
        check_all_sets<float, std::uint32_t>("polygons, float", polygons, Eigen::Vector3d::Zero(),
                                             6.0);
    }
    // More than one block: the blocks' sums join in block order however the
    // blocks run; a mixed mesh over a block boundary too.
    const std::size_t beyond_a_block = polymass::core::kFacesPerBlock + 1001;
    const TestMesh two_blocks = triangle_soup(beyond_a_block, far, random);
    check_all_sets<double, std::uint32_t>("two blocks", two_blocks, far, 4.0);
    check_marks<double, std::uint32_t>("two blocks, marked", two_blocks, far, 4.0);
    check_all_sets<double, std::uint32_t>(
        "two blocks, polygons", polygon_soup(beyond_a_block, random), Eigen::Vector3d::Zero(), 6.0);
#if defined(__unix__) || defined(__APPLE__)
    // 64 triangles: one whole batch, the last vertex in its last lane group.
    const TestMesh to_the_end = triangle_soup(64, Eigen::Vector3d::Zero(), random);
    check_last_vertex_before_unreadable_page<double>(to_the_end);
    check_last_vertex_before_unreadable_page<float>(to_the_end);
#endif
    return polymass_test::finish("test_instruction_sets");
}
