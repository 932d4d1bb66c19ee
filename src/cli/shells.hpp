// The shells of a part: its connected pieces of surface, found here because
// polymass_diagnostics reports the surface as a whole. Faces sharing a vertex
// position are in the same shell, so an unwelded soup splits as its solid does.
#pragma once

#include <cstdint>
#include <vector>

#include "model.hpp"

namespace polymass_cli {

// Each shell as a part of its own (named "shell N"), in the order of their
// first faces. Faces whose every index is out of range belong to no shell.
std::vector<Part> split_shells(const Model& model, const Part& part);

}  // namespace polymass_cli
