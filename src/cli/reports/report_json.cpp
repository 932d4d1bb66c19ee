// --json: one object per file (an array under "files" with a summary when
// several files are given). The keys are documented in the README.
#include <polymass/polymass.h>

#include <cmath>
#include <utility>

#include "library/categories.hpp"
#include "reports/json_output.hpp"
#include "reports/provenance.hpp"
#include "reports/report.hpp"

namespace polymass_cli {
namespace {

Json error_object(const char* category, const std::string& message) {
    return Json{{"category", category}, {"message", message}};
}

// How the answer was reached (the README's schema).
Json provenance_object(const polymass_provenance& p) {
    Json provenance = {{"mode", answer_mode_name(p.mode)}};
    if (p.mode == POLYMASS_MODE_REPAIR) {
        Json repairs = Json::object();
        for (const RepairItem& item : repairs_of(p))
            repairs[item.key] = {{"count", item.count}, {"first", item.first}};
        provenance["repairs"] = repairs;
        provenance["cap_area_fraction"] = json_number(p.cap_area_fraction);
    } else if (p.mode == POLYMASS_MODE_SHELL) {
        provenance["thickness"] = json_number(p.shell_thickness);
        provenance["shell_area"] = json_number(p.shell_area);
    } else if (p.mode == POLYMASS_MODE_HULL) {
        provenance["hull_vertices"] = p.hull_vertex_count;
        provenance["hull_triangles"] = p.hull_triangle_count;
        provenance["hull_volume"] = json_number(p.hull_volume);
    }
    if (p.mode != POLYMASS_MODE_SOLID) {
        // The approximation's share of error_bound; infinite parts left out.
        Json share = Json::object();
        for (const auto& [name, bound] :
             {std::pair{"volume", p.approximation_bound_volume},
              std::pair{"center_of_mass", p.approximation_bound_center_of_mass},
              std::pair{"inertia", p.approximation_bound_inertia}})
            if (std::isfinite(bound)) share[name] = json_number(bound);
        provenance["approximation_bound"] = share;
    }
    return provenance;
}

// The members of a solid's object.
void add_solid_members(Json& solid, const PartReport& part, const OutputSettings& settings) {
    solid["vertices"] = part.vertices;
    solid["faces"] = part.faces;
    if (part.result.status != POLYMASS_OK) {
        solid["error"] = error_object(category_of(part.result.status), part.result.message);
        return;
    }
    const polymass_mass_properties& p = part.result.properties;
    solid["volume"] = json_number(p.volume);
    solid["mass"] = json_number(p.mass);
    solid["density"] = json_number(p.density);
    if (!part.material.empty()) solid["material"] = part.material;
    solid["center_of_mass"] = json_numbers(p.center_of_mass, 3);
    solid["inertia"] = json_tensor(p.inertia);
    solid["inertia_origin"] = json_tensor(p.inertia_origin);
    if (settings.about == About::kPoint) {
        solid["about_point"] = json_numbers(settings.point.data(), 3);
        solid["inertia_point"] = json_tensor(part.result.inertia_point.data());
    }
    solid["principal_moments"] = json_numbers(p.principal_moments, 3);
    // Axis i (the columns of the library's rotation) goes with moment i.
    Json axes = Json::array();
    for (int axis = 0; axis < 3; ++axis)
        axes.push_back(json_numbers(principal_axis(p, axis).data(), 3));
    solid["principal_axes"] = axes;
    solid["surface_area"] = json_number(p.surface_area);
    solid["warnings"] = warning_names(p.warnings);
    // An infinite bound (rounding could be the whole mass) is left out.
    const std::pair<const char*, double> bounds[] = {
        {"volume", p.error_bound_volume},
        {"center_of_mass", p.error_bound_center_of_mass},
        {"inertia", p.error_bound_inertia},
        {"principal_moments", p.error_bound_principal_moments},
        {"principal_axes", p.error_bound_principal_axes}};
    Json error_bound = Json::object();
    for (const auto& [name, bound] : bounds)
        if (std::isfinite(bound)) error_bound[name] = json_number(bound);
    solid["error_bound"] = error_bound;
    solid["provenance"] = provenance_object(part.result.provenance);
}

Json file_object(const FileReport& file, const OutputSettings& settings) {
    Json object = Json::object();
    object["file"] = file.path;
    if (!file.readable) {
        object["error"] = error_object(kUnreadableCategory, file.read_error);
        return object;
    }
    object["format"] = file.format;
    const std::string length_unit = length_unit_of(file, settings);
    if (!length_unit.empty()) object["length_unit"] = length_unit;
    if (!file.notes.empty()) object["notes"] = file.notes;
    add_solid_members(object, file.solid, settings);
    if (!file.parts.empty()) {
        Json parts = Json::array();
        for (const PartReport& part : file.parts) {
            Json entry = Json::object();
            entry["name"] = part.name;
            if (part.computed) {
                add_solid_members(entry, part, settings);
            } else {
                entry["vertices"] = part.vertices;
                entry["faces"] = part.faces;
            }
            parts.push_back(entry);
        }
        object["parts"] = parts;
    }
    return object;
}

}  // namespace

void write_json(std::ostream& out, const std::vector<FileReport>& files,
                const OutputSettings& settings) {
    print_json(out, json_document(files, settings));
}

Json json_document(const std::vector<FileReport>& files, const OutputSettings& settings) {
    if (files.size() == 1) return file_object(files.front(), settings);
    Json all = Json::array();
    for (const FileReport& file : files) all.push_back(file_object(file, settings));
    const Summary summary = summarize(files);
    Json document = Json::object();
    document["files"] = all;
    document["summary"] = {{"files", summary.files},
                           {"valid", summary.valid},
                           {"failed", summary.files - summary.valid},
                           {"total_volume", json_number(summary.total_volume)},
                           {"total_mass", json_number(summary.total_mass)}};
    return document;
}

}  // namespace polymass_cli
