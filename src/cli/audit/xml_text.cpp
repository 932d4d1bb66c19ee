#include "audit/xml_text.hpp"

#include <cmath>

#include "readers/file_bytes.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"
#include "text_streams.hpp"
#include "xml_memory.hpp"

namespace polymass_cli::audit {
namespace {

// The index just past the end of the tag that starts at text[at] == '<',
// quoted attribute values skipped; npos when the text ends first.
std::size_t tag_end(const std::string& text, std::size_t at) {
    char quote = 0;
    for (std::size_t i = at + 1; i < text.size(); ++i) {
        const char c = text[i];
        if (quote != 0) {
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '>') {
            return i + 1;
        }
    }
    return std::string::npos;
}

// The index past the first `terminator` after at, or npos.
std::size_t past(const std::string& text, std::size_t at, const char* terminator) {
    const std::size_t found = text.find(terminator, at);
    return found == std::string::npos ? found : found + std::char_traits<char>::length(terminator);
}

// The end of the element whose start tag begins at text[begin]: the nesting
// of tags followed, comments, CDATA and processing instructions skipped.
std::size_t element_end(const std::string& text, std::size_t begin) {
    std::size_t at = tag_end(text, begin);
    if (at == std::string::npos || text[at - 2] == '/') return at;
    int depth = 1;
    while (at != std::string::npos) {
        at = text.find('<', at);
        if (at == std::string::npos) break;
        if (text.compare(at, 4, "<!--") == 0) {
            at = past(text, at, "-->");
        } else if (text.compare(at, 9, "<![CDATA[") == 0) {
            at = past(text, at, "]]>");
        } else if (text.compare(at, 2, "<?") == 0 || text.compare(at, 2, "<!") == 0) {
            at = past(text, at, ">");
        } else {
            const bool closing = text.compare(at, 2, "</") == 0;
            at = tag_end(text, at);
            if (at == std::string::npos) break;
            if (closing) {
                if (--depth == 0) return at;
            } else if (text[at - 2] != '/') {
                ++depth;
            }
        }
    }
    return std::string::npos;
}

}  // namespace

void load_xml(XmlFile& file, const std::string& path) {
    // Mapped as mesh files are: a device (/dev/zero) or a pipe, which has
    // no end to read to, is refused rather than read without bound.
    try {
        file.text = std::string(FileBytes(path).view());
    } catch (const ReadError& error) {
        throw DescriptionError(path + ": " + error.what());
    }
    file.path = path;
    pugixml_allocates_with_new();
    // Parsed as UTF-8 from a copy of text, so that offsets are text's.
    const pugi::xml_parse_result parsed = file.document.load_buffer(
        file.text.data(), file.text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
        throw DescriptionError(path + ": not well-formed XML at byte " +
                               std::to_string(parsed.offset) + ": " + parsed.description());
    }
}

std::optional<TextRange> element_range(const XmlFile& file, const pugi::xml_node& element) {
    const std::string name = element.name();
    const std::ptrdiff_t offset = element.offset_debug();
    if (offset < 1) return std::nullopt;
    const std::size_t begin = static_cast<std::size_t>(offset) - 1;
    if (file.text.compare(begin, name.size() + 1, "<" + name) != 0) return std::nullopt;
    const std::size_t end = element_end(file.text, begin);
    if (end == std::string::npos) return std::nullopt;
    TextRange range{begin, end, ""};
    std::size_t line = file.text.rfind('\n', begin);
    line = line == std::string::npos ? 0 : line + 1;
    const std::string before = file.text.substr(line, begin - line);
    if (before.find_first_not_of(" \t") == std::string::npos) range.indent = before;
    return range;
}

std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& what) {
    std::vector<double> numbers;
    InputText fields(text);
    std::string field;
    while (fields >> field) {
        double value = 0.0;
        if (!parse_double(field, value) || !std::isfinite(value)) {
            throw DescriptionError(what + ": '" + field + "' is not a finite number");
        }
        numbers.push_back(value);
    }
    if (count != 0 && numbers.size() != count) {
        throw DescriptionError(what + ": wants " + std::to_string(count) + " numbers, not '" +
                               text + "'");
    }
    return numbers;
}

double parse_number(const std::string& text, const std::string& what) {
    return parse_numbers(text, 1, what)[0];
}

std::string describe(const pugi::xml_node& element) {
    std::string text = std::string("<") + element.name() + ">";
    const pugi::xml_attribute name = element.attribute("name");
    if (name) text += " '" + std::string(name.value()) + "'";
    return text;
}

}  // namespace polymass_cli::audit
