// The three description parsers behind read_description, one file each.
#pragma once

#include <functional>

#include "audit/description.hpp"
#include "audit/xml_text.hpp"

namespace polymass_cli::audit {

// What URDF and SDFormat links share: the <inertial> child read by
// read_inertial, each <collision> and <visual> child by read_geometry (false:
// a shape not measured, said in unsupported). An element that cannot be read
// (DescriptionError) becomes the link's invalid_inertial, or a geometry
// marked invalid, so that the rest of the file is still audited.
using InertialReader =
    std::function<Inertial(const pugi::xml_node& inertial, const std::string& what)>;
using GeometryReader =
    std::function<bool(const pugi::xml_node& element, const std::string& what, Geometry& geometry,
                       std::vector<std::string>& unsupported)>;
void read_link_children(const pugi::xml_node& element, const InertialReader& read_inertial,
                        const GeometryReader& read_geometry, Link& link);

Description parse_urdf(const XmlFile& file);
Description parse_sdf(const XmlFile& file);
Description parse_mjcf(const XmlFile& file);

}  // namespace polymass_cli::audit
