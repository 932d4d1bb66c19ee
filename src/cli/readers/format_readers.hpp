// One function per file format, each turning the file's bytes (or, for the
// formats another library reads, its path) into a Model or throwing ReadError.
#pragma once

#include <string>

#include "model/model.hpp"

namespace polymass_cli {

Model read_obj(const std::string& bytes);
Model read_off(const std::string& bytes);
Model read_stl(const std::string& bytes);
Model read_ply(const std::string& bytes);
// glTF 2 (.gltf with embedded or external buffers, .glb) through tinygltf:
// node transforms applied, one part per node with a mesh.
Model read_gltf(const std::string& path);
// 3MF through lib3mf: transforms applied, one part per build item.
Model read_3mf(const std::string& path);
// Collada through assimp: its <unit> and <up_axis> applied (metres, Z up),
// node transforms applied, one part per node with meshes.
Model read_collada(const std::string& path);

}  // namespace polymass_cli
