// The shells of a part and what each one is: a solid (positive volume), a
// cavity (negative, inside a solid shell's bounding box), or inside out
// (negative, outside every solid shell) - taken relative to the orientation
// of the whole surface, so an inverted file accepted as such is no exception.
// The library judges the surface as a whole, where a disjoint inside-out shell
// only lowers the total: finding one is the tool's job.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "library/solid.hpp"
#include "model/model.hpp"

namespace polymass_cli {

struct Shell {
    uint64_t faces = 0;
    double signed_volume = 0;  // NaN when it cannot be integrated on its own
    const char* kind = "";     // "solid", "cavity", "inverted" or "no volume"
};

// Empty when the library cannot split the part (bad indices or coordinates).
// whole_signed_volume is the part's own (its sign says which way is out).
std::vector<Shell> classify_shells(const Library& library, const Model& model, const Part& part,
                                   double whole_signed_volume);

// The message for the first inside-out shell, or "" when there is none.
std::string inverted_shell_message(const std::vector<Shell>& shells);

}  // namespace polymass_cli
