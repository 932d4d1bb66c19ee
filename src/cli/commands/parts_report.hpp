// The report of a file with several parts (OBJ objects, STL solids, glTF
// nodes, 3MF build items): each part validated and integrated once by
// itself, reported from its own mass properties with its own density or mass;
// the parts judged against each other for crossing and nesting, never welded
// to each other (parts that touch are a whole, with a warning); and the whole
// file the exact sum of the parts' moments (docs/moments.md), the same bits
// whatever the chain of modes.
#pragma once

#include <polymass/polymass.h>

#include <optional>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "library/judged_parts.hpp"
#include "library/solid.hpp"
#include "library/solid_moments.hpp"
#include "library/surface_analysis.hpp"
#include "model/model.hpp"
#include "reports/report.hpp"

namespace polymass_cli {

// Fills report.solid (the whole) and report.parts from the parts as judged.
// file_mass is the command line's density or total mass. Throws UsageError
// for --density/--mass NAME=V naming no part of the file.
void report_parts(const Library& library, const std::string& path, const Model& model,
                  const Arguments& arguments, const polymass_mass_desc& file_mass,
                  const JudgedParts& judged, FileReport& report);

}  // namespace polymass_cli
