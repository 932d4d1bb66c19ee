#include "triangle_gather.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <cstring>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace polymass::core {
namespace {

// The position in the index array of corner `corner` of the batch's triangle `slot`.
template <bool listed, class Scalar, class Index>
__attribute__((always_inline)) inline std::size_t corner_position(
    const TriangleBatch<Scalar, Index>& batch, std::size_t slot, int corner) {
    return (listed ? batch.corners[slot] : 3 * (batch.first_face + slot)) + std::size_t(corner);
}

// Marks a vertex read by a marking batch (TriangleBatch::used_marks).
__attribute__((always_inline)) inline void mark_used(unsigned char* used_marks,
                                                     std::uint32_t vertex) {
    __atomic_store_n(&used_marks[vertex], static_cast<unsigned char>(1), __ATOMIC_RELAXED);
}

// Whether every index of a marking batch is below its vertex count (none is
// when there is no vertex). A loop with no branch, of a fixed length for a
// whole batch, which each instruction set's compiler vectorises: the largest
// index, one unsigned maximum for each vector of indices (a comparison or'ed
// into a mask took three, 2.3 instructions a triangle with AVX2).
template <class Scalar, class Index>
__attribute__((always_inline)) inline bool indices_in_range(
    const TriangleBatch<Scalar, Index>& batch) {
    const auto indices = batch.indices;
    const std::size_t first = 3 * batch.first_face;
    if (batch.vertex_count == 0) return batch.count == 0;
    // In 32 bits, which vectorise: the largest index in range (every 32-bit
    // index when there are more vertices).
    const std::uint32_t last =
        std::uint32_t(std::min<std::size_t>(batch.vertex_count, std::size_t{1} << 32) - 1);
    auto largest = [&](std::size_t length) {
        std::uint32_t highest = 0;
        for (std::size_t i = 0; i < length; ++i) highest = std::max(highest, indices[first + i]);
        return highest;
    };
    return (batch.count == batch_capacity ? largest(3 * batch_capacity)
                                          : largest(3 * batch.count)) <= last;
}

// Slots [begin, count) one coordinate at a time, then the padding. The whole
// batch for the baseline; the slots short of a whole group for the others.
template <bool listed, bool marking, class Scalar, class Index>
void gather_one_by_one(const TriangleBatch<Scalar, Index>& batch, std::size_t begin,
                       GatheredTriangles& gathered) {
    for (std::size_t slot = begin; slot < batch.count; ++slot)
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t vertex =
                batch.indices[corner_position<listed>(batch, slot, corner)];
            if constexpr (marking) mark_used(batch.used_marks, vertex);
            const Eigen::Vector3d position = batch.positions[vertex];
            for (int axis = 0; axis < 3; ++axis)
                gathered.coordinates[axis][corner][slot] = position[axis];
        }
    const std::size_t padded = (batch.count + gathered_group - 1) / gathered_group * gathered_group;
    for (std::size_t slot = batch.count; slot < padded; ++slot)
        for (int corner = 0; corner < 3; ++corner)
            for (int axis = 0; axis < 3; ++axis)
                gathered.coordinates[axis][corner][slot] = batch.reference[axis];
}

// Runs gather<listed, marking> for the batch's kind: listed faces, or
// consecutive ones with or without marks (checked first). Inlined into each
// instruction set's gatherer, whose range check it then vectorises too.
template <template <bool, bool> class Gather, class Scalar, class Index>
__attribute__((always_inline)) inline bool gather_batch(const TriangleBatch<Scalar, Index>& batch,
                                                        GatheredTriangles& gathered) {
    if (batch.faces) {
        Gather<true, false>::run(batch, gathered);
    } else if (!batch.marking) {
        Gather<false, false>::run(batch, gathered);
    } else {
        if (!indices_in_range(batch)) return false;
        Gather<false, true>::run(batch, gathered);
    }
    return true;
}

template <bool listed, bool marking>
struct GatherBaseline {
    template <class Scalar, class Index>
    static void run(const TriangleBatch<Scalar, Index>& batch, GatheredTriangles& gathered) {
        gather_one_by_one<listed, marking>(batch, 0, gathered);
    }
};

template <class Scalar, class Index>
bool gather_baseline(const TriangleBatch<Scalar, Index>& batch, GatheredTriangles& gathered) {
    return gather_batch<GatherBaseline>(batch, gathered);
}

#if defined(__x86_64__)
// A vertex as x, y, z and a zero, in one register. The AVX-512 gatherer
// keeps a float row as floats and transposes four of them as floats, with one
// two-register permute into a 512-bit register (store_transposed_avx512), and
// widens afterwards: two conversions a lane group and corner rather than four.
// (Trusted path, float32 torus of 1e6 triangles, Intel Xeon with AVX-512,
// fastest of 30 calls, three interleaved runs: 197-202 M triangles/s with the
// 128-bit transpose and three conversions of stop 39, 224-227 so; float64
// 200-213 in the same runs. That 128-bit transpose had itself beaten widening
// first on Zen 4.) The AVX2 gatherer widens each row as it loads it: there
// the float transpose's shuffles outnumber the conversion saved (the gather
// 27.7 -> 25.4 instructions a triangle, callgrind). (GCC takes no vector
// attribute on a template parameter: a trait.)
template <class Scalar>
struct RowOf;
template <>
struct RowOf<double> {
    using type = Lanes;
};
template <>
struct RowOf<float> {
    using type = float __attribute__((vector_size(lane_count * sizeof(float))));
};
template <class Scalar>
using Row = typename RowOf<Scalar>::type;

// Rows x, y, z, 0 of lane_count triangles, transposed into x, y and z of
// the triangles. Plain vector shuffles: the compiler turns them into its
// unpacks and permutes.
__attribute__((always_inline)) inline void transpose_rows(const Lanes (&rows)[lane_count],
                                                          Lanes (&axes)[3]) {
    const Lanes xz01 = __builtin_shufflevector(rows[0], rows[1], 0, 4, 2, 6);  // x0 x1 z0 z1
    const Lanes y01 = __builtin_shufflevector(rows[0], rows[1], 1, 5, 3, 7);   // y0 y1 0 0
    const Lanes xz23 = __builtin_shufflevector(rows[2], rows[3], 0, 4, 2, 6);
    const Lanes y23 = __builtin_shufflevector(rows[2], rows[3], 1, 5, 3, 7);
    axes[0] = __builtin_shufflevector(xz01, xz23, 0, 1, 4, 5);
    axes[1] = __builtin_shufflevector(y01, y23, 0, 1, 4, 5);
    axes[2] = __builtin_shufflevector(xz01, xz23, 2, 3, 6, 7);
}

// How many triangles ahead of the ones it gathers a gatherer asks for the
// vertices of a block's triangles (when they are not listed): the vertices of
// a large mesh come from beyond the L2 cache, and the index array alone does
// not tell the processor's prefetcher where they are. One corner a triangle
// (the last: in a strip or a grid, the vertex its neighbours have not used
// yet): the loads of three cost more instructions and gained no more. Whole
// trusted path, torus of 1e6 triangles, interleaved runs on a loaded machine:
// 0.82-0.94 of the time without.
constexpr std::size_t fetch_ahead = 32;

// Where the corners of a batch's triangles are, in locals: the stores into
// GatheredTriangles could alias the batch's fields for all the compiler knows,
// and it would read them again after each.
template <bool listed, bool marking, class Scalar, class Index>
struct CornerSource {
    const unsigned char* base;
    std::size_t stride;
    IndexArray<Index> indices;
    std::size_t first_corner;    // when not listed
    const std::size_t* corners;  // when listed
    std::size_t faces_left;      // from the batch's first to its block's last, when not listed
    unsigned char* used_marks;   // when marking

    __attribute__((always_inline)) explicit CornerSource(const TriangleBatch<Scalar, Index>& batch)
        : base(batch.positions.base),
          stride(batch.positions.stride),
          indices(batch.indices),
          first_corner(3 * batch.first_face),
          corners(batch.corners),
          faces_left(listed || batch.last_face < batch.first_face
                         ? 0
                         : batch.last_face - batch.first_face),
          used_marks(batch.used_marks) {}

    __attribute__((always_inline)) std::uint32_t index(std::size_t slot, int corner) const {
        return indices[(listed ? corners[slot] : first_corner + 3 * slot) + std::size_t(corner)];
    }

    // The first coordinate of corner `corner` of the batch's triangle `slot`,
    // marked as used when marking.
    __attribute__((always_inline)) const unsigned char* vertex(std::size_t slot, int corner) const {
        const std::uint32_t vertex = index(slot, corner);
        if constexpr (marking) mark_used(used_marks, vertex);
        return base + std::size_t(vertex) * stride;
    }

    // Asks for that vertex ahead of its batch, whose indices may not be
    // checked yet: the address is formed as an integer (it may lie past the
    // array), and an x86 prefetch never faults.
    __attribute__((always_inline)) void fetch(std::size_t slot, int corner) const {
        __builtin_prefetch(reinterpret_cast<const void*>(
            reinterpret_cast<std::uintptr_t>(base) + std::size_t(index(slot, corner)) * stride));
    }
};

// The rows of a lane group's corners `corner`, double rows (the AVX2
// gatherer widens float rows as it loads them), stored transposed at `slot`.
template <class Scalar>
__attribute__((target("avx2"), always_inline)) inline void store_transposed(
    const Row<Scalar> (&rows)[lane_count], GatheredTriangles& gathered, int corner,
    std::size_t slot) {
    static_assert(sizeof(Scalar) == sizeof(double), "rows of doubles");
    Lanes axes[3];
    transpose_rows(rows, axes);
#pragma GCC unroll 3
    for (int axis = 0; axis < 3; ++axis)
        std::memcpy(&gathered.coordinates[axis][corner][slot], &axes[axis], sizeof(Lanes));
}

// A vertex as x, y, z and a zero, in one register, for each wider set.
// Masked loads: the lane past z is neither read nor able to fault, so the
// last vertex of the array is read like any other. The AVX-512 gatherer
// differs from the AVX2 one in its masked load, which Zen 4 runs much faster
// than AVX2's vmaskmovpd (the whole trusted path at 1e6 triangles, 6.6
// against 7.7 ns per triangle), and in how it transposes and widens floats (above). Each has its
// own loop: a loop shared as a template would have to inline code built for a wider set into code
// that is not. Four rows at a time for both: a transpose of four 256-bit rows takes fewer shuffle
// slots than one of eight in 512-bit registers, which Zen 4 runs as two halves.
template <class Scalar>
__attribute__((target("avx2"), always_inline)) inline void vertex_row_avx2(const unsigned char* xyz,
                                                                           Row<double>& row) {
    if constexpr (sizeof(Scalar) == sizeof(float))
        row = Row<double>(_mm256_cvtps_pd(
            _mm_maskload_ps(reinterpret_cast<const float*>(xyz), _mm_setr_epi32(-1, -1, -1, 0))));
    else
        row = Row<double>(_mm256_maskload_pd(reinterpret_cast<const double*>(xyz),
                                             _mm256_setr_epi64x(-1, -1, -1, 0)));
}

// The gathering loop for one instruction set: four vertex rows at a time,
// loaded by vertex_row_<name> as rows of RowScalar, transposed into the
// batch's lanes.
#define POLYMASS_GATHER(name, target, RowScalar, store)                                            \
    template <bool listed, bool marking>                                                           \
    struct Gather_##name {                                                                         \
        template <class Scalar, class Index>                                                       \
        target static void run(const TriangleBatch<Scalar, Index>& batch,                          \
                               GatheredTriangles& gathered) {                                      \
            const CornerSource<listed, marking, Scalar, Index> source(batch);                      \
            std::size_t slot = 0;                                                                  \
            for (; slot + lane_count <= batch.count; slot += lane_count) {                         \
                if (!listed && slot + fetch_ahead + lane_count <= source.faces_left)               \
                    _Pragma("GCC unroll 4") for (int lane = 0; lane < lane_count; ++lane)          \
                        source.fetch(slot + fetch_ahead + lane, 2);                                \
                _Pragma("GCC unroll 3") for (int corner = 0; corner < 3; ++corner) {               \
                    Row<RowScalar> rows[lane_count];                                               \
                    _Pragma("GCC unroll 4") for (int lane = 0; lane < lane_count; ++lane)          \
                        vertex_row_##name<Scalar>(source.vertex(slot + lane, corner), rows[lane]); \
                    store<RowScalar>(rows, gathered, corner, slot);                                \
                }                                                                                  \
            }                                                                                      \
            gather_one_by_one<listed, marking>(batch, slot, gathered);                             \
        }                                                                                          \
    };                                                                                             \
    template <class Scalar, class Index>                                                           \
    target bool gather_##name(const TriangleBatch<Scalar, Index>& batch,                           \
                              GatheredTriangles& gathered) {                                       \
        return gather_batch<Gather_##name>(batch, gathered);                                       \
    }

POLYMASS_GATHER(avx2, __attribute__((target("avx2"))), double, store_transposed)

#define POLYMASS_AVX512 "avx512f,avx512vl,avx512dq,avx512bw"

template <class Scalar>
__attribute__((target(POLYMASS_AVX512), always_inline)) inline void vertex_row_avx512(
    const unsigned char* xyz, Row<Scalar>& row) {
    if constexpr (sizeof(Scalar) == sizeof(float))
        row = Row<float>(_mm_maskz_loadu_ps(0x7, xyz));
    else
        row = Row<double>(_mm256_maskz_loadu_pd(0x7, xyz));
}

// store_transposed for the AVX-512 gatherer: float rows go into one 512-bit
// register, permuted into x0..x3 y0..y3 z0..z3 and the zeros, and widened
// exactly, x and y with one conversion; double rows go into two, permuted
// into x0..x3 y0..y3 and z0..z3 (two inserts and two permutes rather than six
// 256-bit shuffles: float64 trusted path at 1e6 triangles, fastest of 30
// calls, three interleaved runs, 216.7-217.5 -> 219.2-219.6 M triangles/s).
// (GCC 12's headers fill the unused lanes of these intrinsics with an
// "undefined" vector it then warns about: the warning is silenced here, for
// this function alone.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
template <class Scalar>
__attribute__((target(POLYMASS_AVX512), always_inline)) inline void store_transposed_avx512(
    const Row<Scalar> (&rows)[lane_count], GatheredTriangles& gathered, int corner,
    std::size_t slot) {
    if constexpr (sizeof(Scalar) == sizeof(float)) {
        const __m256 rows01 =
            _mm256_insertf128_ps(_mm256_castps128_ps256(__m128(rows[0])), __m128(rows[1]), 1);
        const __m256 rows23 =
            _mm256_insertf128_ps(_mm256_castps128_ps256(__m128(rows[2])), __m128(rows[3]), 1);
        const __m512 axes = _mm512_permutex2var_ps(
            _mm512_castps256_ps512(rows01),
            _mm512_setr_epi32(0, 4, 16, 20, 1, 5, 17, 21, 2, 6, 18, 22, 3, 7, 19, 23),
            _mm512_castps256_ps512(rows23));
        const __m512d xy = _mm512_cvtps_pd(_mm512_castps512_ps256(axes));
        _mm256_storeu_pd(&gathered.coordinates[0][corner][slot], _mm512_castpd512_pd256(xy));
        _mm256_storeu_pd(&gathered.coordinates[1][corner][slot], _mm512_extractf64x4_pd(xy, 1));
        _mm256_storeu_pd(&gathered.coordinates[2][corner][slot],
                         _mm256_cvtps_pd(_mm512_extractf32x4_ps(axes, 2)));
    } else {
        const __m512d rows01 =
            _mm512_insertf64x4(_mm512_castpd256_pd512(__m256d(rows[0])), __m256d(rows[1]), 1);
        const __m512d rows23 =
            _mm512_insertf64x4(_mm512_castpd256_pd512(__m256d(rows[2])), __m256d(rows[3]), 1);
        const __m512d xy =
            _mm512_permutex2var_pd(rows01, _mm512_setr_epi64(0, 4, 8, 12, 1, 5, 9, 13), rows23);
        const __m512d z_and_zeros =
            _mm512_permutex2var_pd(rows01, _mm512_setr_epi64(2, 6, 10, 14, 3, 7, 11, 15), rows23);
        _mm256_storeu_pd(&gathered.coordinates[0][corner][slot], _mm512_castpd512_pd256(xy));
        _mm256_storeu_pd(&gathered.coordinates[1][corner][slot], _mm512_extractf64x4_pd(xy, 1));
        _mm256_storeu_pd(&gathered.coordinates[2][corner][slot],
                         _mm512_castpd512_pd256(z_and_zeros));
    }
}

#pragma GCC diagnostic pop

POLYMASS_GATHER(avx512, __attribute__((target(POLYMASS_AVX512))), Scalar, store_transposed_avx512)
#undef POLYMASS_GATHER
#undef POLYMASS_AVX512
#endif

}  // namespace

template <class Scalar, class Index>
TriangleGatherer<Scalar, Index> triangle_gatherer(InstructionSet set) {
#if defined(__x86_64__)
    if (set == InstructionSet::avx512) return gather_avx512<Scalar, Index>;
    if (set == InstructionSet::avx2) return gather_avx2<Scalar, Index>;
#endif
    (void)set;
    return gather_baseline<Scalar, Index>;
}

#define POLYMASS_INSTANTIATE(Scalar, Index) \
    template TriangleGatherer<Scalar, Index> triangle_gatherer<Scalar, Index>(InstructionSet);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
