#include "mesh_integration.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "lanes.hpp"
#include "polygon_integrals.hpp"
#include "triangle_gather.hpp"
#include "triangle_integrals.hpp"

namespace polymass::core {
namespace {

struct BatchResult {
    FaceSums sums;
    double surface_area = 0.0;
    // Σ max(|E1|², |E2|²) ≥ Σ |E1||E2|: what scales each triangle's rounding
    // (docs/error_bound.md).
    double extents_squared = 0.0;
    Finding degenerate_faces;
};

// The closed forms over a gathered batch, `Wide` (one or two lane groups) at
// a time. Triangle i of the batch goes to lane i mod 8 of the running sums
// (two lane groups, one WideLanes), whatever Wide is: a Wide of one group
// fills the sums' two groups in turn, one of two fills both at once. So the
// sums, and their bits, are the same for every instruction set, and the
// widest adds each term with one instruction.
//
// Slivers (measured without squaring) and degenerate triangles (reported) are
// rare. The fast pass (`careful` false, for whole batches) only notes whether
// the batch holds one, with no branch per lane group, and then returns false
// without touching `result`: the batch is run again carefully. Both passes
// give the same bits for every triangle that is neither.
template <TriangleForm form, class Wide, bool fused, bool careful, class Scalar, class Index>
__attribute__((always_inline)) inline bool integrate_gathered(
    const TriangleBatch<Scalar, Index>& batch, const GatheredTriangles& gathered,
    BatchResult& result) {
    constexpr int width = width_of<Wide>;
    constexpr int steps = groups_of<WideLanes> / groups_of<Wide>;  // of Wide, per 8 triangles
    static_assert(
        batch_capacity % width_of<WideLanes> == 0 && gathered_group % width_of<WideLanes> == 0,
        "whole steps of 8 triangles, padded to them");
    // Below 2^-1022 squares lose digits (down to none: a well-shaped triangle
    // 1e-150 of the mesh's size squares to zero); above 2^-960 what they lose
    // is under 2^-115 of the sum. So a small δ (coordinates are of order one
    // here) is measured without squaring instead, rarely.
    constexpr double squares_keep_digits = 0x1p-960;
    UnscaledTriangleSums<WideLanes> sums;
    WideLanes twice_areas{}, extents{};
    // Over the fast pass: the smallest squared |δ| and twice area less the
    // degeneracy threshold (1 is above the thresholds of both).
    Wide smallest_norm = Wide{} + 1.0, smallest_margin = Wide{} + 1.0;
    // The reference point in units, exact where the move is fused.
    double reference_in_units[3] = {};
    if constexpr (fused)
        for (int axis = 0; axis < 3; ++axis)
            reference_in_units[axis] = batch.reference[axis] * batch.inverse_unit;
    for (std::size_t eight = 0; eight < batch.count; eight += width_of<WideLanes>) {
#pragma GCC unroll 2
        for (int step = 0; step < steps; ++step) {
            const std::size_t first = eight + std::size_t(step) * width;
            if (careful && first >= batch.count) break;
            const int first_group = step * groups_of<Wide>;
            Wide p[3][3];
#pragma GCC unroll 3
            for (int axis = 0; axis < 3; ++axis)
#pragma GCC unroll 3
                for (int vertex = 0; vertex < 3; ++vertex) {
                    Wide coordinate;
                    std::memcpy(&coordinate, &gathered.coordinates[axis][vertex][first],
                                sizeof coordinate);
                    if constexpr (fused) {
                        // coordinate · unit⁻¹ − reference · unit⁻¹, rounded once: the
                        // same bits as below (fused_move_is_exact); one instruction
                        // for each lane group with FMA.
                        for (int lane = 0; lane < width; ++lane)
                            p[axis][vertex][lane] = std::fma(coordinate[lane], batch.inverse_unit,
                                                             -reference_in_units[axis]);
                    } else {
                        p[axis][vertex] = (coordinate - batch.reference[axis]) * batch.inverse_unit;
                    }
                }
            const TriangleEdges<Wide> edges(p);
            // Lane groups past the batch's end add nothing; padding lanes add zeros.
            const int groups =
                careful ? int(std::min<std::size_t>(
                              groups_of<Wide>, (batch.count - first + lane_count - 1) / lane_count))
                        : groups_of<Wide>;
            add_unscaled_triangle_sums<form>(sums, p, edges.delta, first_group, groups);

            // Started from the first square rather than from zero: 0 + a² is a²
            // exactly (a square is never −0), one addition fewer each.
            Wide squared_norm = edges.delta[0] * edges.delta[0];
            Wide e1_squared = edges.e1[0] * edges.e1[0], e2_squared = edges.e2[0] * edges.e2[0];
#pragma GCC unroll 2
            for (int axis = 1; axis < 3; ++axis) {
                squared_norm += edges.delta[axis] * edges.delta[axis];
                e1_squared += edges.e1[axis] * edges.e1[axis];
                e2_squared += edges.e2[axis] * edges.e2[axis];
            }
            Wide twice_area;
            for (int lane = 0; lane < width; ++lane)
                twice_area[lane] = std::sqrt(squared_norm[lane]);
            // A degenerate triangle is reported; its terms, at rounding level, stay:
            // they are what keeps a closed surface's sum balanced.
            const Wide extent_squared = e1_squared > e2_squared ? e1_squared : e2_squared;
            if constexpr (careful) {
                if (any_lane((squared_norm < squares_keep_digits) |
                             (twice_area <= degenerate_area_ratio * extent_squared))) {
                    for (int lane = 0; lane < width; ++lane)
                        if (squared_norm[lane] < squares_keep_digits)
                            twice_area[lane] = std::hypot(
                                edges.delta[0][lane], edges.delta[1][lane], edges.delta[2][lane]);
                    const MaskOf<Wide> degenerate =
                        twice_area <= degenerate_area_ratio * extent_squared;
                    const std::size_t used = std::min<std::size_t>(width, batch.count - first);
                    for (std::size_t lane = 0; lane < used; ++lane)
                        if (degenerate[lane])
                            result.degenerate_faces.record(batch.face(first + lane));
                }
            } else {
                // Minima rather than or'ed masks, which compilers build a lane at
                // a time. The margin is ≤ 0 wherever the test above holds (and at
                // worst also where it does not, when the subtraction underflows
                // to zero under flush-to-zero: a needless careful pass).
                smallest_norm = squared_norm < smallest_norm ? squared_norm : smallest_norm;
                const Wide margin = twice_area - degenerate_area_ratio * extent_squared;
                smallest_margin = margin < smallest_margin ? margin : smallest_margin;
            }
            add_lane_groups(twice_areas, twice_area, first_group, groups);
            add_lane_groups(extents, extent_squared, first_group, groups);
        }
    }
    if (!careful)
        for (int lane = 0; lane < width; ++lane)
            if (smallest_norm[lane] < squares_keep_digits || smallest_margin[lane] <= 0.0)
                return false;
    result.surface_area += sum_lanes(twice_areas) / 2.0;
    result.extents_squared += sum_lanes(extents);
    UnscaledTriangleSums<double> reduced;
    reduced.x = sum_lanes(sums.x);
    for (int axis = 0; axis < 3; ++axis) {
        reduced.squares[axis] = sum_lanes(sums.squares[axis]);
        reduced.cubes[axis] = sum_lanes(sums.cubes[axis]);
        reduced.mixed[axis] = sum_lanes(sums.mixed[axis]);
    }
    result.sums += scaled<form>(reduced);
    return true;
}

template <TriangleForm form, class Wide, bool fused, class Scalar, class Index>
__attribute__((always_inline)) inline void integrate_batch(
    const TriangleBatch<Scalar, Index>& batch, const GatheredTriangles& gathered,
    BatchResult& result) {
    if (batch.count == batch_capacity &&
        integrate_gathered<form, Wide, fused, false>(batch, gathered, result))
        return;
    integrate_gathered<form, Wide, fused, true>(batch, gathered, result);
}

// Whether the move into the integration frame, (c − r)·u⁻¹ (c a coordinate, r
// the reference point's, u⁻¹ the inverse unit, a power of two), gives the
// same bits fused as c·u⁻¹ − r·u⁻¹ rounded once, for every coordinate within
// `size` of the reference (IntegrationSettings), on every axis
// (docs/integrals.md, section 5): r is zero (c − r is then exact), or r·u⁻¹ is
// a normal double (so exact) at least 2^-1021 and below 2^1000 (then a c − r
// that rounds is at least |r|/2, so its move stays normal, where scaling by a
// power of two commutes with rounding). Any other frame is integrated unfused.
bool fused_move_is_exact(const Eigen::Vector3d& reference, double inverse_unit) {
    for (const double r : reference) {
        const double in_units = std::abs(r) * inverse_unit;
        if (r != 0.0 && !(in_units >= 0x1p-1021 && in_units < 0x1p1000)) return false;
    }
    return true;
}

// The kernel built for each instruction set. The baseline does not fuse a
// multiply and an add (x86-64 without FMA would do it in software): the file
// is compiled with -ffp-contract=off, and the AVX2 and AVX-512 kernels fuse
// the move into the frame alone, only where that gives the baseline's bits
// (the AVX2 set includes FMA: instruction_sets.hpp).
template <TriangleForm form, class Scalar, class Index>
void integrate_batch_baseline(const TriangleBatch<Scalar, Index>& batch,
                              const GatheredTriangles& gathered, BatchResult& result) {
    integrate_batch<form, Lanes, false>(batch, gathered, result);
}

#if defined(__x86_64__)
template <TriangleForm form, bool fused, class Scalar, class Index>
__attribute__((target("avx2,fma"))) void integrate_batch_avx2(
    const TriangleBatch<Scalar, Index>& batch, const GatheredTriangles& gathered,
    BatchResult& result) {
    integrate_batch<form, Lanes, fused>(batch, gathered, result);
}

template <TriangleForm form, class Scalar, class Index>
__attribute__((target("avx512f,avx512vl,avx512dq,avx512bw"))) void integrate_batch_avx512(
    const TriangleBatch<Scalar, Index>& batch, const GatheredTriangles& gathered,
    BatchResult& result) {
    integrate_batch<form, WideLanes, true>(batch, gathered, result);
}
#endif

template <class Scalar, class Index>
using BatchKernel = void (*)(const TriangleBatch<Scalar, Index>&, const GatheredTriangles&,
                             BatchResult&);

// The kernel of `set`; where the fused move would not give the baseline's
// bits (fused_move_is_exact), AVX2's unfused one (a processor with AVX-512
// runs AVX2).
template <TriangleForm form, class Scalar, class Index>
BatchKernel<Scalar, Index> batch_kernel(InstructionSet set, bool fused_move_exact) {
#if defined(__x86_64__)
    if (set != InstructionSet::baseline && !fused_move_exact)
        return integrate_batch_avx2<form, false, Scalar, Index>;
    if (set == InstructionSet::avx512) return integrate_batch_avx512<form, Scalar, Index>;
    if (set == InstructionSet::avx2) return integrate_batch_avx2<form, true, Scalar, Index>;
#endif
    (void)set;
    (void)fused_move_exact;
    return integrate_batch_baseline<form, Scalar, Index>;
}

// A mesh of triangles only takes the cone form, fewer operations; one with
// polygons the flux form, whose face sums add up with the polygons' (the two
// forms agree on a closed surface's totals, not face by face).
template <class Scalar, class Index>
BatchKernel<Scalar, Index> batch_kernel(InstructionSet set, bool all_triangles,
                                        bool fused_move_exact) {
    return all_triangles ? batch_kernel<TriangleForm::cone, Scalar, Index>(set, fused_move_exact)
                         : batch_kernel<TriangleForm::flux, Scalar, Index>(set, fused_move_exact);
}

// What one block of faces adds up, in integration units.
struct BlockSums {
    FaceSums sums;
    double surface_area = 0.0;
    double extents_squared = 0.0;  // Σ over faces, in units²
    std::size_t summed_terms = 0;  // batches and polygons added to sums
    Finding degenerate_faces;
    Finding non_planar_faces;
    double max_non_planarity = 0.0;
    bool indices_in_range = true;

    // Block order: a block's sums join the total after those of the blocks
    // before it.
    void add(const BlockSums& block) {
        sums += block.sums;
        surface_area += block.surface_area;
        extents_squared += block.extents_squared;
        summed_terms += block.summed_terms;
        degenerate_faces.merge(block.degenerate_faces);
        non_planar_faces.merge(block.non_planar_faces);
        max_non_planarity = std::max(max_non_planarity, block.max_non_planarity);
        indices_in_range = indices_in_range && block.indices_in_range;
    }
};

// Sums one block of faces: triangles a batch at a time, polygons one by one,
// each joining the block's sums in face order (a triangle when its batch is
// full or the block ends).
template <class Scalar, class Index>
class BlockIntegrator {
public:
    BlockIntegrator(const MeshView<Scalar, Index>& mesh, const IntegrationSettings& settings,
                    double unit)
        : settings_(settings),
          gatherer_(triangle_gatherer<Scalar, Index>(settings.instruction_set)),
          kernel_(
              batch_kernel<Scalar, Index>(settings.instruction_set, mesh.all_triangles(),
                                          fused_move_is_exact(settings.reference, 1.0 / unit))) {
        batch_.positions = mesh.positions;
        batch_.indices = mesh.indices;
        for (int axis = 0; axis < 3; ++axis) batch_.reference[axis] = settings.reference[axis];
        batch_.inverse_unit = 1.0 / unit;  // a power of two: exact
        if (settings.used_marks) {
            batch_.marking = true;
            batch_.used_marks = settings.used_marks->data();
            batch_.vertex_count = mesh.vertex_count;
        }
    }

    // Faces [begin, end) of an all-triangle mesh: whole batches now, the rest
    // at finish(). Marking, it stops at a batch with an index out of range.
    void add_triangles(std::size_t begin, std::size_t end) {
        batch_.last_face = end;
        for (batch_.first_face = begin; end - batch_.first_face >= batch_capacity;
             batch_.first_face += batch_capacity) {
            batch_.count = batch_capacity;
            if (!flush_triangles()) return;
        }
        batch_.count = end - batch_.first_face;
    }

    // A triangle of a mixed mesh, whose first corner is at position `corner`
    // of the index array.
    void add_triangle(std::size_t face, std::size_t corner) {
        faces_[batch_.count] = face;
        corners_[batch_.count] = corner;
        batch_.faces = faces_;
        batch_.corners = corners_;
        if (++batch_.count == batch_capacity) flush_triangles();
    }

    // vertex_at(i): the i-th vertex relative to the reference point, in units.
    template <class VertexAt>
    void add_polygon(std::size_t face, std::size_t count, VertexAt&& vertex_at) {
        const FacePlane plane = face_plane(count, vertex_at);
        block_.surface_area += plane.area;
        // Each triangle of a fan has |E1||E2| ≤ (2 extent)²; the projection
        // and lift add operations, hence the extra factor (docs/error_bound.md).
        block_.extents_squared += 8.0 * double(count) * 4.0 * plane.extent * plane.extent;
        ++block_.summed_terms;
        if (plane.degenerate) {
            // No normal to project along; its terms would be at rounding level.
            block_.degenerate_faces.record(face);
            return;
        }
        if (settings_.check_planarity) {
            const double relative = plane_deviation(plane, count, vertex_at) / (2.0 * plane.extent);
            block_.max_non_planarity = std::max(block_.max_non_planarity, relative);
            if (relative > settings_.planarity_tolerance) block_.non_planar_faces.record(face);
        }
        block_.sums += polygon_face_sums(plane, count, vertex_at);
    }

    // The last batch, full or not (even empty: it counts as a term).
    BlockSums finish() {
        if (block_.indices_in_range) flush_triangles();
        return block_;
    }

private:
    // False when the batch's indices were found out of range (marking).
    bool flush_triangles() {
        BatchResult batch_result;
        const bool in_range = gatherer_(batch_, gathered_);
        if (in_range) {
            kernel_(batch_, gathered_, batch_result);
            block_.sums += batch_result.sums;
            block_.surface_area += batch_result.surface_area;
            block_.extents_squared += batch_result.extents_squared;
            ++block_.summed_terms;
            block_.degenerate_faces.merge(batch_result.degenerate_faces);
        }
        block_.indices_in_range = block_.indices_in_range && in_range;
        batch_.count = 0;
        return in_range;
    }

    const IntegrationSettings& settings_;
    const TriangleGatherer<Scalar, Index> gatherer_;
    const BatchKernel<Scalar, Index> kernel_;
    TriangleBatch<Scalar, Index> batch_;
    GatheredTriangles gathered_;
    std::size_t faces_[batch_capacity];
    std::size_t corners_[batch_capacity];
    BlockSums block_;
};

// The whole mesh's result from the blocks' sums added in block order.
class ResultBuilder {
public:
    ResultBuilder(const IntegrationSettings& settings, double unit)
        : settings_(settings), unit_(unit) {}

    void add(const BlockSums& block) {
        total_.add(block);
        ++blocks_;
    }

    IntegrationResult finish() const {
        IntegrationResult result;
        const VolumeIntegrals in_units = volume_integrals_from(total_.sums);
        constexpr double slack = 1024.0 * 2.220446049250313e-16;
        result.encloses_no_volume =
            std::abs(in_units.volume) <= slack * total_.surface_area * (settings_.size / unit_);
        result.integrals = in_units.scaled(unit_);
        result.bounds = rounding_bounds().scaled(unit_);
        result.surface_area = times_unit_power(total_.surface_area, unit_, 2);
        result.degenerate_faces = total_.degenerate_faces;
        result.non_planar_faces = total_.non_planar_faces;
        result.max_non_planarity = total_.max_non_planarity;
        result.indices_in_range = total_.indices_in_range;
        return result;
    }

private:
    // docs/error_bound.md: each face's terms carry a relative error of a few
    // dozen roundings of (|δ|/2)·R^k, the sum one rounding per term it adds up
    // (blocks of a batch, then batches and polygons one by one within a
    // block, then the blocks after the first), and rounding the vertices into
    // the integration frame moves them by √3·u·R at most: a shell of the
    // surface's area that thick. In integration units.
    IntegralBounds rounding_bounds() const {
        constexpr double u = 0x1p-53;
        const double radius = settings_.size / 2.0 / unit_;
        const std::size_t block_additions = blocks_ > 0 ? blocks_ - 1 : 0;
        // Within a batch: a lane's triangles, then the lanes (lanes.hpp).
        constexpr std::size_t batch_depth = 64;
        static_assert(batch_capacity / width_of<WideLanes> + 4 <= batch_depth,
                      "a batch's additions, per lane and across lanes, are counted");
        const double depth = double(batch_depth + total_.summed_terms + block_additions);
        const double terms = depth * u * total_.extents_squared / 2.0;
        const double shell = std::sqrt(3.0) * u * radius * total_.surface_area;
        return {terms * radius + shell, terms * radius * radius + shell * radius,
                terms * radius * radius * radius + shell * radius * radius};
    }

    const IntegrationSettings& settings_;
    const double unit_;  // a power of two near the mesh size
    BlockSums total_;
    std::size_t blocks_ = 0;
};

// Blocks are run this many at a time, their sums kept on the stack until
// they join the total in order.
constexpr std::size_t blocks_per_round = 32;

}  // namespace

template <class Scalar, class Index>
IntegrationResult integrate_mesh(const MeshView<Scalar, Index>& mesh,
                                 const IntegrationSettings& settings, TaskRunner& runner) {
    const double unit = unit_length_near(settings.size);
    const double inverse_unit = 1.0 / unit;  // a power of two: exact
    const Eigen::Vector3d reference = settings.reference;
    const std::size_t block_count = (mesh.face_count + kFacesPerBlock - 1) / kFacesPerBlock;
    ResultBuilder builder(settings, unit);
    std::size_t block_corner = 0;  // position in the index array of the round's first face
    for (std::size_t round = 0; round < block_count; round += blocks_per_round) {
        const std::size_t blocks = std::min(blocks_per_round, block_count - round);
        BlockSums sums[blocks_per_round];
        std::size_t first_corners[blocks_per_round];
        for (std::size_t block = 0; block < blocks; ++block) {
            first_corners[block] = block_corner;
            const std::size_t begin = (round + block) * kFacesPerBlock;
            const std::size_t end = std::min(begin + kFacesPerBlock, mesh.face_count);
            if (mesh.all_triangles()) {
                block_corner += 3 * (end - begin);
            } else {
                for (std::size_t face = begin; face < end; ++face)
                    block_corner += mesh.face_sizes[face];
            }
        }
        runner.run(blocks, [&](std::size_t block) {
            const std::size_t begin = (round + block) * kFacesPerBlock;
            const std::size_t end = std::min(begin + kFacesPerBlock, mesh.face_count);
            BlockIntegrator<Scalar, Index> integrator(mesh, settings, unit);
            if (mesh.all_triangles()) {
                integrator.add_triangles(begin, end);
                sums[block] = integrator.finish();
                return;
            }
            std::size_t corner = first_corners[block];
            for (std::size_t face = begin; face < end; corner += mesh.face_sizes[face], ++face) {
                const std::size_t size = mesh.face_sizes[face];
                if (size == 3) {
                    integrator.add_triangle(face, corner);
                    continue;
                }
                integrator.add_polygon(face, size, [&](std::size_t i) {
                    const Eigen::Vector3d p = mesh.positions[mesh.indices[corner + i]];
                    return Eigen::Vector3d((p - reference) * inverse_unit);
                });
            }
            sums[block] = integrator.finish();
        });
        for (std::size_t block = 0; block < blocks; ++block) builder.add(sums[block]);
    }
    return builder.finish();
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                   \
    template IntegrationResult integrate_mesh<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const IntegrationSettings&, TaskRunner&);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
