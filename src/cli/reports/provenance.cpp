#include "reports/provenance.hpp"

#include <cmath>

#include "reports/number_format.hpp"

namespace polymass_cli {
namespace {

std::vector<std::vector<uint64_t>> locations(
    const uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS]) {
    std::vector<std::vector<uint64_t>> list;
    for (const uint64_t location : first)
        if (location != POLYMASS_NONE) list.push_back({location});
    return list;
}

std::vector<std::vector<uint64_t>> locations(
    const uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS][2]) {
    std::vector<std::vector<uint64_t>> list;
    for (const auto& pair : first)
        if (pair[0] != POLYMASS_NONE) list.push_back({pair[0], pair[1]});
    return list;
}

std::string bound_text(double bound) {
    return std::isfinite(bound) ? readable_number(bound) : std::string("unbounded");
}

}  // namespace

const char* answer_mode_name(int32_t mode) {
    switch (mode) {
        case POLYMASS_MODE_REPAIR:
            return "repaired";
        case POLYMASS_MODE_SHELL:
            return "shell";
        case POLYMASS_MODE_HULL:
            return "hull";
        default:
            return "solid";
    }
}

std::vector<RepairItem> repairs_of(const polymass_provenance& p) {
    const RepairItem all[] = {
        {"reoriented_faces", "faces turned to agree with their shell", p.reoriented_faces,
         locations(p.first_reoriented_faces)},
        {"turned_shells", "shells turned inside out (first faces)", p.turned_shells,
         locations(p.first_turned_shells)},
        {"duplicate_faces", "duplicate faces dropped", p.duplicate_faces,
         locations(p.first_duplicate_faces)},
        {"degenerate_faces", "faces of fewer than 3 vertices dropped", p.degenerate_faces,
         locations(p.first_degenerate_faces)},
        {"triangulated_faces", "non-planar faces triangulated", p.triangulated_faces,
         locations(p.first_triangulated_faces)},
        {"split_edges", "non-manifold edges split", p.split_edges, locations(p.first_split_edges)},
        {"holes", "holes capped (lowest vertices)", p.holes, locations(p.first_holes)},
    };
    std::vector<RepairItem> made;
    for (const RepairItem& item : all)
        if (item.count > 0) made.push_back(item);
    return made;
}

std::string provenance_text(const polymass_provenance& p) {
    switch (p.mode) {
        case POLYMASS_MODE_SHELL:
            return "shell: a thin wall " + readable_number(p.shell_thickness) +
                   " thick over the surface's area " + readable_number(p.shell_area);
        case POLYMASS_MODE_HULL:
            return "hull: the convex hull of the vertices (" + std::to_string(p.hull_vertex_count) +
                   " vertices, " + std::to_string(p.hull_triangle_count) +
                   " triangles): an upper bound of the solid";
        case POLYMASS_MODE_REPAIR:
            break;
        default:
            return "solid: exact, as given";
    }
    std::string text = "repaired:";
    for (const RepairItem& item : repairs_of(p)) {
        text += (text.back() == ':' ? " " : "; ") + std::to_string(item.count) + " " + item.label +
                " (first";
        for (const auto& location : item.first) {
            text += " " + std::to_string(location[0]);
            if (location.size() > 1) text += "-" + std::to_string(location[1]);
        }
        text += ")";
    }
    if (p.holes > 0)
        text += "; caps " + readable_number(100.0 * p.cap_area_fraction) + "% of the surface";
    return text;
}

std::string error_bound_text(const polymass_mass_properties& p) {
    return "volume " + bound_text(p.error_bound_volume) + ", centre of mass " +
           bound_text(p.error_bound_center_of_mass) + " (each coordinate), inertia " +
           bound_text(p.error_bound_inertia) + " (each entry)";
}

}  // namespace polymass_cli
