// A mesh for the core tests: coordinates, indices and (for polygon faces)
// face sizes in vectors, seen through the core's MeshView.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <initializer_list>
#include <memory_resource>
#include <vector>

#include "core/mesh_view.hpp"
#include "core/shells.hpp"

namespace polymass_test {

struct TestMesh {
    std::vector<double> coordinates;  // x, y, z per vertex
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> face_sizes;  // empty: all triangles
    bool polygons = false;

    std::uint32_t add_vertex(const Eigen::Vector3d& p) {
        coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
        return std::uint32_t(coordinates.size() / 3 - 1);
    }
    void add_face(std::initializer_list<std::uint32_t> corners) {
        indices.insert(indices.end(), corners);
        face_sizes.push_back(std::uint32_t(corners.size()));
        polygons = polygons || corners.size() != 3;
    }
    Eigen::Vector3d vertex(std::size_t i) const {
        return {coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]};
    }
    std::size_t vertex_count() const { return coordinates.size() / 3; }

    polymass::core::MeshView<double, std::uint32_t> view() const {
        polymass::core::MeshView<double, std::uint32_t> mesh;
        mesh.positions.base = reinterpret_cast<const unsigned char*>(coordinates.data());
        mesh.positions.stride = 3 * sizeof(double);
        mesh.vertex_count = vertex_count();
        mesh.indices.base = reinterpret_cast<const unsigned char*>(indices.data());
        mesh.index_count = indices.size();
        mesh.face_sizes = polygons ? face_sizes.data() : nullptr;
        mesh.face_count = face_sizes.size();
        return mesh;
    }
};

// The box spanned from `corner` by three edge vectors (a right-handed, mutually
// orthogonal triple), as six outward quads or twelve triangles.
inline TestMesh box_mesh(const Eigen::Vector3d& corner, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b, const Eigen::Vector3d& c, bool triangles) {
    TestMesh mesh;
    for (int k = 0; k < 8; ++k)
        mesh.add_vertex(corner + double(k & 1) * a + double((k >> 1) & 1) * b +
                        double((k >> 2) & 1) * c);
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        if (triangles) {
            mesh.add_face({q[0], q[1], q[2]});
            mesh.add_face({q[0], q[2], q[3]});
        } else {
            mesh.add_face({q[0], q[1], q[2], q[3]});
        }
    }
    return mesh;
}

// Appends `part`'s vertices and faces to `mesh` (a part of its own: no
// vertex shared).
inline void append(TestMesh& mesh, const TestMesh& part) {
    const std::uint32_t base = std::uint32_t(mesh.vertex_count());
    mesh.coordinates.insert(mesh.coordinates.end(), part.coordinates.begin(),
                            part.coordinates.end());
    for (const std::uint32_t index : part.indices) mesh.indices.push_back(base + index);
    mesh.face_sizes.insert(mesh.face_sizes.end(), part.face_sizes.begin(), part.face_sizes.end());
    mesh.polygons = mesh.polygons || part.polygons;
}

// The shells of a surface: faces joined through shared vertices.
inline polymass::core::Shells shells_of(const TestMesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.vertex_count());
    for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
    auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v];
        return v;
    };
    const std::size_t faces = mesh.indices.size() / 3;
    for (std::size_t f = 0; f < faces; ++f)
        for (int k = 1; k < 3; ++k)
            parent[root(mesh.indices[3 * f + k])] = root(mesh.indices[3 * f]);
    polymass::core::Shells shells(std::pmr::get_default_resource());
    std::vector<std::uint32_t> number(mesh.vertex_count(), UINT32_MAX);
    for (std::size_t f = 0; f < faces; ++f) {
        std::uint32_t& shell = number[root(mesh.indices[3 * f])];
        if (shell == UINT32_MAX) shell = std::uint32_t(shells.count++);
        shells.of_face.push_back(shell);
    }
    return shells;
}

}  // namespace polymass_test
