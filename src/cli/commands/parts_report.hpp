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
#include "library/parts_apart.hpp"
#include "library/solid.hpp"
#include "library/solid_moments.hpp"
#include "library/surface_analysis.hpp"
#include "model/model.hpp"
#include "reports/report.hpp"

namespace polymass_cli {

// A file of several parts judged once, for its report and for polymass
// check: each part analysed by itself, as an exact solid and without the
// intersection check; then, when every part is a valid solid by itself as
// given (not inside out), the parts apart (library/parts_apart, each welded
// by itself) checked against each other for crossing and nesting, unless the
// options skip that check. Otherwise the file is one welded surface (a
// closed surface split into parts by material, a cavity exported as a
// part), analysed once with the options' chain, and apart and between are
// empty.
struct JudgedParts {
    std::vector<SurfaceAnalysis> solids;
    std::optional<PartsApart> apart;
    std::optional<SurfaceAnalysis> between;  // the parts apart (analyse_between)
    std::optional<SurfaceAnalysis> whole;    // the file as one welded surface
};

JudgedParts judge_parts(const Library& library, const Model& model);

// The parts apart against each other, as exact solids: each already welded
// by itself (the options' weld off), the options' checks, the solid alone.
SurfaceAnalysis analyse_between(const Library& library, const PartsApart& apart);

// Fills report.solid (the whole) and report.parts from the parts as judged.
// file_mass is the command line's density or total mass. Throws UsageError
// for --density/--mass NAME=V naming no part of the file.
void report_parts(const Library& library, const std::string& path, const Model& model,
                  const Arguments& arguments, const polymass_mass_desc& file_mass,
                  const JudgedParts& judged, FileReport& report);

}  // namespace polymass_cli
