// Typed, read-only views of the caller's flat arrays.
//
// Positions may be float or double at any byte stride and any alignment (an
// interleaved engine vertex buffer, a NumPy row-strided view), so elements are
// read with memcpy, which compilers turn into plain loads. Indices may be
// 16- or 32-bit. Everything in core/ that walks a mesh is a template over
// MeshView<Scalar, Index>, instantiated for the four combinations.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace polymass::core {

template <class Scalar>
struct PositionArray {
    const unsigned char* base = nullptr;
    std::size_t stride = 0;  // bytes from one vertex to the next

    Eigen::Vector3d operator[](std::size_t vertex) const {
        const unsigned char* xyz = base + vertex * stride;
        // One memcpy per coordinate: into an array, GCC copies through the stack.
        return {coordinate(xyz), coordinate(xyz + sizeof(Scalar)),
                coordinate(xyz + 2 * sizeof(Scalar))};
    }

private:
    static double coordinate(const unsigned char* bytes) {
        Scalar value;
        std::memcpy(&value, bytes, sizeof value);
        return double(value);
    }
};

template <class Index>
struct IndexArray {
    const unsigned char* base = nullptr;

    std::uint32_t operator[](std::size_t position) const {
        Index index;
        std::memcpy(&index, base + position * sizeof(Index), sizeof index);
        return index;
    }
};

template <class Scalar, class Index>
struct MeshView {
    PositionArray<Scalar> positions;
    std::size_t vertex_count = 0;
    IndexArray<Index> indices;
    std::size_t index_count = 0;  // the faces' sizes add up to it (checked by the C API)
    const std::uint32_t* face_sizes = nullptr;  // nullptr: every face is a triangle
    std::size_t face_count = 0;

    bool all_triangles() const { return face_sizes == nullptr; }
};

// Calls visit(face, first, size) for each face in order, where `first` is the
// position in the index array of the face's first vertex.
template <class View, class Visit>
void for_each_face(const View& mesh, Visit&& visit) {
    if (mesh.all_triangles()) {
        // A separate loop, so that visit() is compiled for a constant size of 3.
        for (std::size_t face = 0; face < mesh.face_count; ++face) visit(face, 3 * face, 3);
        return;
    }
    std::size_t first = 0;
    for (std::size_t face = 0; face < mesh.face_count; ++face) {
        const std::size_t size = mesh.face_sizes[face];
        visit(face, first, size);
        first += size;
    }
}

}  // namespace polymass::core

// The element types the C API accepts; each core/*.cpp that defines a template
// over MeshView instantiates it for all of them through this list.
#define POLYMASS_FOR_EACH_MESH_VIEW(X) \
    X(double, std::uint32_t)           \
    X(double, std::uint16_t)           \
    X(float, std::uint32_t)            \
    X(float, std::uint16_t)
