#include "mesh_integration.hpp"

#include <algorithm>
#include <cmath>

#include "lanes.hpp"
#include "polygon_integrals.hpp"
#include "triangle_integrals.hpp"

namespace polymass::core {
namespace {

// Triangles wait here, as the caller's coordinates laid out axis by vertex by
// slot, until lane_count of them can go through the closed forms at once; the
// move into the integration frame happens there too, a lane group at a time.
// A batch is also a block of the summation: its sums are reduced before they
// join the total, so rounding grows with the number of batches rather than of
// triangles.
struct TriangleBatch {
    static constexpr std::size_t capacity = 64;
    // pad() fills up to the next multiple of lane_count: it must stay inside.
    static_assert(capacity % lane_count == 0, "a batch holds whole groups of lanes");
    alignas(64) double coordinates[3][3][capacity];
    std::size_t faces[capacity];
    std::size_t size = 0;
    // Integration coordinates are (coordinate − reference) · inverse_unit.
    double reference[3];
    double inverse_unit;

    TriangleBatch(const Eigen::Vector3d& reference_point, double unit)
        : reference{reference_point.x(), reference_point.y(), reference_point.z()},
          inverse_unit(1.0 / unit) {}  // a power of two: exact

    // Fills a slot; the caller counts it in size.
    void put(std::size_t slot, std::size_t face, const Eigen::Vector3d& p0,
             const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
        auto put = [&](int vertex, const Eigen::Vector3d& p) {
            coordinates[0][vertex][slot] = p.x();
            coordinates[1][vertex][slot] = p.y();
            coordinates[2][vertex][slot] = p.z();
        };
        put(0, p0), put(1, p1), put(2, p2);
        faces[slot] = face;
    }

    // Empty slots of the last lane group become triangles with all three
    // vertices at the reference point: zero triangles, which add nothing.
    void pad() {
        const std::size_t end = (size + lane_count - 1) / lane_count * lane_count;
        for (int axis = 0; axis < 3; ++axis)
            for (auto& vertex : coordinates[axis])
                std::fill(vertex + size, vertex + end, reference[axis]);
    }
};

struct BatchResult {
    FaceSums sums;
    double surface_area = 0.0;
    // Σ max(|E1|², |E2|²) ≥ Σ |E1||E2|: what scales each triangle's rounding
    // (docs/error_bound.md).
    double extents_squared = 0.0;
    Finding degenerate_faces;
};

// Built for baseline x86-64 and for x86-64-v3 (AVX2, FMA); the loader picks
// the best one the processor runs.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void integrate_triangle_batch(
    const TriangleBatch& batch, BatchResult& result) {
    UnscaledTriangleSums<Lanes> sums;
    Lanes twice_areas{}, extents{};
    for (std::size_t first = 0; first < batch.size; first += lane_count) {
        Lanes p[3][3];
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) {
#pragma GCC unroll 3
            for (int vertex = 0; vertex < 3; ++vertex) {
                Lanes coordinate;
                load_lanes(coordinate, &batch.coordinates[axis][vertex][first]);
                p[axis][vertex] = (coordinate - batch.reference[axis]) * batch.inverse_unit;
            }
        }
        const TriangleEdges<Lanes> edges(p);
        add_unscaled_triangle_sums(sums, p, edges.delta);  // padding lanes add zero

        Lanes squared_norm{}, e1_squared{}, e2_squared{};
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) {
            squared_norm += edges.delta[axis] * edges.delta[axis];
            e1_squared += edges.e1[axis] * edges.e1[axis];
            e2_squared += edges.e2[axis] * edges.e2[axis];
        }
        Lanes twice_area;
        for (int lane = 0; lane < lane_count; ++lane)
            twice_area[lane] = std::sqrt(squared_norm[lane]);
        // Below 2^-1022 squares lose digits (down to none: a well-shaped
        // triangle 1e-150 of the mesh's size squares to zero); above 2^-960
        // what they lose is under 2^-115 of the sum. So a small δ (coordinates
        // are of order one here) is measured without squaring instead, rarely.
        constexpr double squares_keep_digits = 0x1p-960;
        const LaneMask sliver = squared_norm < squares_keep_digits;
        if (any_lane(sliver)) {
            for (int lane = 0; lane < lane_count; ++lane)
                if (sliver[lane])
                    twice_area[lane] = std::hypot(edges.delta[0][lane], edges.delta[1][lane],
                                                  edges.delta[2][lane]);
        }
        twice_areas += twice_area;

        // A degenerate triangle is reported; its terms, at rounding level, stay:
        // they are what keeps a closed surface's sum balanced.
        const Lanes extent_squared = e1_squared > e2_squared ? e1_squared : e2_squared;
        extents += extent_squared;  // padding lanes add zero
        const LaneMask degenerate = twice_area <= degenerate_area_ratio * extent_squared;
        if (any_lane(degenerate)) {
            const std::size_t used = std::min<std::size_t>(lane_count, batch.size - first);
            for (std::size_t lane = 0; lane < used; ++lane)
                if (degenerate[lane]) result.degenerate_faces.record(batch.faces[first + lane]);
        }
    }
    result.surface_area += sum_lanes(twice_areas) / 2.0;
    result.extents_squared += sum_lanes(extents);
    UnscaledTriangleSums<double> reduced;
    reduced.x = sum_lanes(sums.x);
    for (int axis = 0; axis < 3; ++axis) {
        reduced.squares[axis] = sum_lanes(sums.squares[axis]);
        reduced.cubes[axis] = sum_lanes(sums.cubes[axis]);
        reduced.mixed[axis] = sum_lanes(sums.mixed[axis]);
    }
    result.sums += scaled(reduced);
}

class Integrator {
public:
    explicit Integrator(const IntegrationSettings& settings)
        : settings_(settings),
          unit_(unit_length_near(settings.size)),
          batch_(settings.reference, unit_) {}

    // Coordinates relative to the reference point are divided by this.
    double unit() const { return unit_; }

    // Vertices in the caller's coordinates.
    void add_triangle(std::size_t face, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                      const Eigen::Vector3d& p2) {
        batch_.put(batch_.size++, face, p0, p1, p2);
        if (batch_.size == TriangleBatch::capacity) flush_triangles();
    }

    // Faces [begin, end), all triangles, with corner(face, i) their vertices in
    // the caller's coordinates. Counting slots in a local, not in the batch,
    // keeps the count in a register across the batch's stores.
    template <class Corner>
    void add_triangles(std::size_t begin, std::size_t end, Corner&& corner) {
        for (std::size_t face = begin; face < end;) {
            const std::size_t first_slot = batch_.size;
            const std::size_t slots = std::min(TriangleBatch::capacity - first_slot, end - face);
            for (std::size_t slot = first_slot; slot < first_slot + slots; ++slot, ++face)
                batch_.put(slot, face, corner(face, 0), corner(face, 1), corner(face, 2));
            batch_.size = first_slot + slots;
            if (batch_.size == TriangleBatch::capacity) flush_triangles();
        }
    }

    // vertex_at(i): the i-th vertex relative to the reference point, in units.
    template <class VertexAt>
    void add_polygon(std::size_t face, std::size_t count, VertexAt&& vertex_at) {
        const FacePlane plane = face_plane(count, vertex_at);
        result_.surface_area += plane.area;
        // Each triangle of a fan has |E1||E2| ≤ (2 extent)²; the projection
        // and lift add operations, hence the extra factor (docs/error_bound.md).
        extents_squared_ += 8.0 * double(count) * 4.0 * plane.extent * plane.extent;
        ++summed_terms_;
        if (plane.degenerate) {
            // No normal to project along; its terms would be at rounding level.
            result_.degenerate_faces.record(face);
            return;
        }
        if (settings_.check_planarity) {
            const double relative = plane_deviation(plane, count, vertex_at) / (2.0 * plane.extent);
            result_.max_non_planarity = std::max(result_.max_non_planarity, relative);
            if (relative > settings_.planarity_tolerance) result_.non_planar_faces.record(face);
        }
        total_ += polygon_face_sums(plane, count, vertex_at);
    }

    IntegrationResult finish() {
        flush_triangles();
        const double unit = unit_;
        const VolumeIntegrals in_units = volume_integrals_from(total_);
        constexpr double slack = 1024.0 * 2.220446049250313e-16;
        result_.encloses_no_volume =
            std::abs(in_units.volume) <= slack * result_.surface_area * (settings_.size / unit);
        result_.integrals = in_units.scaled(unit);
        result_.bounds = rounding_bounds().scaled(unit);
        result_.surface_area = times_unit_power(result_.surface_area, unit, 2);
        return result_;
    }

private:
    // docs/error_bound.md: each face's terms carry a relative error of a few
    // dozen roundings of (|δ|/2)·R^k, the sum one rounding per term it adds up
    // (blocks of a batch, then batches and polygons one by one), and rounding
    // the vertices into the integration frame moves them by √3·u·R at most: a
    // shell of the surface's area that thick. In integration units.
    IntegralBounds rounding_bounds() const {
        constexpr double u = 0x1p-53;
        const double radius = settings_.size / 2.0 / unit_;
        const double depth = 64.0 + double(summed_terms_);
        const double terms = depth * u * extents_squared_ / 2.0;
        const double shell = std::sqrt(3.0) * u * radius * result_.surface_area;
        return {terms * radius + shell, terms * radius * radius + shell * radius,
                terms * radius * radius * radius + shell * radius * radius};
    }

    void flush_triangles() {
        batch_.pad();
        BatchResult batch_result;
        integrate_triangle_batch(batch_, batch_result);
        total_ += batch_result.sums;
        result_.surface_area += batch_result.surface_area;
        extents_squared_ += batch_result.extents_squared;
        ++summed_terms_;
        result_.degenerate_faces.merge(batch_result.degenerate_faces);
        batch_.size = 0;
    }

    const IntegrationSettings& settings_;
    const double unit_;  // a power of two near the mesh size
    TriangleBatch batch_;
    FaceSums total_;
    IntegrationResult result_;
    double extents_squared_ = 0.0;  // Σ over faces, in units²
    std::size_t summed_terms_ = 0;  // batches and polygons added to total_
};

}  // namespace

template <class Scalar, class Index>
IntegrationResult integrate_mesh(const MeshView<Scalar, Index>& mesh,
                                 const IntegrationSettings& settings) {
    Integrator integrator(settings);
    const Eigen::Vector3d reference = settings.reference;
    const double inverse_unit = 1.0 / integrator.unit();  // a power of two: exact
    // Copies: the batch's stores cannot then alias them, and they stay in registers.
    const auto positions = mesh.positions;
    const auto indices = mesh.indices;
    auto vertex = [positions, indices](std::size_t position) {
        return positions[indices[position]];
    };
    if (mesh.all_triangles()) {
        integrator.add_triangles(0, mesh.face_count, [&](std::size_t face, int corner) {
            return vertex(3 * face + corner);
        });
        return integrator.finish();
    }
    for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
        if (size == 3) {
            integrator.add_triangle(face, vertex(first), vertex(first + 1), vertex(first + 2));
            return;
        }
        integrator.add_polygon(face, size, [&](std::size_t i) {
            return Eigen::Vector3d((vertex(first + i) - reference) * inverse_unit);
        });
    });
    return integrator.finish();
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                  \
    template IntegrationResult integrate_mesh<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                                             const IntegrationSettings&);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
