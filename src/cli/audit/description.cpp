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

namespace {

bool ends_with(const std::string& text, const std::string& end) {
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// Whether a <robot> is xacro rather than URDF: its name says so, or it uses
// xacro elements or ${...} expressions. (An expanded URDF often keeps the
// xmlns:xacro declaration, which says nothing.)
bool is_xacro(const std::string& path, const pugi::xml_node& root) {
    if (ends_with(path, ".xacro")) return true;
    struct Finder : pugi::xml_tree_walker {
        bool found = false;
        bool for_each(pugi::xml_node& node) override {
            if (node.type() != pugi::node_element) return true;
            found = std::strncmp(node.name(), "xacro:", 6) == 0;
            for (const pugi::xml_attribute attribute : node.attributes()) {
                found = found || std::strstr(attribute.value(), "${") != nullptr;
            }
            return !found;
        }
    } finder;
    pugi::xml_node walked = root;
    walked.traverse(finder);
    return finder.found;
}

}  // namespace

Description read_description(const std::string& path) {
    XmlFile file;
    load_xml(file, path);
    const pugi::xml_node root = file.document.document_element();
    Description description;
    if (std::strcmp(root.name(), "robot") == 0 && is_xacro(path, root)) {
        throw DescriptionError(path +
                               ": a xacro file (macros and ${...} expressions), not a URDF: "
                               "expand it first, e.g. `xacro " +
                               path +
                               " > robot.urdf` (ROS's xacro package, or pip install xacro), "
                               "then audit robot.urdf");
    }
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
