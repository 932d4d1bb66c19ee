// The command line through CLI11: it knows the options, their values
// (--opt V, --opt=V, --), --help and the check subcommand; the values are
// then read here, so that each refusal says what the option wants.
#include "arguments.hpp"

#include <polymass/polymass.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

#include "model/materials.hpp"
#include "model/units.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

// The options as CLI11 hands them over: text, read into Arguments afterwards.
struct RawOptions {
    std::vector<std::string> files;
    std::vector<std::string> densities, masses;  // D or NAME=D, repeatable
    std::vector<std::string> materials;          // MATERIAL or NAME=MATERIAL
    std::string scale, units, about, origin, weld_tolerance, planarity_tolerance;
    std::string threads;
    bool json = false, urdf = false, sdf = false, mjcf = false, usda = false;
    std::string from, mass_from;  // polymass audit
    bool repair = false, hull = false;
    std::string shell;
    std::string fallback;  // comma-separated
};

double positive_number(std::string_view option, std::string_view text) {
    double value = 0.0;
    if (!parse_double(text, value) || !std::isfinite(value) || value <= 0.0) {
        throw UsageError(std::string(option) + " wants a positive number, not '" +
                         std::string(text) + "'");
    }
    return value;
}

std::array<double, 3> parse_point(std::string_view option, std::string_view what,
                                  std::string_view text) {
    const std::string complaint = std::string(option) + " wants " + std::string(what) +
                                  "X,Y,Z (three numbers), not '" + std::string(text) + "'";
    std::array<double, 3> point{};
    for (int axis = 0; axis < 3; ++axis) {
        const std::string_view::size_type comma = text.find(',');
        const std::string_view field = text.substr(0, comma);
        if (!parse_double(field, point[axis]) || !std::isfinite(point[axis]) ||
            (axis < 2) != (comma != std::string_view::npos)) {
            throw UsageError(complaint);
        }
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    }
    return point;
}

// NAME of NAME=V (the '=' at `equals`), a part no other option named.
std::string part_name(const std::string& option, const std::string& text,
                      std::string::size_type equals, const std::vector<PartMaterial>& parts) {
    const std::string name = text.substr(0, equals);
    if (name.empty()) {
        throw UsageError(option + " NAME=V wants a part's name before '=', not '" + text + "'");
    }
    for (const PartMaterial& given : parts) {
        if (given.part == name) throw UsageError("the part '" + name + "' is given twice");
    }
    return name;
}

// --density or --mass: V gives the whole file's (once), NAME=V a part's.
void read_mass_value(const std::string& option, const std::string& text, bool by_mass,
                     std::optional<double>& whole, std::vector<PartMaterial>& parts) {
    const std::string::size_type equals = text.rfind('=');
    if (equals == std::string::npos) {
        if (whole) {
            throw UsageError(option + " is given twice (" + option +
                             " NAME=V gives the parts named NAME theirs)");
        }
        whole = positive_number(option, text);
        return;
    }
    const std::string name = part_name(option, text, equals, parts);
    const std::string_view value = std::string_view(text).substr(equals + 1);
    parts.push_back({name, by_mass, positive_number(option + " " + name + "=", value), ""});
}

// --material: MATERIAL gives the whole file's density (once), NAME=MATERIAL
// a part's, from the table of model/materials.hpp.
void read_material(const std::string& text, Arguments& arguments) {
    const std::string::size_type equals = text.rfind('=');
    const std::string name = equals == std::string::npos ? text : text.substr(equals + 1);
    const Material* material = find_material(name);
    if (!material) {
        throw UsageError("--material: '" + name + "' is not a known material; the known ones are " +
                         known_materials() + " (docs/materials.md; or give --density D)");
    }
    if (equals != std::string::npos) {
        const std::string part = part_name("--material", text, equals, arguments.part_materials);
        arguments.part_materials.push_back({part, false, material->density, material->name});
        return;
    }
    if (arguments.density || arguments.mass) {
        throw UsageError(
            "give the whole's --density, --mass or --material once (NAME=V gives the parts "
            "named NAME theirs)");
    }
    arguments.density = material->density;
    arguments.material = material->name;
}

// The options of both polymass and polymass check, bound to raw. Help is
// grouped as the README's tool section is.
void add_options(CLI::App& app, RawOptions& raw, Arguments& arguments) {
    const std::string kOutput = "Output (default: a table for people)";
    app.add_option("FILE", raw.files, "mesh files")->option_text(" ");
    app.add_option("--density", raw.densities,
                   "mass = D * volume (default 1: mass equals volume);\n"
                   "NAME=D: the density of the parts named NAME (repeatable)")
        ->group("Mass")
        ->option_text("D|NAME=D")
        ->allow_extra_args(false);
    app.add_option("--mass", raw.masses,
                   "density = M / volume; NAME=M: the mass of the parts\n"
                   "named NAME, the others keeping --density (repeatable)")
        ->group("Mass")
        ->option_text("M|NAME=M")
        ->allow_extra_args(false);
    app.add_option("--material", raw.materials,
                   "the density of a named material (kg/m^3; needs --units), e.g.\n"
                   "aluminium-6061, stainless-316, pla: the table and its sources\n"
                   "are in docs/materials.md; NAME=MATERIAL: the parts named NAME")
        ->group("Mass")
        ->option_text("MATERIAL|NAME=MATERIAL")
        ->allow_extra_args(false);
    app.add_option("--units", raw.units,
                   std::string("the file's length unit, converted to metres: ") + known_units() +
                       "\n(e.g. a CAD STL in millimetres: --units mm --density 2700\n"
                       "gives kg, m and kg*m^2); without it, lengths are the file's;\n"
                       "a file that declares its unit (3MF, Collada) is read in metres\n"
                       "by that unit, --units not applied to it")
        ->group("Lengths")
        ->option_text("U");
    app.add_option("--scale", raw.scale, "multiply every coordinate by S (after --units)")
        ->group("Lengths")
        ->option_text("S");
    app.add_option("--about", raw.about,
                   "com: about the centre of mass (default; always printed)\n"
                   "origin: also about the origin (0, 0, 0)\n"
                   "X,Y,Z: also about that point (in output units)")
        ->group("Inertia")
        ->option_text("com|origin|X,Y,Z");
    app.add_flag("--json", raw.json, "JSON, every digit (schema in the README)")->group(kOutput);
    app.add_flag("--urdf", raw.urdf, "URDF <inertial> (origin at the centre of mass)")
        ->group(kOutput);
    app.add_flag("--sdf", raw.sdf, "SDFormat <inertial> with <pose>")->group(kOutput);
    app.add_flag("--mjcf", raw.mjcf, "MuJoCo <inertial pos mass fullinertia>")->group(kOutput);
    app.add_flag("--usda", raw.usda,
                 "USD text layer: UsdPhysics rigid bodies with PhysicsMassAPI\n"
                 "(32-bit floats; stage metersPerUnit/kilogramsPerUnit 1 when\n"
                 "the lengths are metres: --units, or units the files declare)")
        ->group(kOutput);
    app.add_option("--html", arguments.html,
                   "also write a page that draws the result (one file that opens\n"
                   "offline in a browser: the mesh, what check found, the inertia)")
        ->group(kOutput)
        ->option_text("REPORT.html");
    app.add_option("--origin", raw.origin,
                   "--urdf/--sdf/--mjcf/--usda: the link frame's origin in the file's frame\n"
                   "(output units); the inertial's origin is the centre of mass minus it")
        ->group(kOutput)
        ->option_text("X,Y,Z");
    app.add_option("--format", arguments.format,
                   std::string("the file format, instead of the extension: ") + supported_formats())
        ->group("Reading")
        ->option_text("NAME");
    app.add_flag("--accept-inverted", arguments.accept_inverted,
                 "an inside-out mesh is turned and reported, not refused")
        ->group("Checks");
    app.add_flag("--no-check", arguments.no_check,
                 "skip the topology checks (trusted input; faster)")
        ->group("Checks");
    app.add_flag("--no-intersection-check", arguments.no_intersection_check,
                 "do not look for faces that cross each other or parts nested\n"
                 "in parts (overlaps counted twice); faster on large meshes")
        ->group("Checks");
    app.add_option("--weld-tolerance", raw.weld_tolerance,
                   "vertices closer than T times the mesh size are one vertex\n"
                   "(default 1e-9; 0: exact positions only)")
        ->group("Checks")
        ->option_text("T");
    app.add_option("--planarity-tolerance", raw.planarity_tolerance,
                   "how far (relative to its size) a polygon face's vertex may\n"
                   "be off the face's plane (default 1e-6)")
        ->group("Checks")
        ->option_text("T");
    app.add_flag("--triangulate", arguments.triangulate,
                 "split polygon faces into fans of triangles from their first\n"
                 "corner: a non-planar face then counts as that surface")
        ->group("Checks");
    const std::string kModes = "When the mesh is not a valid solid (default: refuse it)";
    app.add_flag("--repair", raw.repair,
                 "repair what has one right fix (orientation, duplicate faces,\n"
                 "holes, ...) and say what was done and how far off it can be")
        ->group(kModes);
    app.add_option("--shell", raw.shell,
                   "the surface as a thin wall of thickness T (sheet metal, open\n"
                   "visual meshes): mass = density * T * area")
        ->group(kModes)
        ->option_text("T");
    app.add_flag("--hull", raw.hull, "the convex hull of the mesh's vertices (an upper bound)")
        ->group(kModes);
    app.add_option("--fallback", raw.fallback,
                   "modes tried in order after the solid, from repair, shell\n"
                   "(with --shell T), hull: e.g. --fallback repair,hull")
        ->group(kModes)
        ->option_text("LIST");
    app.add_option("--threads", raw.threads,
                   "threads the library may use; the results do not depend\n"
                   "on it (default: all cores)")
        ->group("Checks")
        ->option_text("N");
    app.add_flag("--timings", arguments.timings,
                 "print the time spent reading and computing to stderr")
        ->group("Checks");
}

std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::string::size_type start = 0;
    while (start <= text.size()) {
        const std::string::size_type comma = std::min(text.find(',', start), text.size());
        items.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}

// The chain of modes the mode options ask for.
void read_modes(const RawOptions& raw, Arguments& arguments) {
    if (!raw.shell.empty()) arguments.shell_thickness = positive_number("--shell", raw.shell);
    if (raw.repair + raw.hull + !raw.shell.empty() + !raw.fallback.empty() > 1 &&
        (raw.fallback.empty() || raw.repair || raw.hull)) {
        throw UsageError(
            "choose one of --repair, --shell, --hull, or --fallback with a list of them");
    }
    if (raw.repair) arguments.modes = {POLYMASS_MODE_REPAIR};
    if (raw.hull) arguments.modes = {POLYMASS_MODE_HULL};
    if (!raw.shell.empty()) arguments.modes = {POLYMASS_MODE_SHELL};
    if (raw.fallback.empty()) return;
    arguments.modes = {POLYMASS_MODE_SOLID};
    for (const std::string& name : split_list(raw.fallback)) {
        const uint32_t mode = name == "repair"  ? POLYMASS_MODE_REPAIR
                              : name == "shell" ? POLYMASS_MODE_SHELL
                              : name == "hull"  ? POLYMASS_MODE_HULL
                                                : POLYMASS_MODE_NONE;
        if (mode == POLYMASS_MODE_NONE)
            throw UsageError("--fallback wants a list of repair, shell and hull, not '" + name +
                             "'");
        if (std::find(arguments.modes.begin(), arguments.modes.end(), mode) ==
            arguments.modes.end())
            arguments.modes.push_back(mode);
    }
    const bool shell = std::find(arguments.modes.begin(), arguments.modes.end(),
                                 POLYMASS_MODE_SHELL) != arguments.modes.end();
    if (shell != !raw.shell.empty())
        throw UsageError(shell ? "--fallback shell wants the wall's thickness: --shell T"
                               : "--shell with --fallback: list shell in the fallback");
}

// Reads the option values CLI11 collected into arguments.
void read_values(const RawOptions& raw, Arguments& arguments) {
    arguments.files = raw.files;
    if (raw.json + raw.urdf + raw.sdf + raw.mjcf + raw.usda > 1) {
        throw UsageError("choose one of --json, --urdf, --sdf, --mjcf, --usda");
    }
    if (raw.json) arguments.output = OutputFormat::kJson;
    if (raw.urdf) arguments.output = OutputFormat::kUrdf;
    if (raw.sdf) arguments.output = OutputFormat::kSdf;
    if (raw.mjcf) arguments.output = OutputFormat::kMjcf;
    if (raw.usda) arguments.output = OutputFormat::kUsda;
    for (const std::string& text : raw.densities)
        read_mass_value("--density", text, false, arguments.density, arguments.part_materials);
    for (const std::string& text : raw.masses)
        read_mass_value("--mass", text, true, arguments.mass, arguments.part_materials);
    for (const std::string& text : raw.materials) read_material(text, arguments);
    // A material's density is in kg/m^3: with lengths of unknown unit the
    // mass would be off by the cube of that unit in metres.
    if (!raw.materials.empty() && raw.units.empty() && arguments.command != Command::kAssembly) {
        throw UsageError(
            "--material gives a density in kg/m^3: give the file's length unit with --units "
            "(m for a file in metres)");
    }
    if (arguments.mass && !arguments.part_materials.empty()) {
        throw UsageError("give the whole's --mass M or parts' --density/--mass NAME=V, not both");
    }
    if (!raw.scale.empty()) arguments.scale = positive_number("--scale", raw.scale);
    if (!raw.units.empty()) {
        double metres = 0.0;
        if (!metres_per_unit(raw.units, metres)) {
            throw UsageError("--units wants one of " + std::string(known_units()) + ", not '" +
                             raw.units + "'");
        }
        arguments.metres_per_unit = metres;
    }
    if (raw.about == "origin") {
        arguments.about = About::kOrigin;
    } else if (!raw.about.empty() && raw.about != "com") {
        arguments.about = About::kPoint;
        arguments.point = parse_point("--about", "com, origin or ", raw.about);
    }
    if (!raw.origin.empty()) {
        if (arguments.output == OutputFormat::kTable || arguments.output == OutputFormat::kJson) {
            throw UsageError("--origin places the inertial of --urdf, --sdf, --mjcf or --usda");
        }
        arguments.link_origin = parse_point("--origin", "", raw.origin);
    }
    if (!raw.weld_tolerance.empty()) {
        double tolerance = -1.0;
        if (!parse_double(raw.weld_tolerance, tolerance) || !(tolerance >= 0.0) ||
            tolerance > POLYMASS_MAX_WELD_TOLERANCE) {
            throw UsageError("--weld-tolerance wants a number in [0, " +
                             std::to_string(POLYMASS_MAX_WELD_TOLERANCE) + "], not '" +
                             raw.weld_tolerance + "'");
        }
        arguments.weld_tolerance = tolerance;
    }
    if (!raw.planarity_tolerance.empty()) {
        double tolerance = -1.0;
        if (!parse_double(raw.planarity_tolerance, tolerance) ||
            !(tolerance > 0.0 && tolerance < 1.0)) {
            throw UsageError("--planarity-tolerance wants a number in (0, 1), not '" +
                             raw.planarity_tolerance + "'");
        }
        arguments.planarity_tolerance = tolerance;
    }
    if (!raw.threads.empty()) {
        double threads = 0.0;
        if (!parse_double(raw.threads, threads) || !(threads >= 1.0) ||
            threads > POLYMASS_MAX_THREADS || threads != std::floor(threads)) {
            throw UsageError("--threads wants a whole number in [1, " +
                             std::to_string(POLYMASS_MAX_THREADS) + "], not '" + raw.threads + "'");
        }
        arguments.threads = uint32_t(threads);
    }
    read_modes(raw, arguments);
}

// An assembly file gives each part's mesh, units and material itself.
void refuse_assembly_settings(const RawOptions& raw, const Arguments& arguments) {
    if (arguments.files.size() > 1) {
        throw UsageError("polymass assembly reads one assembly file, not " +
                         std::to_string(arguments.files.size()));
    }
    const std::pair<bool, const char*> per_part[] = {
        {!raw.densities.empty(), "--density"},  {!raw.masses.empty(), "--mass"},
        {!raw.materials.empty(), "--material"}, {!raw.units.empty(), "--units"},
        {!raw.scale.empty(), "--scale"},        {!arguments.format.empty(), "--format"}};
    if (!arguments.html.empty()) throw UsageError("polymass assembly writes no --html page");
    for (const auto& [given, option] : per_part) {
        if (given) {
            throw UsageError(std::string("polymass assembly: ") + option +
                             " is given per part in the assembly file");
        }
    }
}

// polymass audit's options: its own, and --json and --density shared with
// the other commands' RawOptions.
void add_audit_options(CLI::App& app, RawOptions& raw, Arguments& arguments) {
    AuditArguments& audit = arguments.audit;
    app.add_option("FILE", raw.files, "URDF, SDFormat or MJCF files")->option_text(" ");
    app.add_flag("--json", raw.json, "JSON (schema in the README)");
    app.add_option("--html", arguments.html,
                   "also write a page that draws each robot: its links' geometry,\n"
                   "declared and computed inertia boxes, findings (opens offline)")
        ->option_text("REPORT.html");
    app.add_option("--from", raw.from,
                   "URDF, SDFormat: the geometry measured (default collision);\n"
                   "MJCF: the geoms MuJoCo weighs, whatever this says")
        ->check(CLI::IsMember({"collision", "visual"}))
        ->option_text("collision|visual");
    app.add_option("--fail-on", audit.fail_on,
                   "exit 1 when a finding is this severe or more (default error)")
        ->check(CLI::IsMember({"info", "warning", "error"}))
        ->option_text("info|warning|error");
    app.add_option("--fix", audit.fix,
                   "write the description with the computed inertials to OUT\n"
                   "(one FILE; declared masses kept unless --density or --mass-from)")
        ->option_text("OUT");
    app.add_option("--density", raw.densities,
                   "kg/m^3: URDF and SDFormat links without a mass are computed\n"
                   "at D (default 1000; MJCF geoms have their own density);\n"
                   "with --fix, every mass becomes D * volume")
        ->option_text("D");
    app.add_option("--mass-from", raw.mass_from,
                   "with --fix: geometry writes D * volume (D from --density, default 1000)")
        ->check(CLI::IsMember({"declared", "geometry"}))
        ->option_text("declared|geometry");
}

constexpr const char* kFooter =
    "Conventions: faces counter-clockwise seen from outside; inertia tensor\n"
    "I = integral rho (|r|^2 1 - r r^T) dV, so Ixy = -integral rho x y dV, as\n"
    "URDF, SDFormat and MuJoCo expect.\n"
    "\n"
    "Exit status: 0 all good, 1 a mesh is not a valid solid, 2 usage error,\n"
    "3 a file cannot be read, 4 internal error. With several files, the highest.\n"
    "\n"
    "Examples:\n"
    "  polymass part.stl --units mm --density 2700\n"
    "  polymass link.obj --mass 1.5 --urdf\n"
    "  polymass arm.stl --units mm --mass 0.8 --urdf --origin 0,0,0.25\n"
    "  polymass check scan.ply\n"
    "  polymass visual.stl --fallback repair,hull --json\n";

constexpr const char* kAuditFooter =
    "Per link: the declared mass, centre of mass and inertia next to those of its\n"
    "geometry (meshes and shapes): URDF and SDFormat at the declared mass, MJCF as\n"
    "MuJoCo's compiler infers it (its mass rules: docs/audit.md); findings with a\n"
    "kind, a severity and a message (README: the kinds and their thresholds).\n"
    "\n"
    "Exit status: 0 no finding as severe as --fail-on, 1 some, 2 usage error,\n"
    "3 a description cannot be read, 4 internal error.\n"
    "\n"
    "Examples:\n"
    "  polymass audit robot.urdf\n"
    "  polymass audit model.sdf --json --fail-on warning\n"
    "  polymass audit arm.xml --fix arm.fixed.xml\n";

std::string description() {
    return std::string(
               "polymass - mass properties of solid meshes: volume, mass, centre of mass,\n"
               "inertia tensor, principal moments and axes, surface area; polymass check\n"
               "FILE... says whether each file is a valid closed solid, and why not;\n"
               "polymass assembly FILE.json gives each placed part and the whole.\n"
               "\n"
               "Formats (by extension, or --format NAME): ") +
           supported_formats() +
           ".\n"
           "Polygon faces are kept as they are; vertices at the same position are one vertex.\n"
           "A file with several objects/solids/nodes gives each part and the combined solid.";
}

// The command line's grammar: polymass [OPTIONS] FILE..., polymass check
// [OPTIONS] FILE... and polymass assembly [OPTIONS] FILE, with the same options.
struct CommandLine {
    CLI::App app{description(), "polymass"};
    CLI::App* check = nullptr;
    CLI::App* assembly = nullptr;
    CLI::App* audit = nullptr;
    RawOptions raw;
    bool version = false;

    explicit CommandLine(Arguments& arguments) {
        app.footer(kFooter);
        app.add_flag("--version", version, "print the version and exit");
        check = app.add_subcommand("check", "is each file a valid closed solid? why not?");
        check->footer(kFooter);
        add_options(app, raw, arguments);
        add_options(*check, raw, arguments);
        assembly = app.add_subcommand(
            "assembly",
            "each part of an assembly file (JSON: meshes placed, each with its\n"
            "units and density or mass; the schema is in the README) and the whole");
        assembly->footer(kFooter);
        add_options(*assembly, raw, arguments);
        audit = app.add_subcommand("audit",
                                   "check (and --fix) the inertials of URDF, SDFormat and MJCF "
                                   "robot descriptions against their geometry");
        audit->footer(kAuditFooter);
        add_audit_options(*audit, raw, arguments);
    }
};

}  // namespace

Arguments parse_arguments(int argc, const char* const* argv) {
    Arguments arguments;
    CommandLine line(arguments);
    try {
        line.app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        // The help of the subcommand asked, with its own options.
        arguments.command = Command::kHelp;
        arguments.help = line.app.help();
        for (const CLI::App* subcommand : {line.check, line.assembly, line.audit}) {
            if (subcommand->parsed()) arguments.help = subcommand->help("polymass");
        }
        return arguments;
    } catch (const CLI::ParseError& error) {
        throw UsageError(std::string(error.what()) + " (see polymass --help)");
    }
    if (line.version) {
        arguments.command = Command::kVersion;
        return arguments;
    }
    if (line.check->parsed()) arguments.command = Command::kCheck;
    if (line.assembly->parsed()) arguments.command = Command::kAssembly;
    if (line.audit->parsed()) {
        arguments.command = Command::kAudit;
        arguments.audit.from_visual = line.raw.from == "visual";
        arguments.audit.mass_from_geometry = line.raw.mass_from == "geometry";
        if (arguments.audit.fix.empty() && !line.raw.mass_from.empty()) {
            throw UsageError("--mass-from chooses the masses --fix writes");
        }
        if (!arguments.audit.fix.empty() && line.raw.files.size() != 1) {
            throw UsageError("--fix writes one description: give one FILE");
        }
    }
    read_values(line.raw, arguments);
    if (arguments.command == Command::kAssembly) refuse_assembly_settings(line.raw, arguments);
    if (arguments.command == Command::kAudit && !arguments.part_materials.empty()) {
        throw UsageError("polymass audit: --density takes one density D, not NAME=D");
    }
    if (arguments.files.empty()) {
        throw UsageError(arguments.command == Command::kAudit
                             ? "no description file given (see polymass audit --help)"
                             : "no mesh file given (see polymass --help)");
    }
    if (arguments.density && arguments.mass) {
        throw UsageError("give --density or --mass, not both");
    }
    if (arguments.command == Command::kCheck && arguments.output != OutputFormat::kTable &&
        arguments.output != OutputFormat::kJson) {
        throw UsageError(
            "polymass check prints a report or --json, not --urdf/--sdf/--mjcf/--usda");
    }
    return arguments;
}

std::string help_text() {
    Arguments arguments;
    return CommandLine(arguments).app.help();
}

}  // namespace polymass_cli
