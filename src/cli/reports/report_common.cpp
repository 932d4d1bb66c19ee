#include <polymass/polymass.h>

#include "library/categories.hpp"
#include "model/materials.hpp"
#include "reports/number_format.hpp"
#include "reports/report.hpp"

namespace polymass_cli {

ExitCode FileReport::exit_code() const {
    if (!readable) return kExitUnreadable;
    return exit_code_of(solid.result.status);
}

std::string length_unit_of(const FileReport& file, const OutputSettings& settings) {
    return file.in_metres ? "m" : settings.length_unit;
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

namespace {

const struct {
    uint32_t bit;
    const char* name;
    const char* meaning;
} kWarnings[] = {
    {POLYMASS_WARNING_INVERTED, "inverted", "the mesh was inside out: its faces were reversed"},
    {POLYMASS_WARNING_DEGENERATE_FACES, "degenerate_faces", "faces of zero area, harmless"},
    {POLYMASS_WARNING_UNCHECKED, "unchecked", "the topology checks were skipped"},
    {POLYMASS_WARNING_NON_MANIFOLD, "non_manifold", "edges with more than two faces, accepted"},
    {POLYMASS_WARNING_TOUCHING_FACES, "touching_faces",
     "faces touch without crossing (parts resting on each other)"},
    {POLYMASS_WARNING_REPAIRED, "repaired", "not a valid solid: the surface was repaired"},
    {POLYMASS_WARNING_SHELL, "shell", "computed as a thin wall, not a solid"},
    {POLYMASS_WARNING_HULL, "hull", "the convex hull, not the solid: an upper bound"},
    {POLYMASS_WARNING_INTERSECTIONS_UNCHECKED, "intersections_unchecked",
     "the intersection check was skipped: overlapping parts would count twice"}};

}  // namespace

std::vector<std::string> warning_names(uint32_t warnings) {
    std::vector<std::string> names;
    for (const auto& warning : kWarnings) {
        if (warnings & warning.bit) names.emplace_back(warning.name);
    }
    return names;
}

std::string warning_text(uint32_t warnings) {
    std::string text;
    for (const auto& warning : kWarnings) {
        if (!(warnings & warning.bit)) continue;
        if (!text.empty()) text += ", ";
        text += std::string(warning.name) + " (" + warning.meaning + ")";
    }
    return text;
}

std::string material_text(const PartReport& part) {
    const Material* material = find_material(part.material);
    std::string text =
        part.material + ", density " + readable_number(part.result.properties.density) + " kg/m^3";
    if (material) text += std::string(" (") + material->source + ")";
    return text;
}

std::array<double, 9> symmetric_tensor(const double* values) {
    std::array<double, 9> symmetric{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            const int upper = row <= column ? 3 * row + column : 3 * column + row;
            symmetric[3 * row + column] = values[upper] + 0.0;
        }
    }
    return symmetric;
}

}  // namespace polymass_cli
