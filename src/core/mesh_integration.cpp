#include "mesh_integration.hpp"

#include "polygon_integrals.hpp"
#include "triangle_integrals.hpp"

namespace polymass::core {
namespace {

// Faces are summed in blocks, and blocks into the total, so that rounding
// grows with the number of blocks rather than the number of faces.
constexpr std::size_t block_size = 1024;

struct BlockSums {
    FaceSums unscaled_triangles;  // see add_unscaled_triangle_sums
    FaceSums polygons;
    double surface_area = 0.0;
};

struct Integrator {
    const IntegrationSettings& settings;
    IntegrationResult result;
    FaceSums total;
    BlockSums block;

    void flush_block() {
        total += scaled_triangle_sums(block.unscaled_triangles);
        total += block.polygons;
        result.surface_area += block.surface_area;
        block = BlockSums{};
    }

    void add_triangle(std::size_t face, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                      const Eigen::Vector3d& p2) {
        const Eigen::Vector3d delta = add_unscaled_triangle_sums(block.unscaled_triangles, p0, p1, p2);
        const double twice_area = delta.norm();
        block.surface_area += twice_area / 2.0;
        const double extent_squared = std::max((p1 - p0).squaredNorm(), (p2 - p0).squaredNorm());
        if (is_degenerate_face(twice_area, extent_squared)) result.degenerate_faces.record(face);
    }

    template <class VertexAt>
    void add_polygon(std::size_t face, std::size_t count, VertexAt&& vertex_at) {
        const FacePlane plane = face_plane(count, vertex_at);
        if (plane.degenerate) {
            result.degenerate_faces.record(face);
            return;
        }
        if (settings.check_planarity) {
            const double relative = plane_deviation(plane, count, vertex_at) / (2.0 * plane.extent);
            result.max_non_planarity = std::max(result.max_non_planarity, relative);
            if (relative > settings.planarity_tolerance) result.non_planar_faces.record(face);
        }
        block.polygons += polygon_face_sums(plane, count, vertex_at);
        block.surface_area += plane.area;
    }
};

}  // namespace

template <class Scalar, class Index>
IntegrationResult integrate_mesh(const MeshView<Scalar, Index>& mesh,
                                 const IntegrationSettings& settings) {
    Integrator integrator{settings, {}, {}, {}};
    const Eigen::Vector3d reference = settings.reference;
    auto vertex = [&](std::size_t position) {
        return Eigen::Vector3d(mesh.positions[mesh.indices[position]] - reference);
    };
    for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
        if (size == 3)
            integrator.add_triangle(face, vertex(first), vertex(first + 1), vertex(first + 2));
        else
            integrator.add_polygon(face, size, [&](std::size_t i) { return vertex(first + i); });
        if ((face + 1) % block_size == 0) integrator.flush_block();
    });
    integrator.flush_block();
    integrator.result.integrals = volume_integrals_from(integrator.total);
    return integrator.result;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                     \
    template IntegrationResult integrate_mesh<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const IntegrationSettings&);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
