// An assembly file (JSON, schema in the README): parts, each a mesh file
// placed in the assembly's frame with its units and its density, material
// or mass.
// Every field is checked; an unknown or repeated key, a missing or ill-typed
// value, an ambiguous or improper rotation is an error naming the part and
// the JSON path of the field.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymass_cli {

struct AssemblyPart {
    std::string name;    // "name", or the "mesh" as written
    std::string where;   // parts[2] "name": how messages name the part
    std::string mesh;    // the mesh file's path, relative ones resolved against the assembly's
    std::string format;  // "format": empty means by extension
    // "units": metres per mesh unit; empty: the mesh's lengths are taken as they are.
    std::optional<double> metres_per_unit;
    bool by_mass = false;  // value is "mass", else "density"
    double value = 1.0;
    std::string material;  // "material": the table's name, value its density
    // x_assembly = rotation x_part + translation (row-major; orthonormal).
    std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::array<double, 3> translation{0, 0, 0};
};

struct Assembly {
    std::vector<AssemblyPart> parts;  // at least one
    bool in_metres = false;           // every part gave "units" (none did otherwise)
};

// An assembly file that cannot be read or is not as the schema says.
class AssemblyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads and checks path. Throws AssemblyError.
Assembly read_assembly_file(const std::string& path);

}  // namespace polymass_cli
