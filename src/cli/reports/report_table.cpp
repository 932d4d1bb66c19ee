// The default output: a readable table per file, then a summary line when
// several files are given.
#include <polymass/polymass.h>

#include <cstdio>
#include <string>

#include "library/categories.hpp"
#include "reports/number_format.hpp"
#include "reports/provenance.hpp"
#include "reports/report.hpp"

namespace polymass_cli {
namespace {

std::string vector_text(const double* v) {
    return "(" + readable_number(v[0]) + ", " + readable_number(v[1]) + ", " +
           readable_number(v[2]) + ")";
}

void write_row(std::ostream& out, const std::string& label, const std::string& value,
               const std::string& unit = "") {
    char padded[64];
    std::snprintf(padded, sizeof padded, "  %-20s", label.c_str());
    out << padded << value << (unit.empty() ? "" : "  " + unit) << '\n';
}

void write_matrix(std::ostream& out, const std::string& label, const double* tensor,
                  const std::string& unit) {
    const std::array<double, 9> m = symmetric_tensor(tensor);
    for (int row = 0; row < 3; ++row) {
        char line[160];
        std::snprintf(line, sizeof line, "[%17s %17s %17s]", readable_number(m[3 * row]).c_str(),
                      readable_number(m[3 * row + 1]).c_str(),
                      readable_number(m[3 * row + 2]).c_str());
        write_row(out, row == 0 ? label : "", line, row == 0 ? unit : "");
    }
}

struct Units {
    std::string length, area, volume, density, mass, inertia;
};

Units units_for(const std::string& length_unit) {
    if (length_unit.empty()) {
        return {"(file units)", "", "", "", "", ""};
    }
    // Lengths in metres: SI throughout, so --density is read as kg/m^3 and
    // --mass as kg (what --help promises).
    return {"m", "m^2", "m^3", "kg/m^3", "kg", "kg*m^2"};
}

void write_solid(std::ostream& out, const PartReport& part, const OutputSettings& settings) {
    write_row(out, "vertices, faces",
              std::to_string(part.vertices) + ", " + std::to_string(part.faces));
    if (part.result.status != POLYMASS_OK) {
        write_row(out, "NOT A VALID SOLID",
                  std::string(category_of(part.result.status)) + ": " + part.result.message);
        return;
    }
    const Units units = units_for(settings.length_unit);
    const polymass_mass_properties& p = part.result.properties;
    write_row(out, "volume", readable_number(p.volume), units.volume);
    write_row(out, "mass", readable_number(p.mass), units.mass);
    write_row(out, "density", readable_number(p.density), units.density);
    if (!part.material.empty()) write_row(out, "material", material_text(part));
    write_row(out, "surface area", readable_number(p.surface_area), units.area);
    write_row(out, "centre of mass", vector_text(p.center_of_mass), units.length);
    write_matrix(out, "inertia about COM", p.inertia, units.inertia);
    if (settings.about == About::kOrigin) {
        write_matrix(out, "inertia about origin", p.inertia_origin, units.inertia);
    } else if (settings.about == About::kPoint) {
        write_matrix(out, "inertia about point", part.result.inertia_point.data(), units.inertia);
        write_row(out, "  (the point)", vector_text(settings.point.data()), units.length);
    }
    write_row(out, "principal moments", vector_text(p.principal_moments), units.inertia);
    for (int axis = 0; axis < 3; ++axis) {
        write_row(out, axis == 0 ? "principal axes" : "",
                  vector_text(principal_axis(p, axis).data()));
    }
    std::string warnings;
    for (const std::string& name : warning_names(p.warnings)) {
        warnings += (warnings.empty() ? "" : ", ") + name;
    }
    write_row(out, "warnings", warnings.empty() ? "none" : warnings);
    write_row(out, "provenance", provenance_text(part.result.provenance));
    write_row(out, "error bound", error_bound_text(p));
}

}  // namespace

void write_table(std::ostream& out, const std::vector<FileReport>& files,
                 const OutputSettings& settings) {
    for (const FileReport& file : files) {
        if (&file != &files.front()) out << '\n';
        if (!file.readable) {
            out << file.path << ": CANNOT READ: " << file.read_error << '\n';
            continue;
        }
        out << file.path << " (" << file.format;
        if (!file.parts.empty()) out << ", " << file.parts.size() << " parts, combined";
        out << ")\n";
        for (const std::string& note : file.notes) out << "  note: " << note << '\n';
        OutputSettings file_settings = settings;
        file_settings.length_unit = length_unit_of(file, settings);
        write_solid(out, file.solid, file_settings);
        for (const PartReport& part : file.parts) {
            out << "\n part '" << part.name << "'\n";
            if (part.computed) {
                write_solid(out, part, file_settings);
            } else {
                write_row(out, "vertices, faces",
                          std::to_string(part.vertices) + ", " + std::to_string(part.faces));
            }
        }
    }
    if (files.size() > 1) {
        const Summary summary = summarize(files);
        out << "\nsummary: " << summary.files << " files, " << summary.valid << " valid, "
            << summary.files - summary.valid << " failed; total mass of the valid ones "
            << readable_number(summary.total_mass) << '\n';
    }
}

}  // namespace polymass_cli
