#include "audit/measure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>

#include "audit/mujoco_legacy.hpp"
#include "audit/resolve.hpp"
#include "library/categories.hpp"
#include "library/judged_parts.hpp"
#include "library/solid_moments.hpp"
#include "library/surface_analysis.hpp"
#include "readers/mesh_reader.hpp"
#include "reports/provenance.hpp"

namespace polymass_cli::audit {
namespace {

constexpr double kPi = 3.14159265358979323846;

Measured failure(const std::string& kind, const std::string& message) {
    Measured measured;
    measured.kind = kind;
    measured.message = message;
    return measured;
}

// Moments about the centre of a body symmetric under x, y, z -> -x, -y, -z
// per axis: no first moments, no products.
polymass_moments centred_moments(double volume, const Eigen::Vector3d& second) {
    polymass_moments moments{};
    moments.struct_size = sizeof moments;
    moments.volume = volume;
    moments.mass = volume;
    for (int i = 0; i < 3; ++i) moments.second[i] = second[i];
    return moments;
}

std::vector<Eigen::Vector3d> box_corners(const Eigen::Vector3d& half) {
    std::vector<Eigen::Vector3d> corners;
    for (int k = 0; k < 8; ++k) {
        corners.emplace_back((k & 1 ? 1 : -1) * half[0], (k & 2 ? 1 : -1) * half[1],
                             (k & 4 ? 1 : -1) * half[2]);
    }
    return corners;
}

bool positive_finite(const Eigen::Vector3d& v, int count) {
    for (int i = 0; i < count; ++i) {
        if (!(std::isfinite(v[i]) && v[i] > 0.0)) return false;
    }
    return true;
}

// A cylinder (r, length h along z) or a capsule (its caps of radius r
// beyond +-h/2) as a solid.
polymass_moments round_solid(double r, double h, bool capsule) {
    const double cylinder = kPi * r * r * h;
    Eigen::Vector3d second(cylinder * r * r / 4, cylinder * r * r / 4, cylinder * h * h / 12);
    double volume = cylinder;
    if (capsule) {
        // Two hemispheres, whole sphere about the axis; along it, each about
        // its flat face moved to +-h/2 (docs/audit.md).
        const double sphere = 4.0 / 3.0 * kPi * r * r * r;
        volume += sphere;
        second[0] += sphere * r * r / 5;
        second[1] += sphere * r * r / 5;
        second[2] += kPi * r * r * r * h * h / 3 + kPi * r * r * r * r * h / 2 +
                     4.0 / 15.0 * kPi * r * r * r * r * r;
    }
    return centred_moments(volume, second);
}

// Their surfaces (MuJoCo's shellinertia; docs/audit.md): the side
// 2 pi r h (int x^2 = A r^2 / 2, int z^2 = A h^2 / 12), then two discs
// pi r^2 at z = +-h/2 (int x^2 = A r^2 / 4), or two hemispherical caps
// whose flat faces are at +-h/2 (about the axis a sphere's A r^2 / 3;
// along it A ((h/2)^2 + h r / 2 + r^2 / 3) for both).
polymass_moments round_surface(double r, double h, bool capsule) {
    const double side = 2 * kPi * r * h;
    Eigen::Vector3d second(side * r * r / 2, side * r * r / 2, side * h * h / 12);
    double area = side;
    if (capsule) {
        const double sphere = 4 * kPi * r * r;
        area += sphere;
        second[0] += sphere * r * r / 3;
        second[1] += sphere * r * r / 3;
        second[2] += sphere * (h * h / 4 + h * r / 2 + r * r / 3);
    } else {
        const double discs = 2 * kPi * r * r;
        area += discs;
        second[0] += discs * r * r / 4;
        second[1] += discs * r * r / 4;
        second[2] += discs * h * h / 4;
    }
    return centred_moments(area, second);
}

// A box's six faces (edges e): a face of area A across axis i, at
// x_i = +-e_i/2, has int x_i^2 = A e_i^2 / 4 and int x_j^2 = A e_j^2 / 12.
polymass_moments box_surface(const Eigen::Vector3d& e) {
    double area = 0.0;
    Eigen::Vector3d second = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i) {
        const double face = 2 * e[(i + 1) % 3] * e[(i + 2) % 3];  // both faces across i
        area += face;
        for (int j = 0; j < 3; ++j) second[j] += face * e[j] * e[j] / (j == i ? 4.0 : 12.0);
    }
    return centred_moments(area, second);
}

// An ellipsoid's surface as MuJoCo weighs it, which has no closed form: the
// area by Thomsen's approximation (p = 1.6075, within 1.1 %), the moments
// those of the solid ellipsoid of radii + 1e-6 less the solid of radii,
// at the density that gives that area's mass (docs/audit.md).
polymass_moments mujoco_ellipsoid_surface(const Eigen::Vector3d& radii) {
    const double p = 1.6075;
    const double a = radii[0], b = radii[1], c = radii[2];
    const double mean = (std::pow(a * b, p) + std::pow(b * c, p) + std::pow(c * a, p)) / 3;
    const double area = 4 * kPi * std::pow(mean, 1 / p);
    const Eigen::Vector3d grown = radii.array() + 1e-6;
    const double inner = 4 * kPi * radii.prod() / 3;
    const double outer = 4 * kPi * grown.prod() / 3;
    const double density = area / (outer - inner);
    const Eigen::Vector3d second =
        density * (outer * grown.cwiseProduct(grown) - inner * radii.cwiseProduct(radii)) / 5;
    return centred_moments(area, second);
}

// The chain of modes that answers for a body: the hull, the surface as a
// sheet, or the solid - else the surface repaired, else its hull.
std::vector<uint32_t> modes_for(MeshBody body) {
    switch (body) {
        case MeshBody::kHull:
            return {POLYMASS_MODE_HULL};
        case MeshBody::kSurface:
            return {POLYMASS_MODE_SHELL};
        case MeshBody::kSolid:
            break;
    }
    return {POLYMASS_MODE_SOLID, POLYMASS_MODE_REPAIR, POLYMASS_MODE_HULL};
}

// A mesh analysed once, answered by the chain of modes, first answer first
// (docs/repair.md); a sheet (SHELL) of unit thickness.
SurfaceAnalysis analysed_by_modes(const Library& library, polymass_options options,
                                  const Model& model, const std::vector<uint32_t>& modes) {
    std::fill(std::begin(options.modes), std::end(options.modes), uint32_t(POLYMASS_MODE_NONE));
    std::copy(modes.begin(), modes.end(), std::begin(options.modes));
    options.shell_thickness = 1.0;
    return SurfaceAnalysis(library, model, combined_part(model), options);
}

// The body that answered, at unit density (a sheet: unit area density);
// not ok when none did. When it is not the exact solid, the message says
// what was done and how far off it can be.
Measured measured_answer(const Library& library, const SurfaceAnalysis& analysis) {
    Measured measured;
    polymass_mass_desc unit{};
    polymass_mass_desc_init(&unit, sizeof unit);
    const SolidResult answer = analysis.properties(library, unit);
    if (answer.status != POLYMASS_OK) {
        measured.message = answer.message;
        return measured;
    }
    measured.ok = true;
    measured.moments = analysis.moments(library);
    if (answer.provenance.mode != POLYMASS_MODE_SOLID)
        measured.message = provenance_text(answer.provenance) + " (off by at most " +
                           error_bound_text(answer.properties) + ")";
    return measured;
}

// The mesh as the body asked for, answered by its chain of modes; not ok
// (a finding) when none answered. A solid answered otherwise than as the
// exact solid says so, with the surface's defect and the bound.
Measured measured_by_modes(const Library& library, const polymass_options& options,
                           const Model& model, MeshBody body, const std::string& path) {
    const SurfaceAnalysis analysis = analysed_by_modes(library, options, model, modes_for(body));
    Measured measured = measured_answer(library, analysis);
    if (body != MeshBody::kSolid) {
        if (!measured.ok)
            return failure("bad_geometry", path + ": not measured: " + measured.message);
        measured.message.clear();  // the body asked for, exact: nothing to report
        return measured;
    }
    // The surface's defect in words; when no mode answered, each later
    // mode's reason follows it.
    const std::string defect = path + ": " + category_of(analysis.diagnostics().status);
    const std::string why = analysis.failure().message;
    if (!measured.ok) return failure("not_a_solid", defect + ": not measured: solid: " + why);
    if (!measured.message.empty()) {
        measured.kind = "approximated_geometry";
        measured.message =
            defect + (why.empty() ? "" : ": " + why) + "; measured as " + measured.message;
    }
    return measured;
}

}  // namespace

MeshBody mesh_body(const Weighing& weighing) {
    switch (weighing.mesh_inertia) {
        case MeshInertia::kConvex:
            return MeshBody::kHull;
        case MeshInertia::kShell:
            return MeshBody::kSurface;
        case MeshInertia::kLegacy:
        case MeshInertia::kExact:
            break;
    }
    return MeshBody::kSolid;
}

Measured measure_mesh_file(const Library& library, const polymass_options& options,
                           const std::string& path, MeshBody body, const Eigen::Vector3d& scale,
                           bool legacy) {
    Model model;
    try {
        model = read_mesh_file(path, "");
    } catch (const ReadError& error) {
        return failure("unreadable_mesh", path + ": " + error.what());
    }
    if (body == MeshBody::kSurface) {
        // A surface's area does not follow a per-axis stretch of its moments:
        // the vertices are scaled first (and a mirror needs no turning).
        std::vector<double>& positions = model.positions.as_doubles();
        for (std::size_t v = 0; v < positions.size(); ++v) {
            positions[v] *= scale[static_cast<int>(v % 3)];
        }
    }
    Measured measured;
    // A solid of several parts (a link exported as objects resting on each
    // other) is their exact sum, as `polymass FILE` answers it (with the
    // library's options, which are the audit's).
    const std::optional<SolidParts> parts =
        body == MeshBody::kSolid ? solid_parts(library, model) : std::nullopt;
    if (parts) {
        measured.ok = true;
        measured.moments = parts->moments;
    } else {
        measured = measured_by_modes(library, options, model, body, path);
        if (!measured.ok) return measured;
    }
    for (uint64_t v = 0; v < model.vertex_count(); ++v) {
        const std::array<double, 3> p = model.positions.vertex(v);
        measured.points.emplace_back(p[0], p[1], p[2]);
    }
    if (legacy) {
        measured.legacy_asked = true;
        measured.legacy = mujoco_legacy_moments(model, scale);
    }
    if (body == MeshBody::kSurface) return measured;
    const MomentsResult step = scaled(library, measured.moments, {scale[0], scale[1], scale[2]});
    if (step.status != POLYMASS_OK) {
        return failure("bad_geometry", path + ": cannot be scaled: " + step.message);
    }
    measured.moments = step.moments;
    for (Eigen::Vector3d& point : measured.points) point = point.cwiseProduct(scale);
    return measured;
}

Measured measure_primitive(const Geometry& geometry) {
    const Eigen::Vector3d& s = geometry.size;
    const bool surface = geometry.weighing.shell;
    Measured measured;
    switch (geometry.shape) {
        case Shape::kBox: {
            if (!positive_finite(s, 3)) break;
            measured.moments = surface
                                   ? box_surface(s)
                                   : centred_moments(s.prod(), s.prod() * s.cwiseProduct(s) / 12.0);
            measured.points = box_corners(s / 2);
            measured.ok = true;
            break;
        }
        case Shape::kSphere:
        case Shape::kEllipsoid: {
            const Eigen::Vector3d radii =
                geometry.shape == Shape::kSphere ? Eigen::Vector3d::Constant(s[0]) : s;
            if (!positive_finite(radii, 3)) break;
            const double volume = 4.0 / 3.0 * kPi * radii.prod();
            if (!surface) {
                measured.moments =
                    centred_moments(volume, volume * radii.cwiseProduct(radii) / 5.0);
            } else if (geometry.shape == Shape::kSphere) {
                const double area = 4 * kPi * s[0] * s[0];
                measured.moments = centred_moments(area, area * radii.cwiseProduct(radii) / 3.0);
            } else {
                measured.moments = mujoco_ellipsoid_surface(radii);
            }
            measured.points = box_corners(radii);
            measured.ok = true;
            break;
        }
        case Shape::kCylinder:
        case Shape::kCapsule: {
            const double r = s[0], h = s[1];
            if (!(std::isfinite(r) && r > 0.0 && std::isfinite(h) && h >= 0.0)) break;
            if (geometry.shape == Shape::kCylinder && !(h > 0.0)) break;
            const bool capsule = geometry.shape == Shape::kCapsule;
            measured.moments = surface ? round_surface(r, h, capsule) : round_solid(r, h, capsule);
            measured.points = box_corners({r, r, h / 2 + (capsule ? r : 0.0)});
            measured.ok = true;
            break;
        }
        case Shape::kMesh:
            break;
    }
    if (!measured.ok) {
        return failure("bad_geometry", "a shape whose sizes are not positive and finite");
    }
    return measured;
}

namespace {

// The geometry's body placed by its pose; a failure when the library
// refuses (a result out of range).
Measured placed(const Library& library, const Geometry& geometry, Measured measured) {
    std::array<double, 9> rotation{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            rotation[3 * row + column] = geometry.pose.rotation(row, column);
        }
    }
    const Eigen::Vector3d& t = geometry.pose.position;
    const MomentsResult step = transformed(library, measured.moments, rotation, {t[0], t[1], t[2]});
    if (step.status != POLYMASS_OK) {
        return failure("bad_geometry", "cannot be placed: " + step.message);
    }
    measured.moments = step.moments;
    if (measured.legacy) {
        const MomentsResult legacy =
            transformed(library, *measured.legacy, rotation, {t[0], t[1], t[2]});
        if (legacy.status != POLYMASS_OK) {
            return failure("bad_geometry", "cannot be placed: " + legacy.message);
        }
        measured.legacy = legacy.moments;
    }
    for (Eigen::Vector3d& point : measured.points) {
        point = geometry.pose.rotation * point + geometry.pose.position;
    }
    return measured;
}

}  // namespace

Measured measure_geometry(const Library& library, const polymass_options& options,
                          const Geometry& geometry, const std::string& description_path) {
    Measured measured;
    if (!geometry.invalid.empty()) return failure("invalid_element", geometry.invalid);
    if (geometry.shape == Shape::kMesh) {
        const Resolved resolved = resolve_mesh(geometry.uri, description_path);
        if (resolved.path.empty()) return failure("unreadable_mesh", resolved.error);
        if (!(geometry.scale.array().isFinite().all() && (geometry.scale.array() != 0).all())) {
            return failure("bad_geometry",
                           geometry.uri + ": a mesh scale with a zero or non-finite factor");
        }
        measured = measure_mesh_file(library, options, resolved.path, mesh_body(geometry.weighing),
                                     geometry.scale,
                                     geometry.weighing.mesh_inertia == MeshInertia::kLegacy);
    } else {
        measured = measure_primitive(geometry);
    }
    if (!measured.ok) return measured;
    return placed(library, geometry, std::move(measured));
}

}  // namespace polymass_cli::audit
