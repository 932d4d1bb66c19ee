#include "library/moments.hpp"

#include <stdexcept>
#include <string>

namespace polymass_cli {
namespace {

void require(const Library& library, int32_t status, const char* call) {
    if (status != POLYMASS_OK) {
        throw std::runtime_error(std::string(call) + ": " + library.message());
    }
}

polymass_moments blank_moments() {
    polymass_moments moments{};
    moments.struct_size = sizeof moments;
    return moments;
}

}  // namespace

polymass_moments scaled_moments(const Library& library, const polymass_moments& moments,
                                const std::array<double, 3>& factors) {
    polymass_moments out = blank_moments();
    require(library, polymass_moments_scale(&out, library.context(), &moments, factors.data()),
            "polymass_moments_scale");
    return out;
}

polymass_moments moved_moments(const Library& library, const polymass_moments& moments,
                               const std::array<double, 9>& rotation,
                               const std::array<double, 3>& translation) {
    polymass_moments out = blank_moments();
    require(library,
            polymass_moments_transform(&out, library.context(), &moments, rotation.data(),
                                       translation.data()),
            "polymass_moments_transform");
    return out;
}

polymass_moments added_moments(const Library& library, const polymass_moments& a,
                               const polymass_moments& b) {
    polymass_moments out = blank_moments();
    require(library, polymass_moments_add(&out, library.context(), &a, &b), "polymass_moments_add");
    return out;
}

polymass_mass_properties properties_at_mass(const Library& library, const polymass_moments& moments,
                                            double mass, const std::array<double, 3>& point) {
    polymass_mass_desc desc{};
    desc.struct_size = sizeof desc;
    desc.mass_mode = POLYMASS_MASS_FROM_TOTAL;
    desc.mass = mass;
    std::copy(point.begin(), point.end(), desc.point);
    polymass_mass_properties properties{};
    properties.struct_size = sizeof properties;
    require(library,
            polymass_moments_mass_properties(&properties, library.context(), &moments, &desc),
            "polymass_moments_mass_properties");
    return properties;
}

}  // namespace polymass_cli
