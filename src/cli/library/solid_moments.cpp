#include "library/solid_moments.hpp"

#include <new>
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
                          double surface_area, uint32_t warnings) {
    SolidResult result;
    polymass_mass_properties_init(&result.properties, sizeof result.properties);
    result.status =
        polymass_moments_mass_properties(&result.properties, library.context(), &moments, nullptr);
    if (result.status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (result.status != POLYMASS_OK) {
        result.message = library.message();
        return result;
    }
    polymass_provenance_init(&result.provenance, sizeof result.provenance);
    result.provenance.mode = POLYMASS_MODE_SOLID;
    result.properties.surface_area = surface_area;
    result.properties.warnings = warnings;
    add_inertia_point(library, result);
    return result;
}

}  // namespace polymass_cli
