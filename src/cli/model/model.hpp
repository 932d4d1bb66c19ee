// What a mesh file holds once read: one array of vertex positions shared by
// the file's parts (OBJ objects, STL solids, glTF nodes, 3MF objects), each part
// a list of polygon faces indexing it. Faces keep the file's polygons; an index
// the file gives past the end of the vertices is kept as such (or as
// kIndexOutOfRange when it does not fit) so the library reports it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace polymass_cli {

// The index a reader stores for a face corner that refers to no vertex (an
// OBJ index 0, a negative or too large index): past the end of any mesh.
inline constexpr uint32_t kIndexOutOfRange = std::numeric_limits<uint32_t>::max();

struct Part {
    std::string name;
    std::vector<uint32_t> indices;  // the faces' vertex indices, one face after another
    // Vertices of each face; empty when every face is a triangle (a binary
    // STL, most meshes: read_mesh_file, triangulate_model and the parts'
    // combinations drop the threes), which saves 4 bytes a face and is what
    // the library reads as "triangles only".
    std::vector<uint32_t> face_sizes;

    uint64_t face_count() const {
        return face_sizes.empty() ? indices.size() / 3 : face_sizes.size();
    }
    uint32_t face_size(size_t face) const { return face_sizes.empty() ? 3 : face_sizes[face]; }
    // Drops face_sizes (and its memory) when every face is a triangle.
    void drop_triangle_sizes();
};

// The x, y, z of each vertex in the precision its file stores them: float32
// from the formats that store float32 (binary STL, MuJoCo's .msh), handed to
// the library as such (12 bytes a vertex, not 24; it widens each coordinate
// exactly, as the tool would), float64 otherwise. Arithmetic on them (a unit,
// --scale) is done on doubles (as_doubles), as it always was.
class Positions {
public:
    Positions() = default;
    explicit Positions(std::vector<float> narrow) : narrow_(std::move(narrow)) {}
    explicit Positions(std::vector<double> wide) : wide_(std::move(wide)) {}

    uint64_t vertex_count() const { return (narrow_.size() + wide_.size()) / 3; }
    bool is_float32() const { return !narrow_.empty(); }
    // The coordinates, float or double as is_float32() says.
    const void* data() const {
        return is_float32() ? static_cast<const void*>(narrow_.data()) : wide_.data();
    }
    // Coordinate k (axis k % 3 of vertex k / 3), widened.
    double operator[](size_t k) const { return is_float32() ? double(narrow_[k]) : wide_[k]; }
    std::array<double, 3> vertex(uint64_t v) const {
        return {(*this)[3 * v], (*this)[3 * v + 1], (*this)[3 * v + 2]};
    }
    // The coordinates as doubles to append to or change, float32 ones
    // widened first (once; exactly).
    std::vector<double>& as_doubles();

private:
    std::vector<float> narrow_;  // at most one of the two holds coordinates
    std::vector<double> wide_;
};

struct Model {
    std::string format;  // "obj", "stl", "ply", "off", "msh", "gltf", "glb", "3mf", "dae"
    Positions positions;
    std::vector<Part> parts;  // at least one
    // The length unit the file declares (3MF's <model unit>, Collada's
    // <unit>), which its reader applied: the positions are then in metres and
    // --units does not apply. Empty for the formats that declare none: the
    // positions are in the file's own, unknown unit.
    std::string declared_unit;
    // What the reader must tell the user about the numbers (a unit the file
    // declares, a precision it cannot keep), printed with the results.
    std::vector<std::string> notes;

    uint64_t vertex_count() const { return positions.vertex_count(); }
};

// All faces of all parts as one part: the file's solid.
Part combined_part(const Model& model);

// How many distinct vertices (as the file numbers them) the part's faces use.
uint64_t used_vertices(const Model& model, const Part& part);

// Multiplies every coordinate by factor (unit conversion and --scale).
void scale_model(Model& model, double factor);

// Splits every face of more than 3 corners into a fan of triangles from its
// first corner. A planar face keeps its solid; a non-planar one becomes one
// of the surfaces it could stand for (the fan's).
void triangulate_model(Model& model);

}  // namespace polymass_cli
