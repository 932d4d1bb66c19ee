// One pass over the faces: the ten volume integrals, the surface area, and
// what the pass sees on the way (degenerate and non-planar faces).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "mesh_view.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {

struct IntegrationSettings {
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();  // integrate about this point
    double unit_length = 1.0;  // in this unit (unit_length_near the mesh size)
    double size = 0.0;         // the mesh's bounding-box diagonal
    bool check_planarity = true;
    double planarity_tolerance = 1e-6;  // off-plane distance / face diameter
};

struct FaceFinding {
    std::size_t count = 0;
    std::size_t first = 0;  // the lowest face index, when count > 0

    void record(std::size_t face) {
        if (count++ == 0 || face < first) first = face;
    }

    void merge(const FaceFinding& other) {
        if (other.count > 0 && (count == 0 || other.first < first)) first = other.first;
        count += other.count;
    }
};

struct IntegrationResult {
    VolumeIntegrals integrals;  // about settings.reference
    double surface_area = 0.0;
    FaceFinding degenerate_faces;
    FaceFinding non_planar_faces;
    double max_non_planarity = 0.0;  // relative to the face's diameter
    // The signed volume is at rounding level: each face's term carries an
    // error of order ε·area·size, so a surface of area A and size L (bounding
    // box diagonal) cannot tell |V| ≲ ε·A·L from zero. A slack of 1024 keeps
    // plates as thin as 1e-13 of their width solid. Decided in the integration
    // unit, where neither side can overflow.
    bool encloses_no_volume = false;
};

// Indices must be in range and used coordinates finite (checked before).
template <class Scalar, class Index>
IntegrationResult integrate_mesh(const MeshView<Scalar, Index>& mesh,
                                 const IntegrationSettings& settings);

}  // namespace polymass::core
