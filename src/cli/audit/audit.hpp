// The audit of a description: each link's declared inertial next to the one
// computed from its geometry, and what is wrong (findings).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "audit/description.hpp"
#include "library/solid.hpp"

namespace polymass_cli::audit {

enum class Severity { kInfo, kWarning, kError };
const char* severity_name(Severity severity);
// "info", "warning", "error" -> severity; false for another word.
bool severity_from_name(const std::string& name, Severity& severity);

struct Finding {
    std::string kind;  // snake_case, listed in the README
    Severity severity = Severity::kInfo;
    std::string message;
};

enum class GeometrySource { kCollision, kVisual };

// The link's geometry as one body. URDF and SDFormat: at the declared mass
// (or, without one, at the density the audit was given). MJCF: what MuJoCo's
// compiler infers from the geoms (their densities and masses, the groups it
// weighs, shells, the <compiler> rules), every mesh integrated exactly.
struct Computed {
    double volume = 0.0;
    double mass = 0.0;
    double density = 0.0;
    Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  // link frame
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass, link axes
    Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();      // about the link frame's origin
    Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();   // ascending
    Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();  // columns
    Eigen::Vector3d box_min = Eigen::Vector3d::Zero();             // the geometry's bounding box
    Eigen::Vector3d box_max = Eigen::Vector3d::Zero();
    std::vector<std::string> rules;  // which rules produced the numbers, in order
};

struct LinkAudit {
    std::string name;
    // What was measured: "collision", "visual", "weighed" (MJCF: the geoms
    // MuJoCo weighs, visual or not) or "none".
    const char* geometry = "none";
    const char* mujoco_uses = nullptr;  // MJCF: "declared", "computed" or "none"
    // Geometry that could not be measured: the link's mass is unknown.
    bool unmeasured = false;
    std::optional<Inertial> declared;
    std::optional<Computed> computed;
    // MJCF, when some of the body's meshes keep MuJoCo's default (legacy)
    // inertia: what MuJoCo will use, those meshes weighed by that rule.
    std::optional<Computed> mujoco_legacy;
    // The geometry at the declared mass (its mass distribution kept), which
    // the declared inertial is judged against and --fix writes; the same as
    // computed for URDF and SDFormat.
    std::optional<Computed> at_declared_mass;
    std::vector<Finding> findings;
};

struct FileAudit {
    std::string path;
    Format format = Format::kUrdf;
    std::string error;  // the description could not be read (then no links)
    std::string text;   // the description's bytes (what --fix edits)
    std::vector<LinkAudit> links;
};

struct AuditSettings {
    GeometrySource from = GeometrySource::kCollision;
    // Links without a declared mass are computed at this density (kg/m^3).
    double density = 1000.0;
    polymass_options options{};  // how meshes are validated
};

// Reads, measures and judges one description file.
FileAudit audit_file(const Library& library, const std::string& path,
                     const AuditSettings& settings);

}  // namespace polymass_cli::audit
