// Closing holes: each loop of rim edges capped by triangles, and the
// region between the cap and the missing surface bounded (docs/repair.md,
// "Holes").
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

#include "repair_surface.hpp"
#include "smallest_index_sets.hpp"

namespace polymass::core {
namespace {

// Longer loops bound their diameter by their box, not pair by pair.
constexpr std::size_t kLongLoop = 2048;

struct RimStep {
    std::uint32_t from, to, triangle;
};

using Triangle = std::array<std::uint32_t, 3>;

// The loop's diameter: pairwise for loops of usual sizes, the box's diagonal
// (at most √3 times larger) for long ones.
double loop_diameter(const RepairSurface& surface, const std::pmr::vector<std::uint32_t>& loop,
                     const Eigen::AlignedBox3d& box) {
    if (loop.size() > kLongLoop) return box.diagonal().norm();
    double squared = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        for (std::size_t j = i + 1; j < loop.size(); ++j)
            squared =
                std::max(squared, (surface.point(loop[i]) - surface.point(loop[j])).squaredNorm());
    return std::sqrt(squared);
}

// The region between a cap and the surface it stands for (docs/repair.md,
// "The bound of a cap"), under the assumption that the missing surface lies
// within the loop's diameter D of the cap. A cap of ears clipped over the
// loop's simple projection on its mean plane: the missing surface a height
// field over that projection within D of the plane, the cap within h (the
// loop's largest distance from the plane), so the region is at most the
// projection's area times D + h. Otherwise the prisms of height D along the
// cap's normals, A D, and the wedges where neighbouring triangles' normals
// part, l θ D² / 2 at each inner edge of length l.
UncertainRegion cap_region(const RepairSurface& surface,
                           const std::pmr::vector<std::uint32_t>& loop,
                           const std::pmr::vector<Triangle>& cap, bool over_projection,
                           double& cap_area, std::pmr::memory_resource* memory) {
    Eigen::AlignedBox3d box;
    for (std::uint32_t id : loop) box.extend(surface.point(id));
    const double diameter = loop_diameter(surface, loop, box);
    const UncertainRegion ball{0.0, box.center(), box.diagonal().norm() / 2.0 + diameter};
    auto normal = [&](const Triangle& t) {
        const Eigen::Vector3d& a = surface.point(t[0]);
        return Eigen::Vector3d((surface.point(t[1]) - a).cross(surface.point(t[2]) - a));
    };
    // Each inner edge is used by two of the cap's triangles: found by sorting.
    struct Use {
        std::uint32_t low, high, triangle;
    };
    std::pmr::vector<Use> uses(memory);
    double area = 0.0;
    for (std::uint32_t t = 0; t < cap.size(); ++t) {
        area += 0.5 * normal(cap[t]).norm();
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = cap[t][k], b = cap[t][(k + 1) % 3];
            uses.push_back({std::min(a, b), std::max(a, b), t});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
        return std::tie(x.low, x.high, x.triangle) < std::tie(y.low, y.high, y.triangle);
    });
    double wedges = 0.0;
    for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
        if (uses[i].low != uses[i + 1].low || uses[i].high != uses[i + 1].high) continue;
        const Eigen::Vector3d n1 = normal(cap[uses[i].triangle]);
        const Eigen::Vector3d n2 = normal(cap[uses[i + 1].triangle]);
        if (n1.norm() > 0.0 && n2.norm() > 0.0) {
            const double angle = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
            const double length = (surface.point(uses[i].high) - surface.point(uses[i].low)).norm();
            wedges += length * angle * diameter * diameter / 2.0;
        }
    }
    cap_area = area;
    UncertainRegion region = ball;
    region.volume = area * diameter + wedges;
    if (over_projection) {
        const Eigen::Vector3d& origin = surface.point(loop[0]);
        Eigen::Vector3d newell = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Eigen::Vector3d p = surface.point(loop[i]) - origin;
            newell += p.cross(surface.point(loop[(i + 1) % loop.size()]) - origin);
            centroid += p / double(loop.size());
        }
        const Eigen::Vector3d normal = newell.normalized();
        double off_plane = 0.0;
        for (std::uint32_t id : loop)
            off_plane =
                std::max(off_plane, std::abs((surface.point(id) - origin - centroid).dot(normal)));
        region.volume = newell.norm() / 2.0 * (diameter + off_plane);
    }
    return region;
}

// The polygon `corners` (the cap's order) cut into triangles by ear clipping
// in the plane of its Newell normal: for a loop whose projection is a simple
// polygon, triangles inside it, with no edge between two of its corners
// outside it, and for a planar loop its exact area. False when the
// projection is not simple (no ear left); `out` is then incomplete.
bool clip_ears(const RepairSurface& surface, const std::pmr::vector<std::uint32_t>& corners,
               std::pmr::vector<Triangle>& out, std::pmr::memory_resource* memory) {
    const std::size_t n = corners.size();
    const Eigen::Vector3d& origin = surface.point(corners[0]);
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < n; ++i)
        newell += (surface.point(corners[i]) - origin)
                      .cross(surface.point(corners[(i + 1) % n]) - origin);
    if (!(newell.norm() > 0.0)) return false;
    const Eigen::Vector3d w = newell.normalized(), u = w.unitOrthogonal(), v = w.cross(u);
    std::pmr::vector<Eigen::Vector2d> flat(memory);
    for (std::uint32_t id : corners) {
        const Eigen::Vector3d p = surface.point(id) - origin;
        flat.emplace_back(p.dot(u), p.dot(v));  // counter-clockwise: its area is positive
    }
    auto turn = [&](std::size_t a, std::size_t b, std::size_t c) {
        const Eigen::Vector2d e1 = flat[b] - flat[a], e2 = flat[c] - flat[a];
        return e1.x() * e2.y() - e1.y() * e2.x();
    };
    std::pmr::vector<std::size_t> left(memory);
    for (std::size_t i = 0; i < n; ++i) left.push_back(i);
    while (left.size() > 3) {
        bool clipped = false;
        for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
            const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                              c = left[(k + 1) % left.size()];
            if (!(turn(a, b, c) > 0.0)) continue;  // a reflex or flat corner
            bool empty = true;
            for (std::size_t other : left) {
                if (other == a || other == b || other == c) continue;
                if (turn(a, b, other) >= 0.0 && turn(b, c, other) >= 0.0 &&
                    turn(c, a, other) >= 0.0) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            out.push_back({corners[a], corners[b], corners[c]});
            left.erase(left.begin() + std::ptrdiff_t(k));
            clipped = true;
        }
        if (!clipped) return false;
    }
    out.push_back({corners[left[0]], corners[left[1]], corners[left[2]]});
    return true;
}

}  // namespace

void cap_holes(RepairSurface& surface, const std::pmr::vector<RimEdge>& rim,
               std::pmr::vector<std::uint32_t>& component, std::size_t& component_count,
               RepairReport& report, std::pmr::vector<UncertainRegion>& uncertain,
               std::pmr::memory_resource* memory) {
    if (rim.empty()) return;
    // Each rim edge in the direction its (oriented) triangle traverses it.
    std::pmr::vector<RimStep> steps(memory);
    steps.reserve(rim.size());
    for (const RimEdge& edge : rim) {
        const auto& c = surface.triangles[edge.triangle].corners;
        bool a_to_b = false;
        for (int k = 0; k < 3; ++k) a_to_b |= c[k] == edge.a && c[(k + 1) % 3] == edge.b;
        steps.push_back(a_to_b ? RimStep{edge.a, edge.b, edge.triangle}
                               : RimStep{edge.b, edge.a, edge.triangle});
    }
    std::sort(steps.begin(), steps.end(), [](const RimStep& x, const RimStep& y) {
        return std::tie(x.from, x.to) < std::tie(y.from, y.to);
    });
    std::pmr::vector<char> used(steps.size(), 0, memory);
    auto next_from = [&](std::uint32_t vertex) -> std::size_t {
        auto it = std::lower_bound(steps.begin(), steps.end(), vertex,
                                   [](const RimStep& s, std::uint32_t v) { return s.from < v; });
        for (; it != steps.end() && it->from == vertex; ++it)
            if (!used[std::size_t(it - steps.begin())]) return std::size_t(it - steps.begin());
        return steps.size();
    };
    std::pmr::vector<std::uint32_t> parent(component_count, memory);
    std::iota(parent.begin(), parent.end(), 0u);
    SmallestIndexSets pieces(parent);
    std::pmr::vector<std::uint32_t> loop(memory), holes(memory);
    std::pmr::vector<Triangle> cap(memory);
    for (std::size_t first = 0; first < steps.size(); ++first) {
        if (used[first]) continue;
        loop.clear();
        const std::uint32_t piece = component[steps[first].triangle];
        std::size_t step = first;
        bool closed = false;
        while (step < steps.size()) {
            used[step] = 1;
            loop.push_back(steps[step].from);
            pieces.join(piece, component[steps[step].triangle]);
            if (steps[step].to == steps[first].from) {
                closed = true;
                break;
            }
            step = next_from(steps[step].to);
        }
        if (!closed || loop.size() < 3) continue;  // the verdict finds the rim still open
        holes.push_back(*std::min_element(loop.begin(), loop.end()));
        // The cap traverses the rim backwards, as a closed surface must: ears
        // clipped from the loop, or, when its projection is not a simple
        // polygon, triangles from the loop's centre (a new vertex, so no cap
        // edge joins two rim vertices). Either is the loop's exact polygon
        // when the loop is planar.
        std::reverse(loop.begin(), loop.end());
        cap.clear();
        const bool clipped = clip_ears(surface, loop, cap, memory);
        if (!clipped) {
            cap.clear();
            Eigen::Vector3d centre = Eigen::Vector3d::Zero();
            const Eigen::Vector3d origin = surface.point(loop[0]);
            for (std::uint32_t id : loop) centre += surface.point(id) - origin;
            const auto apex = std::uint32_t(surface.points.size());
            surface.points.push_back(origin + centre / double(loop.size()));
            for (std::size_t i = 0; i < loop.size(); ++i)
                cap.push_back({apex, loop[i], loop[(i + 1) % loop.size()]});
        }
        double area = 0.0;
        uncertain.push_back(cap_region(surface, loop, cap, clipped, area, memory));
        report.cap_area += area;
        for (const Triangle& t : cap) {
            surface.triangles.push_back({t, kCapFace});
            component.push_back(piece);
            ++report.cap_triangles;
        }
    }
    std::sort(holes.begin(), holes.end());
    for (std::uint32_t vertex : holes) report.holes.record(vertex);
    // Pieces a cap joined are one piece now: renumber by their sets.
    std::pmr::vector<std::uint32_t> number(component_count, UINT32_MAX, memory);
    std::size_t count = 0;
    for (std::uint32_t& c : component) {
        std::uint32_t& n = number[pieces.find(c)];
        if (n == UINT32_MAX) n = std::uint32_t(count++);
        c = n;
    }
    component_count = count;
}

}  // namespace polymass::core
