#include "library/solid.hpp"

#include <algorithm>
#include <iterator>
#include <new>
#include <stdexcept>
#include <utility>

#include "library/huge_page_memory.hpp"

namespace polymass_cli {

polymass_mesh_desc describe(const Model& model, const Part& part) {
    polymass_mesh_desc desc{};
    polymass_mesh_desc_init(&desc, sizeof desc);
    desc.position_type =
        model.positions.is_float32() ? POLYMASS_POSITION_FLOAT32 : POLYMASS_POSITION_FLOAT64;
    desc.positions = model.positions.data();
    desc.vertex_count = model.vertex_count();
    desc.index_type = POLYMASS_INDEX_UINT32;
    desc.indices = part.indices.data();
    desc.index_count = part.indices.size();
    // Triangles only (an STL, most meshes: a part without face sizes): none,
    // so that the library takes its triangle paths (the integrals eight
    // triangles at a time).
    const bool triangles = part.face_sizes.empty();
    desc.face_sizes = triangles ? nullptr : part.face_sizes.data();
    desc.face_count = part.face_sizes.size();
    return desc;
}

namespace {

// The tool's options that ask for each mode, in the order they are
// suggested: the closest answer first; a thin wall last, for a flat surface
// that neither a repair nor a hull answers.
constexpr std::pair<uint32_t, const char*> kSuggested[] = {
    {POLYMASS_MODE_REPAIR, "--repair"},
    {POLYMASS_MODE_HULL, "--hull"},
    {POLYMASS_MODE_SHELL, "--shell T"},
};

// Whether some mode may answer a surface refused with status: none reads
// faces that use a vertex past the end or a coordinate that is not finite.
bool some_mode_may_answer(int32_t status) {
    return status != POLYMASS_ERROR_INDEX_OUT_OF_RANGE && status != POLYMASS_ERROR_NON_FINITE;
}

}  // namespace

Library::Library(const polymass_options& options, uint32_t threads,
                 const std::array<double, 3>& point)
    : options_(options), point_(point) {
    const int32_t created = polymass_context_create(&context_, huge_page_allocator());
    if (created == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (created != POLYMASS_OK) {
        throw std::runtime_error(std::string("polymass_context_create: ") +
                                 polymass_status_string(created));
    }
    // The tool analyses each surface once: scratch blocks kept for a next
    // call would only add to the peak memory of the one call that counts
    // (blocks the topology checks free, kept beside the larger ones the
    // intersection check asks for: 10 MB of a million-triangle STL's peak).
    polymass_context_set_scratch_limit(context_, 0);
    const int32_t set = polymass_context_set_threads(context_, threads);
    if (set != POLYMASS_OK) {
        const std::string message = polymass_context_message(context_);
        polymass_context_destroy(context_);
        if (set == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
        throw std::invalid_argument(message);
    }
}

Library::~Library() { polymass_context_destroy(context_); }

void add_inertia_point(const Library& library, SolidResult& result) {
    if (result.status != POLYMASS_OK) return;
    result.status = polymass_inertia_about(result.inertia_point.data(), &result.properties,
                                           library.point().data());
    // The point is finite (the command line checks it): only a moment
    // beyond a double is refused.
    if (result.status != POLYMASS_OK)
        result.message = "the inertia about the point " +
                         std::string(polymass_status_string(result.status)) +
                         ": a moment does not fit in a double";
}

SolidResult compute_solid(const Library& library, const Model& model, const Part& part,
                          const polymass_mass_desc& mass) {
    const polymass_mesh_desc desc = describe(model, part);
    SolidResult result;
    polymass_mass_properties_init(&result.properties, sizeof result.properties);
    polymass_provenance_init(&result.provenance, sizeof result.provenance);
    result.status =
        polymass_mass_properties_compute(&result.properties, &result.provenance, library.context(),
                                         &desc, &library.options(), &mass);
    if (result.status == POLYMASS_OK) {
        add_inertia_point(library, result);
        return result;
    }
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    result.message = library.message();
    suggest_option(library, desc, result.status, result);
    return result;
}

void suggest_option(const Library& library, const polymass_mesh_desc& desc, int32_t status,
                    SolidResult& result) {
    result.options_tried = true;
    if (!some_mode_may_answer(status)) return;
    // Whether a mode answers a surface the status does not rule out is
    // known only by trying it: a second analysis, of a refused surface only,
    // whose chain is the modes the options lack, in the order suggested (the
    // first that answers is the one suggested).
    const polymass_options& options = library.options();
    polymass_options trial = options;
    std::fill(std::begin(trial.modes), std::end(trial.modes), uint32_t(POLYMASS_MODE_NONE));
    const uint32_t* chain_end = std::end(options.modes);
    uint32_t* next = trial.modes;
    for (const auto& [mode, option] : kSuggested)
        if (std::find(std::begin(options.modes), chain_end, mode) == chain_end) *next++ = mode;
    if (next == trial.modes) return;
    trial.shell_thickness = 1.0;  // any: whether the surface has an area to make a wall of
    polymass_mass_properties properties{};
    polymass_mass_properties_init(&properties, sizeof properties);
    polymass_provenance provenance{};
    polymass_provenance_init(&provenance, sizeof provenance);
    const int32_t answered = polymass_mass_properties_compute(
        &properties, &provenance, library.context(), &desc, &trial, nullptr);
    // Out of memory says nothing of whether a mode would answer.
    if (answered == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (answered != POLYMASS_OK) return;
    for (const auto& [mode, option] : kSuggested) {
        if (uint32_t(provenance.mode) != mode) continue;
        result.answering_option = option;
        result.answering_provenance = provenance;
        result.message += " (" + result.answering_option + " would give an answer)";
    }
}

const char* shell_kind_name(int32_t kind) {
    switch (kind) {
        case POLYMASS_SHELL_SOLID:
            return "solid";
        case POLYMASS_SHELL_CAVITY:
            return "cavity";
        case POLYMASS_SHELL_INVERTED:
            return "inverted";
        case POLYMASS_SHELL_OVERLAPPING:
            return "overlapping";
        case POLYMASS_SHELL_NO_VOLUME:
            return "no volume";
        default:
            return "unjudged";
    }
}

}  // namespace polymass_cli
