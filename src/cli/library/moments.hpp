// Composing bodies through the library's moments (polymass_moments_*):
// scaled, moved and added exactly as the library defines it, then turned
// into mass properties. The operands come from the tool's own checks (finite
// factors, proper rotations), so a refusal is a bug: std::runtime_error.
#pragma once

#include <polymass/polymass.h>

#include <array>

#include "library/solid.hpp"

namespace polymass_cli {

polymass_moments scaled_moments(const Library& library, const polymass_moments& moments,
                                const std::array<double, 3>& factors);

// rotation row-major.
polymass_moments moved_moments(const Library& library, const polymass_moments& moments,
                               const std::array<double, 9>& rotation,
                               const std::array<double, 3>& translation);

polymass_moments added_moments(const Library& library, const polymass_moments& a,
                               const polymass_moments& b);

// The mass properties of the body at total mass `mass`, inertia_point about
// `point`.
polymass_mass_properties properties_at_mass(const Library& library, const polymass_moments& moments,
                                            double mass, const std::array<double, 3>& point);

}  // namespace polymass_cli
