// A surface as a thin wall: a sheet of area density equal to the thickness,
// integrated exactly (closed forms per triangle), with neither closure nor
// orientation needed. docs/approximations.md states the model and derives how
// far it can be from a solid wall of that thickness.
#pragma once

#include <Eigen/Core>

#include "approximation_bound.hpp"
#include "mesh_view.hpp"
#include "moments.hpp"

namespace polymass::core {

struct ThinShell {
    // The sheet of unit density about the given reference: volume and mass
    // are thickness · area, with their rounding bounds (docs/error_bound.md).
    Moments moments;
    double area = 0.0;
    double area_bound = 0.0;  // on the rounding error of `area`
    // How far a solid wall of the thickness, centred on the surface, can be
    // from the sheet (on top of the rounding), for unit density.
    ApproximationBound wall_bound;
};

// `reference` a point near the surface and `size` the diagonal of its
// bounding box, as in IntegrationSettings (MeshScan gives both). Indices must
// be in range and used coordinates finite (checked before), the thickness
// positive and finite. Polygon faces are cut into a fan from their first
// corner, each triangle counted with the sign of its turn against the face's
// (Newell) normal: exact for any simple planar polygon, convex or not.
template <class Scalar, class Index>
ThinShell thin_shell_moments(const MeshView<Scalar, Index>& mesh, double thickness,
                             const Eigen::Vector3d& reference, double size);

}  // namespace polymass::core
