#include "surface_triangles.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "exact_predicates.hpp"

namespace polymass::core {
namespace {

// Cuts one simple polygon into triangles by ear clipping. The polygon is seen
// in the coordinate plane where its (Newell) normal's largest component is
// dropped; `turn` is the sign of that component, so that a polygon
// counter-clockwise seen from outside turns `turn` in the projection.
class EarClipper {
public:
    explicit EarClipper(std::pmr::memory_resource* memory)
        : points_(memory), next_(memory), prev_(memory) {}

    template <class Corner, class Emit>
    void clip(std::size_t count, Corner&& corner, Emit&& emit) {
        // Newell's normal, about the first corner so that a face far from the
        // origin keeps its digits.
        const Eigen::Vector3d origin = corner(0);
        Eigen::Vector3d normal = Eigen::Vector3d::Zero();
        for (std::size_t i = 1; i + 1 < count; ++i)
            normal += (corner(i) - origin).cross(corner(i + 1) - origin);
        int drop = 0;
        normal.cwiseAbs().maxCoeff(&drop);
        const int turn = normal[drop] < 0 ? -1 : 1;
        const int u = (drop + 1) % 3, v = (drop + 2) % 3;
        points_.resize(count);
        next_.resize(count);
        prev_.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const Eigen::Vector3d p = corner(i);
            points_[i] = {p[u], p[v]};
            next_[i] = (i + 1) % count;
            prev_[i] = (i + count - 1) % count;
        }
        std::size_t left = count, at = 0, misses = 0;
        while (left > 3) {
            if (is_ear(at, left, turn)) {
                emit(prev_[at], at, next_[at]);
                next_[prev_[at]] = next_[at];
                prev_[next_[at]] = prev_[at];
                at = prev_[at];
                --left;
                misses = 0;
            } else if (++misses > left) {
                break;  // no ear: not a simple polygon in this projection
            } else {
                at = next_[at];
            }
        }
        // Three corners left, or a polygon with no ear (self-overlapping, or
        // its last corners collinear): a fan over what is left.
        const std::size_t first = at;
        for (std::size_t b = next_[first]; next_[b] != first; b = next_[b])
            emit(first, b, next_[b]);
    }

private:
    bool is_ear(std::size_t at, std::size_t left, int turn) const {
        const std::size_t a = prev_[at], b = next_[at];
        if (orient2d(points_[a], points_[at], points_[b]) != turn) return false;  // reflex or flat
        for (std::size_t i = next_[b], k = 3; k < left; i = next_[i], ++k) {
            const Eigen::Vector2d& p = points_[i];
            if (p == points_[a] || p == points_[at] || p == points_[b]) continue;
            if (orient2d(points_[a], points_[at], p) * turn >= 0 &&
                orient2d(points_[at], points_[b], p) * turn >= 0 &&
                orient2d(points_[b], points_[a], p) * turn >= 0)
                return false;
        }
        return true;
    }

    std::pmr::vector<Eigen::Vector2d> points_;
    std::pmr::vector<std::size_t> next_, prev_;
};

}  // namespace

template <class Scalar, class Index>
SurfaceTriangles triangulate_faces(const MeshView<Scalar, Index>& mesh,
                                   std::pmr::memory_resource* memory) {
    SurfaceTriangles triangles(memory);
    const std::size_t expected = mesh.index_count >= 2 * mesh.face_count
                                     ? mesh.index_count - 2 * mesh.face_count
                                     : mesh.face_count;
    triangles.corners.reserve(3 * expected);
    triangles.face.reserve(expected);
    EarClipper clipper(memory);
    for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
        auto emit = [&](std::size_t a, std::size_t b, std::size_t c) {
            for (const std::size_t corner : {a, b, c})
                triangles.corners.push_back(mesh.indices[first + corner]);
            triangles.face.push_back(std::uint32_t(face));
        };
        if (size == 3) {
            emit(0, 1, 2);
            return;
        }
        clipper.clip(
            size, [&](std::size_t i) { return mesh.positions[mesh.indices[first + i]]; }, emit);
    });
    return triangles;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                    \
    template SurfaceTriangles triangulate_faces<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                                               std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
