#include "surface_answer.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "rigid_body.hpp"
#include "thin_shell.hpp"

namespace polymass::core {
namespace {

// The body of a surface its verdict accepts as a solid.
Body solid_body(const MeshAnalysis& analysis) {
    const IntegrationResult& integration = *analysis.integration;
    Body body;
    body.integrals =
        analysis.verdict.outward < 0 ? integration.integrals.negated() : integration.integrals;
    body.bounds = integration.bounds;
    body.reference = analysis.scan.reference_point();
    body.surface_area = integration.surface_area;
    body.warnings = analysis.verdict.warnings;
    return body;
}

// Whether the chain can take a valid solid as its answer: solid and repair
// answer one as it is; shell and hull describe another body.
bool judges_solid(const AnswerSettings& settings) {
    if (settings.mode_count == 0) return true;
    return std::any_of(settings.modes.begin(), settings.modes.begin() + settings.mode_count,
                       [](Mode mode) { return mode == Mode::solid || mode == Mode::repair; });
}

// A surface of the library's own making (a repair, a hull) judged as a
// solid with these checks, stopping at its first problem.
template <class Scalar, class Index>
MeshAnalysis judge_own_surface(const MeshView<Scalar, Index>& surface, AnalysisSettings settings,
                               std::pmr::memory_resource* memory) {
    settings.stop_at_first_problem = true;
    settings.list_shells = false;
    settings.weld = false;
    return analyse_mesh(surface, settings, memory);
}

MeshView<double, std::uint32_t> triangles_view(const std::pmr::vector<double>& positions,
                                               const std::pmr::vector<std::uint32_t>& indices) {
    return {{reinterpret_cast<const unsigned char*>(positions.data()), 3 * sizeof(double)},
            positions.size() / 3,
            {reinterpret_cast<const unsigned char*>(indices.data())},
            indices.size(),
            nullptr,
            indices.size() / 3};
}

Refusal repair_refusal(RepairFailure failure) {
    switch (failure) {
        case RepairFailure::nothing_left:
            return Refusal::nothing_left;
        case RepairFailure::unbalanced_non_manifold:
            return Refusal::unbalanced_non_manifold;
        default:
            return Refusal::non_orientable;
    }
}

Refusal hull_refusal(HullStatus status) {
    switch (status) {
        case HullStatus::too_few_points:
            return Refusal::hull_too_few_points;
        case HullStatus::collinear:
            return Refusal::hull_collinear;
        case HullStatus::coplanar:
            return Refusal::hull_coplanar;
        default:  // beyond_exact_range (non-finite coordinates are refused before the hull)
            return Refusal::hull_beyond_exact_range;
    }
}

template <class Scalar, class Index>
class Chain {
public:
    Chain(const MeshView<Scalar, Index>& mesh, const AnswerSettings& settings,
          std::pmr::memory_resource* memory, SurfaceAnswer& answer)
        : mesh_(mesh), settings_(settings), memory_(memory), answer_(answer) {}

    // Tries the modes in order; the first that answers gives the body.
    void run() {
        const std::size_t length = std::max<std::size_t>(settings_.mode_count, 1);
        bool solid_refused = false;
        for (std::size_t i = 0; i < length; ++i) {
            const Mode mode = settings_.mode_count == 0 ? Mode::solid : settings_.modes[i];
            std::optional<ModeFailure> failure;
            if (mode == Mode::solid || mode == Mode::repair) {
                // A valid solid is its own answer, in either mode.
                if (answer_.surface.verdict.valid()) {
                    answer_.body = solid_body(answer_.surface);
                    answer_.answered = Mode::solid;
                    return;
                }
                if (!solid_refused) {
                    solid_refused = true;
                    add_failure({Mode::solid, Refusal::defect, answer_.surface.verdict.defect});
                }
                if (mode == Mode::solid) continue;
                failure = repair();
            } else if (mode == Mode::shell) {
                failure = shell();
            } else {
                failure = hull();
            }
            if (!failure) {
                answer_.answered = mode;
                return;
            }
            add_failure(*failure);
        }
    }

private:
    void add_failure(const ModeFailure& failure) {
        answer_.failures[answer_.failure_count++] = failure;
    }

    // A surface whose indices, coordinates or extent cannot be read gives no
    // body in any mode.
    std::optional<ModeFailure> unreadable(Mode mode) const {
        const Defect defect = coordinates_defect(answer_.surface.scan);
        if (defect == Defect::none) return std::nullopt;
        return ModeFailure{mode, Refusal::defect, defect};
    }

    // The verdict of a surface the mode made refused it.
    ModeFailure refused_own_surface(Mode mode, MeshAnalysis analysis, std::size_t triangles) {
        ModeFailure failure{mode, Refusal::defect, analysis.verdict.defect, true, triangles};
        answer_.own_surface.emplace(std::move(analysis));
        return failure;
    }

    // The repair mode once the surface is known not to be a valid solid.
    std::optional<ModeFailure> repair() {
        if (auto failure = unreadable(Mode::repair)) return failure;
        const AnalysisSettings& checks = settings_.analysis;
        const RepairedMesh repaired =
            repair_mesh(mesh_, answer_.surface.scan,
                        {checks.weld_tolerance, checks.planarity_tolerance}, memory_);
        if (repaired.report.failure != RepairFailure::none) {
            answer_.repairs = repaired.report;
            return ModeFailure{Mode::repair, repair_refusal(repaired.report.failure)};
        }
        // The repaired triangles, judged as any surface is. Split edges and
        // caps meeting at a vertex their loop passes twice leave edges used
        // by pairs of faces, as often each way.
        const MeshView<double, std::uint32_t> fixed =
            triangles_view(repaired.positions, repaired.triangles);
        AnalysisSettings judged = checks;
        judged.check_topology = true;
        judged.policy = {};
        judged.policy.accept_balanced_non_manifold = true;
        MeshAnalysis analysis = judge_own_surface(fixed, judged, memory_);
        if (!analysis.verdict.valid())
            return refused_own_surface(Mode::repair, std::move(analysis), fixed.face_count);
        Body body = solid_body(analysis);
        body.warnings |= kWarningRepaired;
        body.approximation = approximation_bound(
            repaired.uncertain, rigid_body(body.integrals, body.reference, 1.0), repaired.bounds);
        answer_.body = body;
        answer_.repairs = repaired.report;
        return std::nullopt;
    }

    // The shell mode: the surface as a sheet of area density shell_thickness.
    std::optional<ModeFailure> shell() {
        if (auto failure = unreadable(Mode::shell)) return failure;
        const MeshScan& scan = answer_.surface.scan;
        const ThinShell sheet = thin_shell_moments(mesh_, settings_.shell_thickness,
                                                   scan.reference_point(), scan.diagonal());
        if (!(sheet.moments.mass.volume >= DBL_MIN)) {
            ModeFailure failure{Mode::shell, Refusal::no_area};
            failure.area = sheet.area;
            return failure;
        }
        Body& body = answer_.body;
        body.integrals = sheet.moments.mass;
        body.bounds = sheet.moments.mass_bounds;
        body.reference = sheet.moments.reference;
        body.surface_area = sheet.area;
        body.warnings = kWarningShell;
        body.approximation = sheet.wall_bound;
        answer_.shell_area = sheet.area;
        return std::nullopt;
    }

    // The hull mode: the convex hull of the used vertices, integrated as a
    // solid. The true solid lies inside it (docs/repair.md, "Hull"): its
    // volume is in [0, V_H], its centre of mass in the hull's box, and, at a
    // given density, 0 <= I_true <= I_hull, so each entry is off by at most
    // twice the hull's largest moment.
    std::optional<ModeFailure> hull() {
        if (auto failure = unreadable(Mode::hull)) return failure;
        const MeshScan& scan = answer_.surface.scan;
        const ConvexHull hull = convex_hull(mesh_, scan, memory_);
        if (hull.status != HullStatus::ok)
            return ModeFailure{Mode::hull, hull_refusal(hull.status)};
        AnalysisSettings judged;  // every check
        judged.planarity_tolerance = settings_.analysis.planarity_tolerance;
        judged.tasks = settings_.analysis.tasks;
        MeshAnalysis analysis = judge_own_surface(hull.view(), judged, memory_);
        // A hull the exact predicates built is a valid solid of finite
        // points; its integrals can still overflow.
        if (!analysis.verdict.valid())
            return refused_own_surface(Mode::hull, std::move(analysis), hull.triangle_count());
        Body body = solid_body(analysis);
        body.warnings |= kWarningHull;
        const RigidBody hull_body = rigid_body(body.integrals, body.reference, 1.0);
        body.approximation.volume = hull_body.volume;
        body.approximation.center_of_mass = scan.bounds.sizes().maxCoeff();
        body.approximation.inertia = 2.0 * hull_body.inertia.diagonal().maxCoeff();
        answer_.body = body;
        answer_.hull_vertex_count = hull.coordinates.size() / 3;
        answer_.hull_triangle_count = hull.triangle_count();
        answer_.hull_volume = hull_body.volume;
        return std::nullopt;
    }

    const MeshView<Scalar, Index>& mesh_;
    const AnswerSettings& settings_;
    std::pmr::memory_resource* memory_;
    SurfaceAnswer& answer_;
};

}  // namespace

template <class Scalar, class Index>
SurfaceAnswer answer_surface(const MeshView<Scalar, Index>& mesh, const AnswerSettings& settings,
                             std::pmr::memory_resource* memory) {
    // The surface judged as a solid, once: in full for the findings,
    // otherwise as far as the chain needs.
    const bool findings = !settings.analysis.stop_at_first_problem;
    SerialTaskRunner serial;
    TaskRunner& tasks = settings.analysis.tasks ? *settings.analysis.tasks : serial;
    SurfaceAnswer answer(findings || judges_solid(settings)
                             ? analyse_mesh(mesh, settings.analysis, memory)
                             : scan_surface(mesh, memory, tasks));
    Chain<Scalar, Index>(mesh, settings, memory, answer).run();
    return answer;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)               \
    template SurfaceAnswer answer_surface<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const AnswerSettings&, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
