// The parts of a file as one surface whose parts share no vertex, for judging
// them against each other. Welded as one surface, two parts resting on each
// other (plates stacked, a bolt in its hole) would share their touching
// edges, each then used by four faces, and the whole would be refused as
// non-manifold. Here each part is welded by itself, with the library's
// welding (polymass_weld_positions) at the options' tolerance, and no vertex is
// shared by two parts: the library, told not to weld, sees each part's own
// shells, and judges parts that touch as touching (a warning) and parts that
// cross or nest as intersecting.
#pragma once

#include <optional>

#include "library/solid.hpp"
#include "model/model.hpp"

namespace polymass_cli {

struct PartsApart {
    // The file's positions, then a copy of each vertex a later part uses
    // too; one part holding every part's faces, in the file's order (so the
    // faces keep the numbers they have in combined_part).
    Model model;
};

// Empty when a part cannot be welded (indices out of range; with a weld
// tolerance, coordinates that are not finite): the library says why when it
// judges that part. library gives the weld tolerance.
std::optional<PartsApart> parts_apart(const Library& library, const Model& model);

// The options without POLYMASS_OPTION_WELD_VERTICES: for a surface already
// welded (PartsApart).
polymass_options unwelded_options(const polymass_options& options);

}  // namespace polymass_cli
