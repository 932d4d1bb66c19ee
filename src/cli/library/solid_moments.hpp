// Moments composed with the library's moments API (polymass_moments_*): the
// parts of a file or of an assembly are each analysed once
// (library/surface_analysis), reported from their own mass properties, and
// the whole is the exact sum of their moments (docs/moments.md), so a part
// far from the origin keeps its digits in the sum.
#pragma once

#include <polymass/polymass.h>

#include <array>
#include <string>
#include <vector>

#include "library/solid.hpp"

namespace polymass_cli {

// A step of the composition: the moments, or the status and message of the
// library's refusal (an overflow, a body of no volume).
struct MomentsResult {
    int32_t status = POLYMASS_OK;
    std::string message;
    polymass_moments moments{};
};

// The moments with a density or a mass.
MomentsResult weighted(const Library& library, const polymass_moments& moments,
                       const polymass_mass_desc& mass);
// Every length times factor (a unit conversion), about the origin.
MomentsResult scaled(const Library& library, const polymass_moments& moments, double factor);
// Stretched by factors[i] along axis i, about the origin (a mesh's scale).
MomentsResult scaled(const Library& library, const polymass_moments& moments,
                     const std::array<double, 3>& factors);
// Moved by x -> rotation x + translation (rotation row-major, orthonormal).
MomentsResult transformed(const Library& library, const polymass_moments& moments,
                          const std::array<double, 9>& rotation,
                          const std::array<double, 3>& translation);
// The bodies as one, added in order (at least one).
MomentsResult sum(const Library& library, const std::vector<polymass_moments>& bodies);

// The mass properties of moments as weighted, inertia_point about the
// library's point, the SOLID mode's provenance (moments keep no other: the
// warnings say what answered the bodies added up); moments keep no surface,
// so the area and warnings are the caller's.
SolidResult properties_of(const Library& library, const polymass_moments& moments,
                          double surface_area, uint32_t warnings);

}  // namespace polymass_cli
