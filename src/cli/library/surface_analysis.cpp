#include "library/surface_analysis.hpp"

#include <new>
#include <stdexcept>
#include <utility>

namespace polymass_cli {
namespace {

// A getter's status: out of memory thrown; anything else but OK is a bug of
// the tool's (a getter of a mesh that exists answers).
void expect_ok(const Library& library, int32_t status, const char* what) {
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK) throw std::logic_error(std::string(what) + ": " + library.message());
}

}  // namespace

SurfaceAnalysis::SurfaceAnalysis(const Library& library, const Model& model, const Part& part,
                                 const polymass_options& options)
    : face_count_(part.face_count()) {
    polymass_diagnostics_init(&diagnostics_, sizeof diagnostics_);
    const polymass_mesh_desc desc = describe(model, part);
    status_ = polymass_mesh_create(&mesh_, library.context(), &desc, &options);
    if (status_ == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (mesh_ == nullptr) {
        // The analysis could not run (a description the library refuses):
        // its verdict is that refusal.
        message_ = library.message();
        diagnostics_.status = status_;
        return;
    }
    message_ = polymass_mesh_message(mesh_);
    expect_ok(library, polymass_mesh_diagnostics(&diagnostics_, library.context(), mesh_),
              "polymass_mesh_diagnostics");
    if (!valid()) return;
    polymass_mass_properties own{};
    polymass_mass_properties_init(&own, sizeof own);
    const int32_t status = polymass_mesh_mass_properties(&own, library.context(), mesh_, nullptr);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();  // its warnings unknown
    if (status == POLYMASS_OK) warnings_ = own.warnings;
}

SurfaceAnalysis::~SurfaceAnalysis() { polymass_mesh_destroy(mesh_); }

SurfaceAnalysis::SurfaceAnalysis(SurfaceAnalysis&& other) noexcept
    : mesh_(std::exchange(other.mesh_, nullptr)),
      status_(other.status_),
      message_(std::move(other.message_)),
      warnings_(other.warnings_),
      diagnostics_(other.diagnostics_),
      face_count_(other.face_count_) {}

SolidResult SurfaceAnalysis::failure() const {
    SolidResult result;
    result.status = status_;
    result.message = message_;
    return result;
}

SolidResult SurfaceAnalysis::properties(const Library& library,
                                        const polymass_mass_desc& mass) const {
    if (!valid()) return failure();
    SolidResult result;
    polymass_mass_properties_init(&result.properties, sizeof result.properties);
    polymass_provenance_init(&result.provenance, sizeof result.provenance);
    result.status =
        polymass_mesh_mass_properties(&result.properties, library.context(), mesh_, &mass);
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (result.status != POLYMASS_OK) {
        result.message = library.message();
        return result;
    }
    expect_ok(library, polymass_mesh_provenance(&result.provenance, library.context(), mesh_),
              "polymass_mesh_provenance");
    add_inertia_point(library, result);
    return result;
}

polymass_moments SurfaceAnalysis::moments(const Library& library) const {
    if (!valid()) throw std::logic_error("the moments of a surface no mode answered");
    polymass_moments moments{};
    polymass_moments_init(&moments, sizeof moments);
    // Reading an answered mesh's moments only copies its integrals.
    expect_ok(library, polymass_mesh_moments(&moments, library.context(), mesh_),
              "polymass_mesh_moments");
    return moments;
}

std::vector<polymass_shell> SurfaceAnalysis::shells(const Library& library) const {
    if (mesh_ == nullptr) return {};
    uint64_t count = 0;
    expect_ok(library, polymass_mesh_shells(nullptr, 0, &count, library.context(), mesh_),
              "polymass_mesh_shells");
    polymass_shell blank{};
    polymass_shell_init(&blank, sizeof blank);
    std::vector<polymass_shell> shells(count, blank);
    expect_ok(library,
              polymass_mesh_shells(shells.data(), shells.size(), &count, library.context(), mesh_),
              "polymass_mesh_shells");
    return shells;
}

std::vector<uint32_t> SurfaceAnalysis::shell_of_each_face(const Library& library) const {
    if (mesh_ == nullptr) return {};
    std::vector<uint32_t> shells(face_count_);
    const int32_t status =
        polymass_mesh_shell_of_face(shells.data(), shells.size(), library.context(), mesh_);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK) shells.clear();
    return shells;
}

SolidResult answer_of(const Library& library, const SurfaceAnalysis& analysis, const Model& model,
                      const Part& part, const polymass_mass_desc& mass) {
    SolidResult result = analysis.properties(library, mass);
    if (!analysis.valid()) suggest_option(library, describe(model, part), result.status, result);
    return result;
}

}  // namespace polymass_cli
