// A batch of triangles' vertices gathered from the caller's arrays into the
// layout the closed forms read: one array per axis and corner, one triangle
// per slot. Per instruction set: gathering is what wider hardware does with
// shuffles, and each set needs its own loads (mesh_integration.cpp runs the
// gatherer of the set it integrates with).
#pragma once

#include <cstddef>
#include <cstdint>

#include "face_blocks.hpp"
#include "instruction_sets.hpp"
#include "lanes.hpp"
#include "mesh_view.hpp"

namespace polymass::core {

// A batch is a block of the summation: its lane sums are reduced before they
// join the block's total, so rounding grows with the number of batches rather
// than of triangles.
inline constexpr std::size_t batch_capacity = 256;
// Gathered slots past the batch's end are filled up to a whole lane group of
// the widest kernel, which reads a group at a time.
inline constexpr std::size_t gathered_group = 2 * lane_count;
static_assert(batch_capacity % gathered_group == 0, "a batch holds whole wide lane groups");
static_assert(kFacesPerBlock % batch_capacity == 0, "a block of triangles holds whole batches");

// Where the triangles of a batch are: faces first_face, first_face + 1, ...
// of an all-triangle mesh, or the listed faces of a mixed one.
template <class Scalar, class Index>
struct TriangleBatch {
    PositionArray<Scalar> positions;
    IndexArray<Index> indices;
    std::size_t count = 0;       // at most batch_capacity
    std::size_t first_face = 0;  // when not listed
    // When not listed: the faces from first_face up to this one are all to
    // be gathered (this batch and the next ones of its block), so their
    // vertices may be fetched ahead.
    std::size_t last_face = 0;
    const std::size_t* faces = nullptr;    // listed faces, or nullptr
    const std::size_t* corners = nullptr;  // their first corner's position in the index array
    double reference[3];
    double inverse_unit;  // a power of two: exact
    // When set (faces not listed): the gatherer checks the batch's indices
    // against vertex_count before it reads a vertex, and marks each vertex
    // it reads in used_marks (addressable_vertices(mesh) bytes, mesh_scan.hpp)
    // with a relaxed byte store: blocks run at the same time may mark one
    // vertex together. The scan's pass over the index array, made by the
    // gather that reads the indices anyway.
    bool marking = false;
    unsigned char* used_marks = nullptr;
    std::size_t vertex_count = 0;

    std::size_t face(std::size_t slot) const { return faces ? faces[slot] : first_face + slot; }
};

// coordinates[axis][corner][slot]: the coordinate along `axis` of corner
// `corner` of the batch's triangle `slot`, as the caller stores it (a float
// widened to double, which is exact). Slots from the batch's count to the
// next multiple of gathered_group hold the reference point: after the move
// into the integration frame, a triangle of zeros, which adds nothing.
struct GatheredTriangles {
    alignas(64) double coordinates[3][3][batch_capacity];
};

// False, having read no vertex, when the batch is marking and an index is
// out of range.
template <class Scalar, class Index>
using TriangleGatherer = bool (*)(const TriangleBatch<Scalar, Index>&, GatheredTriangles&);

// The gatherer built for `set` (which this processor must run). Every one
// gathers the same values and sets the same marks.
template <class Scalar, class Index>
TriangleGatherer<Scalar, Index> triangle_gatherer(InstructionSet set);

}  // namespace polymass::core
