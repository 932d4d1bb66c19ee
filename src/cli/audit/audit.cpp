// Each link of a description: its geometry chosen (collision, or visual with
// --from visual, the other kind when a link has only that), each geometry
// measured in the link frame, the bodies added through the library's
// moments, the sum taken at the declared mass, and the findings judged.
#include "audit/audit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "audit/judge.hpp"
#include "audit/measure.hpp"
#include "audit/mirror.hpp"
#include "audit/mujoco_inertia.hpp"
#include "library/solid_moments.hpp"

namespace polymass_cli::audit {
namespace {

std::vector<Geometry> chosen_geometry(const Link& link, GeometrySource from, LinkAudit& audit) {
    const bool collision_first = from == GeometrySource::kCollision;
    const std::vector<Geometry>& first = collision_first ? link.collision : link.visual;
    const std::vector<Geometry>& second = collision_first ? link.visual : link.collision;
    const char* first_name = collision_first ? "collision" : "visual";
    const char* second_name = collision_first ? "visual" : "collision";
    if (!first.empty() || second.empty()) {
        audit.geometry = first.empty() ? "none" : first_name;
        return first;
    }
    audit.geometry = second_name;
    audit.findings.push_back({"geometry_source", Severity::kInfo,
                              std::string("no ") + first_name + " geometry: the " + second_name +
                                  " geometry is measured"});
    return second;
}

Computed computed_from(const polymass_mass_properties& p,
                       const std::vector<Eigen::Vector3d>& points) {
    using RowMajor = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>;
    Computed computed;
    computed.volume = p.volume;
    computed.mass = p.mass;
    computed.density = p.density;
    computed.center_of_mass = Eigen::Vector3d(p.center_of_mass);
    computed.inertia = RowMajor(p.inertia);
    computed.inertia_origin = RowMajor(p.inertia_origin);
    computed.principal_moments = Eigen::Vector3d(p.principal_moments);
    computed.principal_axes = RowMajor(p.principal_axes);
    computed.box_min = computed.box_max = points.front();
    for (const Eigen::Vector3d& point : points) {
        computed.box_min = computed.box_min.cwiseMin(point);
        computed.box_max = computed.box_max.cwiseMax(point);
    }
    return computed;
}

// Whether the link declares a mass the geometry can be weighed to.
bool has_mass(const std::optional<Inertial>& declared) {
    return declared && std::isfinite(declared->mass) && declared->mass > 0.0;
}

// The moments with their mass set to mass (the distribution kept).
MomentsResult at_mass(const Library& library, const polymass_moments& moments, double mass) {
    polymass_mass_desc desc{};
    polymass_mass_desc_init(&desc, sizeof desc);
    desc.mass_mode = POLYMASS_MASS_FROM_TOTAL;
    desc.mass = mass;
    return weighted(library, moments, desc);
}

// The mass properties of weighted moments (inertia_origin about the link
// origin), the bounding box of points; or the finding why not.
std::optional<Computed> computed_of(const Library& library, const MomentsResult& total,
                                    const std::vector<Eigen::Vector3d>& points, LinkAudit& audit) {
    SolidResult result;
    if (total.status == POLYMASS_OK) {
        result = properties_of(library, total.moments, NAN, 0);
    } else {
        result.status = total.status;
        result.message = total.message;
    }
    if (result.status != POLYMASS_OK) {
        audit.findings.push_back({"bad_geometry", Severity::kError,
                                  "the link's geometry cannot be added up: " + result.message});
        return std::nullopt;
    }
    return computed_from(result.properties, points);
}

// The finding for geometry without an inertial: MuJoCo infers one from the
// geoms (unless inertiafromgeom is false); URDF and SDFormat simulators
// substitute defaults.
Finding no_inertial_finding(const Description& description) {
    if (description.format != Format::kMjcf) {
        return {"no_inertial", Severity::kWarning,
                "geometry but no <inertial>: simulators substitute a default mass"};
    }
    if (description.compiler.inertia_from_geom == MujocoCompiler::FromGeom::kFalse) {
        return {"no_inertial", Severity::kWarning,
                "no <inertial> and inertiafromgeom=\"false\": MuJoCo gives the body no mass"};
    }
    return {"no_inertial", Severity::kInfo,
            "no <inertial>: MuJoCo infers it from the geoms (their densities)"};
}

// The bodies (each weighted already) as one: audit.computed as they weigh
// (MJCF) or at the declared mass, else the density (URDF, SDFormat); judged
// against the declared inertial at its mass.
void add_up(const Library& library, const std::vector<Measured>& bodies, bool weighted_already,
            bool has_mesh, const AuditSettings& settings, LinkAudit& audit) {
    std::vector<polymass_moments> moments;
    std::vector<Eigen::Vector3d> points;
    for (const Measured& body : bodies) {
        moments.push_back(body.moments);
        points.insert(points.end(), body.points.begin(), body.points.end());
    }
    const MomentsResult total = sum(library, moments);
    MomentsResult reported = total;
    if (!weighted_already && total.status == POLYMASS_OK) {
        reported = at_mass(library, total.moments,
                           has_mass(audit.declared) ? audit.declared->mass
                                                    : settings.density * total.moments.volume);
    }
    audit.computed = computed_of(library, reported, points, audit);
    if (!audit.computed || !has_mass(audit.declared)) return;
    std::optional<Computed> judged = audit.computed;
    if (weighted_already) {
        judged = computed_of(library, at_mass(library, total.moments, audit.declared->mass), points,
                             audit);
    }
    if (!judged) return;
    for (Finding& finding : judge_against_geometry(*audit.declared, *judged, has_mesh)) {
        audit.findings.push_back(std::move(finding));
    }
    audit.at_declared_mass = std::move(judged);
}

// What MuJoCo weighs of a body: the geoms in inertiagrouprange, collision
// and visual alike; the others are said in the rules.
std::vector<Geometry> mujoco_geometry(const Description& description, const Link& link,
                                      std::vector<std::string>& rules) {
    std::vector<Geometry> weighed;
    std::size_t left_out = 0;
    for (const std::vector<Geometry>* list : {&link.collision, &link.visual}) {
        for (const Geometry& geometry : *list) {
            if (weighed_by_mujoco(geometry.weighing, description.compiler)) {
                weighed.push_back(geometry);
            } else {
                ++left_out;
            }
        }
    }
    if (left_out > 0) {
        rules.push_back("inertiagrouprange " + std::to_string(description.compiler.group_low) +
                        " " + std::to_string(description.compiler.group_high) + ": " +
                        std::to_string(left_out) + " geom(s) of other groups not weighed");
    }
    return weighed;
}

// The geom's body at MuJoCo's mass, and its legacy body (when it has one)
// at the mass MuJoCo gives that; false (and the finding) when the library
// refuses.
bool weigh(const Library& library, const Weighing& weighing, double mass, Measured& measured,
           LinkAudit& audit) {
    MomentsResult step = at_mass(library, measured.moments, mass);
    if (step.status == POLYMASS_OK && measured.legacy) {
        const MomentsResult legacy =
            at_mass(library, *measured.legacy, mujoco_geom_mass(weighing, measured.legacy->volume));
        measured.legacy = legacy.moments;
        if (legacy.status != POLYMASS_OK) step = legacy;
    }
    if (step.status != POLYMASS_OK) {
        audit.findings.push_back(
            {"bad_geometry", Severity::kError, "a geom cannot be weighed: " + step.message});
        return false;
    }
    measured.moments = step.moments;
    return true;
}

// MuJoCo's own figure for a body some of whose meshes keep its default
// (legacy) inertia: those meshes weighed by that rule, the other geoms as
// they are; and how far it is from the exact one.
void add_legacy_figure(const Library& library, const std::vector<Measured>& bodies,
                       const MujocoCompiler& compiler, LinkAudit& audit) {
    if (std::none_of(bodies.begin(), bodies.end(),
                     [](const Measured& body) { return body.legacy_asked; })) {
        return;
    }
    if (std::any_of(bodies.begin(), bodies.end(),
                    [](const Measured& body) { return body.legacy_asked && !body.legacy; })) {
        audit.findings.push_back({"legacy_mesh_inertia", Severity::kWarning,
                                  "MuJoCo refuses a mesh of this body in its default (legacy) "
                                  "inertia mode: no volume by that rule; set inertia=\"exact\" "
                                  "on the <mesh>"});
        return;
    }
    std::vector<polymass_moments> moments;
    std::vector<Eigen::Vector3d> points;
    for (const Measured& body : bodies) {
        moments.push_back(body.legacy ? *body.legacy : body.moments);
        points.insert(points.end(), body.points.begin(), body.points.end());
    }
    audit.mujoco_legacy = computed_of(library, sum(library, moments), points, audit);
    if (!audit.mujoco_legacy) return;
    for (const std::string& rule : audit.computed->rules) {
        audit.mujoco_legacy->rules.push_back(
            rule.rfind("mesh inertia legacy", 0) == 0
                ? "mesh inertia legacy (MuJoCo's default): MuJoCo's legacy rule"
                : rule);
    }
    apply_body_rules(compiler, *audit.mujoco_legacy);
    if (std::optional<Finding> finding = judge_legacy(*audit.computed, *audit.mujoco_legacy)) {
        audit.findings.push_back(std::move(*finding));
    }
}

// The rules that weighed an MJCF body's geoms, said once each.
void add_rule(std::vector<std::string>& rules, const std::string& rule) {
    if (std::find(rules.begin(), rules.end(), rule) == rules.end()) rules.push_back(rule);
}

std::string weighing_rule(const Geometry& geometry) {
    const Weighing& w = geometry.weighing;
    if (w.mass) return "geom mass: the geom's mass given, its density derived";
    if (geometry.shape == Shape::kMesh) {
        switch (w.mesh_inertia) {
            case MeshInertia::kConvex:
                return "mesh inertia convex: the mesh's convex hull, exactly";
            case MeshInertia::kShell:
                return "mesh inertia shell: the mesh's surface at the density per area";
            case MeshInertia::kExact:
                return "mesh inertia exact: the solid mesh, exactly";
            case MeshInertia::kLegacy:
                return "mesh inertia legacy (MuJoCo's default): the solid mesh here, exactly";
        }
    }
    if (w.shell) return "shellinertia: the shape's surface at the density per area";
    return "geom density";
}

LinkAudit audit_link(const Library& library, const Description& description, const Link& link,
                     const AuditSettings& settings) {
    LinkAudit audit;
    audit.name = link.name;
    audit.declared = link.inertial;
    for (const std::string& message : link.unsupported) {
        audit.findings.push_back({"unsupported", Severity::kInfo, message});
    }
    if (!link.invalid_inertial.empty()) {
        audit.findings.push_back({"invalid_element", Severity::kError,
                                  link.invalid_inertial + " (the inertial is not checked)"});
    }
    const bool mjcf = description.format == Format::kMjcf;
    std::vector<std::string> rules;
    std::vector<Geometry> geometries;
    if (mjcf) {
        geometries = mujoco_geometry(description, link, rules);
        audit.geometry = geometries.empty() ? "none" : "weighed";
    } else {
        geometries = chosen_geometry(link, settings.from, audit);
    }
    if (audit.declared) {
        for (Finding& finding : judge_declared(*audit.declared)) {
            audit.findings.push_back(std::move(finding));
        }
    }
    if (geometries.empty()) {
        audit.unmeasured = link.weighs_unmeasured;
        if (audit.declared) {
            audit.findings.push_back({"no_geometry", Severity::kInfo,
                                      "an inertial with no geometry to check it against"});
        }
        return audit;
    }
    if (!audit.declared && link.invalid_inertial.empty()) {
        audit.findings.push_back(no_inertial_finding(description));
    }
    std::vector<Measured> bodies;
    bool all_measured = true;
    for (const Geometry& geometry : geometries) {
        Measured measured = measure_geometry(library, settings.options, geometry, description.path);
        if (measured.ok && !measured.kind.empty()) {
            // Measured, but not exactly: the finding says how.
            audit.findings.push_back({measured.kind, Severity::kWarning, measured.message});
        } else if (!measured.ok) {
            const Severity severity =
                measured.kind == "not_a_solid" ? Severity::kWarning : Severity::kError;
            audit.findings.push_back({measured.kind, severity,
                                      measured.message + " (the link's inertia is not checked)"});
            all_measured = false;
            continue;
        }
        if (mjcf && all_measured) {
            // MuJoCo leaves out what weighs nothing.
            const double mass = mujoco_geom_mass(geometry.weighing, measured.moments.volume);
            if (mass == 0.0) continue;
            if (!weigh(library, geometry.weighing, mass, measured, audit)) return audit;
            add_rule(rules, weighing_rule(geometry));
        }
        bodies.push_back(std::move(measured));
    }
    if (!all_measured || link.weighs_unmeasured) {
        audit.unmeasured = true;  // a partial sum would mislead
        return audit;
    }
    if (bodies.empty()) {
        rules.push_back("every geom weighs nothing (mass or density 0)");
    } else {
        const bool has_mesh =
            std::any_of(geometries.begin(), geometries.end(),
                        [](const Geometry& geometry) { return geometry.shape == Shape::kMesh; });
        add_up(library, bodies, mjcf, has_mesh, settings, audit);
        audit.unmeasured = !audit.computed;
    }
    if (!mjcf) {
        // URDF and SDFormat give geometry no density: uniform, at the mass.
        if (audit.computed) {
            audit.computed->rules.push_back(
                std::string(audit.geometry) + " geometry at a uniform density: " +
                (has_mass(audit.declared) ? "the declared mass" : "--density (default 1000)"));
        }
        return audit;
    }
    if (audit.computed) {
        audit.computed->rules = rules;
        add_legacy_figure(library, bodies, description.compiler, audit);
        apply_body_rules(description.compiler, *audit.computed);
    }
    return audit;
}
}  // namespace

const char* severity_name(Severity severity) {
    switch (severity) {
        case Severity::kInfo:
            return "info";
        case Severity::kWarning:
            return "warning";
        case Severity::kError:
            return "error";
    }
    return "error";
}

bool severity_from_name(const std::string& name, Severity& severity) {
    for (const Severity candidate : {Severity::kInfo, Severity::kWarning, Severity::kError}) {
        if (name == severity_name(candidate)) {
            severity = candidate;
            return true;
        }
    }
    return false;
}

FileAudit audit_file(const Library& library, const std::string& path,
                     const AuditSettings& settings) {
    FileAudit audit;
    audit.path = path;
    Description description;
    try {
        description = read_description(path);
    } catch (const DescriptionError& error) {
        audit.error = error.what();
        return audit;
    }
    audit.format = description.format;
    for (const Link& link : description.links) {
        audit.links.push_back(audit_link(library, description, link, settings));
    }
    if (description.format == Format::kMjcf) apply_model_rules(description, audit);
    judge_mirror_pairs(audit);
    audit.text = std::move(description.text);
    return audit;
}

}  // namespace polymass_cli::audit
