// Collada (.dae), the usual mesh format of ROS robot descriptions, through
// assimp, which reads the geometry and node transforms in single precision.
// The asset's <unit meter> and <up_axis> are applied here in double precision
// (assimp's own unit scaling is a float factor, 0.001 off in its 8th digit):
// lengths in metres (Model::declared_unit), and the file's up axis along +Z,
// as robot descriptions and the simulators reading Collada for them (RViz,
// Gazebo) have it: a Z_UP file stays as written, a Y_UP one is turned by +90
// degrees about X, an X_UP one by -90 degrees about Y.
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
#include <pugixml.hpp>
#include <string>
#include <string_view>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/transform.hpp"
#include "reports/utf8.hpp"
#include "xml_memory.hpp"

namespace polymass_cli {
namespace {

// The file's <unit meter> and <up_axis> as one transform (Collada's
// defaults: 1 metre, Y_UP); a value that is neither is a ReadError. unit_text
// is set to the unit as the file gives it, for the notes.
Transform asset_transform(std::string_view bytes, std::string& unit_text) {
    pugixml_allocates_with_new();
    pugi::xml_document document;
    if (!document.load_buffer(bytes.data(), bytes.size()))
        throw ReadError("not a readable Collada (XML) file");
    const pugi::xml_node asset = document.child("COLLADA").child("asset");
    const pugi::xml_attribute meter = asset.child("unit").attribute("meter");
    const double unit = meter ? meter.as_double(0.0) : 1.0;
    if (!(unit > 0.0 && unit < 1e300)) {
        throw ReadError("<unit meter='" + valid_utf8(meter.value()) +
                        "'> is not a positive length");
    }
    const pugi::xml_attribute name = asset.child("unit").attribute("name");
    if (!meter)
        unit_text = "meter, Collada's default";
    else if (name)
        unit_text = valid_utf8(name.value()) + ", " + valid_utf8(meter.value()) + " m";
    else
        unit_text = valid_utf8(meter.value()) + " m";
    const std::string up = asset.child("up_axis") ? asset.child("up_axis").text().get() : "Y_UP";
    if (up == "Z_UP") return {unit, 0, 0, 0, 0, unit, 0, 0, 0, 0, unit, 0};
    if (up == "Y_UP") return {unit, 0, 0, 0, 0, 0, -unit, 0, 0, unit, 0, 0};
    if (up == "X_UP") return {0, 0, -unit, 0, 0, unit, 0, 0, unit, 0, 0, 0};
    throw ReadError("<up_axis> '" + valid_utf8(up) + "' is none of X_UP, Y_UP, Z_UP");
}

Transform node_transform(const aiMatrix4x4& m) {
    return {m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4};
}

void append_mesh(Model& model, Part& part, const aiMesh& mesh, const Transform& transform) {
    const uint64_t first = model.vertex_count();
    if (first + mesh.mNumVertices >= kIndexOutOfRange)
        throw ReadError("more than 4294967294 vertices");
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        append_transformed(model.positions.as_doubles(), transform, p.x, p.y, p.z);
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
    // The root is the visual scene, which has no transform in Collada: its
    // transform in assimp is the unit scaling, applied by the caller instead.
    const Transform transform =
        depth == 0 ? parent : compose(parent, node_transform(node.mTransformation));
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

Model read_collada(std::string_view document) {
    std::string unit;
    const Transform placement = asset_transform(document, unit);
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    // Only the geometry: no post-processing that would change the faces. The
    // bytes already read, rather than the file opened again: a second reading
    // could see another file, and assimp's file layer reports a failed
    // allocation as a file it cannot open.
    const aiScene* scene = importer.ReadFileFromMemory(document.data(), document.size(), 0, "dae");
    if (scene == nullptr || scene->mRootNode == nullptr) {
        throw ReadError("not a readable Collada file: " + valid_utf8(importer.GetErrorString()));
    }
    Model model;
    append_node(model, *scene, *scene->mRootNode, placement, 0);
    model.declared_unit = unit;
    model.notes.push_back(
        "Collada: its up axis along +Z; coordinates and transforms as assimp reads them, in "
        "single precision (7 significant digits)");
    return model;
}

}  // namespace polymass_cli
