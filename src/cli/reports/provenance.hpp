// What the outputs say about how an answer was reached: the mode that gave
// it, what it did (polymass_provenance), and its error bound.
#pragma once

#include <polymass/polymass.h>

#include <cstdint>
#include <string>
#include <vector>

namespace polymass_cli {

// The mode as the outputs name it: "solid", "repaired", "shell" or "hull".
const char* answer_mode_name(int32_t mode);

// One kind of repair: its count and first locations (faces, or vertices for
// holes, or vertex pairs for split edges).
struct RepairItem {
    const char* key;    // JSON key
    const char* label;  // for people
    uint64_t count;
    std::vector<std::vector<uint64_t>> first;  // each one number, or a pair for edges
};

// The repairs made, those with a count only.
std::vector<RepairItem> repairs_of(const polymass_provenance& provenance);

// The provenance as a sentence for people: "repaired: 3 faces turned to
// agree with their shell (first 2, 9, 14), 1 hole capped (caps 2.1% of the
// surface)", "hull of 120 vertices", "thin wall 0.002 thick", "solid".
std::string provenance_text(const polymass_provenance& provenance);

// The error bound as a sentence: "volume ±.., centre of mass ±.. (each
// coordinate), inertia ±.. (each entry)".
std::string error_bound_text(const polymass_mass_properties& properties);

}  // namespace polymass_cli
