// polymass assembly FILE: each part's mesh read and analysed once (a mesh of
// several objects judged as `polymass FILE` judges it), its
// moments converted to metres, weighted with its density or mass and moved
// into the assembly's frame (polymass_moments_scale, _weight,
// _transform), reported from those moments; the whole is their exact sum.
// The parts are not checked against each other: parts that overlap count
// twice (the report's notes say so).
#include <algorithm>
#include <iostream>
#include <optional>
#include <utility>

#include "assembly/assembly_file.hpp"
#include "commands/commands.hpp"
#include "commands/part_materials.hpp"
#include "library/judged_parts.hpp"
#include "library/solid_moments.hpp"
#include "library/surface_analysis.hpp"
#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

inline constexpr const char* kNotCheckedNote =
    "the parts are not checked against each other: parts that overlap count twice";

// A part placed, or the step at which it failed.
struct PlacedPart {
    PartReport report;
    polymass_moments moments{};  // in the assembly's frame, weighted
};

SolidResult failure(int32_t status, std::string message) {
    SolidResult result;
    result.status = status;
    result.message = std::move(message);
    return result;
}

// A part's mesh as one solid at unit density: the exact sum of its parts
// when the file's parts are a whole apart (library/judged_parts.hpp: objects
// resting on each other, never welded together), else its whole surface
// analysed once. The properties (surface area and warnings, or the refusal)
// and the moments.
struct UnitSolid {
    SolidResult properties;
    polymass_moments moments{};
};

UnitSolid unit_solid(const Library& library, const Model& model, const Part& whole) {
    UnitSolid solid;
    if (const std::optional<SolidParts> parts = solid_parts(library, model)) {
        solid.properties =
            properties_of(library, parts->moments, parts->surface_area, parts->warnings);
        solid.moments = parts->moments;
        return solid;
    }
    const SurfaceAnalysis analysis(library, model, whole, library.options());
    if (!analysis.valid()) {
        solid.properties = analysis.failure();
        return solid;
    }
    polymass_mass_desc unit{};
    polymass_mass_desc_init(&unit, sizeof unit);
    solid.properties = analysis.properties(library, unit);
    solid.moments = analysis.moments(library);
    return solid;
}

// The part's moments through each step, stopping at the first refusal;
// factor is the metres per unit of the model's lengths.
PlacedPart place_part(const Library& library, const Model& model, const AssemblyPart& part,
                      double factor) {
    PlacedPart placed;
    const Part whole = combined_part(model);
    placed.report.name = part.name;
    placed.report.vertices = used_vertices(model, whole);
    placed.report.faces = whole.face_count();
    placed.report.computed = true;
    placed.report.material = part.material;
    const UnitSolid solid = unit_solid(library, model, whole);
    const SolidResult& own = solid.properties;  // its surface area and warnings
    if (own.status != POLYMASS_OK) {
        placed.report.result = own;
        return placed;
    }
    polymass_mass_desc unit{};
    polymass_mass_desc_init(&unit, sizeof unit);
    MomentsResult step{POLYMASS_OK, {}, solid.moments};
    if (factor != 1.0) step = scaled(library, step.moments, {factor, factor, factor});
    polymass_mass_desc material = unit;
    material.mass_mode = part.by_mass ? POLYMASS_MASS_FROM_TOTAL : POLYMASS_MASS_FROM_DENSITY;
    (part.by_mass ? material.mass : material.density) = part.value;
    if (step.status == POLYMASS_OK) step = weighted(library, step.moments, material);
    if (step.status == POLYMASS_OK)
        step = transformed(library, step.moments, part.rotation, part.translation);
    if (step.status != POLYMASS_OK) {
        placed.report.result = failure(step.status, step.message);
        return placed;
    }
    placed.moments = step.moments;
    placed.report.result =
        properties_of(library, step.moments, own.properties.surface_area * factor * factor,
                      own.properties.warnings);
    return placed;
}

FileReport assembly_report(const Library& library, const std::string& path,
                           const Assembly& assembly, const Arguments& arguments) {
    FileReport report;
    report.path = path;
    report.format = "assembly";
    std::vector<polymass_moments> bodies;
    double surface_area = 0.0;
    uint32_t warnings = 0;
    SolidResult broken;  // the first part that is not a valid solid
    // A mesh that declares its unit (3MF, Collada) is read in metres: the
    // first part whose mesh does, and the first whose mesh does not.
    const AssemblyPart* declares = nullptr;
    const AssemblyPart* declares_none = nullptr;
    for (const AssemblyPart& part : assembly.parts) {
        Model model;
        try {
            model = read_mesh_file(part.mesh, part.format);
        } catch (const ReadError& error) {
            report.read_error = path + ": " + part.where + ": " + error.what();
            return report;
        }
        if (arguments.triangulate) triangulate_model(model);
        // The declared unit is the mesh's truth: "units" is for meshes
        // that declare none, and never scales a length twice.
        double factor = part.metres_per_unit.value_or(1.0);
        if (!model.declared_unit.empty()) {
            if (part.metres_per_unit)
                model.notes.push_back("\"units\" not applied: the mesh declares its unit");
            factor = 1.0;
        }
        (model.declared_unit.empty() ? declares_none : declares) = &part;
        for (const std::string& note : model.notes)
            report.notes.push_back(part.where + ": " + note);
        PlacedPart placed = place_part(library, model, part, factor);
        const SolidResult& result = placed.report.result;
        if (result.status == POLYMASS_OK) {
            bodies.push_back(placed.moments);
            surface_area += result.properties.surface_area;
            warnings |= result.properties.warnings;
        } else if (broken.status == POLYMASS_OK) {
            broken = failure(result.status, part.where + ": " + result.message);
        }
        report.parts.push_back(std::move(placed.report));
    }
    // Without "units" (given for every part or none), a part in metres and
    // one in its file's unit cannot be added.
    if (!assembly.in_metres && declares != nullptr && declares_none != nullptr) {
        report.read_error = path + ": " + declares->where +
                            ": its mesh declares its unit (its lengths are metres) where " +
                            declares_none->where +
                            "'s does not: give every part's \"units\" (the results are then "
                            "in metres)";
        return report;
    }
    report.readable = true;
    report.in_metres = assembly.in_metres || declares_none == nullptr;
    if (assembly.parts.size() > 1) report.notes.push_back(kNotCheckedNote);
    report.solid.name = "assembly";
    report.solid.material = common_material(report.parts);
    for (const PartReport& part : report.parts) {
        report.solid.vertices += part.vertices;
        report.solid.faces += part.faces;
    }
    report.solid.computed = true;
    if (broken.status != POLYMASS_OK) {
        report.solid.result = broken;
        return report;
    }
    const MomentsResult total = sum(library, bodies);
    report.solid.result = total.status == POLYMASS_OK
                              ? properties_of(library, total.moments, surface_area, warnings)
                              : failure(total.status, total.message);
    // One part is the whole: listing it again says nothing.
    if (report.parts.size() == 1) report.parts.clear();
    return report;
}

}  // namespace

ExitCode run_assembly(const Arguments& arguments) {
    const Library library = library_for(arguments);
    const std::string& path = arguments.files.front();
    FileReport report;
    try {
        const Assembly assembly = read_assembly_file(path);
        report = assembly_report(library, path, assembly, arguments);
    } catch (const AssemblyError& error) {
        report.path = path;
        report.read_error = error.what();
    }
    for (const std::string& note : report.notes)
        std::cerr << "polymass: " << path << ": note: " << note << '\n';
    return write_reports({report}, arguments);
}

}  // namespace polymass_cli
