#include "model/materials.hpp"

#include <cctype>

namespace polymass_cli {
namespace {

// Nominal densities: a real part's alloy, temper, fill or print settings can
// differ by a few per cent (docs/materials.md says where and by how much).
constexpr Material kMaterials[] = {
    {"aluminium-2024", 2780, "ASM Handbook Vol. 2 (1990)"},
    {"aluminium-5052", 2680, "ASM Handbook Vol. 2 (1990)"},
    {"aluminium-6061", 2700, "ASM Handbook Vol. 2 (1990)"},
    {"aluminium-7075", 2810, "ASM Handbook Vol. 2 (1990)"},
    {"steel", 7850, "EN 1993-1-1 (Eurocode 3) 3.2.6, structural steel"},
    {"steel-1018", 7870, "ASM Handbook Vol. 1 (1990), AISI 1018"},
    {"steel-4140", 7850, "ASM Handbook Vol. 1 (1990), AISI 4140"},
    {"stainless-304", 8000, "ASM Handbook Vol. 1 (1990), wrought stainless steels"},
    {"stainless-316", 8000, "ASM Handbook Vol. 1 (1990), wrought stainless steels"},
    {"titanium-grade2", 4510, "ASM Materials Properties Handbook: Titanium Alloys (1994)"},
    {"ti-6al-4v", 4430, "ASM Materials Properties Handbook: Titanium Alloys (1994)"},
    {"brass-c26000", 8530, "Copper Development Association, C26000 cartridge brass"},
    {"brass-c36000", 8500, "Copper Development Association, C36000 free-cutting brass"},
    {"copper-c11000", 8890, "Copper Development Association, C11000 ETP copper"},
    {"abs", 1040, "Stratasys ABS-M30 datasheet (ASTM D792)"},
    {"pla", 1240, "NatureWorks Ingeo 4043D datasheet (ASTM D792)"},
    {"petg", 1270, "Eastman Eastar 6763 datasheet (ASTM D792)"},
    {"nylon-pa12", 1010, "Evonik VESTAMID L1901 datasheet (ISO 1183)"},
    {"nylon-pa12-sls", 930, "EOS PA 2200 datasheet, laser-sintered part"},
    {"polycarbonate", 1200, "Covestro Makrolon 2405 datasheet (ISO 1183-1)"},
    {"pom", 1420, "DuPont Delrin 100 datasheet (ISO 1183)"},
    {"tpu-95a", 1220, "Ultimaker TPU 95A technical data sheet (ASTM D792)"},
};

std::string folded(const std::string& name) {
    std::string lower;
    for (const char c : name) lower += char(std::tolower(static_cast<unsigned char>(c)));
    const std::string american = "aluminum";
    if (lower.compare(0, american.size(), american) == 0)
        lower = "aluminium" + lower.substr(american.size());
    return lower;
}

}  // namespace

const Material* find_material(const std::string& name) {
    const std::string key = folded(name);
    for (const Material& material : kMaterials) {
        if (key == material.name) return &material;
    }
    return nullptr;
}

std::string known_materials() {
    std::string names;
    for (const Material& material : kMaterials) {
        names += (names.empty() ? "" : ", ") + std::string(material.name);
    }
    return names;
}

}  // namespace polymass_cli
