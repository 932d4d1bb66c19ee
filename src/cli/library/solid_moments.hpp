// Solids integrated once, and their moments composed with the library's
// moments API (polymass_moments_*): the parts of a file or of an assembly are
// each integrated once, reported from their own mass properties, and the whole
// is the exact sum of their moments (docs/moments.md), so a part far from the
// origin keeps its digits in the sum.
#pragma once

#include <polymass/polymass.h>

#include <array>
#include <string>
#include <vector>

#include "library/solid.hpp"
#include "model/model.hpp"

namespace polymass_cli {

// A part validated and integrated once by the library (a polymass_mesh),
// whose mass properties and moments are then read without integrating again.
class IntegratedSolid {
public:
    IntegratedSolid(const Library& library, const Model& model, const Part& part,
                    const polymass_options& options);
    ~IntegratedSolid();
    IntegratedSolid(IntegratedSolid&& other) noexcept;
    IntegratedSolid(const IntegratedSolid&) = delete;
    IntegratedSolid& operator=(const IntegratedSolid&) = delete;
    IntegratedSolid& operator=(IntegratedSolid&&) = delete;

    bool valid() const { return status_ == POLYMASS_OK; }
    // Valid as given: not inside out and turned by --accept-inverted (a
    // cavity exported as a part of its own is inside out by itself).
    bool valid_as_given() const { return valid() && !(warnings_ & POLYMASS_WARNING_INVERTED); }
    // Why the part is not a valid solid (status and the library's message).
    SolidResult failure() const;
    // Its mass properties with the given density or mass (valid() only).
    SolidResult properties(const Library& library, const polymass_mass_desc& mass) const;
    // Its moments at unit density (valid() only).
    polymass_moments moments(const Library& library) const;

private:
    polymass_mesh* mesh_ = nullptr;
    int32_t status_ = POLYMASS_OK;
    std::string message_;
    uint32_t warnings_ = 0;
};

// A step of the composition: the moments, or the status and message of the
// library's refusal (an overflow, a body of no volume).
struct MomentsResult {
    int32_t status = POLYMASS_OK;
    std::string message;
    polymass_moments moments{};
};

// The moments with a density or a mass (mass.point is not used).
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

// The mass properties of moments as weighted, inertia_point about `point`;
// moments keep no surface, so the area and warnings are the caller's.
SolidResult properties_of(const Library& library, const polymass_moments& moments,
                          const std::array<double, 3>& point, double surface_area,
                          uint32_t warnings);

}  // namespace polymass_cli
