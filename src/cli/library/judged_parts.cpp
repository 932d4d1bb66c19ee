#include "library/judged_parts.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "library/solid_moments.hpp"

namespace polymass_cli {
namespace {

// Each part judged alone and, when every one is a solid as given, the parts
// apart and the check between them; the whole surface is left to
// judge_parts, which needs it when they are not (solid_parts does not).
JudgedParts judge_apart(const Library& library, const Model& model) {
    // Each part judged alone as an exact solid, whatever the chain, so that
    // a whole of exact parts gets the same bits with --fallback as without.
    // The check between the parts sees every part's faces: each part is
    // judged without it.
    polymass_options part_options = library.options();
    part_options.flags |= POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    std::fill(std::begin(part_options.modes), std::end(part_options.modes),
              uint32_t(POLYMASS_MODE_NONE));
    part_options.modes[0] = POLYMASS_MODE_SOLID;
    JudgedParts judged;
    judged.solids.reserve(model.parts.size());
    for (const Part& part : model.parts)
        judged.solids.emplace_back(library, model, part, part_options);
    if (!std::all_of(judged.solids.begin(), judged.solids.end(),
                     [](const SurfaceAnalysis& s) { return s.valid_as_given(); }))
        return judged;
    judged.apart = parts_apart(library, model);
    // Every part is a valid solid by now: in range, finite, weldable.
    if (!judged.apart) throw std::logic_error("a valid part could not be welded");
    // Parts crossing each other, or one inside another, would count twice.
    const uint32_t skips =
        POLYMASS_OPTION_SKIP_INTERSECTION_CHECK | POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
    if (!(library.options().flags & skips))
        judged.between.emplace(analyse_between(library, *judged.apart));
    return judged;
}

}  // namespace

JudgedParts judge_parts(const Library& library, const Model& model) {
    JudgedParts judged = judge_apart(library, model);
    if (!judged.apart)
        judged.whole.emplace(library, model, combined_part(model), library.options());
    return judged;
}

SurfaceAnalysis analyse_between(const Library& library, const PartsApart& apart) {
    polymass_options options = unwelded_options(library.options());
    std::fill(std::begin(options.modes), std::end(options.modes), uint32_t(POLYMASS_MODE_NONE));
    options.modes[0] = POLYMASS_MODE_SOLID;
    return SurfaceAnalysis(library, apart.model, apart.model.parts.front(), options);
}

SolidResult part_properties(const Library& library, const JudgedParts& judged, std::size_t k,
                            const polymass_mass_desc& mass) {
    SolidResult result = judged.solids[k].properties(library, mass);
    const std::optional<SurfaceAnalysis>& cover = judged.apart ? judged.between : judged.whole;
    if (cover && (cover->diagnostics().checks & POLYMASS_CHECKED_INTERSECTIONS))
        result.properties.warnings &= ~uint32_t(POLYMASS_WARNING_INTERSECTIONS_UNCHECKED);
    return result;
}

std::optional<SolidParts> solid_parts(const Library& library, const Model& model) {
    if (model.parts.size() < 2) return std::nullopt;
    const JudgedParts judged = judge_apart(library, model);
    if (!judged.apart || (judged.between && !judged.between->valid())) return std::nullopt;
    polymass_mass_desc unit{};
    polymass_mass_desc_init(&unit, sizeof unit);
    SolidParts whole;
    std::vector<polymass_moments> bodies;
    for (std::size_t k = 0; k < judged.solids.size(); ++k) {
        const SolidResult part = part_properties(library, judged, k, unit);
        if (part.status != POLYMASS_OK) return std::nullopt;
        whole.surface_area += part.properties.surface_area;
        whole.warnings |= part.properties.warnings;
        bodies.push_back(judged.solids[k].moments(library));
    }
    if (judged.between && judged.between->diagnostics().touching_face_pairs > 0)
        whole.warnings |= POLYMASS_WARNING_TOUCHING_FACES;
    const MomentsResult total = sum(library, bodies);
    if (total.status != POLYMASS_OK) return std::nullopt;
    whole.moments = total.moments;
    return whole;
}

}  // namespace polymass_cli
