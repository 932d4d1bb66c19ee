// What the description parsers share: the text of an element found again in
// the file's bytes (for --fix), and attribute or element values read as
// numbers, each refusal naming the element.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "audit/description.hpp"

namespace polymass_cli::audit {

// A parsed XML file whose nodes know their offsets in text.
struct XmlFile {
    std::string path;
    std::string text;
    pugi::xml_document document;
};

// Reads and parses path (DescriptionError when it cannot).
void load_xml(XmlFile& file, const std::string& path);

// The bytes of element in file.text, from its '<' to the end of its closing
// tag, or empty when they cannot be told (a document not parsed from text).
std::optional<TextRange> element_range(const XmlFile& file, const pugi::xml_node& element);

// The numbers of a whitespace-separated list; DescriptionError, naming what,
// unless there are exactly count (any count when count is 0).
std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& what);
double parse_number(const std::string& text, const std::string& what);

// "<name> 'value'" of an element, for messages: the element and its name
// attribute when it has one.
std::string describe(const pugi::xml_node& element);

}  // namespace polymass_cli::audit
