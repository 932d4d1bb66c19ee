// The body of each geometry of a link, as unit-density moments in the link
// frame, with the points that bound it (for the link's size and whether the
// declared centre of mass lies within it).
#pragma once

#include <polymass/polymass.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "audit/description.hpp"
#include "library/solid.hpp"

namespace polymass_cli::audit {

struct Measured {
    bool ok = false;
    polymass_moments moments{};           // unit density
    std::vector<Eigen::Vector3d> points;  // its vertices, or its bounding box's corners
    // When not ok: the finding's kind ("unreadable_mesh", "not_a_solid",
    // "bad_geometry") and what the reader or the library said. When ok but
    // not exact ("approximated_geometry": a mesh that is not a solid,
    // repaired or replaced by its hull): what was done and its bound.
    std::string kind;
    std::string message;
    // A mesh whose MJCF asset keeps MuJoCo's default (legacy) inertia: the
    // body that rule weighs (audit/mujoco_legacy), or nothing when MuJoCo
    // refuses the mesh in that mode.
    bool legacy_asked = false;
    std::optional<polymass_moments> legacy;
};

// What of a mesh is weighed: the solid it bounds, its convex hull, or its
// surface as a sheet (unit area density).
enum class MeshBody { kSolid, kHull, kSurface };

// The body MuJoCo weighs for a mesh of this inertia mode (legacy weighs the
// solid too, by its own rule: audit/mujoco_legacy); the solid for URDF and
// SDFormat, whose weighing keeps the defaults.
MeshBody mesh_body(const Weighing& weighing);

// A mesh file in its own frame and units, stretched by scale per axis. A
// mesh that is not a valid solid is measured as the library's modes answer
// it (repaired, else its convex hull), the provenance and bound said. With
// legacy, MuJoCo's legacy body too.
Measured measure_mesh_file(const Library& library, const polymass_options& options,
                           const std::string& path, MeshBody body, const Eigen::Vector3d& scale,
                           bool legacy);

// A primitive shape in closed form (docs/audit.md), about its centre, its
// axis along z: box, cylinder, sphere, capsule, ellipsoid; with
// weighing.shell its surface, as MuJoCo weighs it (unit area density).
Measured measure_primitive(const Geometry& geometry);

// The geometry in the link frame: its mesh resolved (from the description's
// directory) and measured (validated with options), or its shape, scaled
// then placed by its pose.
Measured measure_geometry(const Library& library, const polymass_options& options,
                          const Geometry& geometry, const std::string& description_path);

}  // namespace polymass_cli::audit
