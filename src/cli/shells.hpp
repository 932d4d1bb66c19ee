// The number of shells (connected pieces of surface) of a part, counted here
// because polymass_diagnostics does not report it: faces sharing a vertex
// position are in the same shell.
#pragma once

#include <cstdint>

#include "model.hpp"

namespace polymass_cli {

uint64_t count_shells(const Model& model, const Part& part);

}  // namespace polymass_cli
