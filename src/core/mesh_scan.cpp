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

// Bounds of packed vertices (x, y, z, x, y, z, ...) kept as vectors of
// `bytes` bytes, the registers of the instruction set that runs them (a wider
// vector is split by compilers, and GCC splits its comparisons into one
// scalar minimum per coordinate): three vectors hold a whole number of
// vertices (64 of them span 192 coordinates, a multiple of three vectors), so
// element e of vector k always holds axis (k * width + e) mod 3, whichever 64
// vertices were read.
template <class Scalar, int bytes>
struct PackedBounds {
    // (A typedef: GCC ignores a vector attribute on a dependent type in a using.)
    typedef Scalar Vector __attribute__((vector_size(bytes)));
    static constexpr int width = int(sizeof(Vector) / sizeof(Scalar));
    static constexpr int vectors_per_block = 3 * 64 / width;
    static_assert(vectors_per_block % 3 == 0, "whole vertices in three vectors");
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
#pragma GCC unroll 96
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
// through the reference point of a surface flat along that axis.) A null
// seen_vertex: every vertex counts.
template <class Scalar, class Index>
void keep_first_zero_signs(const MeshView<Scalar, Index>& mesh, const unsigned char* seen_vertex,
                           std::size_t addressable, Eigen::AlignedBox3d& bounds) {
    for (int axis = 0; axis < 3; ++axis) {
        double* const ends[2] = {&bounds.min()[axis], &bounds.max()[axis]};
        for (double* end : ends) {
            if (*end != 0.0) continue;
            for (std::size_t vertex = 0; vertex < addressable; ++vertex) {
                if (seen_vertex && !seen_vertex[vertex]) continue;
                const Eigen::Vector3d p = mesh.positions[vertex];
                if (!p.allFinite() || p[axis] != 0.0) continue;
                *end = p[axis];
                break;
            }
        }
    }
}

// The scan runs in fixed parts, the same whatever the number of threads:
// first the index array, a part at a time, marking the vertices it uses; then
// the vertices, a part of whole 64-vertex blocks at a time, bounding the used
// ones. Each part keeps its own results, joined in part order: the bounds are
// exact minima and maxima (a tie keeps the earlier value, as a running
// minimum does), the counts sums and the findings' lowest locations merged,
// so every thread count gives the scan of one.
constexpr std::size_t kIndicesPerPart = std::size_t{1} << 18;
constexpr std::size_t kBlocksPerPart = std::size_t{1} << 10;  // 65,536 vertices

// What a part of the index array found: whether every index was in range.
struct IndexPart {
    bool all_in_range = true;
};

// Marks seen_vertex[i] for the indices in [begin, end). Parts run at the same
// time may mark one vertex together: a relaxed atomic store of the same byte,
// a plain store on every processor the library runs on.
template <class Scalar, class Index>
__attribute__((always_inline)) inline IndexPart mark_indices_as(const MeshView<Scalar, Index>& mesh,
                                                                std::size_t begin, std::size_t end,
                                                                unsigned char* seen_vertex) {
    IndexPart part;
    // (Copies in locals: a byte store may alias anything, so what it could
    // overwrite would be read again after each.)
    const auto indices = mesh.indices;
    const std::size_t vertex_count = mesh.vertex_count;
    // A chunk at a time: whether an index is out of range first (a loop
    // without branches and, in a whole chunk, of a fixed length, which
    // compilers vectorise), then, when none is, one store per index and
    // nothing else, while the chunk is still in the L1 cache.
    constexpr std::size_t chunk = 2048;
    static_assert(kIndicesPerPart % chunk == 0, "a part holds whole chunks");
    // In 32 bits, which vectorise: the largest index in range (none when
    // there is no vertex; every 32-bit index when there are more).
    const std::uint32_t last = std::uint32_t(
        std::min<std::size_t>(vertex_count, std::size_t{1} << 32) - (vertex_count > 0));
    auto count_out_of_range = [&](std::size_t first, std::size_t length) {
        std::uint32_t out = 0;
        for (std::size_t i = 0; i < length; ++i) out += indices[first + i] > last;
        return out;
    };
    auto mark = [&](std::size_t vertex) {
        __atomic_store_n(&seen_vertex[vertex], static_cast<unsigned char>(1), __ATOMIC_RELAXED);
    };
    for (std::size_t first = begin; first < end; first += chunk) {
        const std::size_t length = std::min(end - first, chunk);
        const std::uint32_t out =
            length == chunk ? count_out_of_range(first, chunk) : count_out_of_range(first, length);
        if (out == 0 && vertex_count > 0) {
            // Unrolled so that the loop's own counting and branch are a
            // sixteenth of an index's (this function, AVX2: 3.65 -> 3.09
            // instructions an index).
#pragma GCC unroll 16
            for (std::size_t i = first; i < first + length; ++i) mark(indices[i]);
            continue;
        }
        part.all_in_range = false;
        for (std::size_t i = first; i < first + length; ++i) {
            const std::size_t vertex = indices[i];
            if (vertex < vertex_count) mark(vertex);
        }
    }
    return part;
}

// What a part of the vertices found.
struct VertexPart {
    Eigen::Vector3d low = Eigen::AlignedBox3d().min(), high = Eigen::AlignedBox3d().max();
    std::size_t used_vertex_count = 0;
    Finding non_finite;

    // Joins the part of the blocks after this one's.
    void append(const VertexPart& later) {
        low = low.cwiseMin(later.low);
        high = high.cwiseMax(later.high);
        used_vertex_count += later.used_vertex_count;
        non_finite.merge(later.non_finite);
    }
};

// Bounds the used vertices of blocks [first_block, last_block) (64 vertices
// each, the last one maybe fewer) and sets their bits of `used`. A null
// seen_vertex: every vertex is taken as used; a null used_words: no bits kept.
// Packed blocks in vectors of vector_bytes.
template <int vector_bytes, class Scalar, class Index>
__attribute__((always_inline)) inline VertexPart bound_vertices_as(
    const MeshView<Scalar, Index>& mesh, const unsigned char* seen_vertex, std::size_t addressable,
    std::size_t first_block, std::size_t last_block, std::uint64_t* used_words) {
    VertexPart part;
    // Locals rather than the part's members, which the stores into `used` might alias.
    Eigen::Vector3d low = part.low, high = part.high;
    std::size_t used_vertex_count = 0;
    const auto positions = mesh.positions;
    const bool packed = positions.stride == 3 * sizeof(Scalar);
    PackedBounds<Scalar, vector_bytes> packed_bounds;
    for (std::size_t block = first_block; block < last_block; ++block) {
        const std::size_t begin = 64 * block, end = std::min(addressable, begin + 64);
        // Usually every vertex of a block is used and finite: then no test
        // per vertex. x − x is 0 for a finite x and NaN otherwise, and a NaN
        // stays in a sum: one test for the block.
        if (end - begin == 64 && (!seen_vertex || all_set(seen_vertex + begin))) {
            if (packed && packed_bounds.add_block(positions.base + begin * positions.stride)) {
                if (used_words) used_words[block] = ~std::uint64_t{0};
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
                if (used_words) used_words[block] = ~std::uint64_t{0};
                used_vertex_count += 64;
                low = block_low, high = block_high;
                continue;
            }
        }
        std::uint64_t used = 0;
        for (std::size_t vertex = begin; vertex < end; ++vertex) {
            if (seen_vertex && !seen_vertex[vertex]) continue;
            used |= std::uint64_t{1} << (vertex % 64);
            ++used_vertex_count;
            const Eigen::Vector3d p = positions[vertex];
            const double finite_if_zero = (p.x() - p.x()) + (p.y() - p.y()) + (p.z() - p.z());
            if (finite_if_zero != 0.0) {
                part.non_finite.record(vertex);
                continue;
            }
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
        if (used_words) used_words[block] = used;
    }
    packed_bounds.reduce(low, high);
    part.low = low, part.high = high;
    part.used_vertex_count = used_vertex_count;
    return part;
}

// The two loops built for each instruction set.
template <class Scalar, class Index>
struct ScanKernels {
    IndexPart (*mark_indices)(const MeshView<Scalar, Index>&, std::size_t, std::size_t,
                              unsigned char*);
    VertexPart (*bound_vertices)(const MeshView<Scalar, Index>&, const unsigned char*, std::size_t,
                                 std::size_t, std::size_t, std::uint64_t*);
};

#define POLYMASS_SCAN_KERNELS(name, target, vector_bytes)                                          \
    template <class Scalar, class Index>                                                           \
    target IndexPart mark_indices_##name(const MeshView<Scalar, Index>& mesh, std::size_t begin,   \
                                         std::size_t end, unsigned char* seen_vertex) {            \
        return mark_indices_as(mesh, begin, end, seen_vertex);                                     \
    }                                                                                              \
    template <class Scalar, class Index>                                                           \
    target VertexPart bound_vertices_##name(                                                       \
        const MeshView<Scalar, Index>& mesh, const unsigned char* seen_vertex,                     \
        std::size_t addressable, std::size_t first, std::size_t last, std::uint64_t* used) {       \
        return bound_vertices_as<vector_bytes>(mesh, seen_vertex, addressable, first, last, used); \
    }
POLYMASS_SCAN_KERNELS(baseline, , 16)
#if defined(__x86_64__)
POLYMASS_SCAN_KERNELS(avx2, __attribute__((target("avx2"))), 32)
POLYMASS_SCAN_KERNELS(avx512, __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw"))), 64)
#endif
#undef POLYMASS_SCAN_KERNELS

template <class Scalar, class Index>
ScanKernels<Scalar, Index> scan_kernels(InstructionSet set) {
#if defined(__x86_64__)
    switch (set) {
        case InstructionSet::avx512:
            return {mark_indices_avx512<Scalar, Index>, bound_vertices_avx512<Scalar, Index>};
        case InstructionSet::avx2:
            return {mark_indices_avx2<Scalar, Index>, bound_vertices_avx2<Scalar, Index>};
        case InstructionSet::baseline:
            break;
    }
#endif
    return {mark_indices_baseline<Scalar, Index>, bound_vertices_baseline<Scalar, Index>};
}

// The vertex pass over blocks [0, blocks) of 64 vertices, in fixed parts:
// the parts' bounds, counts and findings joined in part order (seen_vertex
// and used_words as bound_vertices_as takes them).
template <class Scalar, class Index>
VertexPart bound_in_parts(const MeshView<Scalar, Index>& mesh,
                          const ScanKernels<Scalar, Index>& kernels,
                          const unsigned char* seen_vertex, std::size_t addressable,
                          std::uint64_t* used_words, std::pmr::memory_resource* memory,
                          TaskRunner& tasks) {
    const std::size_t blocks = block_count(addressable, 64);
    const std::size_t vertex_parts = block_count(blocks, kBlocksPerPart);
    std::pmr::vector<VertexPart> bounded(vertex_parts, memory);
    tasks.run(vertex_parts, [&](std::size_t part) {
        const std::size_t first = part * kBlocksPerPart;
        bounded[part] =
            kernels.bound_vertices(mesh, seen_vertex, addressable, first,
                                   std::min(blocks, first + kBlocksPerPart), used_words);
    });
    VertexPart joined;
    for (const VertexPart& part : bounded) joined.append(part);
    return joined;
}

// How many 64-vertex blocks a follower is handed at a time: 12 KiB of
// double positions, which stay in a 32 KiB L1 cache beside the follower's own
// reads.
constexpr std::size_t kBlocksPerStretch = 8;

// The vertex pass of bound_in_parts on the calling thread, a stretch at a
// time, each handed to `follower` as soon as it is bounded. The stretches'
// results joined in order are the parts': minima, maxima, sums and the
// lowest locations do not depend on how the blocks are grouped.
template <class Scalar, class Index>
VertexPart bound_in_stretches(const MeshView<Scalar, Index>& mesh,
                              const ScanKernels<Scalar, Index>& kernels,
                              const unsigned char* seen_vertex, std::size_t addressable,
                              MeshScan& scan, ScanFollower& follower) {
    const std::size_t blocks = block_count(addressable, 64);
    VertexPart joined;
    for (std::size_t first = 0; first < blocks; first += kBlocksPerStretch) {
        const std::size_t last = std::min(blocks, first + kBlocksPerStretch);
        joined.append(
            kernels.bound_vertices(mesh, seen_vertex, addressable, first, last, scan.used.data()));
        follower.follow(scan, 64 * first, std::min(addressable, 64 * last));
    }
    return joined;
}

// The bounds, counts and used bits of a scan from its marks.
template <class Scalar, class Index>
void bound_used_vertices(const MeshView<Scalar, Index>& mesh,
                         const ScanKernels<Scalar, Index>& kernels,
                         const std::pmr::vector<unsigned char>& seen, MeshScan& scan,
                         std::pmr::memory_resource* memory, TaskRunner& tasks,
                         ScanFollower* follower = nullptr) {
    scan.used.assign((seen.size() + 63) / 64, 0);
    const VertexPart bounded =
        follower ? bound_in_stretches(mesh, kernels, seen.data(), seen.size(), scan, *follower)
                 : bound_in_parts(mesh, kernels, seen.data(), seen.size(), scan.used.data(), memory,
                                  tasks);
    scan.used_vertex_count = bounded.used_vertex_count;
    scan.non_finite = bounded.non_finite;
    scan.bounds = Eigen::AlignedBox3d(bounded.low, bounded.high);
    if (mesh.positions.stride == 3 * sizeof(Scalar))
        keep_first_zero_signs(mesh, seen.data(), seen.size(), scan.bounds);
}

}  // namespace

template <class Scalar, class Index>
std::size_t addressable_vertices(const MeshView<Scalar, Index>& mesh) {
    return std::min<std::size_t>(mesh.vertex_count,
                                 std::size_t(std::numeric_limits<Index>::max()) + 1);
}

template <class Scalar, class Index>
std::optional<Eigen::AlignedBox3d> bound_every_vertex(const MeshView<Scalar, Index>& mesh,
                                                      std::pmr::memory_resource* memory,
                                                      TaskRunner& tasks, InstructionSet set) {
    const std::size_t addressable = addressable_vertices(mesh);
    if (addressable != mesh.vertex_count || mesh.positions.stride != 3 * sizeof(Scalar))
        return std::nullopt;
    const VertexPart bounded = bound_in_parts(mesh, scan_kernels<Scalar, Index>(set), nullptr,
                                              addressable, nullptr, memory, tasks);
    if (bounded.non_finite.count > 0) return std::nullopt;
    Eigen::AlignedBox3d bounds(bounded.low, bounded.high);
    keep_first_zero_signs(mesh, nullptr, addressable, bounds);
    return bounds;
}

template <class Scalar, class Index>
MeshScan scan_from_marks(const MeshView<Scalar, Index>& mesh,
                         const std::pmr::vector<unsigned char>& seen,
                         const Eigen::AlignedBox3d& every_vertex, std::pmr::memory_resource* memory,
                         TaskRunner& tasks, InstructionSet set) {
    MeshScan scan(memory);
    // 64 marks at a time (every byte is 0 or 1).
    std::size_t vertex = 0;
    while (vertex + 64 <= seen.size() && all_set(seen.data() + vertex)) vertex += 64;
    const bool every_vertex_used = std::all_of(seen.begin() + std::ptrdiff_t(vertex), seen.end(),
                                               [](unsigned char mark) { return mark != 0; });
    if (!every_vertex_used) {
        bound_used_vertices(mesh, scan_kernels<Scalar, Index>(set), seen, scan, memory, tasks);
        return scan;
    }
    scan.used.assign((seen.size() + 63) / 64, ~std::uint64_t{0});
    if (seen.size() % 64 != 0) scan.used.back() = (std::uint64_t{1} << (seen.size() % 64)) - 1;
    scan.used_vertex_count = seen.size();
    scan.bounds = every_vertex;
    return scan;
}

template <class Scalar, class Index>
MeshScan scan_mesh(const MeshView<Scalar, Index>& mesh, std::pmr::memory_resource* memory,
                   TaskRunner& tasks, InstructionSet set, ScanFollower* follower) {
    const ScanKernels<Scalar, Index> kernels = scan_kernels<Scalar, Index>(set);
    MeshScan scan(memory);
    // A byte per vertex, packed into scan.used afterwards: setting bits in
    // place would chain each face's read-modify-write of a word to the last
    // one's (neighbouring faces share vertices), a byte store waits for nothing.
    std::pmr::vector<unsigned char> seen(addressable_vertices(mesh), 0, memory);
    const std::size_t index_parts = block_count(mesh.index_count, kIndicesPerPart);
    std::pmr::vector<IndexPart> marked(index_parts, memory);
    tasks.run(index_parts, [&](std::size_t part) {
        const std::size_t begin = part * kIndicesPerPart;
        marked[part] = kernels.mark_indices(
            mesh, begin, std::min(mesh.index_count, begin + kIndicesPerPart), seen.data());
    });
    // The faces matter only to report an index out of range, which is rare
    // enough to look for again.
    const bool all_in_range = std::all_of(marked.begin(), marked.end(),
                                          [](const IndexPart& part) { return part.all_in_range; });
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
    bound_used_vertices(mesh, kernels, seen, scan, memory, tasks, follower);
    return scan;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                       \
    template MeshScan scan_mesh<Scalar, Index>(const MeshView<Scalar, Index>&,                    \
                                               std::pmr::memory_resource*, TaskRunner&,           \
                                               InstructionSet, ScanFollower*);                    \
    template std::size_t addressable_vertices<Scalar, Index>(const MeshView<Scalar, Index>&);     \
    template std::optional<Eigen::AlignedBox3d> bound_every_vertex<Scalar, Index>(                \
        const MeshView<Scalar, Index>&, std::pmr::memory_resource*, TaskRunner&, InstructionSet); \
    template MeshScan scan_from_marks<Scalar, Index>(                                             \
        const MeshView<Scalar, Index>&, const std::pmr::vector<unsigned char>&,                   \
        const Eigen::AlignedBox3d&, std::pmr::memory_resource*, TaskRunner&, InstructionSet);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
