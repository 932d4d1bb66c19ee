// Per-part materials of a file with several parts: --density NAME=D and
// --mass NAME=M give the parts named NAME their density or mass; the other
// parts take the file's --density (or 1).
#pragma once

#include <polymass/polymass.h>

#include <string>
#include <vector>

#include "arguments.hpp"
#include "model/model.hpp"

namespace polymass_cli {

// The mass description of each part of model, in order: `file_mass` with the
// part's own density or mass when the command line names the part. Throws
// UsageError for a name that is no part of the model (read from path),
// listing its parts.
std::vector<polymass_mass_desc> part_masses(const Arguments& arguments, const std::string& path,
                                            const Model& model,
                                            const polymass_mass_desc& file_mass);

}  // namespace polymass_cli
