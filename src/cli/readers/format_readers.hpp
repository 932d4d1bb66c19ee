// One function per file format, each turning the file's bytes (or, for
// assimp, its path) into a Model or throwing ReadError.
#pragma once

#include <string>

#include "model/model.hpp"

namespace polymass_cli {

Model read_obj(const std::string& bytes);
Model read_off(const std::string& bytes);
Model read_stl(const std::string& bytes);
Model read_ply(const std::string& bytes);
// glTF 2 (.gltf with embedded or external buffers, .glb) and 3MF, through
// assimp: node transforms applied, one part per mesh instance.
Model read_with_assimp(const std::string& path, const std::string& format);

}  // namespace polymass_cli
