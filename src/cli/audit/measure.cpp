#include "audit/measure.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "audit/resolve.hpp"
#include "library/categories.hpp"
#include "library/solid_moments.hpp"
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

// A mesh that is not a valid solid, as the library's chain answers it:
// repaired, else its convex hull (docs/repair.md), at unit density. Its
// moments are written about its centre of mass from the mass properties:
// there the first moments vanish and the second ones are
// S = tr(I)/2 * 1 - I, since I = tr(S) * 1 - S. The message says what was
// done and how far off it can be (or, when no mode answers, why).
Measured measured_by_chain(const Library& library, polymass_options options, const Model& model) {
    std::fill(std::begin(options.modes), std::end(options.modes), uint32_t(POLYMASS_MODE_NONE));
    options.modes[0] = POLYMASS_MODE_REPAIR;
    options.modes[1] = POLYMASS_MODE_HULL;
    const Part whole = combined_part(model);  // describe() points into it
    const polymass_mesh_desc desc = describe(model, whole);
    polymass_mass_properties p{};
    polymass_mass_properties_init(&p, sizeof p);
    polymass_provenance provenance{};
    polymass_provenance_init(&provenance, sizeof provenance);
    Measured measured;
    const int32_t status = polymass_mass_properties_with_provenance(
        &p, &provenance, library.context(), &desc, nullptr, &options);
    if (status != POLYMASS_OK) {
        measured.message = "neither repaired nor its hull measured: " + library.message();
        return measured;
    }
    measured.ok = true;
    polymass_moments_init(&measured.moments, sizeof measured.moments);
    measured.moments.volume = p.volume;
    measured.moments.mass = p.mass;
    const double half_trace = (p.inertia[0] + p.inertia[4] + p.inertia[8]) / 2;
    const double second[6] = {half_trace - p.inertia[0],
                              half_trace - p.inertia[4],
                              half_trace - p.inertia[8],
                              -p.inertia[1],
                              -p.inertia[5],
                              -p.inertia[2]};
    for (int k = 0; k < 3; ++k) measured.moments.reference[k] = p.center_of_mass[k];
    for (int k = 0; k < 6; ++k) measured.moments.second[k] = second[k];
    measured.message =
        provenance_text(provenance) + " (off by at most " + error_bound_text(p) + ")";
    return measured;
}

}  // namespace

Measured measure_mesh_file(const Library& library, const polymass_options& options,
                           const std::string& path) {
    Model model;
    try {
        model = read_mesh_file(path, "");
    } catch (const ReadError& error) {
        return failure("unreadable_mesh", path + ": " + error.what());
    }
    const IntegratedSolid solid(library, model, combined_part(model), options);
    Measured measured;
    if (solid.valid()) {
        measured.moments = solid.moments(library);
    } else {
        const SolidResult why = solid.failure();
        const std::string not_a_solid = path + ": " + category_of(why.status) + ": " + why.message;
        measured = measured_by_chain(library, options, model);
        if (!measured.ok) {
            return failure("not_a_solid", not_a_solid + "; " + measured.message);
        }
        measured.kind = "approximated_geometry";
        measured.message = not_a_solid + "; measured as " + measured.message;
    }
    measured.ok = true;
    for (std::size_t v = 0; v + 2 < model.positions.size(); v += 3) {
        measured.points.emplace_back(model.positions[v], model.positions[v + 1],
                                     model.positions[v + 2]);
    }
    return measured;
}

Measured measure_primitive(const Geometry& geometry) {
    const Eigen::Vector3d& s = geometry.size;
    Measured measured;
    switch (geometry.shape) {
        case Shape::kBox: {
            if (!positive_finite(s, 3)) break;
            const double volume = s[0] * s[1] * s[2];
            measured.moments = centred_moments(volume, volume * s.cwiseProduct(s) / 12.0);
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
            measured.moments = centred_moments(volume, volume * radii.cwiseProduct(radii) / 5.0);
            measured.points = box_corners(radii);
            measured.ok = true;
            break;
        }
        case Shape::kCylinder:
        case Shape::kCapsule: {
            const double r = s[0], h = s[1];
            if (!(std::isfinite(r) && r > 0.0 && std::isfinite(h) && h >= 0.0)) break;
            if (geometry.shape == Shape::kCylinder && !(h > 0.0)) break;
            const double cylinder = kPi * r * r * h;
            Eigen::Vector3d second(cylinder * r * r / 4, cylinder * r * r / 4,
                                   cylinder * h * h / 12);
            double volume = cylinder;
            double half_height = h / 2;
            if (geometry.shape == Shape::kCapsule) {
                // Two hemispheres, whole sphere about the axis; along it,
                // each about its flat face moved to +-h/2 (docs/audit.md).
                const double sphere = 4.0 / 3.0 * kPi * r * r * r;
                volume += sphere;
                second[0] += sphere * r * r / 5;
                second[1] += sphere * r * r / 5;
                second[2] += kPi * r * r * r * h * h / 3 + kPi * r * r * r * r * h / 2 +
                             4.0 / 15.0 * kPi * r * r * r * r * r;
                half_height += r;
            }
            measured.moments = centred_moments(volume, second);
            measured.points = box_corners({r, r, half_height});
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

// The geometry's body scaled (a mesh) and placed by its pose; a failure
// when the library refuses a step (a result out of range).
Measured placed(const Library& library, const Geometry& geometry, Measured measured) {
    MomentsResult step{POLYMASS_OK, {}, measured.moments};
    if (geometry.shape == Shape::kMesh) {
        step = scaled(library, step.moments,
                      {geometry.scale[0], geometry.scale[1], geometry.scale[2]});
        for (Eigen::Vector3d& point : measured.points) point = point.cwiseProduct(geometry.scale);
    }
    std::array<double, 9> rotation{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            rotation[3 * row + column] = geometry.pose.rotation(row, column);
        }
    }
    const Eigen::Vector3d& t = geometry.pose.position;
    if (step.status == POLYMASS_OK) {
        step = transformed(library, step.moments, rotation, {t[0], t[1], t[2]});
    }
    if (step.status != POLYMASS_OK) {
        return failure("bad_geometry", "cannot be scaled or placed: " + step.message);
    }
    measured.moments = step.moments;
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
        measured = measure_mesh_file(library, options, resolved.path);
    } else {
        measured = measure_primitive(geometry);
    }
    if (!measured.ok) return measured;
    return placed(library, geometry, std::move(measured));
}

}  // namespace polymass_cli::audit
