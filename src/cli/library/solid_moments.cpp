#include "library/solid_moments.hpp"

#include <new>
#include <stdexcept>
#include <utility>

namespace polymass_cli {
namespace {

polymass_moments blank_moments() {
    polymass_moments moments{};
    polymass_moments_init(&moments, sizeof moments);
    return moments;
}

// Runs one polymass_moments_* call into a fresh result.
template <class Call>
MomentsResult moments_step(const Library& library, Call&& call) {
    MomentsResult result;
    result.moments = blank_moments();
    result.status = call(&result.moments);
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (result.status != POLYMASS_OK) result.message = library.message();
    return result;
}

}  // namespace

IntegratedSolid::IntegratedSolid(const Library& library, const Model& model, const Part& part,
                                 const polymass_options& options) {
    const polymass_mesh_desc desc = describe(model, part);
    status_ = polymass_mesh_create_with_options(&mesh_, library.context(), &desc, &options);
    if (status_ == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status_ != POLYMASS_OK) {
        message_ = library.message();
        return;
    }
    polymass_mass_properties own{};
    polymass_mass_properties_init(&own, sizeof own);
    const int32_t status = polymass_mesh_mass_properties(&own, library.context(), mesh_, nullptr);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();  // its warnings unknown
    if (status == POLYMASS_OK) warnings_ = own.warnings;
}

IntegratedSolid::~IntegratedSolid() { polymass_mesh_destroy(mesh_); }

IntegratedSolid::IntegratedSolid(IntegratedSolid&& other) noexcept
    : mesh_(std::exchange(other.mesh_, nullptr)),
      status_(other.status_),
      message_(std::move(other.message_)),
      warnings_(other.warnings_) {}

SolidResult IntegratedSolid::failure() const {
    SolidResult result;
    result.status = status_;
    result.message = message_;
    return result;
}

SolidResult IntegratedSolid::properties(const Library& library,
                                        const polymass_mass_desc& mass) const {
    SolidResult result;
    polymass_mass_properties_init(&result.properties, sizeof result.properties);
    result.status =
        polymass_mesh_mass_properties(&result.properties, library.context(), mesh_, &mass);
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (result.status != POLYMASS_OK) result.message = library.message();
    return result;
}

polymass_moments IntegratedSolid::moments(const Library& library) const {
    polymass_moments moments = blank_moments();
    // Reading a valid mesh's moments only copies its integrals.
    if (polymass_mesh_moments(&moments, library.context(), mesh_) != POLYMASS_OK)
        throw std::logic_error("polymass_mesh_moments: " + library.message());
    return moments;
}

MomentsResult weighted(const Library& library, const polymass_moments& moments,
                       const polymass_mass_desc& mass) {
    return moments_step(library, [&](polymass_moments* out) {
        return polymass_moments_weight(out, library.context(), &moments, &mass);
    });
}

MomentsResult scaled(const Library& library, const polymass_moments& moments, double factor) {
    return scaled(library, moments, {factor, factor, factor});
}

MomentsResult scaled(const Library& library, const polymass_moments& moments,
                     const std::array<double, 3>& factors) {
    return moments_step(library, [&](polymass_moments* out) {
        return polymass_moments_scale(out, library.context(), &moments, factors.data());
    });
}

MomentsResult transformed(const Library& library, const polymass_moments& moments,
                          const std::array<double, 9>& rotation,
                          const std::array<double, 3>& translation) {
    return moments_step(library, [&](polymass_moments* out) {
        return polymass_moments_transform(out, library.context(), &moments, rotation.data(),
                                          translation.data());
    });
}

MomentsResult sum(const Library& library, const std::vector<polymass_moments>& bodies) {
    MomentsResult total;
    total.moments = bodies.at(0);
    for (size_t k = 1; k < bodies.size() && total.status == POLYMASS_OK; ++k) {
        total = moments_step(library, [&](polymass_moments* out) {
            return polymass_moments_add(out, library.context(), &total.moments, &bodies[k]);
        });
    }
    return total;
}

SolidResult properties_of(const Library& library, const polymass_moments& moments,
                          const std::array<double, 3>& point, double surface_area,
                          uint32_t warnings) {
    // The library takes the point from a mass description, which also
    // weights: the body's own mass weights it by exactly 1.
    polymass_mass_desc own{};
    polymass_mass_desc_init(&own, sizeof own);
    own.mass_mode = POLYMASS_MASS_FROM_TOTAL;
    own.mass = moments.mass;
    for (int axis = 0; axis < 3; ++axis) own.point[axis] = point[axis];
    SolidResult result;
    polymass_mass_properties_init(&result.properties, sizeof result.properties);
    result.status =
        polymass_moments_mass_properties(&result.properties, library.context(), &moments, &own);
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (result.status != POLYMASS_OK) {
        result.message = library.message();
        return result;
    }
    result.properties.surface_area = surface_area;
    result.properties.warnings = warnings;
    return result;
}

}  // namespace polymass_cli
