// The convex hull of the vertices a mesh's faces use, computed with exact
// orientation predicates (exact_predicates.hpp): every used vertex is inside
// or on the hull, every hull triangle turns outward, whatever the coordinates'
// magnitude. The hull is returned as a triangle mesh for the exact solid path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mesh_scan.hpp"
#include "mesh_view.hpp"

namespace polymass::core {

enum class HullStatus {
    ok,
    non_finite,      // a used vertex has a NaN or infinite coordinate
    too_few_points,  // fewer than 4 distinct used vertices
    collinear,       // all used vertices on one line
    coplanar,        // all used vertices in one plane: the hull has no volume
    // the orientation tests' signs disagreed (a horizon that is not one
    // loop): nonzero coordinates beyond their exact range, more than 2^640
    // apart in magnitude (exact_predicates.hpp)
    beyond_exact_range,
};

struct ConvexHull {
    HullStatus status = HullStatus::ok;
    std::pmr::vector<double> coordinates;  // x, y, z of each hull vertex (the caller's values)
    std::pmr::vector<std::uint32_t> source_vertex;  // the mesh vertex each hull vertex is
    std::pmr::vector<std::uint32_t> indices;  // 3 per triangle, counter-clockwise from outside
    std::size_t distinct_points = 0;          // distinct used vertices seen

    explicit ConvexHull(std::pmr::memory_resource* memory)
        : coordinates(memory), source_vertex(memory), indices(memory) {}

    std::size_t triangle_count() const { return indices.size() / 3; }
    // The hull as a mesh of triangles (valid while this object lives).
    MeshView<double, std::uint32_t> view() const;
};

// `scan` is scan_mesh(mesh): its used vertices are the hull's input. Indices
// must be in range (checked before); non-finite used vertices give
// HullStatus::non_finite.
template <class Scalar, class Index>
ConvexHull convex_hull(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                       std::pmr::memory_resource* memory);

}  // namespace polymass::core
