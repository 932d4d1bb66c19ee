// The three description parsers behind read_description, one file each.
#pragma once

#include "audit/description.hpp"
#include "audit/xml_text.hpp"

namespace polymass_cli::audit {

Description parse_urdf(const XmlFile& file);
Description parse_sdf(const XmlFile& file);
Description parse_mjcf(const XmlFile& file);

}  // namespace polymass_cli::audit
