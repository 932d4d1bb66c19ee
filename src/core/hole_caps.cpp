// Closing holes: each loop of rim edges capped by triangles from its centre, and the
// region between the cap and the missing surface bounded (docs/repair.md,
// "Holes").
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "repair_surface.hpp"
#include "smallest_index_sets.hpp"

namespace polymass::core {
namespace {

// Longer loops bound their diameter by their box, not pair by pair.
constexpr std::size_t kLongLoop = 2048;

struct RimStep {
    std::uint32_t from, to, triangle;
};

// The region between a cap and the surface it stands for, under the
// assumption that the missing surface lies along the cap's normals within
// the loop's diameter D of it: the prisms over the cap's triangles, A D, and
// the wedges where neighbouring triangles' normals part, l θ D² / 2 at each
// spoke of length l. `apex` is the cap's centre, the loop its rim.
UncertainRegion cap_region(const RepairSurface& surface,
                           const std::pmr::vector<std::uint32_t>& loop, const Eigen::Vector3d& apex,
                           double& cap_area) {
    Eigen::AlignedBox3d box;
    for (std::uint32_t id : loop) box.extend(surface.point(id));
    const std::size_t n = loop.size();
    // The loop's diameter: pairwise for loops of usual sizes, the box's
    // diagonal (at most √3 times larger) for long ones.
    double diameter = box.diagonal().norm();
    if (n <= kLongLoop) {
        double squared = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                squared = std::max(squared,
                                   (surface.point(loop[i]) - surface.point(loop[j])).squaredNorm());
        diameter = std::sqrt(squared);
    }
    auto normal = [&](std::size_t i) {  // of the cap triangle (apex, loop[i + 1], loop[i])
        return (surface.point(loop[(i + 1) % n]) - apex).cross(surface.point(loop[i]) - apex);
    };
    double area = 0.0, wedges = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d here = normal(i), before = normal((i + n - 1) % n);
        area += 0.5 * here.norm();
        if (here.norm() > 0.0 && before.norm() > 0.0) {
            const double angle = std::atan2(here.cross(before).norm(), here.dot(before));
            wedges += (surface.point(loop[i]) - apex).norm() * angle * diameter * diameter / 2.0;
        }
    }
    cap_area = area;
    return {area * diameter + wedges, box.center(), box.diagonal().norm() / 2.0 + diameter};
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
        // The cap: triangles from the loop's centre, traversing the rim
        // backwards as a closed surface must. For a planar loop it is the
        // loop's polygon exactly, convex or not.
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        const Eigen::Vector3d& origin = surface.point(loop[0]);
        for (std::uint32_t id : loop) centre += surface.point(id) - origin;
        centre = origin + centre / double(loop.size());
        double area = 0.0;
        uncertain.push_back(cap_region(surface, loop, centre, area));
        report.cap_area += area;
        const auto apex = std::uint32_t(surface.points.size());
        surface.points.push_back(centre);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            surface.triangles.push_back({{apex, loop[(i + 1) % loop.size()], loop[i]}, kCapFace});
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
