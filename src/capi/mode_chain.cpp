// The options' chain of modes: the first that answers gives the body, and the
// provenance says which it was and what it did (docs/repair.md).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>

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

polymass_provenance blank_provenance() {
    polymass_provenance provenance = zeroed<polymass_provenance>();
    for (uint64_t* location :
         {&provenance.first_reoriented_faces[0], &provenance.first_turned_shells[0],
          &provenance.first_duplicate_faces[0], &provenance.first_degenerate_faces[0],
          &provenance.first_triangulated_faces[0], &provenance.first_holes[0]})
        std::fill_n(location, POLYMASS_DIAGNOSTIC_LOCATIONS, POLYMASS_NONE);
    std::fill_n(&provenance.first_split_edges[0][0], 2 * POLYMASS_DIAGNOSTIC_LOCATIONS,
                POLYMASS_NONE);
    return provenance;
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
    input.sizes_add_up = true;
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

// The REPAIR mode once the surface is known not to be a valid solid.
int32_t build_repaired(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, polymass_mesh& mesh,
                       polymass_provenance& provenance) {
    return visit_mesh(input, [&](const auto& view) -> int32_t {
        const core::MeshScan scan =
            core::scan_mesh(view, &context->memory, context->tasks(options));
        if (scan.out_of_range_indices > 0 || scan.non_finite.count > 0 ||
            !std::isfinite(scan.diagonal()))
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "indices out of range and coordinates that are not finite or "
                                 "overflow have no repair");
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
        if (const int32_t status = build_solid(context, fixed, judged, mesh)) {
            char reason[sizeof context->message];
            std::memcpy(reason, context->message, sizeof reason);
            return context->fail(status,
                                 "the repaired surface (faces numbered as its %llu "
                                 "triangles): %s",
                                 u64(fixed.face_count), reason);
        }
        mesh.warnings |= POLYMASS_WARNING_REPAIRED;
        mesh.approximation = core::approximation_bound(
            repaired.uncertain, core::rigid_body(mesh.integrals, mesh.reference, 1.0),
            repaired.bounds);
        record_repairs(repaired.report, mesh.surface_area, provenance);
        return POLYMASS_OK;
    });
}

// The scan shell and hull start from; a status when they cannot.
template <class View>
int32_t scan_for(polymass_context* context, const View& view, const polymass_options& options,
                 core::MeshScan& scan) {
    scan = core::scan_mesh(view, &context->memory, context->tasks(options));
    if (scan.out_of_range_indices > 0 || scan.non_finite.count > 0 ||
        !std::isfinite(scan.diagonal()))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "indices out of range and coordinates that are not finite or "
                             "overflow give no body");
    return POLYMASS_OK;
}

// The SHELL mode: the surface as a sheet of area density shell_thickness.
int32_t build_shell(polymass_context* context, const MeshInput& input,
                    const polymass_options& options, polymass_mesh& mesh,
                    polymass_provenance& provenance) {
    return visit_mesh(input, [&](const auto& view) -> int32_t {
        core::MeshScan scan(&context->memory);
        if (const int32_t status = scan_for(context, view, options, scan)) return status;
        const core::ThinShell shell = core::thin_shell_moments(
            view, options.shell_thickness, scan.reference_point(), scan.diagonal());
        if (!(shell.moments.mass.volume >= DBL_MIN))
            return context->fail(POLYMASS_ERROR_ZERO_VOLUME,
                                 "the surface has no area to make a wall of (area %g)", shell.area);
        mesh.integrals = shell.moments.mass;
        mesh.bounds = shell.moments.mass_bounds;
        mesh.reference = shell.moments.reference;
        mesh.surface_area = shell.area;
        mesh.warnings = POLYMASS_WARNING_SHELL;
        mesh.approximation = shell.wall_bound;
        provenance.shell_thickness = options.shell_thickness;
        provenance.shell_area = shell.area;
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
                   const polymass_options& options, polymass_mesh& mesh,
                   polymass_provenance& provenance) {
    return visit_mesh(input, [&](const auto& view) -> int32_t {
        core::MeshScan scan(&context->memory);
        if (const int32_t status = scan_for(context, view, options, scan)) return status;
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
        if (const int32_t status = build_solid(context, solid, judged, mesh)) return status;
        mesh.warnings |= POLYMASS_WARNING_HULL;
        const core::RigidBody body = core::rigid_body(mesh.integrals, mesh.reference, 1.0);
        mesh.approximation.volume = body.volume;
        mesh.approximation.center_of_mass = scan.bounds.sizes().maxCoeff();
        mesh.approximation.inertia = 2.0 * body.inertia.diagonal().maxCoeff();
        provenance.hull_vertex_count = solid.vertex_count;
        provenance.hull_triangle_count = solid.face_count;
        provenance.hull_volume = body.volume;
        return POLYMASS_OK;
    });
}

}  // namespace

int32_t build_answer(polymass_context* context, const polymass_mesh_desc* desc,
                     const polymass_options& options, polymass_mesh& mesh,
                     polymass_provenance& provenance) {
    MeshInput input;
    const int32_t read = read_mesh_desc(context, desc, input);
    // Faces too small are the solid's error, which repair can mend.
    if (read != POLYMASS_OK && !(read == POLYMASS_ERROR_FACE_TOO_SMALL && input.sizes_add_up))
        return read;
    uint32_t chain[POLYMASS_MAX_MODES] = {POLYMASS_MODE_SOLID};
    std::size_t length = 0;
    while (length < POLYMASS_MAX_MODES && options.modes[length] != POLYMASS_MODE_NONE) {
        chain[length] = options.modes[length];
        ++length;
    }
    length = std::max<std::size_t>(length, 1);

    provenance = blank_provenance();
    Reasons reasons;
    int32_t first_status = POLYMASS_OK;
    auto failed = [&](uint32_t mode, int32_t status) {
        reasons.add(mode, context->message);
        if (first_status == POLYMASS_OK) first_status = status;
    };
    bool solid_tried = false;
    int32_t solid_status = POLYMASS_OK;
    for (std::size_t i = 0; i < length; ++i) {
        const uint32_t mode = chain[i];
        int32_t status = POLYMASS_OK;
        if (mode == POLYMASS_MODE_SOLID || mode == POLYMASS_MODE_REPAIR) {
            // A valid solid is its own answer, in either mode; it is judged once.
            if (!solid_tried) {
                solid_tried = true;
                solid_status =
                    read != POLYMASS_OK ? read : build_solid(context, input, options, mesh);
                if (solid_status != POLYMASS_OK) failed(POLYMASS_MODE_SOLID, solid_status);
            }
            if (solid_status == POLYMASS_OK) {
                provenance.mode = POLYMASS_MODE_SOLID;
                return POLYMASS_OK;
            }
            if (mode == POLYMASS_MODE_SOLID) continue;
            status = build_repaired(context, input, options, mesh, provenance);
        } else if (mode == POLYMASS_MODE_SHELL) {
            status = build_shell(context, input, options, mesh, provenance);
        } else {
            status = build_hull(context, input, options, mesh, provenance);
        }
        if (status == POLYMASS_OK) {
            provenance.mode = int32_t(mode);
            context->clear_message();  // the modes before it failed: a success says nothing
            return POLYMASS_OK;
        }
        failed(mode, status);
    }
    // The solid alone keeps its own message, as before there were modes.
    if (length == 1 && chain[0] == POLYMASS_MODE_SOLID) return first_status;
    return context->fail(first_status, "%s", reasons.text());
}

}  // namespace polymass::capi
