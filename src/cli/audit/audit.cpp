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
#include "library/solid_moments.hpp"

namespace polymass_cli::audit {
namespace {

const std::vector<Geometry>& chosen_geometry(const Link& link, GeometrySource from,
                                             LinkAudit& audit) {
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
    computed.inertia_origin = RowMajor(p.inertia_point);
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

// The link's bodies as one, at the declared mass (or the density), judged.
void add_up(const Library& library, const std::vector<Measured>& bodies,
            const AuditSettings& settings, LinkAudit& audit) {
    std::vector<polymass_moments> moments;
    std::vector<Eigen::Vector3d> points;
    for (const Measured& body : bodies) {
        moments.push_back(body.moments);
        points.insert(points.end(), body.points.begin(), body.points.end());
    }
    MomentsResult total = sum(library, moments);
    if (total.status == POLYMASS_OK) {
        polymass_mass_desc mass{};
        polymass_mass_desc_init(&mass, sizeof mass);
        mass.mass_mode = POLYMASS_MASS_FROM_TOTAL;
        mass.mass = has_mass(audit.declared) ? audit.declared->mass
                                             : settings.density * total.moments.volume;
        total = weighted(library, total.moments, mass);
    }
    // Weighted, the body's inertia_point is about the link origin.
    SolidResult result;
    if (total.status == POLYMASS_OK) {
        result = properties_of(library, total.moments, {0, 0, 0}, NAN, 0);
    } else {
        result.status = total.status;
        result.message = total.message;
    }
    if (result.status != POLYMASS_OK) {
        audit.findings.push_back({"bad_geometry", Severity::kError,
                                  "the link's geometry cannot be added up: " + result.message});
        return;
    }
    audit.computed = computed_from(result.properties, points);
    if (has_mass(audit.declared)) {
        for (Finding& finding : judge_against_geometry(*audit.declared, *audit.computed)) {
            audit.findings.push_back(std::move(finding));
        }
    }
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
    const std::vector<Geometry>& geometries = chosen_geometry(link, settings.from, audit);
    if (audit.declared) {
        for (Finding& finding : judge_declared(*audit.declared)) {
            audit.findings.push_back(std::move(finding));
        }
    }
    if (geometries.empty()) {
        if (audit.declared) {
            audit.findings.push_back({"no_geometry", Severity::kInfo,
                                      "an inertial with no geometry to check it against"});
        }
        return audit;
    }
    if (!audit.declared && link.invalid_inertial.empty()) {
        // MuJoCo computes a body's inertia from its geoms when it declares
        // none; URDF and SDFormat simulators substitute defaults.
        const bool inferred = description.format == Format::kMjcf;
        audit.findings.push_back(
            {"no_inertial", inferred ? Severity::kInfo : Severity::kWarning,
             inferred ? "no <inertial>: MuJoCo infers it from the geoms (their densities)"
                      : "geometry but no <inertial>: simulators substitute a default mass"});
    }
    std::vector<Measured> bodies;
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
        }
        bodies.push_back(std::move(measured));
    }
    if (std::all_of(bodies.begin(), bodies.end(), [](const Measured& m) { return m.ok; })) {
        add_up(library, bodies, settings, audit);
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
    audit.text = std::move(description.text);
    return audit;
}

}  // namespace polymass_cli::audit
