// What a mesh file holds once read: one array of vertex positions shared by
// the file's parts (OBJ objects, STL solids, glTF nodes, 3MF objects), each part
// a list of polygon faces indexing it. Faces keep the file's polygons; an index
// the file gives past the end of the vertices is kept as such (or as
// kIndexOutOfRange when it does not fit) so the library reports it.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace polymass_cli {

// The index a reader stores for a face corner that refers to no vertex (an
// OBJ index 0, a negative or too large index): past the end of any mesh.
inline constexpr uint32_t kIndexOutOfRange = std::numeric_limits<uint32_t>::max();

struct Part {
    std::string name;
    std::vector<uint32_t> indices;     // the faces' vertex indices, one face after another
    std::vector<uint32_t> face_sizes;  // vertices of each face
};

struct Model {
    std::string format;  // "obj", "stl", "ply", "off", "msh", "gltf", "glb", "3mf", "dae"
    std::vector<double> positions;  // x, y, z of each vertex
    std::vector<Part> parts;        // at least one
    // The length unit the file declares (3MF's <model unit>, Collada's
    // <unit>), which its reader applied: the positions are then in metres and
    // --units does not apply. Empty for the formats that declare none: the
    // positions are in the file's own, unknown unit.
    std::string declared_unit;
    // What the reader must tell the user about the numbers (a unit the file
    // declares, a precision it cannot keep), printed with the results.
    std::vector<std::string> notes;

    uint64_t vertex_count() const { return positions.size() / 3; }
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
