#include "commands/parts_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "commands/commands.hpp"
#include "commands/part_materials.hpp"
#include "library/solid_moments.hpp"

namespace polymass_cli {
namespace {

PartReport counted(const Model& model, const Part& part) {
    PartReport report;
    report.name = part.name;
    report.vertices = used_vertices(model, part);
    report.faces = part.face_count();
    return report;
}

void set_result(PartReport& report, SolidResult result) {
    report.computed = true;
    report.result = std::move(result);
}

SolidResult failure(int32_t status, std::string message) {
    SolidResult result;
    result.status = status;
    result.message = std::move(message);
    return result;
}

polymass_mass_desc with_density(polymass_mass_desc mass, double density) {
    mass.mass_mode = POLYMASS_MASS_FROM_DENSITY;
    mass.density = density;
    return mass;
}

// A part is not a solid by itself (a closed surface split into parts by
// material, say), or only once turned (a cavity exported as a part): the
// whole is computed as one surface, and the parts that are solids get its
// density, so that their masses add up to it. Parts of their own materials
// cannot be told apart from such a whole: refused.
void report_as_one(const Library& library, const Model& model, const Part& whole_part,
                   const Arguments& arguments, const JudgedParts& judged,
                   const std::vector<polymass_mass_desc>& masses,
                   const polymass_mass_desc& file_mass, FileReport& report) {
    const std::vector<SurfaceAnalysis>& solids = judged.solids;
    const size_t broken =
        std::find_if(solids.begin(), solids.end(),
                     [](const SurfaceAnalysis& s) { return !s.valid_as_given(); }) -
        solids.begin();
    const bool own_materials = !arguments.part_materials.empty();
    if (own_materials) {
        const SolidResult why = solids[broken].valid()
                                    ? failure(POLYMASS_ERROR_INVERTED,
                                              "inside out by itself, a cavity of another part?")
                                    : solids[broken].failure();
        set_result(report.solid,
                   failure(why.status, "part '" + model.parts[broken].name +
                                           "' is not a solid by itself (" + why.message +
                                           "), so it cannot have a density or mass of its own"));
    } else {
        set_result(report.solid, answer_of(library, *judged.whole, model, whole_part, file_mass));
    }
    const SolidResult& whole = report.solid.result;
    const bool density_known = whole.status == POLYMASS_OK || !arguments.mass;
    for (size_t k = 0; k < solids.size(); ++k) {
        PartReport part = counted(model, model.parts[k]);
        if (!solids[k].valid()) {
            set_result(part, solids[k].failure());
        } else if (own_materials) {
            set_result(part, part_properties(library, judged, k, masses[k]));
        } else if (density_known) {
            const polymass_mass_desc mass = whole.status == POLYMASS_OK
                                                ? with_density(file_mass, whole.properties.density)
                                                : file_mass;
            set_result(part, part_properties(library, judged, k, mass));
        }
        report.parts.push_back(std::move(part));
    }
}

// Every part weighted with its material (or, for the whole's --mass, at unit
// density) and added in the file's order; then the whole's --mass applied.
MomentsResult whole_moments(const Library& library, const std::vector<SurfaceAnalysis>& solids,
                            const std::vector<polymass_mass_desc>& masses,
                            const polymass_mass_desc& file_mass) {
    const bool whole_mass = file_mass.mass_mode == POLYMASS_MASS_FROM_TOTAL;
    std::vector<polymass_moments> bodies;
    for (size_t k = 0; k < solids.size(); ++k) {
        MomentsResult body{POLYMASS_OK, {}, solids[k].moments(library)};
        if (!whole_mass) body = weighted(library, body.moments, masses[k]);
        if (body.status != POLYMASS_OK) return body;
        bodies.push_back(body.moments);
    }
    MomentsResult total = sum(library, bodies);
    if (whole_mass && total.status == POLYMASS_OK)
        total = weighted(library, total.moments, file_mass);
    return total;
}

// With modes beyond the exact solid (--repair, --shell, --hull, --fallback)
// and a part that is no exact solid, or parts crossing each other: each part
// and the whole are answered by the chain, each with its own provenance (a
// whole the solid mode refuses may still have an approximate answer). Each
// face is then integrated twice: each part's own check is the chain's, which
// judges it with the intersection check the parts' exact analyses skip.
void report_by_chain(const Library& library, const Model& model, const Part& whole_part,
                     const JudgedParts& judged, const std::vector<polymass_mass_desc>& masses,
                     const polymass_mass_desc& file_mass, FileReport& report) {
    report.solid = counted(model, whole_part);
    set_result(report.solid, judged.whole
                                 ? answer_of(library, *judged.whole, model, whole_part, file_mass)
                                 : compute_solid(library, model, whole_part, file_mass));
    const SolidResult& whole = report.solid.result;
    const bool whole_mass = file_mass.mass_mode == POLYMASS_MASS_FROM_TOTAL;
    for (size_t k = 0; k < model.parts.size(); ++k) {
        PartReport part = counted(model, model.parts[k]);
        if (!whole_mass || whole.status == POLYMASS_OK) {
            const polymass_mass_desc mass =
                whole_mass ? with_density(file_mass, whole.properties.density) : masses[k];
            set_result(part, compute_solid(library, model, model.parts[k], mass));
        }
        report.parts.push_back(std::move(part));
    }
}

}  // namespace

void report_parts(const Library& library, const std::string& path, const Model& model,
                  const Arguments& arguments, const polymass_mass_desc& file_mass,
                  const JudgedParts& judged, FileReport& report) {
    const std::vector<polymass_mass_desc> masses = part_masses(arguments, path, model, file_mass);
    const Part whole = combined_part(model);  // every part's indices, copied once
    const bool by_chain = arguments.modes != std::vector<uint32_t>{POLYMASS_MODE_SOLID};
    const std::vector<SurfaceAnalysis>& solids = judged.solids;

    report.solid = counted(model, whole);
    if (!judged.apart) {
        if (by_chain) {
            report_by_chain(library, model, whole, judged, masses, file_mass, report);
        } else {
            report_as_one(library, model, whole, arguments, judged, masses, file_mass, report);
        }
        return;
    }

    const MomentsResult total = whole_moments(library, solids, masses, file_mass);
    SolidResult verdict = failure(total.status, total.message);
    uint32_t warnings = 0;
    if (verdict.status == POLYMASS_OK && judged.between) {
        verdict = judged.between->failure();
        if (judged.between->diagnostics().touching_face_pairs > 0)
            warnings |= POLYMASS_WARNING_TOUCHING_FACES;
    }
    if (verdict.status != POLYMASS_OK && by_chain) {
        report_by_chain(library, model, whole, judged, masses, file_mass, report);
        return;
    }

    // With the whole's --mass, the parts' density is the whole's.
    const bool whole_mass = file_mass.mass_mode == POLYMASS_MASS_FROM_TOTAL;
    double surface_area = 0.0;
    for (size_t k = 0; k < solids.size(); ++k) {
        PartReport part = counted(model, model.parts[k]);
        if (!whole_mass || verdict.status == POLYMASS_OK) {
            const polymass_mass_desc mass =
                whole_mass ? with_density(file_mass, total.moments.mass / total.moments.volume)
                           : masses[k];
            set_result(part, part_properties(library, judged, k, mass));
            const SolidResult& result = part.result;
            surface_area += result.status == POLYMASS_OK ? result.properties.surface_area
                                                         : std::numeric_limits<double>::quiet_NaN();
            warnings |= result.properties.warnings;
        }
        report.parts.push_back(std::move(part));
    }
    set_result(report.solid, verdict.status == POLYMASS_OK
                                 ? properties_of(library, total.moments, surface_area, warnings)
                                 : verdict);
}

}  // namespace polymass_cli
