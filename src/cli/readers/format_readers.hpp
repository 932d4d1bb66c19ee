// One function per file format, each turning the file's bytes (mapped, not
// copied; for the formats another library reads, its path) into a Model or
// throwing ReadError.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "model/model.hpp"
#include "readers/file_bytes.hpp"

namespace polymass_cli {

Model read_obj(std::string_view bytes);
Model read_off(std::string_view bytes);
// MuJoCo's binary mesh: its counts checked against the file's length.
Model read_msh(std::string_view bytes);
Model read_ply(std::string_view bytes);
Model read_stl(std::string_view bytes);
// The same from the file itself, let go as its triangles are decoded.
Model read_stl(FileBytes file);
// glTF 2 (.gltf with embedded or external buffers, .glb) through tinygltf:
// node transforms applied, one part per node with a mesh.
Model read_gltf(const std::string& path);
// 3MF through libzip and pugixml, from the package's bytes, in double
// precision: transforms applied, one part per build item; a package whose
// parts inflate past reader_memory_budget(package.size()) is refused.
Model read_3mf(std::string_view package);
// Collada through assimp, from the document's bytes: its <unit> and
// <up_axis> applied (metres, Z up), node transforms applied, one part per
// node with meshes.
Model read_collada(std::string_view document);

}  // namespace polymass_cli
