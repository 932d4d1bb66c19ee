// Stanford PLY, ASCII and binary (little- and big-endian): the header declares
// elements and their properties; `vertex` gives x, y, z (any numeric type) and
// `face` a list property `vertex_indices` (or `vertex_index`). Other elements
// and properties are read past. Every read is bounds-checked: a truncated body
// is an error naming the element, never a read past the end of the file.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

enum class Scalar { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct Property {
    std::string name;
    Scalar type = Scalar::kFloat32;  // of the value, or of a list's items
    bool is_list = false;
    Scalar count_type = Scalar::kUint8;  // of a list's length
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

enum class Encoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

bool scalar_from_name(std::string_view name, Scalar& type) {
    static const struct {
        const char* names[2];
        Scalar type;
    } kTypes[] = {
        {{"char", "int8"}, Scalar::kInt8},        {{"uchar", "uint8"}, Scalar::kUint8},
        {{"short", "int16"}, Scalar::kInt16},     {{"ushort", "uint16"}, Scalar::kUint16},
        {{"int", "int32"}, Scalar::kInt32},       {{"uint", "uint32"}, Scalar::kUint32},
        {{"float", "float32"}, Scalar::kFloat32}, {{"double", "float64"}, Scalar::kFloat64}};
    for (const auto& candidate : kTypes) {
        if (name == candidate.names[0] || name == candidate.names[1]) {
            type = candidate.type;
            return true;
        }
    }
    return false;
}

bool is_integer(Scalar type) { return type != Scalar::kFloat32 && type != Scalar::kFloat64; }

size_t size_of(Scalar type) {
    switch (type) {
        case Scalar::kInt8:
        case Scalar::kUint8:
            return 1;
        case Scalar::kInt16:
        case Scalar::kUint16:
            return 2;
        case Scalar::kInt32:
        case Scalar::kUint32:
        case Scalar::kFloat32:
            return 4;
        case Scalar::kFloat64:
            return 8;
    }
    return 8;
}

// The body's values one after another, whatever the encoding. Every value is
// returned as a double, which holds any PLY integer exactly.
class BodyReader {
public:
    BodyReader(std::string_view bytes, std::string_view::size_type start, Encoding encoding)
        : bytes_(bytes), offset_(start), encoding_(encoding), lines_(bytes, start) {}

    // element and item say where, for the error message.
    double read(Scalar type, const Element& element, uint64_t item) {
        return encoding_ == Encoding::kAscii ? read_text(type, element, item)
                                             : read_binary(type, element, item);
    }

private:
    static std::string where(const Element& element, uint64_t item) {
        return element.name + " " + std::to_string(item);
    }

    double read_text(Scalar type, const Element& element, uint64_t item) {
        std::string_view token;
        while (!lines_.next_token(token)) {
            if (!lines_.next_line(false))
                throw ReadError("the file ends inside " + where(element, item));
        }
        double value = 0.0;
        int64_t integer = 0;
        if (is_integer(type) ? !parse_integer(token, integer) : !parse_double(token, value)) {
            lines_.fail("expected a number in " + where(element, item));
        }
        return is_integer(type) ? static_cast<double>(integer) : value;
    }

    double read_binary(Scalar type, const Element& element, uint64_t item) {
        const size_t size = size_of(type);
        if (bytes_.size() - offset_ < size) {
            throw ReadError("the file ends inside " + where(element, item) +
                            " (truncated binary PLY)");
        }
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + offset_, size);
        offset_ += size;
        if (encoding_ == Encoding::kBinaryBigEndian) {
            for (size_t i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
        }
        switch (type) {
            case Scalar::kInt8:
                return static_cast<int8_t>(raw[0]);
            case Scalar::kUint8:
                return raw[0];
            case Scalar::kInt16:
                return load<int16_t>(raw);
            case Scalar::kUint16:
                return load<uint16_t>(raw);
            case Scalar::kInt32:
                return load<int32_t>(raw);
            case Scalar::kUint32:
                return load<uint32_t>(raw);
            case Scalar::kFloat32:
                return load<float>(raw);
            case Scalar::kFloat64:
                return load<double>(raw);
        }
        return 0.0;
    }

    // Host byte order is little-endian on every platform the tool is built for;
    // big-endian data was swapped above.
    template <typename T>
    static double load(const unsigned char* raw) {
        T value;
        std::memcpy(&value, raw, sizeof value);
        return static_cast<double>(value);
    }

    std::string_view bytes_;
    std::string::size_type offset_;
    Encoding encoding_;
    TextLines lines_;
};

struct Header {
    Encoding encoding = Encoding::kAscii;
    std::vector<Element> elements;
    std::string_view::size_type body_start = 0;
};

Header read_header(std::string_view bytes) {
    TextLines lines(bytes);
    std::string_view token;
    if (!lines.next_line(false) || !lines.next_token(token) || token != "ply") {
        throw ReadError("not a PLY file: it does not start with 'ply'");
    }
    Header header;
    bool has_format = false;
    while (true) {
        if (!lines.next_line(false)) throw ReadError("the PLY header has no end_header");
        if (!lines.next_token(token) || token == "comment" || token == "obj_info") continue;
        if (token == "end_header") break;
        if (token == "format") {
            const std::string_view encoding = lines.expect_token("the format");
            if (encoding == "ascii") {
                header.encoding = Encoding::kAscii;
            } else if (encoding == "binary_little_endian") {
                header.encoding = Encoding::kBinaryLittleEndian;
            } else if (encoding == "binary_big_endian") {
                header.encoding = Encoding::kBinaryBigEndian;
            } else {
                lines.fail("unknown PLY format '" + std::string(encoding.substr(0, 40)) + "'");
            }
            has_format = true;
        } else if (token == "element") {
            Element& element = header.elements.emplace_back();
            element.name = std::string(lines.expect_token("an element name"));
            const int64_t count = lines.expect_integer("an element count");
            // Each element takes at least one byte: a larger count is corrupt.
            if (count < 0 || static_cast<uint64_t>(count) > bytes.size()) {
                lines.fail("impossible element count " + std::to_string(count));
            }
            element.count = static_cast<uint64_t>(count);
        } else if (token == "property") {
            if (header.elements.empty()) lines.fail("a property before any element");
            Property property;
            std::string_view type = lines.expect_token("a property type");
            if (type == "list") {
                property.is_list = true;
                if (!scalar_from_name(lines.expect_token("a list count type"),
                                      property.count_type) ||
                    !is_integer(property.count_type)) {
                    lines.fail("a list's count type must be an integer type");
                }
                type = lines.expect_token("a list item type");
            }
            if (!scalar_from_name(type, property.type)) {
                lines.fail("unknown property type '" + std::string(type.substr(0, 40)) + "'");
            }
            property.name = std::string(lines.expect_token("a property name"));
            header.elements.back().properties.push_back(property);
        } else {
            lines.fail("unexpected '" + std::string(token.substr(0, 40)) + "' in the PLY header");
        }
    }
    if (!has_format) throw ReadError("the PLY header has no format line");
    header.body_start = lines.offset();
    return header;
}

// An index is kept as written when it fits, so the library reports a bad one.
uint32_t vertex_index(double value) {
    if (value < 0.0 || value >= static_cast<double>(kIndexOutOfRange)) return kIndexOutOfRange;
    return static_cast<uint32_t>(value);
}

}  // namespace

Model read_ply(std::string_view bytes) {
    const Header header = read_header(bytes);
    BodyReader body(bytes, header.body_start, header.encoding);
    Model model;
    Part& part = model.parts.emplace_back();
    std::vector<double>& positions = model.positions.as_doubles();
    for (const Element& element : header.elements) {
        const bool is_vertex = element.name == "vertex";
        const bool is_face = element.name == "face";
        // The coordinate (0, 1, 2 for x, y, z) each vertex property holds, or -1.
        std::vector<int> axis_of(element.properties.size(), -1);
        if (is_vertex && element.count > 0) {
            bool has_xyz[3] = {false, false, false};
            for (size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                for (int axis = 0; axis < 3; ++axis) {
                    if (!property.is_list && property.name == std::string(1, "xyz"[axis])) {
                        axis_of[p] = axis;
                        has_xyz[axis] = true;
                    }
                }
            }
            if (!(has_xyz[0] && has_xyz[1] && has_xyz[2])) {
                throw ReadError("the PLY vertices have no x, y and z properties");
            }
        }
        // An element without properties takes no token or byte, whatever its
        // count: skipped at once, not counted through (a header can declare
        // such elements by the million).
        if (element.properties.empty()) continue;
        for (uint64_t item = 0; item < element.count; ++item) {
            double xyz[3] = {0.0, 0.0, 0.0};
            for (size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                if (!property.is_list) {
                    const double value = body.read(property.type, element, item);
                    if (axis_of[p] >= 0) xyz[axis_of[p]] = value;
                    continue;
                }
                const double length = body.read(property.count_type, element, item);
                if (length < 0.0 || length > static_cast<double>(bytes.size())) {
                    throw ReadError("impossible list length in " + element.name + " " +
                                    std::to_string(item));
                }
                const bool is_corners =
                    is_face && is_integer(property.type) &&
                    (property.name == "vertex_indices" || property.name == "vertex_index");
                for (uint64_t i = 0; i < static_cast<uint64_t>(length); ++i) {
                    const double value = body.read(property.type, element, item);
                    if (is_corners) part.indices.push_back(vertex_index(value));
                }
                if (is_corners) part.face_sizes.push_back(static_cast<uint32_t>(length));
            }
            if (is_vertex) positions.insert(positions.end(), xyz, xyz + 3);
        }
    }
    return model;
}

}  // namespace polymass_cli
