#include "model/units.hpp"

namespace polymass_cli {

bool metres_per_unit(const std::string& unit, double& metres) {
    // The inch and the foot are exact by definition (1959).
    static const struct {
        const char* name;
        double metres;
    } kUnits[] = {{"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}, {"in", 0.0254}, {"ft", 0.3048}};
    for (const auto& known : kUnits) {
        if (unit == known.name) {
            metres = known.metres;
            return true;
        }
    }
    return false;
}

const char* known_units() { return "mm, cm, m, in, ft"; }

}  // namespace polymass_cli
