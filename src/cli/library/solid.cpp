#include "library/solid.hpp"

#include <new>
#include <stdexcept>

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
    result.status =
        polymass_mass_properties_compute(&result.properties, library.context(), &desc, &mass);
    if (result.status != POLYMASS_OK) result.message = library.message();
    return result;
}

CheckResult check_solid(const Library& library, const Model& model, const Part& part) {
    const polymass_mesh_desc desc = describe(model, part);
    CheckResult result;
    result.diagnostics.struct_size = sizeof result.diagnostics;
    if (polymass_mesh_check(&result.diagnostics, library.context(), &desc) != POLYMASS_OK) {
        result.message = library.message();
    }
    return result;
}

std::vector<uint32_t> shell_of_each_face(const Library& library, const Model& model,
                                         const Part& part) {
    const polymass_mesh_desc desc = describe(model, part);
    std::vector<uint32_t> shells(part.face_sizes.size());
    uint64_t count = 0;
    if (polymass_mesh_shells(shells.data(), &count, library.context(), &desc) != POLYMASS_OK)
        shells.clear();
    return shells;
}

std::vector<polymass_shell> shell_list(const Library& library, const Model& model,
                                       const Part& part) {
    const polymass_mesh_desc desc = describe(model, part);
    uint64_t count = 0;
    if (polymass_mesh_shell_list(nullptr, 0, &count, library.context(), &desc) != POLYMASS_OK)
        return {};
    polymass_shell blank{};
    blank.struct_size = sizeof blank;
    std::vector<polymass_shell> shells(count, blank);
    if (polymass_mesh_shell_list(shells.data(), count, &count, library.context(), &desc) !=
        POLYMASS_OK)
        return {};
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
