// MuJoCo's legacy mesh inertia, its default (<mesh inertia="legacy">), which
// is not the solid's: docs/audit.md ("MuJoCo's legacy mesh inertia"). The
// audit computes it to say what MuJoCo will use and how far that is from
// the exact figure.
#pragma once

#include <polymass/polymass.h>

#include <Eigen/Core>
#include <optional>

#include "model/model.hpp"

namespace polymass_cli::audit {

// The mesh's moments (unit density, about its centre of mass) as MuJoCo's
// legacy rule weighs it, its vertices first stretched by scale per axis:
// the mesh's triangles (polygons cut into fans from their first corner);
// the pyramids from the area centroid of the faces give the centre of mass,
// the tetrahedra from that centre the volume and second moments, each
// counted positive whichever way its face turns. Nothing when MuJoCo refuses
// the mesh (no area, or no volume).
std::optional<polymass_moments> mujoco_legacy_moments(const Model& model,
                                                      const Eigen::Vector3d& scale);

}  // namespace polymass_cli::audit
