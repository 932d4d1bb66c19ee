// The options' chain of modes: the first that answers gives the body, and the
// provenance says which it was and what it did (docs/repair.md).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "core/convex_hull.hpp"
#include "core/mesh_repair.hpp"
#include "core/rigid_body.hpp"
#include "core/thin_shell.hpp"
#include "mesh.hpp"
#include "mesh_findings.hpp"
#include "mesh_input.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

using u64 = unsigned long long;  // for printf

const char* mode_name(uint32_t mode) {
    switch (mode) {
        case POLYMASS_MODE_SOLID:
            return "solid";
        case POLYMASS_MODE_REPAIR:
            return "repair";
        case POLYMASS_MODE_SHELL:
            return "shell";
        default:
            return "hull";
    }
}

// Why each mode tried gave no answer, for the message when none does.
class Reasons {
public:
    void add(uint32_t mode, const char* message) {
        const int written = std::snprintf(text_ + length_, sizeof text_ - length_, "%s%s: %s",
                                          length_ ? "; " : "", mode_name(mode), message);
        length_ = std::min(sizeof text_ - 1, length_ + std::size_t(std::max(written, 0)));
    }
    const char* text() const { return text_; }

private:
    char text_[sizeof(polymass_context::message)] = "";
    std::size_t length_ = 0;
};

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
    provenance.cap_area_fraction = surface_area > 0.0 ? report.cap_area / surface_area : 0.0;
}

// A surface of triangles over packed double positions, as the library's own
// steps (repair, hull) make them.
MeshInput triangles_input(const std::pmr::vector<double>& positions,
                          const std::pmr::vector<uint32_t>& indices) {
    MeshInput input;
    input.position_type = POLYMASS_POSITION_FLOAT64;
    input.positions = reinterpret_cast<const unsigned char*>(positions.data());
    input.vertex_count = positions.size() / 3;
    input.position_stride = 3 * sizeof(double);
    input.index_type = POLYMASS_INDEX_UINT32;
    input.indices = reinterpret_cast<const unsigned char*>(indices.data());
    input.index_count = indices.size();
    input.face_count = indices.size() / 3;
    return input;
}

int32_t fail_repair(polymass_context* context, const core::RepairReport& report) {
    switch (report.failure) {
        case core::RepairFailure::nothing_left:
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "no face is left once faces of fewer than three distinct "
                                 "vertices and duplicates are dropped");
        case core::RepairFailure::unbalanced_non_manifold:
            return context->fail(POLYMASS_ERROR_NON_MANIFOLD,
                                 "edge (%u, %u) is used by %llu faces one way and %llu the other: "
                                 "no split into pairs of faces is the right one",
                                 report.failed_edge[0], report.failed_edge[1],
                                 u64(report.failed_forward), u64(report.failed_backward));
        case core::RepairFailure::non_orientable:
            return context->fail(POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
                                 "the shell of face %llu cannot be oriented: its faces cannot "
                                 "all agree (a one-sided surface, like a Moebius strip)",
                                 u64(report.failed_face));
        case core::RepairFailure::none:
            break;
    }
    return POLYMASS_OK;
}

// The scan repair, shell and hull start from; the scan's status (indices out
// of range, coordinates not finite or overflowing: no body) when they cannot.
template <class View>
int32_t scan_for(polymass_context* context, const MeshInput& input, const View& view,
                 core::MeshScan& scan) {
    core::MeshAnalysis scanned(core::scan_mesh(view, &context->memory, context->tasks()));
    scanned.verdict = core::judge(scanned, {});
    uint32_t warnings = 0;
    const polymass_options defaults = StructVersions<polymass_options>::defaults();
    if (const int32_t status = report_verdict(context, input, defaults, scanned, warnings))
        return status;
    scan = std::move(scanned.scan);
    return POLYMASS_OK;
}

// The REPAIR mode once the surface is known not to be a valid solid.
int32_t build_repaired(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, Answer& answer) {
    return visit_mesh(input, [&](const auto& view) -> int32_t {
        core::MeshScan scan(&context->memory);
        if (const int32_t status = scan_for(context, input, view, scan)) return status;
        const core::RepairSettings settings{options.weld_tolerance, options.planarity_tolerance};
        const core::RepairedMesh repaired =
            core::repair_mesh(view, scan, settings, &context->memory);
        if (const int32_t status = fail_repair(context, repaired.report)) return status;

        // The repaired triangles, judged as any surface is. Split edges and
        // caps meeting at a vertex their loop passes twice leave edges used
        // by pairs of faces, as often each way.
        const MeshInput fixed = triangles_input(repaired.positions, repaired.triangles);
        polymass_options judged = options;
        judged.flags = (options.flags & POLYMASS_OPTION_SKIP_INTERSECTION_CHECK) |
                       POLYMASS_OPTION_ACCEPT_NON_MANIFOLD;
        Body& body = answer.body;
        if (const int32_t status = build_solid(context, fixed, judged, body)) {
            char reason[sizeof context->message];
            std::memcpy(reason, context->message, sizeof reason);
            return context->fail(status,
                                 "the repaired surface (faces numbered as its %llu "
                                 "triangles): %s",
                                 u64(fixed.face_count), reason);
        }
        body.warnings |= POLYMASS_WARNING_REPAIRED;
        body.approximation = core::approximation_bound(
            repaired.uncertain, core::rigid_body(body.integrals, body.reference, 1.0),
            repaired.bounds);
        record_repairs(repaired.report, body.surface_area, answer.provenance);
        return POLYMASS_OK;
    });
}

// The SHELL mode: the surface as a sheet of area density shell_thickness.
int32_t build_shell(polymass_context* context, const MeshInput& input,
                    const polymass_options& options, Answer& answer) {
    return visit_mesh(input, [&](const auto& view) -> int32_t {
        core::MeshScan scan(&context->memory);
        if (const int32_t status = scan_for(context, input, view, scan)) return status;
        const core::ThinShell shell = core::thin_shell_moments(
            view, options.shell_thickness, scan.reference_point(), scan.diagonal());
        if (!(shell.moments.mass.volume >= DBL_MIN))
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the surface has no area to make a wall of (area %g)", shell.area);
        Body& body = answer.body;
        body.integrals = shell.moments.mass;
        body.bounds = shell.moments.mass_bounds;
        body.reference = shell.moments.reference;
        body.surface_area = shell.area;
        body.warnings = POLYMASS_WARNING_SHELL;
        body.approximation = shell.wall_bound;
        answer.provenance.shell_thickness = options.shell_thickness;
        answer.provenance.shell_area = shell.area;
        return POLYMASS_OK;
    });
}

const char* hull_failure(core::HullStatus status) {
    switch (status) {
        case core::HullStatus::too_few_points:
            return "the faces use fewer than 4 distinct vertices";
        case core::HullStatus::collinear:
            return "the vertices lie on one line";
        case core::HullStatus::coplanar:
            return "the vertices lie in one plane";
        default:
            return "a vertex is not finite";
    }
}

// The HULL mode: the convex hull of the used vertices, integrated as a solid.
// The true solid lies inside it (docs/repair.md, "Hull"): its volume is in
// [0, V_H], its centre of mass in the hull's box, and, at a given density,
// 0 <= I_true <= I_hull, so each entry is off by at most twice the hull's
// largest moment.
int32_t build_hull(polymass_context* context, const MeshInput& input,
                   const polymass_options& options, Answer& answer) {
    return visit_mesh(input, [&](const auto& view) -> int32_t {
        core::MeshScan scan(&context->memory);
        if (const int32_t status = scan_for(context, input, view, scan)) return status;
        const core::ConvexHull hull = core::convex_hull(view, scan, &context->memory);
        if (hull.status == core::HullStatus::beyond_exact_range)
            return context->fail(POLYMASS_ERROR_OVERFLOW,
                                 "the convex hull cannot be built exactly: its orientation "
                                 "tests disagreed, as they can for nonzero coordinates more "
                                 "than 2^640 apart in magnitude, beyond their exact range");
        if (hull.status != core::HullStatus::ok)
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME, "the convex hull has no volume: %s",
                                 hull_failure(hull.status));
        const MeshInput solid = triangles_input(hull.coordinates, hull.indices);
        polymass_options judged = options;
        judged.flags = 0;
        Body& body = answer.body;
        if (const int32_t status = build_solid(context, solid, judged, body)) return status;
        body.warnings |= POLYMASS_WARNING_HULL;
        const core::RigidBody hull_body = core::rigid_body(body.integrals, body.reference, 1.0);
        body.approximation.volume = hull_body.volume;
        body.approximation.center_of_mass = scan.bounds.sizes().maxCoeff();
        body.approximation.inertia = 2.0 * hull_body.inertia.diagonal().maxCoeff();
        answer.provenance.hull_vertex_count = solid.vertex_count;
        answer.provenance.hull_triangle_count = solid.face_count;
        answer.provenance.hull_volume = hull_body.volume;
        return POLYMASS_OK;
    });
}

// The body of a valid solid, from its analysis.
void solid_body(const core::MeshAnalysis& analysis, uint32_t warnings, Body& body) {
    const core::IntegrationResult& integration = *analysis.integration;
    body.integrals = (warnings & POLYMASS_WARNING_INVERTED) ? integration.integrals.negated()
                                                            : integration.integrals;
    body.bounds = integration.bounds;
    body.reference = analysis.scan.reference_point();
    body.surface_area = integration.surface_area;
    body.warnings = warnings;
    body.approximation = {};
}

// The options' chain, SOLID alone when it is empty.
struct Chain {
    uint32_t modes[POLYMASS_MAX_MODES] = {POLYMASS_MODE_SOLID};
    std::size_t length = 0;

    explicit Chain(const polymass_options& options) {
        while (length < POLYMASS_MAX_MODES && options.modes[length] != POLYMASS_MODE_NONE) {
            modes[length] = options.modes[length];
            ++length;
        }
        length = std::max<std::size_t>(length, 1);
    }
    // Whether the surface's verdict as a solid can answer: SOLID and REPAIR
    // answer a valid solid as it is.
    bool judges_solid() const {
        return std::any_of(modes, modes + length, [](uint32_t mode) {
            return mode == POLYMASS_MODE_SOLID || mode == POLYMASS_MODE_REPAIR;
        });
    }
};

}  // namespace

int32_t build_solid(polymass_context* context, const MeshInput& input,
                    const polymass_options& options, Body& body) {
    const core::MeshAnalysis analysis = analyse(context, input, options, false);
    uint32_t warnings = 0;
    if (const int32_t status = report_verdict(context, input, options, analysis, warnings))
        return status;
    solid_body(analysis, warnings, body);
    return POLYMASS_OK;
}

int32_t answer_surface(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, Answer& answer, polymass_mesh* findings) {
    const Chain chain(options);
    // The surface judged as a solid, once: in full for a mesh's findings,
    // otherwise only when the chain can take a valid solid as its answer.
    std::optional<core::MeshAnalysis> analysis;
    int32_t solid_status = report_small_faces(context, input);
    uint32_t solid_warnings = 0;
    if (solid_status == POLYMASS_OK && (findings || chain.judges_solid())) {
        analysis.emplace(analyse(context, input, options, findings != nullptr));
        solid_status = report_verdict(context, input, options, *analysis, solid_warnings);
    }
    if (findings) {
        fill_report(findings->diagnostics, input, analysis ? &*analysis : nullptr);
        findings->diagnostics.status = solid_status;
        if (analysis) list_shells(*analysis, findings->shells, findings->shell_of_face);
    }

    answer.provenance = StructVersions<polymass_provenance>::defaults();
    Reasons reasons;
    int32_t first_status = POLYMASS_OK;
    auto failed = [&](uint32_t mode, int32_t status) {
        reasons.add(mode, context->message);
        if (first_status == POLYMASS_OK) first_status = status;
    };
    bool solid_reported = false;
    for (std::size_t i = 0; i < chain.length; ++i) {
        const uint32_t mode = chain.modes[i];
        int32_t status = POLYMASS_OK;
        if (mode == POLYMASS_MODE_SOLID || mode == POLYMASS_MODE_REPAIR) {
            // A valid solid is its own answer, in either mode; its verdict
            // is the analysis's.
            if (solid_status == POLYMASS_OK) {
                solid_body(*analysis, solid_warnings, answer.body);
                answer.provenance.mode = POLYMASS_MODE_SOLID;
                return POLYMASS_OK;
            }
            if (!solid_reported) {
                solid_reported = true;
                failed(POLYMASS_MODE_SOLID, solid_status);
            }
            if (mode == POLYMASS_MODE_SOLID) continue;
            status = build_repaired(context, input, options, answer);
        } else if (mode == POLYMASS_MODE_SHELL) {
            status = build_shell(context, input, options, answer);
        } else {
            status = build_hull(context, input, options, answer);
        }
        if (status == POLYMASS_OK) {
            const core::ApproximationBound& approximation = answer.body.approximation;
            answer.provenance.mode = int32_t(mode);
            answer.provenance.approximation_bound_volume = approximation.volume;
            answer.provenance.approximation_bound_center_of_mass = approximation.center_of_mass;
            answer.provenance.approximation_bound_inertia = approximation.inertia;
            context->clear_message();  // the modes before it failed: a success says nothing
            return POLYMASS_OK;
        }
        failed(mode, status);
    }
    // The solid alone keeps its own message, as before there were modes.
    if (chain.length == 1 && chain.modes[0] == POLYMASS_MODE_SOLID) return first_status;
    return context->fail(first_status, "%s", reasons.text());
}

}  // namespace polymass::capi
