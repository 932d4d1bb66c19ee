// One pass over the faces: the ten volume integrals, the surface area, and
// what the pass sees on the way (degenerate and non-planar faces).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory_resource>
#include <vector>

#include "face_blocks.hpp"
#include "findings.hpp"
#include "instruction_sets.hpp"
#include "mesh_view.hpp"
#include "task_runner.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {

struct IntegrationSettings {
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();  // integrate about this point
    // Twice the largest distance of a vertex from the reference (about the
    // centre of the bounding box: its diagonal): sets the integration unit,
    // and bounds the coordinates for the rounding bound.
    double size = 0.0;
    bool check_planarity = true;
    double planarity_tolerance = 1e-6;  // off-plane distance / face diameter
    // Tests force each set the processor runs, to compare their bits.
    InstructionSet instruction_set = widest_instruction_set();
    // When set (all-triangle meshes only): the pass marks the vertices the
    // faces use here, as scan_mesh (mesh_scan.hpp) marks them, and checks
    // the indices of each batch of faces before it reads their vertices - the
    // scan's own pass over the index array, made by the gather that reads the
    // indices anyway (triangle_gather.hpp). addressable_vertices(mesh) bytes,
    // zero to start with. (The
    // vector, not its data: a mesh of no vertex has no marks, and its indices
    // must still be checked - every one is out of range.)
    std::pmr::vector<unsigned char>* used_marks = nullptr;
};

struct IntegrationResult {
    VolumeIntegrals integrals;  // about settings.reference
    IntegralBounds bounds;      // on the rounding errors of `integrals`
    double surface_area = 0.0;
    Finding degenerate_faces;
    Finding non_planar_faces;
    double max_non_planarity = 0.0;  // relative to the face's diameter
    // With used_marks: false when an index is out of range, and then nothing
    // else here is meaningful (some faces were not read).
    bool indices_in_range = true;
    // The signed volume is at rounding level: each face's term carries an
    // error of order ε·area·size, so a surface of area A and size L (bounding
    // box diagonal) cannot tell |V| ≲ ε·A·L from zero. A slack of 1024 keeps
    // plates as thin as 1e-13 of their width solid. Decided in the integration
    // unit, where neither side can overflow.
    bool encloses_no_volume = false;
};

// Indices must be in range (checked before, or with used_marks as it goes)
// and used coordinates finite. The
// blocks of faces (face_blocks.hpp) run as tasks of `runner`, each summed on
// its own, and the blocks' sums are added in block order: the bits depend on
// the mesh alone, not on how many threads run the blocks.
template <class Scalar, class Index>
IntegrationResult integrate_mesh(const MeshView<Scalar, Index>& mesh,
                                 const IntegrationSettings& settings, TaskRunner& runner);

}  // namespace polymass::core
