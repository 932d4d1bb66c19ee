// --json: one object per file (an array under "files" with a summary when
// several files are given). The keys are documented in the README.
#include <polymass/polymass.h>

#include <cmath>
#include <utility>

#include "categories.hpp"
#include "json_writer.hpp"
#include "report.hpp"

namespace polymass_cli {
namespace {

void write_error(JsonWriter& json, const char* category, const std::string& message) {
    json.key("error").begin_object();
    json.key("category").value(std::string(category));
    json.key("message").value(message);
    json.end_object();
}

// The members of a solid's object (the caller opens and closes it).
void write_solid_members(JsonWriter& json, const PartReport& part, const OutputSettings& settings) {
    json.key("vertices").value(part.vertices);
    json.key("faces").value(part.faces);
    if (part.result.status != POLYMASS_OK) {
        write_error(json, category_of(part.result.status), part.result.message);
        return;
    }
    const polymass_mass_properties& p = part.result.properties;
    json.key("volume").value(p.volume);
    json.key("mass").value(p.mass);
    json.key("density").value(p.density);
    json.key("center_of_mass").numbers(p.center_of_mass, 3);
    json.key("inertia").matrix(p.inertia);
    json.key("inertia_origin").matrix(p.inertia_origin);
    if (settings.about == About::kPoint) {
        json.key("about_point").numbers(settings.point.data(), 3);
        json.key("inertia_point").matrix(p.inertia_point);
    }
    json.key("principal_moments").numbers(p.principal_moments, 3);
    // Axis i (the columns of the library's rotation) goes with moment i.
    json.key("principal_axes").begin_array();
    for (int axis = 0; axis < 3; ++axis) json.numbers(principal_axis(p, axis).data(), 3);
    json.end_array();
    json.key("surface_area").value(p.surface_area);
    json.key("warnings").begin_array();
    for (const std::string& name : warning_names(p.warnings)) json.value(name);
    json.end_array();
    // An infinite bound (rounding could be the whole mass) is left out.
    const std::pair<const char*, double> bounds[] = {
        {"volume", p.error_bound_volume},
        {"center_of_mass", p.error_bound_center_of_mass},
        {"inertia", p.error_bound_inertia},
        {"principal_moments", p.error_bound_principal_moments},
        {"principal_axes", p.error_bound_principal_axes}};
    json.key("error_bound").begin_object();
    for (const auto& [name, bound] : bounds)
        if (std::isfinite(bound)) json.key(name).value(bound);
    json.end_object();
}

void write_file(JsonWriter& json, const FileReport& file, const OutputSettings& settings) {
    json.begin_object();
    json.key("file").value(file.path);
    if (!file.readable) {
        write_error(json, kUnreadableCategory, file.read_error);
        json.end_object();
        return;
    }
    json.key("format").value(file.format);
    if (!settings.length_unit.empty()) json.key("length_unit").value(settings.length_unit);
    write_solid_members(json, file.solid, settings);
    if (!file.parts.empty()) {
        json.key("parts").begin_array();
        for (const PartReport& part : file.parts) {
            json.begin_object();
            json.key("name").value(part.name);
            if (part.computed) {
                write_solid_members(json, part, settings);
            } else {
                json.key("vertices").value(part.vertices);
                json.key("faces").value(part.faces);
            }
            json.end_object();
        }
        json.end_array();
    }
    json.end_object();
}

}  // namespace

void write_json(std::ostream& out, const std::vector<FileReport>& files,
                const OutputSettings& settings) {
    JsonWriter json(out);
    if (files.size() == 1) {
        write_file(json, files.front(), settings);
        return;
    }
    json.begin_object();
    json.key("files").begin_array();
    for (const FileReport& file : files) write_file(json, file, settings);
    json.end_array();
    const Summary summary = summarize(files);
    json.key("summary").begin_object();
    json.key("files").value(summary.files);
    json.key("valid").value(summary.valid);
    json.key("failed").value(summary.files - summary.valid);
    json.key("total_volume").value(summary.total_volume);
    json.key("total_mass").value(summary.total_mass);
    json.end_object();
    json.end_object();
}

}  // namespace polymass_cli
