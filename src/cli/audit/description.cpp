#include <cstring>

#include "audit/description.hpp"
#include "audit/description_parsers.hpp"

namespace polymass_cli::audit {

Pose compose(const Pose& parent, const Pose& child) {
    return {parent.rotation * child.rotation, parent.rotation * child.position + parent.position};
}

const char* format_name(Format format) {
    switch (format) {
        case Format::kUrdf:
            return "urdf";
        case Format::kSdf:
            return "sdf";
        case Format::kMjcf:
            return "mjcf";
    }
    return "unknown";
}

void read_link_children(const pugi::xml_node& element, const InertialReader& read_inertial,
                        const GeometryReader& read_geometry, Link& link) {
    const std::string what = "link '" + link.name + "'";
    if (const pugi::xml_node inertial = element.child("inertial")) {
        try {
            link.inertial = read_inertial(inertial, what + " <inertial>");
        } catch (const DescriptionError& error) {
            link.invalid_inertial = error.what();
        }
    }
    for (const char* kind : {"collision", "visual"}) {
        std::vector<Geometry>& list =
            std::strcmp(kind, "collision") == 0 ? link.collision : link.visual;
        for (const pugi::xml_node child : element.children(kind)) {
            std::string where = what + " <" + kind + ">";
            if (child.attribute("name"))
                where += " '" + std::string(child.attribute("name").value()) + "'";
            Geometry geometry;
            try {
                if (!read_geometry(child, where, geometry, link.unsupported)) continue;
            } catch (const DescriptionError& error) {
                geometry.invalid = error.what();
            }
            list.push_back(std::move(geometry));
        }
    }
}

Description read_description(const std::string& path) {
    XmlFile file;
    load_xml(file, path);
    const pugi::xml_node root = file.document.document_element();
    Description description;
    if (std::strcmp(root.name(), "robot") == 0) {
        description = parse_urdf(file);
    } else if (std::strcmp(root.name(), "sdf") == 0) {
        description = parse_sdf(file);
    } else if (std::strcmp(root.name(), "mujoco") == 0) {
        description = parse_mjcf(file);
    } else {
        throw DescriptionError(path + ": the root element <" + root.name() +
                               "> is none of <robot> (URDF), <sdf> (SDFormat), <mujoco> (MJCF)");
    }
    description.path = path;
    description.text = std::move(file.text);
    return description;
}

}  // namespace polymass_cli::audit
