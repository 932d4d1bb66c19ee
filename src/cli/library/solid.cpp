#include "library/solid.hpp"

#include <new>
#include <stdexcept>

namespace polymass_cli {
namespace {

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
                                         const Part& part, bool weld, uint64_t& shell_count) {
    const polymass_mesh_desc desc = describe(model, part);
    polymass_options options{};
    options.struct_size = sizeof options;
    polymass_context_get_options(&options, library.context());
    polymass_options unwelded = options;
    if (!weld) unwelded.flags &= ~POLYMASS_OPTION_WELD_VERTICES;
    polymass_context_set_options(library.context(), &unwelded);
    std::vector<uint32_t> shells(part.face_sizes.size());
    shell_count = 0;
    if (polymass_mesh_shells(shells.data(), &shell_count, library.context(), &desc) != POLYMASS_OK)
        shells.clear();
    polymass_context_set_options(library.context(), &options);
    return shells;
}

}  // namespace polymass_cli
