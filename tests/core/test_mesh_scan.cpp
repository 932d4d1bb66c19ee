// The scan's bounding box is that of the used, finite vertices, whichever way
// the scan reads them (a vector of packed coordinates at a time, or vertex by
// vertex) and in whatever order its parts run: the same as a minimum and
// maximum taken vertex by vertex, down to which zero a bound of zero is (the
// first such coordinate's, as a running minimum that keeps its value on a tie
// gives), for double and float, packed and strided positions, with unused and
// non-finite vertices among them, in one part and in several, and with the
// kernels of every instruction set this processor runs, which also agree on
// the used vertices, the non-finite ones and indices past the array. The scan
// from marks (the trusted path's: the used vertices marked by the gather,
// then finished from the marks and the bounds of every vertex) is the same
// scan, wherever the bounds of every vertex can be taken. So is the scan
// followed (ScanFollower: run in stretches, each handed on once bounded),
// whose follower is told of every vertex in order, each with its used bit set.
#include "core/mesh_scan.hpp"

#include "check.hpp"
#include "reversed_task_runner.hpp"

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory_resource>
#include <optional>
#include <random>
#include <vector>

namespace {

bool same_bits(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

bool same_finding(const polymass::core::Finding& a, const polymass::core::Finding& b) {
    return a.count == b.count && a.lowest == b.lowest;
}

bool same_scan(const polymass::core::MeshScan& scan, const polymass::core::MeshScan& expected) {
    bool same = scan.out_of_range_indices == expected.out_of_range_indices &&
                same_finding(scan.out_of_range_faces, expected.out_of_range_faces) &&
                scan.first_out_of_range_index == expected.first_out_of_range_index &&
                same_finding(scan.non_finite, expected.non_finite) &&
                scan.used_vertex_count == expected.used_vertex_count && scan.used == expected.used;
    for (int axis = 0; axis < 3; ++axis)
        same = same && same_bits(scan.bounds.min()[axis], expected.bounds.min()[axis]) &&
               same_bits(scan.bounds.max()[axis], expected.bounds.max()[axis]);
    return same;
}

// A follower of the scan that checks what it is told: stretches in order,
// from vertex 0 on, each with the used bits of `expected` already set.
class CheckingFollower final : public polymass::core::ScanFollower {
public:
    explicit CheckingFollower(const polymass::core::MeshScan& expected) : expected_(expected) {}
    void follow(const polymass::core::MeshScan& scan, std::size_t first,
                std::size_t last) override {
        in_order_ = in_order_ && first == followed_ && last > first;
        for (std::size_t vertex = first; vertex < last; ++vertex)
            bits_set_ = bits_set_ && scan.is_used(vertex) == expected_.is_used(vertex);
        followed_ = last;
    }
    // Whether every stretch up to `end` came in order with its bits set.
    bool followed_all(std::size_t end) const { return in_order_ && bits_set_ && followed_ == end; }

private:
    const polymass::core::MeshScan& expected_;
    std::size_t followed_ = 0;
    bool in_order_ = true, bits_set_ = true;
};

// The scan with each instruction set's kernels is `expected`, bit for bit,
// and so is the scan followed (run in stretches on the calling thread, even
// when given a runner of several), whose follower is told of every vertex the
// indices can reach, each stretch once its used bits are set.
template <class Scalar, class Index>
void check_every_instruction_set(const char* name,
                                 const polymass::core::MeshView<Scalar, Index>& view,
                                 const polymass::core::MeshScan& expected) {
    using polymass::core::InstructionSet;
    polymass::core::SerialTaskRunner serial;
    polymass_test::ReversedTaskRunner reversed;
    for (InstructionSet set :
         {InstructionSet::baseline, InstructionSet::avx2, InstructionSet::avx512}) {
        if (!polymass::core::runs_instruction_set(set)) continue;
        const polymass::core::MeshScan scan =
            polymass::core::scan_mesh(view, std::pmr::get_default_resource(), serial, set);
        const bool same = same_scan(scan, expected);
        if (!same)
            std::fprintf(stderr, "%s (%zu vertices): instruction set %d scans otherwise\n", name,
                         std::size_t(view.vertex_count), int(set));
        CHECK(same);
        CheckingFollower follower(expected);
        const polymass::core::MeshScan followed = polymass::core::scan_mesh(
            view, std::pmr::get_default_resource(), reversed, set, &follower);
        const bool same_followed =
            same_scan(followed, expected) &&
            follower.followed_all(polymass::core::addressable_vertices(view));
        if (!same_followed)
            std::fprintf(stderr, "%s (%zu vertices): instruction set %d followed otherwise\n", name,
                         std::size_t(view.vertex_count), int(set));
        CHECK(same_followed);
    }
}

// The scan from marks (the trusted path's) is `expected`, bit for bit, when
// the bounds of every vertex can be taken (`boundable`: packed positions, all
// finite). (It shares its kernels and the joins of its parts with the scan,
// which the runner that reverses them checks.)
template <class Scalar, class Index>
void check_scan_from_marks(const char* name, const polymass::core::MeshView<Scalar, Index>& view,
                           const polymass::core::MeshScan& expected, bool boundable) {
    std::pmr::memory_resource* memory = std::pmr::get_default_resource();
    polymass::core::SerialTaskRunner runner;
    const std::optional<Eigen::AlignedBox3d> every_vertex =
        polymass::core::bound_every_vertex(view, memory, runner);
    CHECK(every_vertex.has_value() == boundable);
    if (!every_vertex) return;
    std::pmr::vector<unsigned char> seen(polymass::core::addressable_vertices(view), 0, memory);
    // Marked as the trusted path's gather marks them (tests/core/
    // test_instruction_sets checks the gather's marks against the indices).
    bool in_range = true;
    for (std::size_t position = 0; position < view.index_count; ++position) {
        const std::uint32_t vertex = view.indices[position];
        if (vertex < seen.size())
            seen[vertex] = 1;
        else
            in_range = false;
    }
    CHECK(in_range == (expected.out_of_range_indices == 0));
    if (!in_range) return;
    const bool same = same_scan(
        polymass::core::scan_from_marks(view, seen, *every_vertex, memory, runner), expected);
    if (!same)
        std::fprintf(stderr, "%s (%zu vertices): the scan from marks differs\n", name,
                     std::size_t(view.vertex_count));
    CHECK(same);
}

// Positions (xyz per vertex, `stride` coordinates apart) and triangles over
// every vertex but the unused ones, listed `copies` times over.
template <class Scalar>
void check_bounds(const char* name, const std::vector<double>& xyz, std::size_t stride,
                  const std::vector<bool>& unused, std::size_t copies) {
    const std::size_t vertices = unused.size();
    std::vector<Scalar> positions(vertices * stride, Scalar(7));
    for (std::size_t v = 0; v < vertices; ++v)
        for (int axis = 0; axis < 3; ++axis)
            positions[v * stride + axis] = Scalar(xyz[3 * v + axis]);
    std::vector<std::uint32_t> indices;
    for (std::size_t copy = 0; copy < copies; ++copy)
        for (std::size_t v = 0; v < vertices; ++v)
            if (!unused[v]) indices.push_back(std::uint32_t(v));
    while (indices.size() % 3 != 0) indices.push_back(indices.back());

    // Vertex by vertex, keeping the first of equal values.
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d high = -low;
    for (std::size_t v = 0; v < vertices; ++v) {
        const Eigen::Vector3d p{double(positions[v * stride]), double(positions[v * stride + 1]),
                                double(positions[v * stride + 2])};
        if (unused[v] || !p.allFinite()) continue;
        for (int axis = 0; axis < 3; ++axis) {
            if (p[axis] < low[axis]) low[axis] = p[axis];
            if (p[axis] > high[axis]) high[axis] = p[axis];
        }
    }

    bool boundable = stride == 3;
    for (const Scalar c : positions) boundable = boundable && std::isfinite(c);

    polymass::core::MeshView<Scalar, std::uint32_t> view;
    view.positions.base = reinterpret_cast<const unsigned char*>(positions.data());
    view.positions.stride = stride * sizeof(Scalar);
    view.vertex_count = vertices;
    view.indices.base = reinterpret_cast<const unsigned char*>(indices.data());
    view.index_count = indices.size();
    view.face_count = indices.size() / 3;
    polymass::core::SerialTaskRunner serial;
    polymass_test::ReversedTaskRunner reversed;
    const polymass::core::MeshScan serial_scan =
        polymass::core::scan_mesh(view, std::pmr::get_default_resource(), serial);
    // Every set's scan (on the serial runner) is the serial one: once, not
    // again against the reversed runner's scan, which is the same scan.
    check_every_instruction_set(name, view, serial_scan);
    for (polymass::core::TaskRunner* runner :
         {static_cast<polymass::core::TaskRunner*>(&serial),
          static_cast<polymass::core::TaskRunner*>(&reversed)}) {
        const polymass::core::MeshScan scan =
            runner == &serial
                ? serial_scan
                : polymass::core::scan_mesh(view, std::pmr::get_default_resource(), *runner);
        CHECK(same_scan(scan, serial_scan));
        bool same = true;
        for (int axis = 0; axis < 3; ++axis)
            same = same && same_bits(scan.bounds.min()[axis], low[axis]) &&
                   same_bits(scan.bounds.max()[axis], high[axis]);
        if (!same)
            std::fprintf(stderr, "%s (%zu vertices, %s): the bounds differ\n", name, vertices,
                         runner == &serial ? "parts in order" : "parts in reverse");
        CHECK(same);
        std::size_t used = 0;
        for (std::size_t v = 0; v < vertices; ++v) used += !unused[v];
        CHECK(scan.used_vertex_count == used);
        if (runner == &serial) check_scan_from_marks(name, view, scan, boundable);
    }

    // 16-bit indices, and two past the vertex array in the last face.
    if (vertices + 2 > 65536) return;
    std::vector<std::uint16_t> short_indices(indices.begin(), indices.end());
    short_indices.insert(short_indices.end(),
                         {std::uint16_t(0), std::uint16_t(vertices + 1), std::uint16_t(vertices)});
    polymass::core::MeshView<Scalar, std::uint16_t> short_view;
    short_view.positions = view.positions;
    short_view.vertex_count = vertices;
    short_view.indices.base = reinterpret_cast<const unsigned char*>(short_indices.data());
    short_view.index_count = short_indices.size();
    short_view.face_count = short_indices.size() / 3;
    const polymass::core::MeshScan scan =
        polymass::core::scan_mesh(short_view, std::pmr::get_default_resource(), serial);
    CHECK(scan.out_of_range_indices == 2);
    check_every_instruction_set(name, short_view, scan);
    check_scan_from_marks(name, short_view, scan, boundable);
}

template <class Scalar>
void check_layouts(const char* name, const std::vector<double>& xyz,
                   const std::vector<bool>& unused, std::size_t copies) {
    check_bounds<Scalar>(name, xyz, 3, unused, copies);
    check_bounds<Scalar>(name, xyz, 5, unused, copies);
}

}  // namespace

int main() {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    // The scan's parts hold 2^18 indices and 2^16 vertices: 66,536 vertices
    // (a whole part, then one ending in a partial block) with their indices
    // listed five times over (two parts of the index array, each marking
    // vertices the other marks too) reach every join of parts. (The test
    // runs unoptimised in the dev build: each vertex costs.)
    for (std::size_t vertices : {5, 64, 200, 1000, 66536}) {
        const std::size_t copies = vertices > 65536 ? 5 : 1;
        std::vector<double> xyz(3 * vertices);
        for (double& c : xyz) c = coordinate(random);
        std::vector<bool> none(vertices, false), some(vertices, false);
        for (std::size_t v = 3; v < vertices; v += 37) some[v] = true;
        check_layouts<double>("random", xyz, none, copies);
        check_layouts<float>("random, float", xyz, none, copies);
        check_layouts<double>("random, some unused", xyz, some, copies);

        // Bounds of zero, reached by zeros of both signs: x ≥ 0 with −0 first
        // and +0 later, y ≤ 0 with +0 first, z ≥ 0 with +0 first.
        std::vector<double> zeros = xyz;
        for (std::size_t v = 0; v < vertices; ++v) {
            zeros[3 * v] = std::abs(zeros[3 * v]);
            zeros[3 * v + 1] = -std::abs(zeros[3 * v + 1]);
            zeros[3 * v + 2] = std::abs(zeros[3 * v + 2]);
        }
        for (std::size_t v = vertices / 3; v < vertices; v += 7) {
            zeros[3 * v] = v == vertices / 3 ? -0.0 : 0.0;
            zeros[3 * v + 1] = v == vertices / 3 ? 0.0 : -0.0;
            zeros[3 * v + 2] = v == vertices / 3 ? 0.0 : -0.0;
        }
        check_layouts<double>("zeros", zeros, none, copies);
        check_layouts<float>("zeros, float", zeros, none, copies);
        check_layouts<double>("zeros, some unused", zeros, some, copies);

        // A non-finite vertex: its block is read vertex by vertex.
        std::vector<double> infinite = zeros;
        infinite[3 * (vertices / 2) + 1] = std::numeric_limits<double>::infinity();
        check_layouts<double>("an infinite coordinate", infinite, none, copies);
    }
    return polymass_test::finish("test_mesh_scan");
}
