#include <polymass/polymass.h>

#include "library/categories.hpp"
#include "reports/report.hpp"

namespace polymass_cli {

ExitCode FileReport::exit_code() const {
    if (!readable) return kExitUnreadable;
    return exit_code_of(solid.result.status);
}

Summary summarize(const std::vector<FileReport>& files) {
    Summary summary;
    summary.files = files.size();
    for (const FileReport& file : files) {
        if (file.exit_code() != kExitOk) continue;
        ++summary.valid;
        summary.total_volume += file.solid.result.properties.volume;
        summary.total_mass += file.solid.result.properties.mass;
    }
    return summary;
}

std::array<double, 3> principal_axis(const polymass_mass_properties& properties, int i) {
    const double* rotation = properties.principal_axes;  // row-major 3x3
    return {rotation[i], rotation[3 + i], rotation[6 + i]};
}

std::vector<std::string> warning_names(uint32_t warnings) {
    static const struct {
        uint32_t bit;
        const char* name;
    } kWarnings[] = {{POLYMASS_WARNING_INVERTED, "inverted"},
                     {POLYMASS_WARNING_DEGENERATE_FACES, "degenerate_faces"},
                     {POLYMASS_WARNING_UNCHECKED, "unchecked"},
                     {POLYMASS_WARNING_NON_MANIFOLD, "non_manifold"}};
    std::vector<std::string> names;
    for (const auto& warning : kWarnings) {
        if (warnings & warning.bit) names.emplace_back(warning.name);
    }
    return names;
}

}  // namespace polymass_cli
