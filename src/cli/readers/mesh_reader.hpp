// Reading a mesh file into a Model. OBJ, STL, PLY, OFF and MuJoCo's .msh are
// read by the project's own readers (obj_reader, ..., msh_reader): they keep
// polygon faces and every index as written, so a bad index or a NaN reaches the
// library's checks instead of being dropped or clamped, and a truncated file is
// an error, not a read past its end. glTF/GLB go through tinygltf, 3MF
// through libzip and pugixml, Collada through assimp, each in a child process
// (isolated_reader), since they parse untrusted JSON, binary buffers and zip
// packages with code not ours.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "model/model.hpp"

namespace polymass_cli {

// A file that cannot be read as a mesh: missing, empty, truncated, malformed,
// or of an unknown format. The message says what and where.
class ReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The most corners a face of a mesh of vertex_count vertices may have: a
// polygon passes through each of its vertices once, or twice where a bridge
// joins a hole to its outline. A face of more is not a polygon but a corrupt
// or hostile file (one line of an OBJ can name 10^8 corners), refused before
// the library spends tens of bytes on each corner. Up to 2^16 corners always
// pass, so that the library names a small face's bad indices.
uint64_t most_face_corners(uint64_t vertex_count);

// The format names --format accepts and the extensions that select them.
const char* supported_formats();

// Reads path. format is a name from supported_formats(), or empty to choose
// by the file's extension. The parts it returns have faces (those without are
// dropped), each part's face sizes add up to its indices, and there is at
// least one part. Throws ReadError.
Model read_mesh_file(const std::string& path, const std::string& format);

}  // namespace polymass_cli
