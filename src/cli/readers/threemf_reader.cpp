// 3MF (3MF Consortium, 3MF Core Specification 1.3), read here with libzip
// (the package) and pugixml (its model), in double precision: the
// specification writes coordinates and transforms as decimal numbers, and
// each is parsed to the nearest double (lib3mf 1.x, read before, rounded them
// to 32-bit floats: a public sample's volume 195037.7183 where its decimals
// give 195037.7039).
//
// The package's root relationships (_rels/.rels) name the model part (the
// relationship of type .../3dmanufacturing/2013/01/3dmodel). Its <model
// unit> (millimeter when absent) is applied: lengths in metres, as Collada's
// <unit> is (Model::declared_unit). Its <resources> hold <object>s, each a
// <mesh> (<vertices><vertex x y z/>..., <triangles><triangle v1 v2 v3/>...)
// or <components> (<component objectid transform/>...) naming objects
// defined before it (the specification's rule, which also rules out cycles);
// each <build><item objectid transform/> is a part: its object's meshes,
// through components to any depth, placed by the item's and the components'
// transforms composed in double precision. A mirroring placement has its
// triangles' corners reversed so the solid stays outside-out. A transform
// is 12 numbers m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32 acting on row
// vectors: (x y z 1) times the 4x3 matrix.
//
// The unit is applied last, each coordinate placed in the file's unit times
// the unit's metres in one rounding: a coordinate a millimetre file writes
// as 12.5 becomes the double nearest 12.5 times the double nearest 0.001,
// within an ulp of the exact metres (a decimal factor has no exact binary
// form). Folding the factor into the composed transforms would round it
// into each of their 12 numbers and change how the translation's sum
// rounds; applied last, the coordinates in the file's unit stay exactly
// those read before, and the metres are one multiplication from them.
//
// Hostile packages: a zip bomb is refused by the sizes its central directory
// declares, before anything is inflated; a part read is never larger than its
// declared size (libzip stops there, and a checksum that does not match is an
// error); the mesh reader runs this in a child process with a memory budget.
#include <zip.h>

#include <algorithm>
#include <map>
#include <memory>
#include <new>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "readers/format_readers.hpp"
#include "readers/isolated_reader.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"
#include "readers/transform.hpp"
#include "reports/utf8.hpp"
#include "xml_memory.hpp"

namespace polymass_cli {
namespace {

constexpr const char* kModelRelationship =
    "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";

[[noreturn]] void fail(const std::string& what) {
    throw ReadError("not a readable 3MF file: " + what);
}

// The package, opened by libzip from the bytes (which stay the caller's).
class Package {
public:
    explicit Package(std::string_view bytes) : size_(bytes.size()) {
        // Fails only when it cannot allocate (the bytes are never NULL).
        zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, nullptr);
        if (source == nullptr) throw std::bad_alloc();
        zip_error_t error;
        zip_error_init(&error);
        archive_ = zip_open_from_source(source, ZIP_RDONLY, &error);
        const bool out_of_memory = zip_error_code_zip(&error) == ZIP_ER_MEMORY;
        const std::string why = zip_error_strerror(&error);
        zip_error_fini(&error);
        if (archive_ == nullptr) {
            zip_source_free(source);
            if (out_of_memory) throw std::bad_alloc();
            fail("not a zip package (" + why + ")");
        }
    }
    ~Package() { zip_discard(archive_); }  // frees the source too
    Package(const Package&) = delete;
    Package& operator=(const Package&) = delete;

    // A zip bomb is refused before it inflates: the sizes the central
    // directory declares for the parts add up to no more than the reader's
    // memory budget (the same bound read_isolated sets). Reading the
    // directory inflates nothing.
    void check_declared_sizes() const {
        const uint64_t most = reader_memory_budget(size_);
        uint64_t declared = 0;
        const zip_int64_t entries = zip_get_num_entries(archive_, 0);
        for (zip_int64_t i = 0; i < entries && declared <= most; ++i) {
            zip_stat_t part;
            // The name as stored (ZIP_FL_ENC_RAW): converting it would
            // allocate, and only the size is wanted.
            if (zip_stat_index(archive_, zip_uint64_t(i), ZIP_FL_ENC_RAW, &part) == 0 &&
                (part.valid & ZIP_STAT_SIZE) != 0) {
                // Saturates: two parts declaring 2^63 bytes each do not wrap.
                declared += std::min<uint64_t>(part.size, most + 1);
            }
        }
        if (declared > most) {
            fail("its parts inflate to more than " + std::to_string(most >> 20) + " MiB from " +
                 std::to_string(size_) +
                 " bytes, more than a mesh of that size can hold (a zip bomb?)");
        }
    }

    // The part's bytes (OPC part names are case-insensitive), its declared
    // size at most: a part that inflates to another size, or whose checksum
    // does not match, is an error.
    std::string part(const std::string& name) const {
        const zip_int64_t index = zip_name_locate(archive_, name.c_str(), ZIP_FL_NOCASE);
        if (index < 0) fail("the package has no part " + valid_utf8(name));
        zip_stat_t stat;
        if (zip_stat_index(archive_, zip_uint64_t(index), 0, &stat) != 0 ||
            (stat.valid & ZIP_STAT_SIZE) == 0)
            fail("the part " + valid_utf8(name) + " has no size");
        std::string bytes(stat.size, '\0');
        zip_file_t* file = zip_fopen_index(archive_, zip_uint64_t(index), 0);
        if (file == nullptr) fail(valid_utf8(name) + ": " + zip_strerror(archive_));
        const zip_int64_t read = zip_fread(file, bytes.data(), bytes.size());
        // Reading on at the end checks the checksum (libzip's CRC error).
        char extra = 0;
        const zip_int64_t after =
            read == zip_int64_t(bytes.size()) ? zip_fread(file, &extra, 1) : -1;
        const std::string why = zip_file_strerror(file);
        zip_fclose(file);
        if (after != 0) fail(valid_utf8(name) + ": " + (after > 0 ? "longer than declared" : why));
        return bytes;
    }

private:
    zip_t* archive_ = nullptr;
    uint64_t size_;
};

pugi::xml_document parse(const std::string& bytes, const std::string& part) {
    pugixml_allocates_with_new();
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_buffer(bytes.data(), bytes.size());
    if (!parsed) {
        fail(part + " is not well-formed XML (" + parsed.description() + " at byte " +
             std::to_string(parsed.offset) + ")");
    }
    return document;
}

// The model part's name, from the package's root relationships.
std::string model_part_name(const Package& package) {
    const pugi::xml_document relationships = parse(package.part("_rels/.rels"), "_rels/.rels");
    for (const pugi::xml_node relationship :
         relationships.child("Relationships").children("Relationship")) {
        if (std::string_view(relationship.attribute("Type").value()) != kModelRelationship)
            continue;
        std::string target = relationship.attribute("Target").value();
        if (!target.empty() && target.front() == '/') target.erase(0, 1);
        return target;
    }
    fail("_rels/.rels names no 3D model part");
}

// Where a value is ("object 3: vertex 17"), spelled out only for an error:
// a model has millions of vertices.
struct Where {
    const std::string& place;
    const char* element = nullptr;  // "vertex", "triangle", or none
    uint64_t index = 0;

    std::string text() const {
        return element ? place + ": " + element + " " + std::to_string(index) : place;
    }
};

double number(const pugi::xml_node element, const char* name, const Where& where) {
    const pugi::xml_attribute attribute = element.attribute(name);
    double value = 0.0;
    if (!attribute || !parse_double(attribute.value(), value))
        fail(where.text() + ": " + name + " is not a number: '" + valid_utf8(attribute.value()) +
             "'");
    return value;
}

uint64_t whole_number(const pugi::xml_node element, const char* name, const Where& where) {
    const pugi::xml_attribute attribute = element.attribute(name);
    int64_t value = -1;
    if (!attribute || !parse_integer(attribute.value(), value) || value < 0)
        fail(where.text() + ": " + name + " is not a whole number: '" +
             valid_utf8(attribute.value()) + "'");
    return uint64_t(value);
}

// A transform attribute as the Transform of readers/transform.hpp (row-major
// 3x4, acting on column vectors): the transpose of 3MF's row-vector matrix.
Transform transform_of(const pugi::xml_node element, const std::string& where) {
    const pugi::xml_attribute attribute = element.attribute("transform");
    if (!attribute) return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    std::string_view text = attribute.value();
    double m[12];
    int count = 0;
    while (!text.empty()) {
        const std::string_view::size_type start = text.find_first_not_of(" \t\r\n");
        if (start == std::string_view::npos) break;
        text.remove_prefix(start);
        const std::string_view token = text.substr(0, text.find_first_of(" \t\r\n"));
        text.remove_prefix(token.size());
        if (count == 12 || !parse_double(token, m[count])) {
            count = -1;  // a 13th token, or one that is no number
            break;
        }
        ++count;
    }
    if (count != 12)
        fail(where + ": the transform is not 12 numbers: '" + valid_utf8(attribute.value()) + "'");
    Transform t{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) t[4 * row + column] = m[3 * column + row];
        t[4 * row + 3] = m[9 + row];
    }
    return t;
}

const std::string kAnObject = "an object", kAComponent = "a component";

class ModelReader {
public:
    explicit ModelReader(Model& model) : model_(model) {}

    void add_object(Part& part, uint64_t id, const Transform& transform, unsigned depth) {
        // Components name objects defined before them, so there is no cycle;
        // this bounds the recursion of a long chain.
        constexpr unsigned kDeepest = 1000;
        if (depth > kDeepest) fail("the components are nested too deep");
        const pugi::xml_node object = objects_.at(id);
        const std::string where = "object " + std::to_string(id);
        if (const pugi::xml_node mesh = object.child("mesh")) {
            add_mesh(part, mesh, transform, where);
            return;
        }
        for (const pugi::xml_node component : object.child("components").children("component")) {
            // collect() checked the object it names.
            add_object(part, whole_number(component, "objectid", {where}),
                       compose(transform, transform_of(component, where + ": a component")),
                       depth + 1);
        }
    }

    // The objects of <resources>, by id, in order.
    void collect(const pugi::xml_node resources) {
        for (const pugi::xml_node object : resources.children("object")) {
            const uint64_t id = whole_number(object, "id", {kAnObject});
            // A component may only name an object defined before it (not
            // itself): so there is no cycle.
            if (!objects_.emplace(id, object).second)
                fail("object id " + std::to_string(id) + " is used twice");
            for (const pugi::xml_node component :
                 object.child("components").children("component")) {
                const uint64_t child = whole_number(component, "objectid", {kAComponent});
                if (component.attribute("p:path"))
                    fail("object " + std::to_string(id) +
                         ": a component in another model part (3MF production extension)");
                if (objects_.find(child) == objects_.end() || child == id)
                    fail("object " + std::to_string(id) + ": a component names object " +
                         std::to_string(child) + ", which is not defined before it");
            }
        }
    }

    pugi::xml_node object(uint64_t id) const {
        const auto found = objects_.find(id);
        return found == objects_.end() ? pugi::xml_node() : found->second;
    }

private:
    void add_mesh(Part& part, const pugi::xml_node mesh, const Transform& transform,
                  const std::string& where) {
        const uint64_t first_vertex = model_.vertex_count();
        uint64_t vertex_count = 0;
        for (const pugi::xml_node vertex : mesh.child("vertices").children("vertex")) {
            const Where at{where, "vertex", vertex_count};
            append_transformed(model_.positions.as_doubles(), transform, number(vertex, "x", at),
                               number(vertex, "y", at), number(vertex, "z", at));
            ++vertex_count;
        }
        if (model_.vertex_count() >= kIndexOutOfRange) fail("more than 4294967294 vertices");
        const bool mirrored = determinant(transform) < 0;
        uint64_t triangle = 0;
        for (const pugi::xml_node corners : mesh.child("triangles").children("triangle")) {
            const Where at{where, "triangle", triangle++};
            uint32_t indices[3];
            const char* names[] = {"v1", "v2", "v3"};
            for (int corner = 0; corner < 3; ++corner) {
                const uint64_t index = whole_number(corners, names[corner], at);
                if (index >= vertex_count)
                    fail(at.text() + ": vertex index " + std::to_string(index) +
                         " is out of range (" + std::to_string(vertex_count) + " vertices)");
                indices[corner] = uint32_t(first_vertex + index);
            }
            for (int corner = 0; corner < 3; ++corner)
                part.indices.push_back(indices[mirrored ? 2 - corner : corner]);
            part.face_sizes.push_back(3);
        }
    }

    Model& model_;
    std::map<uint64_t, pugi::xml_node> objects_;
};

}  // namespace

Model read_3mf(std::string_view bytes) {
    const Package package(bytes);
    package.check_declared_sizes();
    const std::string name = model_part_name(package);
    const pugi::xml_document document = parse(package.part(name), valid_utf8(name));
    const pugi::xml_node root = document.child("model");
    if (!root) fail(valid_utf8(name) + " has no <model>");

    Model model;
    // Metres per unit, each the exact definition (the inch and the foot
    // since 1959) rounded once to a double.
    static const struct {
        const char* name;
        double metres;
    } kUnits[] = {{"micron", 1e-6}, {"millimeter", 1e-3}, {"centimeter", 1e-2},
                  {"inch", 0.0254}, {"foot", 0.3048},     {"meter", 1.0}};
    const pugi::xml_attribute unit_attribute = root.attribute("unit");
    const std::string unit = unit_attribute ? unit_attribute.value() : "millimeter";
    const auto known = std::find_if(std::begin(kUnits), std::end(kUnits),
                                    [&](const auto& candidate) { return unit == candidate.name; });
    if (known == std::end(kUnits))
        fail("<model unit='" + valid_utf8(unit) +
             "'> is none of micron, millimeter, "
             "centimeter, inch, foot, meter");
    model.declared_unit = unit_attribute ? unit : unit + ", 3MF's default";

    ModelReader reader(model);
    reader.collect(root.child("resources"));
    for (const pugi::xml_node item : root.child("build").children("item")) {
        const std::string where = "build item " + std::to_string(model.parts.size() + 1);
        const uint64_t id = whole_number(item, "objectid", {where});
        const pugi::xml_node object = reader.object(id);
        if (!object) fail(where + " names object " + std::to_string(id) + ", which is not defined");
        Part part;
        part.name = object.attribute("name").value();
        if (part.name.empty()) part.name = "item " + std::to_string(model.parts.size() + 1);
        reader.add_object(part, id, transform_of(item, where), 0);
        if (!part.face_sizes.empty()) model.parts.push_back(std::move(part));
    }
    scale_model(model, known->metres);
    return model;
}

}  // namespace polymass_cli
