#include "convex_hull.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

#include "exact_predicates.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {
namespace {

constexpr std::uint32_t none = ~std::uint32_t{0};

// True when a, b, c lie on one line: the three coordinate-plane shadows of the
// triangle all have zero area, exactly.
bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    for (int drop = 0; drop < 3; ++drop) {
        const int i = (drop + 1) % 3, j = (drop + 2) % 3;
        if (orient2d({a[i], a[j]}, {b[i], b[j]}, {c[i], c[j]}) != 0) return false;
    }
    return true;
}

// Quickhull (Barber, Dobkin, Huhdanpaa 1996) with every decision an exact
// orientation test: a point is outside a face when it lies strictly on the
// side its normal points to. Floating point only chooses which outside point
// comes next (the farthest, which keeps the hull small on the way); that
// choice does not affect correctness. docs/approximations.md, "The hull".
class HullBuilder {
public:
    HullBuilder(const std::pmr::vector<Eigen::Vector3d>& points, std::pmr::memory_resource* memory)
        : points_(points),
          faces_(memory),
          starting_at_(points.size(), none, memory),
          memory_(memory) {
        // Coordinates near one, for the farthest-point choice only.
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d& p : points_) box.extend(p);
        centre_ = box.center();
        inverse_unit_ = 1.0 / unit_length_near(box.diagonal().cwiseAbs().maxCoeff());
    }

    // Builds the hull; the status says why not when the points span no volume.
    HullStatus build() {
        std::array<std::uint32_t, 4> simplex;
        if (const HullStatus status = initial_simplex(simplex); status != HullStatus::ok)
            return status;
        start_from(simplex);
        while (!pending_.empty()) {
            const std::uint32_t face = pending_.back();
            pending_.pop_back();
            if (faces_[face].alive && !faces_[face].outside.empty() && !add_point_outside(face))
                return HullStatus::beyond_exact_range;
        }
        return HullStatus::ok;
    }

    // Calls emit(a, b, c) for each hull triangle (point indices, outward turn).
    template <class Emit>
    void for_each_triangle(Emit&& emit) const {
        for (const Face& face : faces_)
            if (face.alive) emit(face.vertex[0], face.vertex[1], face.vertex[2]);
    }

private:
    struct Face {
        std::array<std::uint32_t, 3> vertex;
        std::array<std::uint32_t, 3> neighbour;   // across the edge vertex[e] → vertex[e + 1]
        std::pmr::vector<std::uint32_t> outside;  // points strictly above, assigned here
        std::uint64_t visit = 0;
        bool alive = true;

        Face(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::pmr::memory_resource* memory)
            : vertex{a, b, c}, neighbour{none, none, none}, outside(memory) {}
    };

    const Eigen::Vector3d& point(std::uint32_t i) const { return points_[i]; }

    bool above(const Face& face, std::uint32_t p) const {
        return orient3d(point(face.vertex[0]), point(face.vertex[1]), point(face.vertex[2]),
                        point(p)) > 0;
    }

    Eigen::Vector3d local(std::uint32_t i) const { return (point(i) - centre_) * inverse_unit_; }

    // Far-apart points first (a large first simplex swallows most points at
    // once); every degeneracy is then decided exactly over all points.
    HullStatus initial_simplex(std::array<std::uint32_t, 4>& simplex) const {
        const std::uint32_t n = std::uint32_t(points_.size());
        auto farthest = [&](auto&& measure) {
            std::uint32_t best = 0;
            double best_value = -1.0;
            for (std::uint32_t i = 0; i < n; ++i) {
                const double value = measure(local(i));
                if (value > best_value) best = i, best_value = value;
            }
            return best;
        };
        const std::uint32_t a = farthest([](const Eigen::Vector3d& p) { return -p.x(); });
        const Eigen::Vector3d la = local(a);
        const std::uint32_t farthest_from_a =
            farthest([&](const Eigen::Vector3d& p) { return (p - la).squaredNorm(); });
        // The points are distinct: any other one will do if rounding saw none farther.
        const std::uint32_t b = farthest_from_a != a ? farthest_from_a : (a == 0 ? 1 : 0);
        const Eigen::Vector3d lb = local(b);
        std::uint32_t c = farthest(
            [&](const Eigen::Vector3d& p) { return (lb - la).cross(p - la).squaredNorm(); });
        if (collinear(point(a), point(b), point(c))) {
            c = none;
            for (std::uint32_t i = 0; i < n && c == none; ++i)
                if (!collinear(point(a), point(b), point(i))) c = i;
            if (c == none) return HullStatus::collinear;
        }
        const Eigen::Vector3d normal = (lb - la).cross(local(c) - la);
        std::uint32_t d =
            farthest([&](const Eigen::Vector3d& p) { return std::abs(normal.dot(p - la)); });
        if (orient3d(point(a), point(b), point(c), point(d)) == 0) {
            d = none;
            for (std::uint32_t i = 0; i < n && d == none; ++i)
                if (orient3d(point(a), point(b), point(c), point(i)) != 0) d = i;
            if (d == none) return HullStatus::coplanar;
        }
        simplex = {a, b, c, d};
        return HullStatus::ok;
    }

    void start_from(const std::array<std::uint32_t, 4>& s) {
        // d below abc: abc, then the three faces through d, all turning outward.
        std::array<std::uint32_t, 4> v = s;
        if (orient3d(point(v[0]), point(v[1]), point(v[2]), point(v[3])) > 0) std::swap(v[1], v[2]);
        const std::uint32_t a = v[0], b = v[1], c = v[2], d = v[3];
        faces_.emplace_back(a, b, c, memory_);  // 0
        faces_.emplace_back(b, a, d, memory_);  // 1
        faces_.emplace_back(c, b, d, memory_);  // 2
        faces_.emplace_back(a, c, d, memory_);  // 3
        faces_[0].neighbour = {1, 2, 3};
        faces_[1].neighbour = {0, 3, 2};
        faces_[2].neighbour = {0, 1, 3};
        faces_[3].neighbour = {0, 2, 1};
        for (std::uint32_t i = 0; i < points_.size(); ++i) {
            if (i == a || i == b || i == c || i == d) continue;
            for (std::uint32_t f = 0; f < 4; ++f) {
                if (above(faces_[f], i)) {
                    faces_[f].outside.push_back(i);
                    break;
                }
            }
        }
        for (std::uint32_t f = 0; f < 4; ++f) pending_.push_back(f);
    }

    // Adds the outside point of `face` farthest from its plane: removes every
    // face it lies strictly above (a disc bounded by the horizon), joins it to
    // the horizon's edges, and hands the removed faces' outside points to the
    // new faces (a point above none of them is inside the new hull). False
    // when the horizon is not one loop, which exact signs never give: only
    // coordinates beyond the tests' exact range (nonzero ones more than 2^640
    // apart, exact_predicates.hpp), where signs can disagree. Signs beyond it
    // are still right unless a determinant vanishes at the level of the bits
    // lost, so such clouds are hulled, and refused only when they tear.
    bool add_point_outside(std::uint32_t face) {
        const std::uint32_t apex = farthest_outside(faces_[face]);
        ++visit_;
        visible_.clear();
        horizon_.clear();
        faces_[face].visit = visit_;
        visible_.push_back(face);
        for (std::size_t k = 0; k < visible_.size(); ++k) {
            const std::uint32_t f = visible_[k];
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t next = faces_[f].neighbour[e];
                if (faces_[next].visit == visit_) continue;
                if (above(faces_[next], apex)) {
                    faces_[next].visit = visit_;
                    visible_.push_back(next);
                } else {
                    horizon_.push_back({f, e});
                }
            }
        }
        // Each horizon edge a → b (as the visible face had it) gets the face
        // (a, b, apex), which keeps the outward turn.
        const std::uint32_t first_new = std::uint32_t(faces_.size());
        for (const auto& [f, e] : horizon_) {
            const std::uint32_t a = faces_[f].vertex[e], b = faces_[f].vertex[(e + 1) % 3];
            const std::uint32_t across = faces_[f].neighbour[e];
            const std::uint32_t created = std::uint32_t(faces_.size());
            faces_.emplace_back(a, b, apex, memory_);
            faces_.back().neighbour[0] = across;
            Face& other = faces_[across];
            for (int k = 0; k < 3; ++k)
                if (other.neighbour[k] == f) other.neighbour[k] = created;
            if (starting_at_[a] != none) return false;  // the loop passes a twice
            starting_at_[a] = created;
        }
        // The horizon is one loop: the face from b is the one across b → apex.
        for (std::uint32_t created = first_new; created < faces_.size(); ++created) {
            const std::uint32_t next = starting_at_[faces_[created].vertex[1]];
            if (next == none) return false;  // the loop breaks at b
            faces_[created].neighbour[1] = next;
            faces_[next].neighbour[2] = created;
        }
        for (std::uint32_t created = first_new; created < faces_.size(); ++created)
            starting_at_[faces_[created].vertex[0]] = none;

        for (const std::uint32_t f : visible_) {
            Face& gone = faces_[f];
            gone.alive = false;
            for (const std::uint32_t p : gone.outside) {
                if (p == apex) continue;
                for (std::uint32_t created = first_new; created < faces_.size(); ++created) {
                    if (above(faces_[created], p)) {
                        faces_[created].outside.push_back(p);
                        break;
                    }
                }
            }
            gone.outside.clear();
            gone.outside.shrink_to_fit();
        }
        for (std::uint32_t created = first_new; created < faces_.size(); ++created)
            if (!faces_[created].outside.empty()) pending_.push_back(created);
        return true;
    }

    std::uint32_t farthest_outside(const Face& face) const {
        const Eigen::Vector3d p0 = local(face.vertex[0]);
        const Eigen::Vector3d normal =
            (local(face.vertex[1]) - p0).cross(local(face.vertex[2]) - p0);
        std::uint32_t best = face.outside.front();
        double best_height = -1.0;
        for (const std::uint32_t p : face.outside) {
            const double height = normal.dot(local(p) - p0);
            if (height > best_height) best = p, best_height = height;
        }
        return best;
    }

    const std::pmr::vector<Eigen::Vector3d>& points_;
    std::pmr::vector<Face> faces_;
    std::pmr::vector<std::uint32_t>
        starting_at_;  // per point: the new face whose edge starts there
    std::pmr::memory_resource* memory_;
    std::vector<std::uint32_t> pending_, visible_;
    std::vector<std::pair<std::uint32_t, int>> horizon_;  // (visible face, edge)
    std::uint64_t visit_ = 0;
    Eigen::Vector3d centre_;
    double inverse_unit_ = 1.0;
};

}  // namespace

MeshView<double, std::uint32_t> ConvexHull::view() const {
    MeshView<double, std::uint32_t> mesh;
    mesh.positions.base = reinterpret_cast<const unsigned char*>(coordinates.data());
    mesh.positions.stride = 3 * sizeof(double);
    mesh.vertex_count = coordinates.size() / 3;
    mesh.indices.base = reinterpret_cast<const unsigned char*>(indices.data());
    mesh.index_count = indices.size();
    mesh.face_count = indices.size() / 3;
    return mesh;
}

template <class Scalar, class Index>
ConvexHull convex_hull(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                       std::pmr::memory_resource* memory) {
    ConvexHull hull(memory);
    if (scan.non_finite.count > 0) {
        hull.status = HullStatus::non_finite;
        return hull;
    }
    // The used vertices, each distinct position once (the lowest vertex index).
    std::pmr::vector<std::uint32_t> order(memory);
    order.reserve(scan.used_vertex_count);
    for (std::size_t vertex = 0; vertex < scan.used.size() * 64; ++vertex)
        if (scan.is_used(vertex)) order.push_back(std::uint32_t(vertex));
    std::pmr::vector<Eigen::Vector3d> positions(memory);
    positions.reserve(order.size());
    for (const std::uint32_t vertex : order) positions.push_back(mesh.positions[vertex]);
    std::pmr::vector<std::uint32_t> sorted(order.size(), 0, memory);
    std::iota(sorted.begin(), sorted.end(), 0u);
    auto less = [&](std::uint32_t i, std::uint32_t j) {
        const Eigen::Vector3d &p = positions[i], &q = positions[j];
        return std::tie(p.x(), p.y(), p.z(), i) < std::tie(q.x(), q.y(), q.z(), j);
    };
    std::sort(sorted.begin(), sorted.end(), less);
    std::pmr::vector<Eigen::Vector3d> points(memory);
    std::pmr::vector<std::uint32_t> source(memory);
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        const std::uint32_t i = sorted[k];
        if (k > 0 && positions[i] == positions[sorted[k - 1]]) continue;
        points.push_back(positions[i]);
        source.push_back(order[i]);
    }
    hull.distinct_points = points.size();
    if (points.size() < 4) {
        hull.status = HullStatus::too_few_points;
        return hull;
    }

    HullBuilder builder(points, memory);
    hull.status = builder.build();
    if (hull.status != HullStatus::ok) return hull;
    // Only the points the hull's triangles use, numbered in order of use.
    std::pmr::vector<std::uint32_t> renumbered(points.size(), none, memory);
    builder.for_each_triangle([&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        for (const std::uint32_t p : {a, b, c}) {
            if (renumbered[p] == none) {
                renumbered[p] = std::uint32_t(hull.source_vertex.size());
                hull.source_vertex.push_back(source[p]);
                hull.coordinates.insert(hull.coordinates.end(), points[p].data(),
                                        points[p].data() + 3);
            }
            hull.indices.push_back(renumbered[p]);
        }
    });
    return hull;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                        \
    template ConvexHull convex_hull<Scalar, Index>(const MeshView<Scalar, Index>&, \
                                                   const MeshScan&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
