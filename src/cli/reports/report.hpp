// What the tool found for each file, ready for one of the output writers.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "exit_codes.hpp"
#include "library/solid.hpp"
#include "reports/json_output.hpp"

namespace polymass_cli {

struct PartReport {
    std::string name;
    uint64_t vertices = 0;  // distinct vertices its faces use
    uint64_t faces = 0;
    bool computed = false;  // false: not attempted (see FileReport)
    std::string material;   // the materials table's name of its density, if it has one
    SolidResult result;
};

struct FileReport {
    std::string path;
    std::string format;
    bool readable = false;
    std::string read_error;          // when not readable
    std::vector<std::string> notes;  // the reader's (Model::notes)
    PartReport solid;                // all the file's faces together
    std::vector<PartReport> parts;   // each part, when the file has more than one
    double read_seconds = 0.0;
    double compute_seconds = 0.0;
    // Its lengths are metres whatever --units says: the file declares its
    // unit (Model::declared_unit); an assembly's parts all give their
    // "units", or all their meshes declare theirs.
    bool in_metres = false;

    ExitCode exit_code() const;
};

// How the results are labelled and which extra inertia is printed.
struct OutputSettings {
    About about = About::kCenterOfMass;
    std::array<double, 3> point{0.0, 0.0, 0.0};
    // "m" when every file's lengths are metres (--units, or units the files
    // declare), else empty: the file's unit (see length_unit_of).
    std::string length_unit;
    std::array<double, 3> link_origin{0.0, 0.0, 0.0};  // --origin (XML outputs)
};

// The file's lengths' unit: the settings', or metres when the file's are
// (a 3MF or Collada file among files without a unit).
std::string length_unit_of(const FileReport& file, const OutputSettings& settings);

void write_table(std::ostream& out, const std::vector<FileReport>& files,
                 const OutputSettings& settings);
void write_json(std::ostream& out, const std::vector<FileReport>& files,
                const OutputSettings& settings);
// The document write_json prints (the --html page carries it too).
Json json_document(const std::vector<FileReport>& files, const OutputSettings& settings);
// URDF, SDFormat or MJCF <inertial> elements, one per readable, valid file,
// with comments saying what the numbers cannot (file, warnings, units).
void write_inertial_xml(std::ostream& out, const std::vector<FileReport>& files,
                        OutputFormat format, const OutputSettings& settings);

// --usda: a USD text layer with a UsdPhysics rigid body per readable, valid
// file (its parts as child prims). Problems only USD has (a value past 32-bit
// floats, a centre of mass float rounds more than its error bound) go to
// diagnostics too; returns false when a value left a prim out.
bool write_usda(std::ostream& out, std::ostream& diagnostics, const std::vector<FileReport>& files,
                const OutputSettings& settings);

// The files together, for the summary the table and --json give of several.
struct Summary {
    uint64_t files = 0;
    uint64_t valid = 0;         // readable, and a valid solid
    double total_volume = 0.0;  // of the valid ones
    double total_mass = 0.0;    // of the valid ones
};
Summary summarize(const std::vector<FileReport>& files);

// Principal axis i (0, 1, 2): column i of the library's principal_axes
// rotation, the axis of principal_moments[i].
std::array<double, 3> principal_axis(const polymass_mass_properties& properties, int i);

// The names of the POLYMASS_WARNING_* bits set in warnings.
std::vector<std::string> warning_names(uint32_t warnings);

// The same warnings as a sentence for people: "inverted (the faces were
// reversed: the mesh was inside out), ...", empty when there are none.
std::string warning_text(uint32_t warnings);

// What the outputs say when --units is absent (stderr adds how to give it).
inline constexpr const char* kFileUnitsNote =
    "lengths are in the file's units, not converted to metres: the mass is the density times "
    "the volume in those units, the inertia the mass times length squared";

// The material as the XML and USD comments name it: "aluminium-6061, density
// 2700 kg/m^3 (source)".
std::string material_text(const PartReport& part);

// A symmetric tensor (row-major 3x3) made from its upper triangle, so that
// every output prints one number for [i][j] and [j][i], and -0 made 0.
std::array<double, 9> symmetric_tensor(const double* values);

}  // namespace polymass_cli
