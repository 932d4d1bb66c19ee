// --fix: the description's text with each checked <inertial> element
// replaced by the computed one, every other byte as it was.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"

namespace polymass_cli::audit {

struct FixSettings {
    // The mass written: the declared one, unless a density is given (then
    // density * computed volume, kg/m^3).
    std::optional<double> density;
};

struct FixResult {
    std::string text;
    int replaced = 0;
    std::vector<std::string> left;  // "link: why its inertial was left as it is"
};

FixResult fix_description(const FileAudit& audit, const FixSettings& settings);

}  // namespace polymass_cli::audit
