// The command line: what to do, to which files, with which settings.
#pragma once

#include <polymass/polymass.h>

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymass_cli {

enum class Command { kProperties, kCheck, kHelp, kVersion, kAssembly, kAudit };
enum class OutputFormat { kTable, kJson, kUrdf, kSdf, kMjcf, kUsda };
enum class About { kCenterOfMass, kOrigin, kPoint };

// --density NAME=D, --mass NAME=M or --material NAME=MATERIAL: the material
// of the parts named NAME.
struct PartMaterial {
    std::string part;
    bool by_mass = false;  // value is the part's mass, not its density
    double value = 1.0;
    std::string material;  // --material: the table's name; value is its density
};

// polymass audit's own options.
struct AuditArguments {
    bool from_visual = false;         // --from visual (default: collision)
    std::string fail_on = "error";    // --fail-on: info, warning or error
    std::string fix;                  // --fix OUT: empty for none
    bool mass_from_geometry = false;  // --mass-from geometry
};

struct Arguments {
    Command command = Command::kProperties;
    OutputFormat output = OutputFormat::kTable;
    std::vector<std::string> files;
    std::string format;  // --format: empty means by extension
    std::optional<double> density;
    std::optional<double> mass;
    std::string material;                      // --material NAME: density is then the table's
    std::vector<PartMaterial> part_materials;  // in the order given
    double scale = 1.0;                        // --scale alone
    // --units resolved: metres per file unit; empty: lengths are the file's.
    std::optional<double> metres_per_unit;
    About about = About::kCenterOfMass;
    std::array<double, 3> point{0.0, 0.0, 0.0};  // --about X,Y,Z
    // --origin X,Y,Z: the link frame's origin in the file's frame (output
    // units), subtracted from the centre of mass in --urdf/--sdf/--mjcf/--usda.
    std::array<double, 3> link_origin{0.0, 0.0, 0.0};
    bool accept_inverted = false;
    bool no_check = false;
    bool no_intersection_check = false;
    bool timings = false;
    std::string html;  // --html REPORT.html: empty for none
    double weld_tolerance = 1e-9;
    double planarity_tolerance = 0.0;  // 0: the library's default
    uint32_t threads = 0;              // --threads N; 0: all cores
    bool triangulate = false;
    AuditArguments audit;
    std::string help;  // --help: the text to print (the subcommand's own)
    // The modes to try in order (POLYMASS_MODE_*): the solid alone by
    // default; --repair, --shell, --hull or --fallback change it.
    std::vector<uint32_t> modes{POLYMASS_MODE_SOLID};
    double shell_thickness = 0.0;  // --shell T (output units)
};

// A command line the tool cannot run; the message says what is wrong.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Arguments parse_arguments(int argc, const char* const* argv);

// The --help text (what parse_arguments prints for --help).
std::string help_text();

}  // namespace polymass_cli
