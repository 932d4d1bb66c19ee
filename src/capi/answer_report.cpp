#include "answer_report.hpp"

#include <algorithm>
#include <cstdio>

#include "mesh_findings.hpp"
#include "struct_versions.hpp"

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

static_assert(int(core::Mode::solid) == POLYMASS_MODE_SOLID &&
                  int(core::Mode::repair) == POLYMASS_MODE_REPAIR &&
                  int(core::Mode::shell) == POLYMASS_MODE_SHELL &&
                  int(core::Mode::hull) == POLYMASS_MODE_HULL,
              "the core's modes are the API's");
static_assert(core::kMaxModes == POLYMASS_MAX_MODES, "the core's chain is the API's");
static_assert(core::kWarningRepaired == POLYMASS_WARNING_REPAIRED &&
                  core::kWarningShell == POLYMASS_WARNING_SHELL &&
                  core::kWarningHull == POLYMASS_WARNING_HULL,
              "the core's warning bits are the API's");

const char* mode_name(core::Mode mode) {
    switch (mode) {
        case core::Mode::solid:
            return "solid";
        case core::Mode::repair:
            return "repair";
        case core::Mode::shell:
            return "shell";
        default:
            return "hull";
    }
}

// A message of parts ("...; repair: ...; hull: ..."), truncated to fit.
class Reasons {
public:
    // The surface's own reason, unnamed.
    void add(const char* message) { append("", message); }
    // Why a mode gave no answer.
    void add(core::Mode mode, const char* message) { append(mode_name(mode), message); }
    const char* text() const { return text_; }

private:
    void append(const char* name, const char* message) {
        const int written = std::snprintf(text_ + length_, sizeof text_ - length_, "%s%s%s%s",
                                          length_ ? "; " : "", name, *name ? ": " : "", message);
        length_ = std::min(sizeof text_ - 1, length_ + std::size_t(std::max(written, 0)));
    }

    char text_[sizeof(polymass_context::message)] = "";
    std::size_t length_ = 0;
};

// The status of one mode's failure, with its message in the context.
int32_t report_failure(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, const core::SurfaceAnswer& answer,
                       const core::ModeFailure& failure) {
    const core::RepairReport& repairs = answer.repairs;
    switch (failure.refusal) {
        case core::Refusal::defect: {
            if (!failure.of_own_surface)
                return report_verdict(context, input, options, answer.surface, failure.defect);
            const int32_t status =
                report_verdict(context, input, options, *answer.own_surface, failure.defect);
            if (failure.mode != core::Mode::repair) return status;
            char reason[sizeof context->message];
            std::snprintf(reason, sizeof reason, "%s", context->message);
            return context->fail(status,
                                 "the repaired surface (faces numbered as its %llu triangles): %s",
                                 u64(failure.own_triangles), reason);
        }
        case core::Refusal::nothing_left:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "no face is left once faces of fewer than three distinct "
                                 "vertices and duplicates are dropped");
        case core::Refusal::unbalanced_non_manifold:
            return context->fail(POLYMASS_ERROR_NON_MANIFOLD,
                                 "edge (%u, %u) is used by %llu faces one way and %llu the other: "
                                 "no split into pairs of faces is the right one",
                                 repairs.failed_edge[0], repairs.failed_edge[1],
                                 u64(repairs.failed_forward), u64(repairs.failed_backward));
        case core::Refusal::non_orientable:
            return context->fail(POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                                 "the shell of face %llu cannot be oriented: its faces cannot "
                                 "all agree (a one-sided surface, like a Moebius strip)",
                                 u64(repairs.failed_face));
        case core::Refusal::no_area:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the surface has no area to make a wall of (area %g)",
                                 failure.area);
        case core::Refusal::hull_too_few_points:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the convex hull has no volume: the faces use fewer than 4 "
                                 "distinct vertices");
        case core::Refusal::hull_collinear:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the convex hull has no volume: the vertices lie on one line");
        case core::Refusal::hull_coplanar:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the convex hull has no volume: the vertices lie in one plane");
        case core::Refusal::hull_beyond_exact_range:
            return context->fail(POLYMASS_ERROR_OVERFLOW,
                                 "the convex hull cannot be built exactly: its orientation "
                                 "tests disagreed, as they can for nonzero coordinates more "
                                 "than 2^640 apart in magnitude, beyond their exact range");
    }
    return context->fail(POLYMASS_ERROR_INTERNAL, "unknown refusal");
}

void record_repairs(const core::RepairReport& report, double surface_area,
                    polymass_provenance& provenance) {
    copy_finding(report.reoriented_faces, provenance.reoriented_faces,
                 provenance.first_reoriented_faces);
    copy_finding(report.turned_shells, provenance.turned_shells, provenance.first_turned_shells);
    copy_finding(report.duplicate_faces, provenance.duplicate_faces,
                 provenance.first_duplicate_faces);
    copy_finding(report.degenerate_faces, provenance.degenerate_faces,
                 provenance.first_degenerate_faces);
    copy_finding(report.triangulated_faces, provenance.triangulated_faces,
                 provenance.first_triangulated_faces);
    copy_finding(report.split_edges, provenance.split_edges, provenance.first_split_edges);
    copy_finding(report.holes, provenance.holes, provenance.first_holes);
    provenance.cap_triangles = report.cap_triangles;
    provenance.cap_area = report.cap_area;
    provenance.cap_area_fraction = report.cap_area_fraction(surface_area);
}

}  // namespace

core::AnswerSettings answer_settings(polymass_context* context, const polymass_options& options,
                                     bool findings) {
    core::AnswerSettings settings;
    core::AnalysisSettings& analysis = settings.analysis;
    analysis.check_topology = !(options.flags & POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS);
    analysis.check_intersections = !(options.flags & POLYMASS_OPTION_SKIP_INTERSECTION_CHECK);
    analysis.weld = options.flags & POLYMASS_OPTION_WELD_VERTICES;
    analysis.weld_tolerance = options.weld_tolerance;
    analysis.stop_at_first_problem = !findings;
    analysis.list_shells = findings;
    analysis.planarity_tolerance = options.planarity_tolerance;
    analysis.policy.accept_inverted = options.flags & POLYMASS_OPTION_ACCEPT_INVERTED;
    analysis.policy.accept_balanced_non_manifold =
        options.flags & POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
    analysis.tasks = &context->tasks();
    while (settings.mode_count < POLYMASS_MAX_MODES &&
           options.modes[settings.mode_count] != POLYMASS_MODE_NONE) {
        settings.modes[settings.mode_count] = core::Mode(options.modes[settings.mode_count]);
        ++settings.mode_count;
    }
    settings.shell_thickness = options.shell_thickness;
    return settings;
}

int32_t report_answer(polymass_context* context, const MeshInput& input,
                      const polymass_options& options, const core::SurfaceAnswer& answer) {
    if (answer.answered) return POLYMASS_OK;
    // The solid alone keeps its own message, as before there were modes.
    if (options.modes[0] == POLYMASS_MODE_NONE ||
        (options.modes[0] == POLYMASS_MODE_SOLID && options.modes[1] == POLYMASS_MODE_NONE))
        return report_failure(context, input, options, answer, answer.failures[0]);
    Reasons reasons;
    int32_t first_status = POLYMASS_OK;
    for (std::size_t i = 0; i < answer.failure_count; ++i) {
        const core::ModeFailure& failure = answer.failures[i];
        const int32_t status = report_failure(context, input, options, answer, failure);
        reasons.add(failure.mode, context->message);
        if (first_status == POLYMASS_OK) first_status = status;
    }
    return context->fail(first_status, "%s", reasons.text());
}

void mesh_message(polymass_context* context, const MeshInput& input,
                  const polymass_options& options, const core::SurfaceAnswer& answer,
                  char (&out)[sizeof(polymass_context::message)]) {
    Reasons reasons;
    if (const core::Defect defect = answer.surface.verdict.defect; defect != core::Defect::none) {
        report_verdict(context, input, options, answer.surface, defect);
        reasons.add(context->message);
    }
    for (std::size_t i = 0; !answer.answered && i < answer.failure_count; ++i) {
        const core::ModeFailure& failure = answer.failures[i];
        if (failure.mode == core::Mode::solid) continue;  // the surface's own, above
        report_failure(context, input, options, answer, failure);
        reasons.add(failure.mode, context->message);
    }
    std::snprintf(out, sizeof out, "%s", reasons.text());
}

polymass_provenance provenance_of(const core::SurfaceAnswer& answer,
                                  const polymass_options& options) {
    polymass_provenance provenance = StructVersions<polymass_provenance>::defaults();
    const core::Body& body = answer.body;
    provenance.mode = int32_t(*answer.answered);
    switch (*answer.answered) {
        case core::Mode::repair:
            record_repairs(answer.repairs, body.surface_area, provenance);
            break;
        case core::Mode::shell:
            provenance.shell_thickness = options.shell_thickness;
            provenance.shell_area = answer.shell_area;
            break;
        case core::Mode::hull:
            provenance.hull_vertex_count = answer.hull_vertex_count;
            provenance.hull_triangle_count = answer.hull_triangle_count;
            provenance.hull_volume = answer.hull_volume;
            break;
        case core::Mode::solid:
            break;
    }
    provenance.approximation_bound_volume = body.approximation.volume;
    provenance.approximation_bound_center_of_mass = body.approximation.center_of_mass;
    provenance.approximation_bound_inertia = body.approximation.inertia;
    return provenance;
}

}  // namespace polymass::capi
