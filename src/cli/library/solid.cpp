#include "library/solid.hpp"

#include <algorithm>
#include <iterator>
#include <new>
#include <stdexcept>
#include <utility>

namespace polymass_cli {

polymass_mesh_desc describe(const Model& model, const Part& part) {
    polymass_mesh_desc desc{};
    desc.struct_size = sizeof desc;
    desc.position_type = POLYMASS_POSITION_FLOAT64;
    desc.positions = model.positions.data();
    desc.vertex_count = model.vertex_count();
    desc.index_type = POLYMASS_INDEX_UINT32;
    desc.indices = part.indices.data();
    desc.index_count = part.indices.size();
    desc.face_sizes = part.face_sizes.data();
    desc.face_count = part.face_sizes.size();
    return desc;
}

namespace {

// Which option of the tool would answer a part its options' chain refused:
// --repair, then --hull, then (for a flat surface, which neither answers)
// --shell T, among the modes the chain lacks. Writes
// result.answering_option (empty when none would) and what the mode did.
void probe_modes(const Library& library, const polymass_mesh_desc& desc, SolidResult& result) {
    polymass_options options{};
    options.struct_size = sizeof options;
    polymass_context_get_options(&options, library.context());
    const uint32_t* chain = options.modes;
    const uint32_t* chain_end = chain + POLYMASS_MAX_MODES;
    for (const auto& [mode, option] : {std::pair{uint32_t(POLYMASS_MODE_REPAIR), "--repair"},
                                       std::pair{uint32_t(POLYMASS_MODE_HULL), "--hull"},
                                       std::pair{uint32_t(POLYMASS_MODE_SHELL), "--shell T"}}) {
        if (std::find(chain, chain_end, mode) != chain_end) continue;
        polymass_options single = options;
        std::fill(std::begin(single.modes), std::end(single.modes), uint32_t(POLYMASS_MODE_NONE));
        single.modes[0] = mode;
        single.shell_thickness = 1.0;  // any: whether the surface has an area to make a wall of
        polymass_mass_properties properties{};
        properties.struct_size = sizeof properties;
        polymass_provenance& provenance = result.answering_provenance;
        provenance = polymass_provenance{};
        provenance.struct_size = sizeof provenance;
        const int32_t status = polymass_mass_properties_with_provenance(
            &properties, &provenance, library.context(), &desc, nullptr, &single);
        // Out of memory says nothing of whether the mode would answer.
        if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
        if (status == POLYMASS_OK) {
            result.answering_option = option;
            return;
        }
    }
}

}  // namespace

Library::Library(const polymass_options& options) {
    const int32_t created = polymass_context_create(&context_, nullptr);
    if (created == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (created != POLYMASS_OK) {
        throw std::runtime_error(std::string("polymass_context_create: ") +
                                 polymass_status_string(created));
    }
    const int32_t set = polymass_context_set_options(context_, &options);
    if (set != POLYMASS_OK) {
        const std::string message = polymass_context_message(context_);
        polymass_context_destroy(context_);
        throw std::invalid_argument(message);
    }
}

Library::~Library() { polymass_context_destroy(context_); }

SolidResult compute_solid(const Library& library, const Model& model, const Part& part,
                          const polymass_mass_desc& mass) {
    const polymass_mesh_desc desc = describe(model, part);
    SolidResult result;
    result.properties.struct_size = sizeof result.properties;
    result.provenance.struct_size = sizeof result.provenance;
    result.status = polymass_mass_properties_with_provenance(
        &result.properties, &result.provenance, library.context(), &desc, &mass, nullptr);
    if (result.status == POLYMASS_OK) return result;
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    result.message = library.message();
    probe_modes(library, desc, result);
    if (!result.answering_option.empty())
        result.message += " (" + result.answering_option + " would give an answer)";
    return result;
}

CheckResult check_solid(const Library& library, const Model& model, const Part& part) {
    const polymass_mesh_desc desc = describe(model, part);
    CheckResult result;
    result.diagnostics.struct_size = sizeof result.diagnostics;
    const int32_t status = polymass_mesh_check(&result.diagnostics, library.context(), &desc);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK) result.message = library.message();
    return result;
}

std::vector<uint32_t> shell_of_each_face(const Library& library, const Model& model,
                                         const Part& part) {
    const polymass_mesh_desc desc = describe(model, part);
    std::vector<uint32_t> shells(part.face_sizes.size());
    uint64_t count = 0;
    const int32_t status = polymass_mesh_shells(shells.data(), &count, library.context(), &desc);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK) shells.clear();
    return shells;
}

std::vector<polymass_shell> shell_list(const Library& library, const Model& model, const Part& part,
                                       uint64_t expected_count) {
    const polymass_mesh_desc desc = describe(model, part);
    polymass_shell blank{};
    blank.struct_size = sizeof blank;
    std::vector<polymass_shell> shells(expected_count, blank);
    uint64_t count = 0;
    int32_t status =
        polymass_mesh_shell_list(shells.data(), shells.size(), &count, library.context(), &desc);
    if (status == POLYMASS_OK && count > shells.size()) {
        shells.assign(count, blank);
        status = polymass_mesh_shell_list(shells.data(), shells.size(), &count, library.context(),
                                          &desc);
    }
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK) return {};
    shells.resize(count);
    return shells;
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
        default:
            return "no volume";
    }
}

}  // namespace polymass_cli
