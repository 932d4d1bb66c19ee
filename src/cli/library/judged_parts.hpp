// A file of several parts (OBJ objects, STL solids, glTF nodes, 3MF build
// items) judged as one body without welding the parts to each other: each
// part validated by itself, then the parts apart (parts_apart.hpp) checked
// against each other for crossing and nesting. Parts that touch (plates
// stacked, a bolt in its hole) are a whole, with a warning; the whole is the
// exact sum of the parts' moments (docs/moments.md), the same bits whatever
// the chain of modes. The report of `polymass FILE`, `polymass check`, the
// audit's meshes and the assembly's parts all judge a file so.
#pragma once

#include <polymass/polymass.h>

#include <cstddef>
#include <optional>
#include <vector>

#include "library/parts_apart.hpp"
#include "library/solid.hpp"
#include "library/surface_analysis.hpp"
#include "model/model.hpp"

namespace polymass_cli {

// A file of several parts judged once: each part analysed by itself, as an
// exact solid and without the intersection check; then, when every part is
// a valid solid by itself as given (not inside out), the parts apart (each
// welded by itself) checked against each other for crossing and nesting,
// unless the options skip that check. Otherwise the file is one welded
// surface (a closed surface split into parts by material, a cavity exported
// as a part), analysed once with the options' chain, and apart and between
// are empty.
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

// Part k's mass properties at `mass`. The parts are analysed without the
// intersection check (each by itself); the check that covers them (the parts
// apart against each other, or the whole) says whether it ran: the answer
// keeps the library's POLYMASS_WARNING_INTERSECTIONS_UNCHECKED only when it
// did not.
SolidResult part_properties(const Library& library, const JudgedParts& judged, std::size_t k,
                            const polymass_mass_desc& mass);

// The parts of a file as one solid at unit density, when they are one:
// several parts, each a solid by itself, none crossing another or lying
// inside it (judge_parts). Their moments' exact sum, surface area and
// warnings (touching among them). Empty for a file of one part, or parts
// that are no such whole: the file is then one surface, for the caller's
// chain of modes to answer.
struct SolidParts {
    polymass_moments moments{};
    double surface_area = 0.0;
    uint32_t warnings = 0;
};

std::optional<SolidParts> solid_parts(const Library& library, const Model& model);

}  // namespace polymass_cli
