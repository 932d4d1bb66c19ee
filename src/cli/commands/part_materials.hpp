// Per-part materials of a file with several parts: --density NAME=D,
// --mass NAME=M and --material NAME=MATERIAL give the parts named NAME their
// density or mass; the other parts take the file's --density or --material
// (or 1).
#pragma once

#include <polymass/polymass.h>

#include <string>
#include <vector>

#include "arguments.hpp"
#include "model/model.hpp"
#include "reports/report.hpp"

namespace polymass_cli {

// The mass description of each part of model, in order: `file_mass` with the
// part's own density or mass when the command line names the part. Throws
// UsageError for a name that is no part of the model (read from path),
// listing its parts.
std::vector<polymass_mass_desc> part_masses(const Arguments& arguments, const std::string& path,
                                            const Model& model,
                                            const polymass_mass_desc& file_mass);

// The table's name of the material the command line gives the parts named
// `part` (--material NAME=MATERIAL, else the whole's --material), or "" when
// their density or mass is a number.
std::string material_of(const Arguments& arguments, const std::string& part);

// The material of a whole made of `parts`: the one they all share, else "".
std::string common_material(const std::vector<PartReport>& parts);

}  // namespace polymass_cli
