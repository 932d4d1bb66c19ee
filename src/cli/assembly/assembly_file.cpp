// The assembly file through nlohmann-json, checked field by field: each
// object's keys are taken as they are read, and any left over is an unknown
// key (a typo such as "densty" must not fall back to a default).
#include "assembly/assembly_file.hpp"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "assembly/rotation.hpp"
#include "model/materials.hpp"
#include "model/units.hpp"
#include "readers/file_bytes.hpp"
#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

using Json = nlohmann::json;

// Where in the file a value is: the part it belongs to and its JSON path.
class Place {
public:
    Place(std::string file, std::string part, std::string path)
        : file_(std::move(file)), part_(std::move(part)), path_(std::move(path)) {}

    Place member(const std::string& key) const {
        return {file_, part_, path_.empty() ? key : path_ + "." + key};
    }
    Place element(size_t index) const {
        return {file_, part_, path_ + "[" + std::to_string(index) + "]"};
    }
    Place of_part(std::string part) const { return {file_, std::move(part), path_}; }

    [[noreturn]] void fail(const std::string& what) const {
        std::string where = file_ + ": ";
        if (!part_.empty()) where += part_ + ": ";
        if (!path_.empty()) where += path_ + ": ";
        throw AssemblyError(where + what);
    }

private:
    std::string file_, part_, path_;
};

// An object's members, taken one by one; finish() refuses the rest.
class Members {
public:
    Members(const Json& object, const Place& place) : object_(object), place_(place) {
        if (!object.is_object()) place.fail("an object {...} is expected here");
    }

    const Json* take(const std::string& key) {
        taken_.insert(key);
        const auto found = object_.find(key);
        return found == object_.end() ? nullptr : &*found;
    }

    // Refuses the keys not taken, named from `place` (the object's, by default).
    void finish(const char* known, const Place* place = nullptr) const {
        for (const auto& [key, value] : object_.items()) {
            if (!taken_.count(key))
                (place ? *place : place_).member(key).fail(std::string("unknown key; ") + known);
        }
    }

private:
    const Json& object_;
    Place place_;
    std::set<std::string> taken_;
};

double finite_number(const Json& value, const Place& place) {
    if (!value.is_number()) place.fail("a number is expected, not " + value.dump());
    const double number = value.get<double>();
    if (!std::isfinite(number)) place.fail("the number does not fit in a double");
    return number;
}

double positive_number(const Json& value, const Place& place) {
    const double number = finite_number(value, place);
    if (!(number > 0.0)) place.fail("a positive number is expected, not " + value.dump());
    return number;
}

std::string text(const Json& value, const Place& place) {
    if (!value.is_string()) place.fail("a string is expected, not " + value.dump());
    return value.get<std::string>();
}

template <size_t N>
std::array<double, N> numbers(const Json& value, const Place& place) {
    if (!value.is_array() || value.size() != N)
        place.fail("an array of " + std::to_string(N) + " numbers is expected, not " +
                   value.dump());
    std::array<double, N> out{};
    for (size_t k = 0; k < N; ++k) out[k] = finite_number(value[k], place.element(k));
    return out;
}

// "rotation": {"matrix": [[...], [...], [...]]}, {"quaternion_wxyz": [...]}
// or {"quaternion_xyzw": [...]}, exactly one; "mirror" allows a matrix of
// determinant -1.
std::array<double, 9> read_rotation(const Json& value, bool mirror, const Place& place) {
    Members members(value, place);
    const Json* matrix = members.take("matrix");
    const Json* wxyz = members.take("quaternion_wxyz");
    const Json* xyzw = members.take("quaternion_xyzw");
    members.finish("a rotation has \"matrix\", \"quaternion_wxyz\" or \"quaternion_xyzw\"");
    if ((matrix != nullptr) + (wxyz != nullptr) + (xyzw != nullptr) != 1)
        place.fail(
            "give exactly one of \"matrix\" (3 rows of 3), \"quaternion_wxyz\" "
            "([w, x, y, z]) or \"quaternion_xyzw\" ([x, y, z, w])");
    if (matrix) {
        const Place at = place.member("matrix");
        if (!matrix->is_array() || matrix->size() != 3)
            at.fail("3 rows of 3 numbers are expected, not " + matrix->dump());
        std::array<double, 9> rows{};
        for (size_t row = 0; row < 3; ++row) {
            const std::array<double, 3> values = numbers<3>((*matrix)[row], at.element(row));
            std::copy(values.begin(), values.end(), rows.begin() + 3 * row);
        }
        if (const std::string problem = rotation_problem(rows, mirror); !problem.empty())
            at.fail(problem);
        return rows;
    }
    if (mirror) place.fail("a quaternion cannot mirror; give a matrix with \"mirror\": true");
    const Place at = place.member(wxyz ? "quaternion_wxyz" : "quaternion_xyzw");
    const std::array<double, 4> q = numbers<4>(wxyz ? *wxyz : *xyzw, at);
    std::string error;
    const std::array<double, 9> rotation = wxyz ? quaternion_matrix(q[0], q[1], q[2], q[3], error)
                                                : quaternion_matrix(q[3], q[0], q[1], q[2], error);
    if (!error.empty()) at.fail(error);
    return rotation;
}

AssemblyPart read_part(const Json& value, size_t index, const std::string& file,
                       const std::filesystem::path& folder) {
    const std::string number = "parts[" + std::to_string(index) + "]";
    const Place at(file, number, "");
    Members members(value, at);
    AssemblyPart part;
    const Json* mesh = members.take("mesh");
    if (!mesh) at.fail("the part has no \"mesh\" (its mesh file)");
    part.mesh = text(*mesh, at.member("mesh"));
    if (part.mesh.empty()) at.member("mesh").fail("the mesh file's path is empty");
    part.name = part.mesh;
    if (const Json* name = members.take("name")) part.name = text(*name, at.member("name"));
    part.where = number + " \"" + part.name + "\"";
    const Place place = at.of_part(part.where);
    part.mesh = (folder / std::filesystem::path(part.mesh)).string();
    if (const Json* format = members.take("format"))
        part.format = text(*format, place.member("format"));
    if (const Json* units = members.take("units")) {
        const std::string unit = text(*units, place.member("units"));
        double metres = 0.0;
        if (!metres_per_unit(unit, metres))
            place.member("units").fail("\"" + unit + "\" is not one of " + known_units());
        part.metres_per_unit = metres;
    }
    const Json* density = members.take("density");
    const Json* mass = members.take("mass");
    const Json* material = members.take("material");
    if ((density != nullptr) + (mass != nullptr) + (material != nullptr) != 1)
        place.fail("give exactly one of \"density\", \"material\" and \"mass\"");
    part.by_mass = mass != nullptr;
    if (material) {
        const Place field = place.member("material");
        const std::string name = text(*material, field);
        const Material* known = find_material(name);
        if (!known)
            field.fail("\"" + name + "\" is not a known material; the known ones are " +
                       known_materials() + " (docs/materials.md)");
        // Its density is in kg/m^3, which lengths of unknown unit would misread.
        if (!part.metres_per_unit)
            field.fail("a material's density is in kg/m^3: the part needs its \"units\"");
        part.material = known->name;
        part.value = known->density;
    } else {
        part.value =
            positive_number(mass ? *mass : *density, place.member(mass ? "mass" : "density"));
    }
    if (const Json* translation = members.take("translation"))
        part.translation = numbers<3>(*translation, place.member("translation"));
    bool mirror = false;
    if (const Json* flag = members.take("mirror")) {
        if (!flag->is_boolean()) place.member("mirror").fail("true or false is expected");
        mirror = flag->get<bool>();
    }
    if (const Json* rotation = members.take("rotation")) {
        part.rotation = read_rotation(*rotation, mirror, place.member("rotation"));
    } else if (mirror) {
        place.member("mirror").fail("a mirror needs a \"rotation\" matrix of determinant -1");
    }
    members.finish(
        "a part has \"name\", \"mesh\", \"format\", \"units\", \"density\", \"material\" "
        "or \"mass\", "
        "\"translation\", \"rotation\" and \"mirror\"",
        &place);
    return part;
}

// The document, with a key repeated in one object refused (nlohmann-json
// would keep the last one silently). The file is mapped as mesh files are: a
// device (/dev/zero) or a pipe, which has no end to read to, is refused
// rather than read without bound.
Json parse_document(const std::string& path, const Place& place) {
    std::string content;
    try {
        content = std::string(FileBytes(path).view());
    } catch (const ReadError& error) {
        place.fail(error.what());
    }
    std::vector<std::set<std::string>> keys;  // of each object being read
    std::string repeated;
    const Json::parser_callback_t check_keys = [&](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) keys.emplace_back();
        if (event == Json::parse_event_t::object_end) keys.pop_back();
        if (event == Json::parse_event_t::key &&
            !keys.back().insert(parsed.get<std::string>()).second && repeated.empty())
            repeated = parsed.get<std::string>();
        return true;
    };
    Json document;
    try {
        document = Json::parse(content, check_keys);
    } catch (const Json::exception& error) {
        place.fail(std::string("not valid JSON: ") + error.what());
    }
    if (!repeated.empty()) place.fail("the key \"" + repeated + "\" is given twice in one object");
    return document;
}

}  // namespace

Assembly read_assembly_file(const std::string& path) {
    const Place top(path, "", "");
    const Json document = parse_document(path, top);
    Members members(document, top);
    const Json* parts = members.take("parts");
    members.finish("an assembly file has \"parts\"");
    if (!parts || !parts->is_array() || parts->empty())
        top.member("parts").fail("a non-empty array of parts is expected");
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    Assembly assembly;
    for (size_t k = 0; k < parts->size(); ++k)
        assembly.parts.push_back(read_part((*parts)[k], k, path, folder));
    // Lengths convert to metres for every part or for none: mixing metres
    // with a mesh's own unit would add lengths of different units.
    size_t with_units = 0;
    for (const AssemblyPart& part : assembly.parts) with_units += part.metres_per_unit.has_value();
    if (with_units != 0 && with_units != assembly.parts.size()) {
        for (size_t k = 0; k < assembly.parts.size(); ++k) {
            if (!assembly.parts[k].metres_per_unit)
                top.of_part(assembly.parts[k].where)
                    .fail(
                        "no \"units\", where other parts give theirs: give every part's "
                        "units (the results are then in metres) or none");
        }
    }
    assembly.in_metres = with_units != 0;
    return assembly;
}

}  // namespace polymass_cli
