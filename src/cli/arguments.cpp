// The command line through CLI11: it knows the options, their values
// (--opt V, --opt=V, --), --help and the check subcommand; the values are
// then read here, so that each refusal says what the option wants.
#include "arguments.hpp"

#include <polymass/polymass.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <string_view>

#include "model/units.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

// The options as CLI11 hands them over: text, read into Arguments afterwards.
struct RawOptions {
    std::vector<std::string> files;
    std::string density, mass, scale, units, about, origin, weld_tolerance, planarity_tolerance;
    bool json = false, urdf = false, sdf = false, mjcf = false;
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

// The options of both polymass and polymass check, bound to raw. Help is
// grouped as the README's tool section is.
void add_options(CLI::App& app, RawOptions& raw, Arguments& arguments) {
    const std::string kOutput = "Output (default: a table for people)";
    app.add_option("FILE", raw.files, "mesh files")->option_text(" ");
    app.add_option("--density", raw.density, "mass = D * volume (default 1: mass equals volume)")
        ->group("Mass")
        ->option_text("D");
    app.add_option("--mass", raw.mass, "density = M / volume")->group("Mass")->option_text("M");
    app.add_option("--units", raw.units,
                   std::string("the file's length unit, converted to metres: ") + known_units() +
                       "\n(e.g. a CAD STL in millimetres: --units mm --density 2700\n"
                       "gives kg, m and kg*m^2); without it, lengths are the file's")
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
    app.add_option("--origin", raw.origin,
                   "--urdf/--sdf/--mjcf: the link frame's origin in the file's frame\n"
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
    if (raw.json + raw.urdf + raw.sdf + raw.mjcf > 1) {
        throw UsageError("choose one of --json, --urdf, --sdf, --mjcf");
    }
    if (raw.json) arguments.output = OutputFormat::kJson;
    if (raw.urdf) arguments.output = OutputFormat::kUrdf;
    if (raw.sdf) arguments.output = OutputFormat::kSdf;
    if (raw.mjcf) arguments.output = OutputFormat::kMjcf;
    if (!raw.density.empty()) arguments.density = positive_number("--density", raw.density);
    if (!raw.mass.empty()) arguments.mass = positive_number("--mass", raw.mass);
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
            throw UsageError("--origin places the inertial of --urdf, --sdf or --mjcf");
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
    read_modes(raw, arguments);
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

std::string description() {
    return std::string(
               "polymass - mass properties of solid meshes: volume, mass, centre of mass,\n"
               "inertia tensor, principal moments and axes, surface area; polymass check\n"
               "FILE... says whether each file is a valid closed solid, and why not.\n"
               "\n"
               "Formats (by extension, or --format NAME): ") +
           supported_formats() +
           ".\n"
           "Polygon faces are kept as they are; vertices at the same position are one vertex.\n"
           "A file with several objects/solids/nodes gives each part and the combined solid.";
}

// The command line's grammar: polymass [OPTIONS] FILE... and polymass check
// [OPTIONS] FILE..., both with the same options.
struct CommandLine {
    CLI::App app{description(), "polymass"};
    CLI::App* check = nullptr;
    RawOptions raw;
    bool version = false;

    explicit CommandLine(Arguments& arguments) {
        app.footer(kFooter);
        app.add_flag("--version", version, "print the version and exit");
        check = app.add_subcommand("check", "is each file a valid closed solid? why not?");
        check->footer(kFooter);
        add_options(app, raw, arguments);
        add_options(*check, raw, arguments);
    }
};

}  // namespace

Arguments parse_arguments(int argc, const char* const* argv) {
    Arguments arguments;
    CommandLine line(arguments);
    try {
        line.app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        arguments.command = Command::kHelp;
        return arguments;
    } catch (const CLI::ParseError& error) {
        throw UsageError(std::string(error.what()) + " (see polymass --help)");
    }
    if (line.version) {
        arguments.command = Command::kVersion;
        return arguments;
    }
    if (line.check->parsed()) arguments.command = Command::kCheck;
    read_values(line.raw, arguments);
    if (arguments.files.empty()) throw UsageError("no mesh file given (see polymass --help)");
    if (arguments.density && arguments.mass) {
        throw UsageError("give --density or --mass, not both");
    }
    if (arguments.command == Command::kCheck && arguments.output != OutputFormat::kTable &&
        arguments.output != OutputFormat::kJson) {
        throw UsageError("polymass check prints a report or --json, not --urdf/--sdf/--mjcf");
    }
    return arguments;
}

std::string help_text() {
    Arguments arguments;
    return CommandLine(arguments).app.help();
}

}  // namespace polymass_cli
