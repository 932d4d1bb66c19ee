#include "mesh_scan.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#include "instruction_sets.hpp"

namespace polymass::core {
namespace {

// Whether all 64 bytes from `bytes` are 1.
bool all_set(const unsigned char* bytes) {
    std::uint64_t words[8];
    std::memcpy(words, bytes, sizeof words);
    std::uint64_t all = ~std::uint64_t{0};
    for (std::uint64_t word : words) all &= word;
    return all == 0x0101010101010101u;
}

// 64 bytes of a coordinate type: one AVX-512 register, two AVX2 or four
// baseline ones (GCC takes no vector attribute on a template parameter).
template <class Scalar>
struct CoordinateVector;
template <>
struct CoordinateVector<double> {
    using type = double __attribute__((vector_size(64)));
};
template <>
struct CoordinateVector<float> {
    using type = float __attribute__((vector_size(64)));
};

// Bounds of packed vertices (x, y, z, x, y, z, ...) kept as vectors: three
// vectors hold a whole number of vertices (64 of them span 192 coordinates, a
// multiple of three vectors), so element e of vector k always holds axis
// (k * width + e) mod 3, whichever 64 vertices were read.
template <class Scalar>
struct PackedBounds {
    using Vector = typename CoordinateVector<Scalar>::type;
    static constexpr int width = int(sizeof(Vector) / sizeof(Scalar));
    static constexpr int vectors_per_block = 3 * 64 / width;
    Vector low[3], high[3];

    PackedBounds() {
        for (int k = 0; k < 3; ++k) {
            low[k] = Vector{} + std::numeric_limits<Scalar>::infinity();
            high[k] = Vector{} - std::numeric_limits<Scalar>::infinity();
        }
    }

    // Adds the 64 packed vertices from `xyz` when all their coordinates are
    // finite; false (and nothing added) otherwise.
    __attribute__((always_inline)) bool add_block(const unsigned char* xyz) {
        Vector block_low[3], block_high[3], finite_if_zero{};
#pragma GCC unroll 3
        for (int k = 0; k < 3; ++k) block_low[k] = low[k], block_high[k] = high[k];
#pragma GCC unroll 24
        for (int v = 0; v < vectors_per_block; ++v) {
            Vector c;
            std::memcpy(&c, xyz + v * sizeof(Vector), sizeof c);
            finite_if_zero += c - c;  // x − x: 0 when finite, NaN otherwise
            const int k = v % 3;
            block_low[k] = c < block_low[k] ? c : block_low[k];
            block_high[k] = c > block_high[k] ? c : block_high[k];
        }
        Scalar sum = 0;
        for (int e = 0; e < width; ++e) sum += finite_if_zero[e];
        if (sum != 0) return false;
#pragma GCC unroll 3
        for (int k = 0; k < 3; ++k) low[k] = block_low[k], high[k] = block_high[k];
        return true;
    }

    void reduce(Eigen::Vector3d& into_low, Eigen::Vector3d& into_high) const {
        for (int k = 0; k < 3; ++k)
            for (int e = 0; e < width; ++e) {
                const int axis = (k * width + e) % 3;
                into_low[axis] = std::min(into_low[axis], double(low[k][e]));
                into_high[axis] = std::max(into_high[axis], double(high[k][e]));
            }
    }
};

// A bound of zero takes its sign from the first used, finite vertex (in
// vertex order) with that coordinate ±0, as a running minimum or maximum that
// keeps its value on a tie does; packed blocks are taken a vector at a time,
// which could otherwise keep the other zero. (The sign can reach the results
// through the reference point of a surface flat along that axis.)
template <class Scalar, class Index>
void keep_first_zero_signs(const MeshView<Scalar, Index>& mesh, const unsigned char* seen_vertex,
                           std::size_t addressable, Eigen::AlignedBox3d& bounds) {
    for (int axis = 0; axis < 3; ++axis) {
        double* const ends[2] = {&bounds.min()[axis], &bounds.max()[axis]};
        for (double* end : ends) {
            if (*end != 0.0) continue;
            for (std::size_t vertex = 0; vertex < addressable; ++vertex) {
                if (!seen_vertex[vertex]) continue;
                const Eigen::Vector3d p = mesh.positions[vertex];
                if (!p.allFinite() || p[axis] != 0.0) continue;
                *end = p[axis];
                break;
            }
        }
    }
}

// What the scan looks at twice per index and once per vertex, in one piece so
// that it can be built for each instruction set (`packed`: positions are
// x, y, z, x, y, z, ...).
template <class Scalar, class Index>
__attribute__((always_inline)) inline MeshScan scan_mesh_as(const MeshView<Scalar, Index>& mesh,
                                                            std::pmr::memory_resource* memory) {
    MeshScan scan(memory);
    // No index can reach past this, however long the caller says the array is.
    const std::size_t addressable = std::min<std::size_t>(
        mesh.vertex_count, std::size_t(std::numeric_limits<Index>::max()) + 1);
    // A byte per vertex, packed into scan.used afterwards: setting bits in
    // place would chain each face's read-modify-write of a word to the last
    // one's (neighbouring faces share vertices), a byte store waits for nothing.
    std::pmr::vector<unsigned char> seen(addressable, 0, memory);
    // The index array in one run, faces aside: they matter only to report an
    // index out of range, which is rare enough to look for again.
    // (Copies in locals: a byte store may alias anything, so what it could
    // overwrite would be read again after each.)
    const auto indices = mesh.indices;
    const std::size_t index_count = mesh.index_count, vertex_count = mesh.vertex_count;
    unsigned char* const seen_vertex = seen.data();
    // A chunk at a time: whether an index is out of range first (a loop
    // without branches and, in a whole chunk, of a fixed length, which
    // compilers vectorise), then, when none is, one store per index and
    // nothing else, while the chunk is still in the L1 cache.
    constexpr std::size_t chunk = 2048;
    // In 32 bits, which vectorise: the largest index in range (none when
    // there is no vertex; every 32-bit index when there are more).
    const std::uint32_t last = std::uint32_t(
        std::min<std::size_t>(vertex_count, std::size_t{1} << 32) - (vertex_count > 0));
    auto count_out_of_range = [&](std::size_t begin, std::size_t length) {
        std::uint32_t out = 0;
        for (std::size_t i = 0; i < length; ++i) out += indices[begin + i] > last;
        return out;
    };
    bool all_in_range = true;
    for (std::size_t begin = 0; begin < index_count; begin += chunk) {
        const std::size_t length = std::min(index_count - begin, chunk);
        const std::uint32_t out =
            length == chunk ? count_out_of_range(begin, chunk) : count_out_of_range(begin, length);
        if (out == 0 && vertex_count > 0) {
#pragma GCC unroll 4
            for (std::size_t i = begin; i < begin + length; ++i) seen_vertex[indices[i]] = 1;
            continue;
        }
        all_in_range = false;
        for (std::size_t i = begin; i < begin + length; ++i) {
            const std::size_t vertex = indices[i];
            if (vertex < vertex_count) seen_vertex[vertex] = 1;
        }
    }
    if (!all_in_range) {
        for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
            bool in_range = true;
            for (std::size_t i = first; i < first + size; ++i) {
                if (mesh.indices[i] < mesh.vertex_count) continue;
                if (scan.out_of_range_indices++ == 0)
                    scan.first_out_of_range_index = mesh.indices[i];
                in_range = false;
            }
            if (!in_range) scan.out_of_range_faces.record(face);
        });
    }

    scan.used.assign((addressable + 63) / 64, 0);
    // Locals rather than scan's members, which the stores into scan.used might alias.
    Eigen::Vector3d low = scan.bounds.min(), high = scan.bounds.max();
    std::size_t used_vertex_count = 0;
    const auto positions = mesh.positions;
    const bool packed = positions.stride == 3 * sizeof(Scalar);
    PackedBounds<Scalar> packed_bounds;
    for (std::size_t block = 0; block < scan.used.size(); ++block) {
        const std::size_t begin = 64 * block, end = std::min(addressable, begin + 64);
        // Usually every vertex of a block is used and finite: then no test
        // per vertex. x − x is 0 for a finite x and NaN otherwise, and a NaN
        // stays in a sum: one test for the block.
        if (end - begin == 64 && all_set(seen_vertex + begin)) {
            if (packed && packed_bounds.add_block(positions.base + begin * positions.stride)) {
                scan.used[block] = ~std::uint64_t{0};
                used_vertex_count += 64;
                continue;
            }
            Eigen::Vector3d block_low = low, block_high = high;
            double finite_if_zero = 0.0;
            for (std::size_t vertex = begin; vertex < end; ++vertex) {
                const Eigen::Vector3d p = positions[vertex];
                finite_if_zero += (p.x() - p.x()) + (p.y() - p.y()) + (p.z() - p.z());
                block_low = block_low.cwiseMin(p);
                block_high = block_high.cwiseMax(p);
            }
            if (finite_if_zero == 0.0) {
                scan.used[block] = ~std::uint64_t{0};
                used_vertex_count += 64;
                low = block_low, high = block_high;
                continue;
            }
        }
        std::uint64_t used = 0;
        for (std::size_t vertex = begin; vertex < end; ++vertex) {
            if (!seen_vertex[vertex]) continue;
            used |= std::uint64_t{1} << (vertex % 64);
            ++used_vertex_count;
            const Eigen::Vector3d p = positions[vertex];
            const double finite_if_zero = (p.x() - p.x()) + (p.y() - p.y()) + (p.z() - p.z());
            if (finite_if_zero != 0.0) {
                scan.non_finite.record(vertex);
                continue;
            }
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
        scan.used[block] = used;
    }
    packed_bounds.reduce(low, high);
    scan.used_vertex_count = used_vertex_count;
    scan.bounds = Eigen::AlignedBox3d(low, high);
    if (packed) keep_first_zero_signs(mesh, seen_vertex, addressable, scan.bounds);
    return scan;
}

template <class Scalar, class Index>
MeshScan scan_mesh_baseline(const MeshView<Scalar, Index>& mesh,
                            std::pmr::memory_resource* memory) {
    return scan_mesh_as(mesh, memory);
}

#if defined(__x86_64__)
template <class Scalar, class Index>
__attribute__((target("avx2"))) MeshScan scan_mesh_avx2(const MeshView<Scalar, Index>& mesh,
                                                        std::pmr::memory_resource* memory) {
    return scan_mesh_as(mesh, memory);
}

template <class Scalar, class Index>
__attribute__((target("avx512f,avx512vl,avx512dq,avx512bw"))) MeshScan scan_mesh_avx512(
    const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory) {
    return scan_mesh_as(mesh, memory);
}
#endif

}  // namespace

template <class Scalar, class Index>
MeshScan scan_mesh(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory) {
#if defined(__x86_64__)
    switch (widest_instruction_set()) {
        case InstructionSet::avx512:
            return scan_mesh_avx512(mesh, memory);
        case InstructionSet::avx2:
            return scan_mesh_avx2(mesh, memory);
        case InstructionSet::baseline:
            break;
    }
#endif
    return scan_mesh_baseline(mesh, memory);
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                    \
    template MeshScan scan_mesh<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                               std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
