// A surface as triangles, for the questions that need them (do faces cross?).
//
// Triangles stay as they are. A polygon face is cut into triangles that cover
// exactly its area (ear clipping in the coordinate plane it projects onto
// best, with exact orientation tests), not a fan: a fan of a non-convex
// polygon covers ground outside the polygon and would make faces seem to
// cross that do not.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mesh_view.hpp"

namespace polymass::core {

struct SurfaceTriangles {
    // Three vertex indices a triangle, in the face's turn: laid out as an
    // index array of triangles is, so that a caller's serves in its place
    // (IndexedSurface).
    std::pmr::vector<std::uint32_t> corners;
    std::pmr::vector<std::uint32_t> face;  // the face each one comes from

    explicit SurfaceTriangles(std::pmr::memory_resource* memory) : corners(memory), face(memory) {}
    std::size_t size() const { return face.size(); }
};

// Indices must be in range and the coordinates finite; faces fewer than 2^32.
template <class Scalar, class Index>
SurfaceTriangles triangulate_faces(const MeshView<Scalar, Index>& mesh,
                                   std::pmr::memory_resource* memory);

}  // namespace polymass::core
