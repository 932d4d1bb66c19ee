#include "mesh_repair.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "repair_surface.hpp"
#include "welding.hpp"

namespace polymass::core {
namespace {

// The corners of a face after welding, a vertex repeated in a row (or the
// last as the first) kept once.
template <class View>
void welded_corners(const View& mesh, const std::pmr::vector<std::uint32_t>& ids, std::size_t first,
                    std::size_t size, std::pmr::vector<std::uint32_t>& out) {
    out.clear();
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t id = ids[mesh.indices[first + i]];
        if (out.empty() || out.back() != id) out.push_back(id);
    }
    while (out.size() > 1 && out.back() == out.front()) out.pop_back();
}

// A polygon's fan from its first corner, with the region between it and any
// other triangulation when the polygon is not planar (docs/repair.md): for a
// quadrilateral the tetrahedron between its two diagonal splits; otherwise
// the slab of its vertices' largest distance h from their mean plane, over
// the fan's area, 2 h A.
void triangulate(RepairSurface& surface, const std::pmr::vector<std::uint32_t>& corners,
                 std::uint32_t face, double planarity_tolerance, RepairReport& report,
                 std::pmr::vector<UncertainRegion>& uncertain) {
    const std::size_t n = corners.size();
    const Eigen::Vector3d& origin = surface.point(corners[0]);
    if (n > 3) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (std::uint32_t id : corners) centroid += surface.point(id) - origin;
        centroid = origin + centroid / double(n);
        Eigen::Vector3d newell = Eigen::Vector3d::Zero();
        double radius = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const Eigen::Vector3d p = surface.point(corners[i]) - centroid;
            newell += p.cross(surface.point(corners[(i + 1) % n]) - centroid);
            radius = std::max(radius, p.norm());
        }
        double off_plane = 0.0;
        if (newell.norm() > 0.0)
            for (std::uint32_t id : corners)
                off_plane = std::max(
                    off_plane, std::abs((surface.point(id) - centroid).dot(newell.normalized())));
        if (off_plane > planarity_tolerance * 2.0 * radius) {
            report.triangulated_faces.record(face);
            double volume = 0.0;
            if (n == 4) {
                const Eigen::Vector3d& p0 = surface.point(corners[0]);
                volume = std::abs((surface.point(corners[1]) - p0)
                                      .dot((surface.point(corners[2]) - p0)
                                               .cross(surface.point(corners[3]) - p0))) /
                         6.0;
            } else {
                double area = 0.0;
                for (std::size_t i = 1; i + 1 < n; ++i)
                    area += 0.5 * (surface.point(corners[i]) - origin)
                                      .cross(surface.point(corners[i + 1]) - origin)
                                      .norm();
                volume = 2.0 * off_plane * area;
            }
            uncertain.push_back({volume, centroid, radius});
        }
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const RepairTriangle triangle{{corners[0], corners[i], corners[i + 1]}, face};
        if (triangle.corners[1] != triangle.corners[0] &&
            triangle.corners[2] != triangle.corners[0] &&
            triangle.corners[1] != triangle.corners[2])
            surface.triangles.push_back(triangle);
    }
}

// The welded faces of three or more distinct corners, before triangulation.
struct Polygons {
    std::pmr::vector<std::uint32_t> corners;  // every face's, one after another
    std::pmr::vector<std::size_t> start;      // of face i's corners; one past the last at the end
    std::pmr::vector<std::uint32_t> face;     // the input face

    explicit Polygons(std::pmr::memory_resource* memory)
        : corners(memory), start(1, 0, memory), face(memory) {}
    std::size_t count() const { return face.size(); }
    std::size_t size(std::size_t i) const { return start[i + 1] - start[i]; }
    // Corner k (cyclically) of polygon i read from its smallest corner,
    // forward or backward.
    std::uint32_t canonical(std::size_t i, std::size_t k, std::size_t lowest, bool backward) const {
        const std::size_t n = size(i);
        return corners[start[i] + (backward ? lowest + n - k : lowest + k) % n];
    }
};

// Keeps one face of each set of copies (the same corners in the same cyclic
// order); a face and its reverse cancel (their integrals are opposite), so
// both go. With more of one sense than of the other, one of the majority
// stays. Returns which polygons stay.
std::pmr::vector<char> drop_duplicates(const Polygons& polygons, RepairReport& report,
                                       std::pmr::memory_resource* memory) {
    const std::size_t count = polygons.count();
    // Each polygon read from its smallest corner, towards the smaller neighbour.
    std::pmr::vector<std::size_t> lowest(count, memory);
    std::pmr::vector<char> backward(count, memory);
    for (std::size_t i = 0; i < count; ++i) {
        const auto first = polygons.corners.begin() + std::ptrdiff_t(polygons.start[i]);
        const std::size_t n = polygons.size(i);
        lowest[i] = std::size_t(std::min_element(first, first + std::ptrdiff_t(n)) - first);
        backward[i] =
            polygons.canonical(i, 1, lowest[i], false) > polygons.canonical(i, 1, lowest[i], true);
    }
    auto same_corners = [&](std::size_t a, std::size_t b) {
        if (polygons.size(a) != polygons.size(b)) return false;
        for (std::size_t k = 0; k < polygons.size(a); ++k)
            if (polygons.canonical(a, k, lowest[a], backward[a]) !=
                polygons.canonical(b, k, lowest[b], backward[b]))
                return false;
        return true;
    };
    auto before = [&](std::size_t a, std::size_t b) {
        if (polygons.size(a) != polygons.size(b)) return polygons.size(a) < polygons.size(b);
        for (std::size_t k = 0; k < polygons.size(a); ++k) {
            const std::uint32_t x = polygons.canonical(a, k, lowest[a], backward[a]);
            const std::uint32_t y = polygons.canonical(b, k, lowest[b], backward[b]);
            if (x != y) return x < y;
        }
        return std::make_pair(backward[a], a) < std::make_pair(backward[b], b);
    };
    std::pmr::vector<std::size_t> order(count, memory);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), before);
    std::pmr::vector<char> keep(count, 1, memory);
    std::pmr::vector<std::uint32_t> dropped(memory);
    for (std::size_t begin = 0; begin < count;) {
        std::size_t end = begin + 1, reversed = backward[order[begin]];
        for (; end < count && same_corners(order[begin], order[end]); ++end)
            reversed += backward[order[end]];
        const std::size_t forward = end - begin - reversed;
        if (end - begin > 1) {
            // The group is sorted forward first: keep the first of the majority, if any.
            const std::size_t kept = forward > reversed   ? begin
                                     : reversed > forward ? begin + forward
                                                          : end;
            for (std::size_t i = begin; i < end; ++i) {
                if (i == kept) continue;
                keep[order[i]] = 0;
                dropped.push_back(polygons.face[order[i]]);
            }
        }
        begin = end;
    }
    record_faces(dropped, report.duplicate_faces);
    return keep;
}

struct EdgeUse {
    std::uint64_t key;  // (low id << 32) | high id
    std::uint32_t triangle;
    bool forward;  // traversed from the low id to the high one
};

// The triangles around a non-manifold edge in the order they turn about it,
// paired neighbour with neighbour so that each pair traverses it both ways.
// False when no such pairing exists.
bool pair_around_edge(const RepairSurface& surface, const EdgeUse* uses, std::size_t count,
                      std::pmr::vector<EdgeLink>& links, std::pmr::memory_resource* memory) {
    const std::uint32_t low = std::uint32_t(uses[0].key >> 32);
    const std::uint32_t high = std::uint32_t(uses[0].key);
    const Eigen::Vector3d& a = surface.point(low);
    const Eigen::Vector3d axis = (surface.point(high) - a).normalized();
    Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
    std::pmr::vector<std::pair<double, std::size_t>> around(memory);
    for (std::size_t i = 0; i < count; ++i) {
        const RepairTriangle& t = surface.triangles[uses[i].triangle];
        std::uint32_t third = t.corners[0];
        for (std::uint32_t id : t.corners)
            if (id != low && id != high) third = id;
        const Eigen::Vector3d w = surface.point(third) - a;
        around.emplace_back(std::atan2(w.dot(v), w.dot(u)), i);
    }
    std::sort(around.begin(), around.end());
    for (std::size_t start = 0; start < 2; ++start) {
        bool alternates = true;
        for (std::size_t k = 0; k < count && alternates; k += 2)
            alternates = uses[around[(start + k) % count].second].forward !=
                         uses[around[(start + k + 1) % count].second].forward;
        if (!alternates) continue;
        for (std::size_t k = 0; k < count; k += 2)
            links.push_back({uses[around[(start + k) % count].second].triangle,
                             uses[around[(start + k + 1) % count].second].triangle, false});
        return true;
    }
    return false;
}

// Links the triangles across their shared edges and lists the rim; false,
// with the report's failure, on an edge that cannot be split into pairs.
bool link_edges(const RepairSurface& surface, std::pmr::vector<EdgeLink>& links,
                std::pmr::vector<RimEdge>& rim, RepairReport& report,
                std::pmr::memory_resource* memory) {
    std::pmr::vector<EdgeUse> uses(memory);
    uses.reserve(3 * surface.triangles.size());
    for (std::uint32_t t = 0; t < surface.triangles.size(); ++t) {
        const auto& c = surface.triangles[t].corners;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = c[k], to = c[(k + 1) % 3];
            const std::uint64_t key =
                (std::uint64_t(std::min(from, to)) << 32) | std::max(from, to);
            uses.push_back({key, t, from < to});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.key, x.triangle) < std::tie(y.key, y.triangle);
    });
    for (std::size_t begin = 0; begin < uses.size();) {
        std::size_t end = begin + 1;
        while (end < uses.size() && uses[end].key == uses[begin].key) ++end;
        const std::size_t count = end - begin;
        const std::uint32_t low = std::uint32_t(uses[begin].key >> 32);
        const std::uint32_t high = std::uint32_t(uses[begin].key);
        if (count == 1) {
            rim.push_back({uses[begin].triangle, low, high});
        } else if (count == 2) {
            links.push_back({uses[begin].triangle, uses[begin + 1].triangle,
                             uses[begin].forward == uses[begin + 1].forward});
        } else {
            std::size_t forward = 0;
            for (std::size_t i = begin; i < end; ++i) forward += uses[i].forward;
            if (2 * forward != count ||
                !pair_around_edge(surface, &uses[begin], count, links, memory)) {
                report.failure = RepairFailure::unbalanced_non_manifold;
                report.failed_edge = {low, high};
                report.failed_forward = forward;
                report.failed_backward = count - forward;
                return false;
            }
            report.split_edges.record(low, high, count);
        }
        begin = end;
    }
    return true;
}

}  // namespace

template <class Scalar, class Index>
RepairedMesh repair_mesh(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                         const RepairSettings& settings, std::pmr::memory_resource* memory) {
    RepairedMesh repaired(memory);
    RepairReport& report = repaired.report;
    SerialTaskRunner one_thread;  // the repair runs on the caller's thread
    const std::pmr::vector<std::uint32_t> ids =
        weld_vertices(mesh, scan, settings.weld_tolerance, one_thread, memory);

    RepairSurface surface(memory);
    surface.reference = scan.reference_point();
    surface.points.resize(ids.size());
    for (std::size_t vertex = 0; vertex < ids.size(); ++vertex)
        if (scan.is_used(vertex)) surface.points[vertex] = mesh.positions[vertex];
    Polygons polygons(memory);
    std::pmr::vector<std::uint32_t> corners(memory);
    for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
        welded_corners(mesh, ids, first, size, corners);
        if (corners.size() < 3) {
            report.degenerate_faces.record(face);
            return;
        }
        polygons.corners.insert(polygons.corners.end(), corners.begin(), corners.end());
        polygons.start.push_back(polygons.corners.size());
        polygons.face.push_back(std::uint32_t(face));
    });
    const std::pmr::vector<char> keep = drop_duplicates(polygons, report, memory);
    for (std::size_t i = 0; i < polygons.count(); ++i) {
        if (!keep[i]) continue;
        corners.assign(polygons.corners.begin() + std::ptrdiff_t(polygons.start[i]),
                       polygons.corners.begin() + std::ptrdiff_t(polygons.start[i + 1]));
        triangulate(surface, corners, polygons.face[i], settings.planarity_tolerance, report,
                    repaired.uncertain);
    }
    if (surface.triangles.empty()) {
        report.failure = RepairFailure::nothing_left;
        return repaired;
    }

    std::pmr::vector<EdgeLink> links(memory);
    std::pmr::vector<RimEdge> rim(memory);
    if (!link_edges(surface, links, rim, report, memory)) return repaired;
    std::pmr::vector<std::uint32_t> component(memory);
    std::size_t component_count = 0;
    if (!orient_pieces(surface, links, component, component_count, report, memory)) return repaired;
    cap_holes(surface, rim, component, component_count, report, repaired.uncertain, memory);
    turn_shells(surface, component, component_count, report, memory);

    repaired.positions.reserve(3 * surface.points.size());
    for (const Eigen::Vector3d& point : surface.points)
        repaired.positions.insert(repaired.positions.end(), point.data(), point.data() + 3);
    for (const RepairTriangle& t : surface.triangles)
        for (std::uint32_t id : t.corners) repaired.bounds.extend(surface.point(id));
    repaired.triangles.reserve(3 * surface.triangles.size());
    for (const RepairTriangle& t : surface.triangles)
        repaired.triangles.insert(repaired.triangles.end(), t.corners.begin(), t.corners.end());
    return repaired;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                  \
    template RepairedMesh repair_mesh<Scalar, Index>(const MeshView<Scalar, Index>&,         \
                                                     const MeshScan&, const RepairSettings&, \
                                                     std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
