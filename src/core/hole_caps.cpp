// Closing holes: each loop of rim edges capped by a fan of triangles, and the
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

struct RimStep {
    std::uint32_t from, to, triangle;
};

// The region between a cap and the surface it stands for, under the
// assumption that the missing surface lies along the cap's normals within
// the loop's diameter D of it: the prisms over the cap's triangles, A D, and
// the wedges where neighbouring triangles' normals part, l θ D² / 2 each.
UncertainRegion cap_region(const RepairSurface& surface,
                           const std::pmr::vector<std::uint32_t>& loop, double& cap_area) {
    Eigen::AlignedBox3d box;
    for (std::uint32_t id : loop) box.extend(surface.point(id));
    const double diameter = box.diagonal().norm();
    const Eigen::Vector3d& apex = surface.point(loop[0]);
    double area = 0.0, wedges = 0.0;
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        const Eigen::Vector3d spoke = surface.point(loop[i]) - apex;
        const Eigen::Vector3d normal = (surface.point(loop[i + 1]) - apex).cross(spoke);
        area += 0.5 * normal.norm();
        if (i > 1 && normal.norm() > 0.0 && previous.norm() > 0.0) {
            const double angle = std::atan2(normal.cross(previous).norm(), normal.dot(previous));
            wedges += spoke.norm() * angle * diameter * diameter / 2.0;
        }
        previous = normal;
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
        double area = 0.0;
        uncertain.push_back(cap_region(surface, loop, area));
        report.cap_area += area;
        // The cap traverses the rim backwards, as a closed surface must.
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
            surface.triangles.push_back({{loop[0], loop[i + 1], loop[i]}, kCapFace});
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
