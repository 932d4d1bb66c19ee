// Collada (.dae), the usual mesh format of ROS robot descriptions, through
// assimp. Assimp reads the scene in its own convention: lengths multiplied by
// the asset's <unit meter> (so in metres) and the asset's <up_axis> turned to
// +Y. Robot descriptions are Z-up, and the simulators that read Collada (RViz,
// Gazebo) put the file's up axis along +Z: the scene is turned by +90 degrees
// about X afterwards, which maps assimp's +Y to +Z (a Z_UP file ends where it
// was written, a Y_UP one has its Y along Z).
//
// Every node of the scene with meshes is a part, its vertices moved by the
// node's transform accumulated from the root (in double precision); polygon
// faces are kept as written (no triangulation). Points and lines hold no
// surface and are left out. A node whose transform mirrors has its faces'
// corners reversed, as it turns the solid inside out.
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <string>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/transform.hpp"
#include "reports/utf8.hpp"

namespace polymass_cli {
namespace {

// Assimp's Y-up turned to Z-up: (x, y, z) -> (x, -z, y).
constexpr Transform kYUpToZUp{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0};

Transform node_transform(const aiMatrix4x4& m) {
    return {m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4};
}

void append_mesh(Model& model, Part& part, const aiMesh& mesh, const Transform& transform) {
    const uint64_t first = model.vertex_count();
    if (first + mesh.mNumVertices >= kIndexOutOfRange)
        throw ReadError("more than 4294967294 vertices");
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        append_transformed(model.positions, transform, p.x, p.y, p.z);
    }
    const bool mirrored = determinant(transform) < 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices < 3) continue;  // a point or a line
        part.face_sizes.push_back(face.mNumIndices);
        for (unsigned k = 0; k < face.mNumIndices; ++k) {
            const unsigned corner = mirrored ? face.mNumIndices - 1 - k : k;
            const unsigned index = face.mIndices[corner];
            part.indices.push_back(index < mesh.mNumVertices ? static_cast<uint32_t>(first + index)
                                                             : kIndexOutOfRange);
        }
    }
}

void append_node(Model& model, const aiScene& scene, const aiNode& node, const Transform& parent,
                 int depth) {
    constexpr int kDeepest = 1000;
    if (depth > kDeepest) throw ReadError("the scene's node tree is too deep");
    const Transform transform = compose(parent, node_transform(node.mTransformation));
    if (node.mNumMeshes > 0) {
        Part part;
        part.name = valid_utf8(node.mName.C_Str());
        for (unsigned m = 0; m < node.mNumMeshes; ++m) {
            if (node.mMeshes[m] >= scene.mNumMeshes) {
                throw ReadError("node '" + part.name + "' names a mesh that does not exist");
            }
            append_mesh(model, part, *scene.mMeshes[node.mMeshes[m]], transform);
        }
        model.parts.push_back(std::move(part));
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) {
        append_node(model, scene, *node.mChildren[c], transform, depth + 1);
    }
}

}  // namespace

Model read_collada(const std::string& path) {
    Assimp::Importer importer;
    // Only the geometry: no post-processing that would change the faces.
    const aiScene* scene = importer.ReadFile(path, 0);
    if (scene == nullptr || scene->mRootNode == nullptr) {
        throw ReadError("not a readable Collada file: " + valid_utf8(importer.GetErrorString()));
    }
    Model model;
    append_node(model, *scene, *scene->mRootNode, kYUpToZUp, 0);
    model.notes.push_back("Collada: lengths in metres (the file's <unit>), its up axis along +Z");
    return model;
}

}  // namespace polymass_cli
