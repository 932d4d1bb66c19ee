// The topology check's edge walk, built for each instruction set, against a
// count of every edge in a map: closed grids whose vertices are numbered at
// random (buckets of every size and order), and many separate tetrahedra and
// slivers (an edge that alone links its two vertices: a join left out splits
// their set), then broken by turning, removing and repeating faces, so that small buckets
// hold every kind of edge. Every instruction set this processor runs gives the
// reference's report, and vertex sets that join the ends of every edge, on
// one thread and with the buckets filed in three ranges as on three. Each
// mesh is also checked as a welded soup (every corner its own copy of its
// vertex, the copies numbered at random among more, with unused ones between):
// its welded positions numbered densely (vertex_identities.hpp) give the report
// and the sets of the soup with each copy replaced by its lowest one; with each
// copy at its vertex's position (the unused ones apart), the exact weld's own
// numbering (weld_and_number) is that one, on one share and on several (a
// soup of 204,000 corners: shares of at least 65,536 used vertices), in any
// order of the tasks. Double cones (two vertices of far more edges than a
// small bucket holds, in two ranges) closed and broken, also on a pool of two
// threads; a tetrahedron among a million unused vertices, in the counting
// sort's memory. Positions whose hashes share the tag a weld's table keeps,
// differing in one coordinate, stay apart.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory_resource>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "check.hpp"
#include "core/instruction_sets.hpp"
#include "core/mesh_scan.hpp"
#include "core/position_hash.hpp"
#include "core/task_runner.hpp"
#include "core/topology.hpp"
#include "core/vertex_identities.hpp"
#include "core/welding.hpp"
#include "core/worker_pool.hpp"
#include "reversed_task_runner.hpp"
#include "test_mesh.hpp"

namespace {

using polymass::core::analyse_topology;
using polymass::core::EdgeFinding;
using polymass::core::InstructionSet;
using polymass::core::TopologyReport;
using polymass::core::VertexIdentities;
using polymass_test::TestMesh;

// Runs the tasks last first, as a runner of `concurrency` threads might.
class ReversedRunner final : public polymass::core::TaskRunner {
public:
    explicit ReversedRunner(std::size_t concurrency) : concurrency_(concurrency) {}
    void run(std::size_t count, const std::function<void(std::size_t)>& task) override {
        for (std::size_t i = count; i-- > 0;) task(i);
    }
    std::size_t concurrency() const override { return concurrency_; }

private:
    std::size_t concurrency_;
};

// A closed torus of rows x columns quads, two triangles each, its vertices
// numbered at random.
TestMesh torus_grid(std::uint32_t rows, std::uint32_t columns, std::mt19937& random) {
    std::vector<std::uint32_t> number(std::size_t(rows) * columns);
    std::iota(number.begin(), number.end(), 0u);
    std::shuffle(number.begin(), number.end(), random);
    TestMesh mesh;
    mesh.coordinates.assign(3 * number.size(), 0.0);
    auto at = [&](std::uint32_t r, std::uint32_t c) {
        return number[std::size_t(r % rows) * columns + c % columns];
    };
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t c = 0; c < columns; ++c) {
            mesh.add_face({at(r, c), at(r + 1, c), at(r + 1, c + 1)});
            mesh.add_face({at(r, c), at(r + 1, c + 1), at(r, c + 1)});
        }
    return mesh;
}

// `count` separate tetrahedra, outward, and as many slivers (a triangle with
// a repeated corner: one edge, traversed once each way, the only link of its
// two vertices, so that a join left out splits their set), their vertices
// numbered at random among twice as many: runs of unused vertices between.
TestMesh separate_pieces(std::uint32_t count, std::mt19937& random) {
    std::vector<std::uint32_t> number(12 * std::size_t(count));
    std::iota(number.begin(), number.end(), 0u);
    std::shuffle(number.begin(), number.end(), random);
    TestMesh mesh;
    mesh.coordinates.assign(3 * number.size(), 0.0);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* v = &number[6 * t];
        mesh.add_face({v[0], v[2], v[1]});
        mesh.add_face({v[0], v[1], v[3]});
        mesh.add_face({v[1], v[2], v[3]});
        mesh.add_face({v[2], v[0], v[3]});
        mesh.add_face({v[4], v[4], v[5]});
    }
    return mesh;
}

// Turns, removes or repeats (as it is or turned) `changes` random triangles.
void break_faces(TestMesh& mesh, int changes, std::mt19937& random) {
    for (int k = 0; k < changes; ++k) {
        const std::size_t faces = mesh.indices.size() / 3;
        const std::size_t face = std::uniform_int_distribution<std::size_t>(0, faces - 1)(random);
        std::uint32_t* corners = &mesh.indices[3 * face];
        switch (std::uniform_int_distribution<int>(0, 3)(random)) {
            case 0:
                std::swap(corners[1], corners[2]);
                break;
            case 1:
                mesh.indices.erase(mesh.indices.begin() + std::ptrdiff_t(3 * face),
                                   mesh.indices.begin() + std::ptrdiff_t(3 * face + 3));
                mesh.face_sizes.pop_back();
                break;
            case 2:
                mesh.add_face({corners[0], corners[1], corners[2]});
                break;
            default:
                mesh.add_face({corners[0], corners[2], corners[1]});
                break;
        }
    }
}

// The report by a map from each undirected edge to its traversals each way.
TopologyReport reference_report(const TestMesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::size_t, std::size_t>> edges;
    for (std::size_t first = 0; first < mesh.indices.size(); first += 3)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t from = mesh.indices[first + i];
            const std::uint32_t to = mesh.indices[first + (i + 1) % 3];
            if (from == to) continue;
            auto& ways = edges[{std::min(from, to), std::max(from, to)}];
            (from < to ? ways.first : ways.second) += 1;
        }
    TopologyReport report;
    for (const auto& [edge, ways] : edges) {
        const auto [ups, downs] = ways;
        ++report.edge_count;
        const std::uint32_t from = ups >= downs ? edge.first : edge.second;
        const std::uint32_t to = ups >= downs ? edge.second : edge.first;
        if (ups + downs == 1)
            report.open.record(from, to, 1);
        else if (ups + downs == 2 && ups != 1)
            report.misoriented.record(from, to, 2);
        else if (ups + downs > 2) {
            report.non_manifold.record(from, to, ups + downs);
            report.non_manifold_balanced &= ups == downs;
        }
    }
    return report;
}

bool same_finding(const EdgeFinding& a, const EdgeFinding& b) {
    return a.count == b.count && a.first_traversals == b.first_traversals &&
           std::equal(a.lowest.begin(), a.lowest.begin() + std::ptrdiff_t(a.kept()),
                      b.lowest.begin());
}

bool same_report(const TopologyReport& a, const TopologyReport& b) {
    return a.edge_count == b.edge_count && same_finding(a.open, b.open) &&
           same_finding(a.misoriented, b.misoriented) &&
           same_finding(a.non_manifold, b.non_manifold) &&
           a.non_manifold_balanced == b.non_manifold_balanced;
}

// Each vertex's set, named by its root.
std::vector<std::uint32_t> roots_of(std::vector<std::uint32_t> parent) {
    std::vector<std::uint32_t> roots(parent.size());
    for (std::size_t v = 0; v < parent.size(); ++v) {
        std::uint32_t r = std::uint32_t(v);
        while (parent[r] != r) r = parent[r];
        roots[v] = r;
    }
    return roots;
}

// Each vertex's set when the two ends of every edge are joined, named by its
// smallest vertex.
std::vector<std::uint32_t> reference_roots(const TestMesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.vertex_count());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v];
        return v;
    };
    for (std::size_t first = 0; first < mesh.indices.size(); first += 3)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = root(mesh.indices[first + i]);
            const std::uint32_t b = root(mesh.indices[first + (i + 1) % 3]);
            parent[std::max(a, b)] = std::min(a, b);
        }
    return roots_of(std::move(parent));
}

// `mesh`'s report and vertex sets, on each instruction set this processor
// runs, against those expected; the sets named by each vertex's root through
// `root_vertex`.
// Reversed as on one thread and as on three (each thread filing the edges
// of its own range of lower vertices, the AVX2 pass eight triangles at a
// time).
// With two_threads, also on a pool of two.
template <class RootVertex>
void check_analysis(const TestMesh& mesh, const VertexIdentities& identities,
                    const TopologyReport& expected, RootVertex&& root_vertex,
                    bool two_threads = false) {
    polymass_test::ReversedTaskRunner one;
    ReversedRunner three(3);
    std::optional<polymass::core::WorkerPool> two;
    std::vector<polymass::core::TaskRunner*> runners{&one, &three};
    if (two_threads) runners.push_back(&two.emplace(2, std::pmr::new_delete_resource()));
    for (polymass::core::TaskRunner* tasks : runners)
        for (InstructionSet set :
             {InstructionSet::baseline, InstructionSet::avx2, InstructionSet::avx512}) {
            if (!polymass::core::runs_instruction_set(set)) continue;
            std::pmr::vector<std::uint32_t> sets(std::pmr::new_delete_resource());
            const TopologyReport report = analyse_topology(
                mesh.view(), identities, *tasks, std::pmr::new_delete_resource(), sets, set);
            CHECK(same_report(report, expected));
            CHECK(root_vertex(roots_of({sets.begin(), sets.end()})));
        }
}

// Whether two triangles repeat three vertices in one turn (copies, when the
// vertices are welded), compared in every rotation.
bool repeats_a_triangle(const TestMesh& mesh) {
    std::set<std::array<std::uint32_t, 3>> seen;
    for (std::size_t f = 0; f < mesh.indices.size(); f += 3) {
        std::array<std::uint32_t, 3> t{mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        if (!seen.insert(t).second) return true;
    }
    return false;
}

// copies_ruled_out is said only of meshes that repeat no triangle; counted
// both ways, so that the meshes below reach each.
std::size_t ruled_out_count = 0, repeating_count = 0;
void check_copies_ruled_out(const TestMesh& mesh) {
    const bool ruled_out = polymass::core::copies_ruled_out(true, true, reference_report(mesh));
    const bool repeats = repeats_a_triangle(mesh);
    CHECK(!(ruled_out && repeats));
    ruled_out_count += ruled_out;
    repeating_count += repeats;
}

void check_mesh(const TestMesh& mesh, bool two_threads = false) {
    check_copies_ruled_out(mesh);
    const std::vector<std::uint32_t> expected_roots = reference_roots(mesh);
    check_analysis(
        mesh, {}, reference_report(mesh),
        [&](const std::vector<std::uint32_t>& roots) { return roots == expected_roots; },
        two_threads);
}

// A closed double cone about a ring of `ring` vertices, its apexes numbered 0
// and amid the ring: each the lower end of about 2 * ring and ring entries,
// buckets far past a small one's eight (sorted, not tested: topology.cpp),
// the second one in the second of two ranges of lower vertices.
TestMesh double_cone(std::uint32_t ring) {
    const std::uint32_t count = ring + 2, middle = count / 2;
    TestMesh mesh;
    mesh.coordinates.assign(3 * std::size_t(count), 0.0);
    const auto around = [&](std::uint32_t k) {
        const std::uint32_t v = 1 + k % ring;
        return v < middle ? v : v + 1;
    };
    for (std::uint32_t k = 0; k < ring; ++k) {
        mesh.add_face({0, around(k), around(k + 1)});
        mesh.add_face({middle, around(k + 1), around(k)});
    }
    return mesh;
}

// Large buckets: closed; with non-manifold edges at each apex, one as often
// each way and one not; broken at random; on one, two and three threads.
void check_large_buckets(std::mt19937& random) {
    for (std::uint32_t ring = 9; ring < 60; ring += 10) {
        TestMesh cone = double_cone(ring);
        check_mesh(cone, true);
        const std::uint32_t middle = (ring + 2) / 2;
        TestMesh non_manifold = cone;
        // (0, 1, 2) three times: its edges traversed four times, three one way.
        non_manifold.add_face({0, 1, 2});
        non_manifold.add_face({0, 1, 2});
        // A face at the other apex again and turned: four traversals, two each way.
        non_manifold.add_face({middle, middle + 2, middle + 1});
        non_manifold.add_face({middle, middle + 1, middle + 2});
        check_mesh(non_manifold, true);
        break_faces(cone, 1 + int(ring % 4), random);
        check_mesh(cone, true);
    }
}

// Counts the bytes taken, at most, at once.
class PeakResource final : public std::pmr::memory_resource {
public:
    std::size_t peak = 0;

private:
    std::size_t taken_ = 0;
    void* do_allocate(std::size_t bytes, std::size_t alignment) override {
        taken_ += bytes;
        peak = std::max(peak, taken_);
        return std::pmr::new_delete_resource()->allocate(bytes, alignment);
    }
    void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
        taken_ -= bytes;
        std::pmr::new_delete_resource()->deallocate(p, bytes, alignment);
    }
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
        return this == &other;
    }
};

// A tetrahedron among 2^20 vertices, the others unused: the buckets take the
// counting sort's 4 bytes a vertex (fixed slots, eight a vertex, would take
// 36: docs/integrals.md), and the report is the map's.
void check_mostly_unused_vertices() {
    TestMesh mesh;
    mesh.coordinates.assign(3 * (std::size_t{1} << 20), 0.0);
    const std::uint32_t v[4] = {7, 300000, 700001, (1u << 20) - 1};
    mesh.add_face({v[0], v[2], v[1]});
    mesh.add_face({v[0], v[1], v[3]});
    mesh.add_face({v[1], v[2], v[3]});
    mesh.add_face({v[2], v[0], v[3]});
    polymass::core::SerialTaskRunner serial;
    PeakResource memory;
    std::pmr::vector<std::uint32_t> sets(std::pmr::new_delete_resource());
    const TopologyReport report = analyse_topology(mesh.view(), {}, serial, &memory, sets);
    CHECK(same_report(report, reference_report(mesh)));
    CHECK(memory.peak < 8 * mesh.vertex_count());
}

// The exact weld of `soup` numbers its used vertices as `expected` does, on
// one thread, reversed as on three and on two threads; so does the weld that
// follows the scan (scan_and_weld_exact: in stretches on one thread), whose
// scan is the scan.
void check_weld(const TestMesh& soup, const polymass::core::NumberedVertices& expected) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    polymass::core::SerialTaskRunner serial;
    ReversedRunner reversed(3);
    polymass::core::WorkerPool pool(2, memory);
    for (polymass::core::TaskRunner* tasks :
         std::initializer_list<polymass::core::TaskRunner*>{&serial, &reversed, &pool}) {
        const polymass::core::MeshScan scan =
            polymass::core::scan_mesh(soup.view(), memory, *tasks);
        polymass::core::NumberedVertices followed(memory);
        const polymass::core::MeshScan followed_scan =
            polymass::core::scan_and_weld_exact(soup.view(), followed, *tasks, memory);
        CHECK(followed_scan.used == scan.used &&
              followed_scan.used_vertex_count == scan.used_vertex_count &&
              followed_scan.bounds.min() == scan.bounds.min() &&
              followed_scan.bounds.max() == scan.bounds.max());
        const polymass::core::NumberedVertices welded =
            polymass::core::weld_and_number(soup.view(), scan, 0.0, *tasks, memory);
        for (const polymass::core::NumberedVertices* numbered :
             std::initializer_list<const polymass::core::NumberedVertices*>{&welded, &followed}) {
            CHECK(numbered->lowest_vertex == expected.lowest_vertex);
            bool same = true;
            for (const std::uint32_t vertex : soup.indices)
                same &= numbered->of_vertex[vertex] == expected.of_vertex[vertex];
            CHECK(same);
        }
    }
}

// `mesh` as a welded soup (above).
void check_welded_soup(const TestMesh& mesh, std::mt19937& random) {
    std::vector<std::uint32_t> copy(mesh.indices.size() + mesh.indices.size() / 2);
    std::iota(copy.begin(), copy.end(), 0u);
    std::shuffle(copy.begin(), copy.end(), random);
    TestMesh soup = mesh;
    // Copies of a vertex at one position, each unused copy at one of its own.
    soup.coordinates.assign(3 * copy.size(), 0.0);
    for (std::size_t c = 0; c < copy.size(); ++c) soup.coordinates[3 * c] = -1.0 - double(c);
    for (std::size_t at = 0; at < mesh.indices.size(); ++at) {
        soup.coordinates[3 * copy[at]] = mesh.indices[at];
        soup.coordinates[3 * copy[at] + 1] = 0.5;
    }
    // Each copy's lowest copy (of one vertex), or itself when unused.
    std::pmr::vector<std::uint32_t> welded(copy.size(), std::pmr::new_delete_resource());
    std::iota(welded.begin(), welded.end(), 0u);
    std::map<std::uint32_t, std::uint32_t> lowest_copy;
    for (std::size_t at = 0; at < mesh.indices.size(); ++at) {
        soup.indices[at] = copy[at];
        auto [lowest, first] = lowest_copy.insert({mesh.indices[at], copy[at]});
        if (!first) lowest->second = std::min(lowest->second, copy[at]);
    }
    polymass::core::MeshScan scan(std::pmr::new_delete_resource());
    scan.used.assign((copy.size() + 63) / 64, 0);
    for (std::size_t at = 0; at < mesh.indices.size(); ++at) {
        welded[copy[at]] = lowest_copy[mesh.indices[at]];
        scan.used[copy[at] / 64] |= std::uint64_t{1} << (copy[at] % 64);
    }
    const polymass::core::NumberedVertices numbered = polymass::core::number_welded_vertices(
        welded, scan, lowest_copy.size(), std::pmr::new_delete_resource());
    // Every identity named, in the order of the lowest copies.
    CHECK(std::adjacent_find(numbered.lowest_vertex.begin(), numbered.lowest_vertex.end(),
                             std::greater_equal<>()) == numbered.lowest_vertex.end());
    check_weld(soup, numbered);
    TestMesh lowest = soup;
    for (std::uint32_t& vertex : lowest.indices) vertex = welded[vertex];
    const std::vector<std::uint32_t> expected_roots = reference_roots(lowest);
    check_analysis(
        soup, numbered.identities(), reference_report(lowest),
        [&](const std::vector<std::uint32_t>& roots) {
            if (roots.size() != numbered.lowest_vertex.size()) return false;
            for (const std::uint32_t vertex : soup.indices) {
                const std::uint32_t identity = numbered.of_vertex[vertex];
                if (numbered.lowest_vertex[identity] != welded[vertex] ||
                    numbered.lowest_vertex[roots[identity]] != expected_roots[welded[vertex]])
                    return false;
            }
            return true;
        });
}

// The hash spreads positions that differ only in their coordinates' signs:
// on a grid of points about the origin, of the bits the weld hashes (a
// double's, and a float32's in the low half of a word), the high halves (the
// table's tags, and its slots' first bits) are as distinct as a random
// hash's, about 0.1 pairs alike among 2^15. A hash that sums each
// coordinate's product with a constant gives a point and its turn by half a
// circle about an axis one hash: a quarter of the tags distinct.
void check_weld_hash_spreads_signs() {
    for (const bool through_float : {false, true}) {  // float32 bits, or double
        std::set<std::uint32_t> tags;
        std::size_t count = 0;
        for (int x = -16; x < 16; ++x)
            for (int y = -16; y < 16; ++y)
                for (int z = -16; z < 16; ++z) {
                    const std::array<double, 3> p{(x + 0.25) / 3, (y + 0.5) / 3, (z + 0.75) / 3};
                    std::array<std::uint64_t, 3> bits{};
                    for (std::size_t axis = 0; axis < 3; ++axis)
                        bits[axis] = through_float ? polymass::core::position_bits(float(p[axis]))
                                                   : polymass::core::position_bits(p[axis]);
                    tags.insert(std::uint32_t(polymass::core::position_hash(bits) >> 32));
                    ++count;
                }
        CHECK(tags.size() + 4 >= count);
    }
}

// Positions whose hashes agree in their high half (the tag a table slot
// keeps) are told apart by their bits, each coordinate: for each axis, a run
// of positions differing in that coordinate alone, among which a pair with one
// tag is found (about eight are expected among 2^18), then copies of that pair
// at the end. Each position is its own but the copies, on one share and on
// several. (float32 positions differing in one coordinate gave no shared tag
// among 2^18: the held float32 copies are checked by unit.welding's weld.)
void check_weld_tag_collisions() {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    constexpr std::size_t kCount = std::size_t{1} << 18;
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<double> coordinates;
        std::map<std::uint32_t, std::uint32_t> first_of_tag;
        std::pair<std::uint32_t, std::uint32_t> same_tag{0, 0};
        for (std::uint32_t vertex = 0; vertex < kCount; ++vertex) {
            std::array<double, 3> p{1.5, 2.5, 3.5};
            p[axis] += std::ldexp(double(vertex), -40);
            coordinates.insert(coordinates.end(), p.begin(), p.end());
            const auto tag = std::uint32_t(
                polymass::core::position_hash({polymass::core::position_bits(p[0]),
                                               polymass::core::position_bits(p[1]),
                                               polymass::core::position_bits(p[2])}) >>
                32);
            const auto [held, first] = first_of_tag.insert({tag, vertex});
            if (!first && same_tag.second == 0) same_tag = {held->second, vertex};
        }
        CHECK(same_tag.second != 0);
        for (const std::uint32_t copy : {same_tag.second, same_tag.first})
            coordinates.insert(coordinates.end(), coordinates.begin() + 3 * copy,
                               coordinates.begin() + 3 * copy + 3);
        const polymass::core::PositionArray<double> positions{
            reinterpret_cast<const unsigned char*>(coordinates.data()), 3 * sizeof(double)};
        polymass::core::SerialTaskRunner serial;
        polymass::core::WorkerPool pool(2, memory);
        for (polymass::core::TaskRunner* tasks :
             std::initializer_list<polymass::core::TaskRunner*>{&serial, &pool}) {
            const polymass::core::WeldedPositions welded =
                polymass::core::weld_positions(positions, kCount + 2, 0.0, *tasks, memory);
            bool own = welded.vertex_of.size() == kCount + 2 && welded.distinct == kCount;
            for (std::uint32_t vertex = 0; own && vertex < kCount; ++vertex)
                own = welded.vertex_of[vertex] == vertex;
            CHECK(own);
            CHECK(welded.vertex_of[kCount] == same_tag.second);
            CHECK(welded.vertex_of[kCount + 1] == same_tag.first);
        }
    }
}

// The weld within a tolerance against its rule applied to every pair: two
// positions in one cell of the grid `distance` wide are one, and so are two in
// neighbouring cells within `distance` in each coordinate (weld_within,
// welding.cpp). Clusters of copies, each a little off its first (within and
// past the distance), among 3,000 positions: scattered with a tolerance so
// fine that the cells' x needs more than 32 bits (the weld sorts by its high
// bits, then each run of equal keys in full), and on ten planes of one x each
// (runs of hundreds).
void check_weld_within() {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    std::mt19937 random(31);
    for (const bool planes : {false, true}) {
        const double tolerance = planes ? 1e-6 : 1e-13;
        std::uniform_real_distribution<double> unit(0.0, 1.0), near(-1.2, 1.2);
        std::vector<std::array<double, 3>> points;
        while (points.size() < 3000) {
            std::array<double, 3> first{unit(random), unit(random), unit(random)};
            if (planes) first[0] = double(random() % 10) / 9.0;
            points.push_back(first);
            for (int copy = int(random() % 4); copy > 0; --copy) {
                std::array<double, 3> p = first;
                for (int axis = planes ? 1 : 0; axis < 3; ++axis)
                    p[std::size_t(axis)] += near(random) * tolerance;
                points.push_back(p);
            }
        }
        std::shuffle(points.begin(), points.end(), random);
        const std::size_t count = points.size();
        const polymass::core::PositionArray<double> positions{
            reinterpret_cast<const unsigned char*>(points.data()), 3 * sizeof(double)};
        polymass::core::SerialTaskRunner serial;
        const polymass::core::WeldedPositions welded =
            polymass::core::weld_positions(positions, count, tolerance, serial, memory);

        Eigen::AlignedBox3d bounds;
        for (const auto& p : points) bounds.extend(Eigen::Vector3d(p[0], p[1], p[2]));
        const double distance = tolerance * bounds.sizes().maxCoeff();
        const auto cell = [&](const std::array<double, 3>& p, int axis) {
            return std::int64_t((p[std::size_t(axis)] - bounds.min()[axis]) / distance);
        };
        std::vector<std::uint32_t> parent(count);
        std::iota(parent.begin(), parent.end(), 0u);
        const auto root = [&](std::uint32_t v) {
            while (parent[v] != v) v = parent[v] = parent[parent[v]];
            return v;
        };
        for (std::uint32_t a = 0; a < count; ++a)
            for (std::uint32_t b = a + 1; b < count; ++b) {
                bool same_cell = true, neighbours = true, close = true;
                for (int axis = 0; axis < 3; ++axis) {
                    const std::int64_t apart = cell(points[a], axis) - cell(points[b], axis);
                    same_cell &= apart == 0;
                    neighbours &= apart >= -1 && apart <= 1;
                    close &= std::abs(points[a][std::size_t(axis)] -
                                      points[b][std::size_t(axis)]) <= distance;
                }
                if (same_cell || (neighbours && close)) {
                    const std::uint32_t ra = root(a), rb = root(b);
                    parent[std::max(ra, rb)] = std::min(ra, rb);
                }
            }
        std::size_t welded_away = 0;
        bool same = welded.vertex_of.size() == count;
        for (std::uint32_t v = 0; v < count; ++v) {
            same = same && welded.vertex_of[v] == root(v);
            welded_away += root(v) != v;
        }
        CHECK(same);
        CHECK(welded_away > 500);  // the clusters' copies, most of them
    }
}

}  // namespace

int main() {
    std::mt19937 random(27);
    for (int round = 0; round < 60; ++round) {
        const auto rows = std::uint32_t(3 + round % 7), columns = std::uint32_t(4 + round % 11);
        TestMesh mesh = torus_grid(rows, columns, random);
        check_mesh(mesh);  // every edge common
        check_welded_soup(mesh, random);
        break_faces(mesh, 1 + round % 9, random);
        check_mesh(mesh);
        check_welded_soup(mesh, random);
        TestMesh pieces = separate_pieces(std::uint32_t(5 + round % 23), random);
        check_mesh(pieces);
        check_welded_soup(pieces, random);
        break_faces(pieces, 1 + round % 5, random);
        check_mesh(pieces);
        check_welded_soup(pieces, random);
    }
    // A closed grid with one face written again and once reversed: each of
    // its edges is used twice each way, a balanced non-manifold edge, and
    // the face has a copy.
    TestMesh repeated = torus_grid(4, 5, random);
    repeated.add_face({repeated.indices[0], repeated.indices[1], repeated.indices[2]});
    repeated.add_face({repeated.indices[0], repeated.indices[2], repeated.indices[1]});
    check_mesh(repeated);
    CHECK(ruled_out_count > 0 && repeating_count > 0);
    check_large_buckets(random);
    check_mostly_unused_vertices();
    // Large enough for the weld's shares.
    TestMesh large = torus_grid(170, 200, random);
    break_faces(large, 30, random);
    check_welded_soup(large, random);
    check_weld_hash_spreads_signs();
    check_weld_tag_collisions();
    check_weld_within();
    return polymass_test::finish("test_topology");
}
