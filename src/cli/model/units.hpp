// Length units the tool converts from (--units): a CAD file in millimetres
// becomes metres, so with a density in kg/m^3 the mass is in kg and the
// inertia in kg*m^2.
#pragma once

#include <string>

namespace polymass_cli {

// Metres per unit for "mm", "cm", "m", "in", "ft"; false for anything else.
bool metres_per_unit(const std::string& unit, double& metres);

const char* known_units();

}  // namespace polymass_cli
