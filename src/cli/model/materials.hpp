// Materials by name (--material NAME, an assembly part's "material"): the
// densities of common engineering and printing materials, in kg/m^3, each
// from a handbook or a manufacturer's datasheet (docs/materials.md lists
// them with their sources and what they do not cover).
#pragma once

#include <string>

namespace polymass_cli {

struct Material {
    const char* name;    // as the command line and the outputs spell it
    double density;      // kg/m^3, at room temperature
    const char* source;  // short citation; docs/materials.md gives it in full
};

// The material named `name`, case-insensitively, "aluminum" read as
// "aluminium"; nullptr when there is none.
const Material* find_material(const std::string& name);

// Every name, comma-separated, for the error that lists them.
std::string known_materials();

}  // namespace polymass_cli
