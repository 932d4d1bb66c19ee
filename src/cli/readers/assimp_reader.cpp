// glTF 2 and 3MF through assimp, with no post-processing step: nothing is
// triangulated, welded, or removed, so the faces are the file's. Each node
// that holds meshes becomes a part, its vertices moved by the node's transform
// accumulated from the root (in double precision). An index past the end of
// its mesh is marked out of range, never allowed to reach another mesh's
// vertices.
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <array>
#include <string>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

using Transform = std::array<double, 12>;  // rows of a 3x4 affine matrix

Transform compose(const Transform& parent, const aiMatrix4x4& local) {
    const double m[3][4] = {{local.a1, local.a2, local.a3, local.a4},
                            {local.b1, local.b2, local.b3, local.b4},
                            {local.c1, local.c2, local.c3, local.c4}};
    Transform result{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 4; ++column) {
            double sum = column == 3 ? parent[4 * row + 3] : 0.0;
            for (int k = 0; k < 3; ++k) sum += parent[4 * row + k] * m[k][column];
            result[4 * row + column] = sum;
        }
    }
    return result;
}

void add_mesh(Model& model, Part& part, const aiMesh& mesh, const Transform& transform) {
    const uint64_t first_vertex = model.vertex_count();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const double local[3] = {mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z};
        for (int row = 0; row < 3; ++row) {
            model.positions.push_back(transform[4 * row] * local[0] +
                                      transform[4 * row + 1] * local[1] +
                                      transform[4 * row + 2] * local[2] + transform[4 * row + 3]);
        }
    }
    if (model.vertex_count() >= kIndexOutOfRange) throw ReadError("more than 4294967294 vertices");
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        for (unsigned corner = 0; corner < face.mNumIndices; ++corner) {
            const unsigned index = face.mIndices[corner];
            part.indices.push_back(index < mesh.mNumVertices
                                       ? static_cast<uint32_t>(first_vertex + index)
                                       : kIndexOutOfRange);
        }
        part.face_sizes.push_back(face.mNumIndices);
    }
}

void add_node(Model& model, const aiScene& scene, const aiNode& node, const Transform& parent,
              unsigned depth) {
    // A scene graph deeper than this is a cycle or corrupt.
    constexpr unsigned kDeepest = 1000;
    if (depth > kDeepest) throw ReadError("the scene's node tree is too deep");
    const Transform transform = compose(parent, node.mTransformation);
    if (node.mNumMeshes > 0) {
        Part part;
        part.name = node.mName.C_Str();
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes[i] >= scene.mNumMeshes) throw ReadError("a node names no mesh");
            add_mesh(model, part, *scene.mMeshes[node.mMeshes[i]], transform);
        }
        if (!part.face_sizes.empty()) model.parts.push_back(std::move(part));
    }
    for (unsigned child = 0; child < node.mNumChildren; ++child) {
        add_node(model, scene, *node.mChildren[child], transform, depth + 1);
    }
}

}  // namespace

Model read_with_assimp(const std::string& path, const std::string& format) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    if (scene == nullptr) {
        throw ReadError(std::string("assimp cannot read it as ") + format + ": " +
                        importer.GetErrorString());
    }
    if (scene->mRootNode == nullptr) throw ReadError("the scene has no root node");
    Model model;
    const Transform identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    add_node(model, *scene, *scene->mRootNode, identity, 0);
    return model;
}

}  // namespace polymass_cli
