#include <cstring>

#include "audit/description.hpp"
#include "audit/description_parsers.hpp"

namespace polymass_cli::audit {

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
