// glTF 2 (.gltf with embedded or external buffers, .glb) through tinygltf,
// which parses the document and loads the buffers; the meshes are taken from
// the buffers here, every accessor checked against its buffer view and every
// view against its buffer, so a truncated or inconsistent file is an error
// naming the accessor, never a read past the end.
//
// The default scene (or, with none, every scene) is walked from its root
// nodes; each node with a mesh is a part, its positions moved by the node's
// transform accumulated in double precision. Triangles, strips and fans are
// faces (glTF 2.0, 3.7.2.1); points and lines hold no surface and are left
// out. A node whose transform mirrors (negative determinant) has its
// triangles' corners reversed, as the specification says the winding is then
// clockwise. An index past the primitive's vertices is kept out of range, for
// the library to report.
#include <sys/stat.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "readers/file_bytes.hpp"
#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/transform.hpp"
#include "reports/utf8.hpp"

namespace polymass_cli {
namespace {

// A node's local transform: its matrix (column-major) or translation *
// rotation * scale.
Transform local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        const std::vector<double>& m = node.matrix;
        return {m[0], m[4], m[8], m[12], m[1], m[5], m[9], m[13], m[2], m[6], m[10], m[14]};
    }
    double x = 0, y = 0, z = 0, w = 1;
    if (node.rotation.size() == 4) {
        x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
    }
    const double rotation[9] = {
        1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
        2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
        2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
    const std::vector<double> scale =
        node.scale.size() == 3 ? node.scale : std::vector<double>{1, 1, 1};
    const std::vector<double> move =
        node.translation.size() == 3 ? node.translation : std::vector<double>{0, 0, 0};
    Transform t{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            t[4 * row + column] = rotation[3 * row + column] * scale[column];
        }
        t[4 * row + 3] = move[row];
    }
    return t;
}

// The bytes of accessor number index, checked: elements of element_size
// bytes, stride apart, all inside its view and the view inside its buffer.
struct AccessorBytes {
    const unsigned char* first = nullptr;
    size_t stride = 0;
    size_t count = 0;
};

// Accessor number index, which a primitive names: a ReadError when there is
// no such accessor.
const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
        throw ReadError("accessor " + std::to_string(index) + " does not exist (the file has " +
                        std::to_string(model.accessors.size()) + ")");
    }
    return model.accessors[static_cast<size_t>(index)];
}

AccessorBytes accessor_bytes(const tinygltf::Model& model, int index, size_t element_size) {
    const std::string name = "accessor " + std::to_string(index);
    const tinygltf::Accessor& accessor = accessor_at(model, index);
    if (accessor.sparse.isSparse) throw ReadError(name + " is sparse, which is not supported");
    if (accessor.bufferView < 0 ||
        static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        throw ReadError(name + " has no buffer view");
    }
    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
        throw ReadError("buffer view " + std::to_string(accessor.bufferView) + " has no buffer");
    }
    const std::vector<unsigned char>& buffer = model.buffers[view.buffer].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
        throw ReadError("buffer view " + std::to_string(accessor.bufferView) +
                        " runs past the end of its buffer (" + std::to_string(buffer.size()) +
                        " bytes): the file or its buffer is truncated");
    }
    const size_t stride = view.byteStride != 0 ? view.byteStride : element_size;
    AccessorBytes bytes{buffer.data() + view.byteOffset + accessor.byteOffset, stride,
                        accessor.count};
    // The last element starts at byteOffset + stride * (count - 1) and must
    // end within the view (written so that nothing overflows).
    const size_t length = view.byteLength;
    const bool fits =
        accessor.count == 0 ||
        (accessor.byteOffset <= length && element_size <= length - accessor.byteOffset &&
         (accessor.count - 1) <= (length - accessor.byteOffset - element_size) / stride);
    if (!fits) {
        throw ReadError(name + " (" + std::to_string(accessor.count) +
                        " elements) reads past the end of its buffer view (" +
                        std::to_string(view.byteLength) + " bytes)");
    }
    return bytes;
}

template <class T>
T load(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof value);  // little-endian, as glTF is
    return value;
}

// The primitive's vertex indices: its index accessor's, or 0..count-1.
std::vector<uint32_t> primitive_indices(const tinygltf::Model& model,
                                        const tinygltf::Primitive& primitive, size_t vertex_count) {
    std::vector<uint32_t> indices;
    if (primitive.indices < 0) {
        for (size_t v = 0; v < vertex_count; ++v) indices.push_back(static_cast<uint32_t>(v));
        return indices;
    }
    const tinygltf::Accessor& accessor = accessor_at(model, primitive.indices);
    const int size = accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                     : accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                     : accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                        : 0;
    if (size == 0 || accessor.type != TINYGLTF_TYPE_SCALAR) {
        throw ReadError("accessor " + std::to_string(primitive.indices) +
                        " holds indices that are not unsigned integer scalars");
    }
    const AccessorBytes bytes = accessor_bytes(model, primitive.indices, size);
    indices.reserve(bytes.count);
    for (size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* at = bytes.first + i * bytes.stride;
        const uint64_t index = size == 1   ? *at
                               : size == 2 ? load<uint16_t>(at)
                                           : load<uint32_t>(at);
        indices.push_back(index < vertex_count ? static_cast<uint32_t>(index) : kIndexOutOfRange);
    }
    return indices;
}

// The triangles of a primitive's index list in its mode, as corner triples.
std::vector<std::array<uint32_t, 3>> triangles_of(const std::vector<uint32_t>& i, int mode) {
    std::vector<std::array<uint32_t, 3>> triangles;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (i.size() % 3 != 0) {
            throw ReadError("a triangle primitive has " + std::to_string(i.size()) +
                            " indices, not a multiple of 3");
        }
        for (size_t k = 0; k + 2 < i.size(); k += 3)
            triangles.push_back({i[k], i[k + 1], i[k + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t k = 0; k + 2 < i.size(); ++k) {
            if (k % 2 == 0) {
                triangles.push_back({i[k], i[k + 1], i[k + 2]});
            } else {
                triangles.push_back({i[k + 1], i[k], i[k + 2]});
            }
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (size_t k = 1; k + 1 < i.size(); ++k) triangles.push_back({i[0], i[k], i[k + 1]});
    }
    return triangles;
}

void add_primitive(Model& model, Part& part, const tinygltf::Model& gltf,
                   const tinygltf::Primitive& primitive, const Transform& transform) {
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        throw ReadError("a triangle primitive has no POSITION attribute");
    }
    const tinygltf::Accessor& accessor = accessor_at(gltf, position->second);
    if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
        accessor.type != TINYGLTF_TYPE_VEC3) {
        throw ReadError("accessor " + std::to_string(position->second) +
                        " (POSITION) is not three 32-bit floats per vertex");
    }
    const AccessorBytes bytes = accessor_bytes(gltf, position->second, 3 * sizeof(float));
    const uint64_t first_vertex = model.vertex_count();
    for (size_t v = 0; v < bytes.count; ++v) {
        const unsigned char* at = bytes.first + v * bytes.stride;
        append_transformed(model.positions.as_doubles(), transform, load<float>(at),
                           load<float>(at + 4), load<float>(at + 8));
    }
    if (model.vertex_count() >= kIndexOutOfRange) throw ReadError("more than 4294967294 vertices");
    const bool mirrored = determinant(transform) < 0;
    for (const auto& triangle :
         triangles_of(primitive_indices(gltf, primitive, bytes.count), primitive.mode)) {
        for (int corner = 0; corner < 3; ++corner) {
            const uint32_t index = triangle[mirrored ? 2 - corner : corner];
            part.indices.push_back(index == kIndexOutOfRange
                                       ? kIndexOutOfRange
                                       : static_cast<uint32_t>(first_vertex + index));
        }
        part.face_sizes.push_back(3);
    }
}

// visited: the scene's nodes reached so far. glTF nodes form trees (a node
// has one parent at most), so a node reached twice is a shared child or a
// cycle, which would expand without bound: refused.
void add_node(Model& model, const tinygltf::Model& gltf, int index, const Transform& parent,
              unsigned depth, std::vector<bool>& visited) {
    constexpr unsigned kDeepest = 1000;  // bounds the recursion's stack
    if (depth > kDeepest) throw ReadError("the scene's node tree is too deep");
    if (index < 0 || static_cast<size_t>(index) >= gltf.nodes.size()) {
        throw ReadError("node " + std::to_string(index) + " does not exist");
    }
    if (visited[index]) {
        throw ReadError("node " + std::to_string(index) +
                        " is reached twice: glTF nodes must form trees");
    }
    visited[index] = true;
    const tinygltf::Node& node = gltf.nodes[index];
    const Transform transform = compose(parent, local_transform(node));
    if (node.mesh >= 0) {
        if (static_cast<size_t>(node.mesh) >= gltf.meshes.size()) {
            throw ReadError("node " + std::to_string(index) + " names no mesh");
        }
        Part part;
        part.name = node.name.empty() ? "node " + std::to_string(index) : node.name;
        for (const tinygltf::Primitive& primitive : gltf.meshes[node.mesh].primitives) {
            add_primitive(model, part, gltf, primitive, transform);
        }
        if (!part.face_sizes.empty()) model.parts.push_back(std::move(part));
    }
    for (const int child : node.children) {
        add_node(model, gltf, child, transform, depth + 1, visited);
    }
}

// Images are not needed for mass properties: accept them unread.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
    return true;
}

// A buffer's path as written: tinygltf before 2.6 expanded it as a shell
// word (wordexp), command substitutions included.
std::string path_as_written(const std::string& path, void*) { return path; }

// Buffers in files of their own are read as the mesh file is: regular files
// only. tinygltf's own reading asked for 2^63 bytes when a buffer's URI named
// a directory (ext4 reports that size for one), and its test of existence
// opens the file, which waits forever on a pipe. A fuzzer's find
// (tests/fuzz/gltf/regressions/).
bool buffer_file_exists(const std::string& path, void*) {
    struct stat status {};
    return ::stat(path.c_str(), &status) == 0;
}

bool read_buffer_file(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                      void*) {
    try {
        const FileBytes bytes(path);
        out->assign(bytes.view().begin(), bytes.view().end());
        return true;
    } catch (const ReadError& failure) {
        if (error) *error += "buffer file \"" + path + "\": " + failure.what() + "\n";
        return false;
    }
}

// A stream would take a failed allocation of its buffer for a file too short
// to hold the magic, and the GLB would be parsed as JSON.
bool is_binary(const std::string& path) { return FileBytes(path).view().substr(0, 4) == "glTF"; }

}  // namespace

Model read_gltf(const std::string& path) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    loader.SetFsCallbacks(
        {buffer_file_exists, path_as_written, read_buffer_file, tinygltf::WriteWholeFile, nullptr});
    tinygltf::Model gltf;
    std::string error, warning;
    const bool loaded = is_binary(path) ? loader.LoadBinaryFromFile(&gltf, &error, &warning, path)
                                        : loader.LoadASCIIFromFile(&gltf, &error, &warning, path);
    if (!loaded) {
        while (!error.empty() && error.back() == '\n') error.pop_back();
        // tinygltf's JSON errors quote the byte they stopped at, which may
        // not be UTF-8 (nor text), and a decoded URI ("%00") may hold NUL
        // bytes, which would cut the message short.
        std::replace(error.begin(), error.end(), '\0', '?');
        throw ReadError("not a readable glTF 2 file: " +
                        (error.empty() ? "no reason given" : valid_utf8(error)));
    }
    Model model;
    std::vector<int> scenes;
    if (gltf.defaultScene >= 0 && static_cast<size_t>(gltf.defaultScene) < gltf.scenes.size()) {
        scenes.push_back(gltf.defaultScene);
    } else {
        for (size_t s = 0; s < gltf.scenes.size(); ++s) scenes.push_back(static_cast<int>(s));
    }
    for (const int scene : scenes) {
        std::vector<bool> visited(gltf.nodes.size(), false);
        for (const int root : gltf.scenes[scene].nodes) {
            add_node(model, gltf, root, kIdentity, 0, visited);
        }
    }
    return model;
}

}  // namespace polymass_cli
