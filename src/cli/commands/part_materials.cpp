#include "commands/part_materials.hpp"

#include <string>

namespace polymass_cli {

std::vector<polymass_mass_desc> part_masses(const Arguments& arguments, const std::string& path,
                                            const Model& model,
                                            const polymass_mass_desc& file_mass) {
    std::vector<polymass_mass_desc> masses(model.parts.size(), file_mass);
    for (const PartMaterial& material : arguments.part_materials) {
        bool found = false;
        for (size_t k = 0; k < model.parts.size(); ++k) {
            if (model.parts[k].name != material.part) continue;
            found = true;
            masses[k].mass_mode =
                material.by_mass ? POLYMASS_MASS_FROM_TOTAL : POLYMASS_MASS_FROM_DENSITY;
            (material.by_mass ? masses[k].mass : masses[k].density) = material.value;
        }
        if (found) continue;
        std::string known;
        for (const Part& part : model.parts) {
            const std::string quoted = "'" + part.name + "'";
            if (known.find(quoted) != std::string::npos) continue;  // names may repeat
            known += (known.empty() ? "" : ", ") + quoted;
        }
        const char* option = !material.material.empty() ? "--material "
                             : material.by_mass         ? "--mass "
                                                        : "--density ";
        throw UsageError(option + material.part + "=...: " + path + " has no part named '" +
                         material.part + "'; its parts are " + known);
    }
    return masses;
}

std::string material_of(const Arguments& arguments, const std::string& part) {
    for (const PartMaterial& material : arguments.part_materials) {
        if (material.part == part) return material.material;
    }
    return arguments.material;
}

std::string common_material(const std::vector<PartReport>& parts) {
    for (const PartReport& part : parts) {
        if (part.material != parts.front().material) return "";
    }
    return parts.empty() ? "" : parts.front().material;
}

}  // namespace polymass_cli
