#include "arguments.hpp"

#include <polymass/polymass.h>

#include <cmath>
#include <string_view>

#include "model/units.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

double positive_number(std::string_view option, std::string_view text) {
    double value = 0.0;
    if (!parse_double(text, value) || !std::isfinite(value) || value <= 0.0) {
        throw UsageError(std::string(option) + " wants a positive number, not '" +
                         std::string(text) + "'");
    }
    return value;
}

std::array<double, 3> parse_point(std::string_view text) {
    std::array<double, 3> point{};
    for (int axis = 0; axis < 3; ++axis) {
        const std::string_view::size_type comma = text.find(',');
        const std::string_view field = text.substr(0, comma);
        if (!parse_double(field, point[axis]) || !std::isfinite(point[axis]) ||
            (axis < 2) != (comma != std::string_view::npos)) {
            throw UsageError("--about wants com, origin or X,Y,Z (three numbers), not '" +
                             std::string(text) + "'");
        }
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    }
    return point;
}

void set_output(Arguments& arguments, OutputFormat output, bool& output_set) {
    if (output_set) throw UsageError("choose one of --json, --urdf, --sdf, --mjcf");
    arguments.output = output;
    output_set = true;
}

}  // namespace

Arguments parse_arguments(int argc, const char* const* argv) {
    Arguments arguments;
    bool output_set = false;
    bool options_end = false;
    int first = 1;
    if (argc > 1 && std::string_view(argv[1]) == "check") {
        arguments.command = Command::kCheck;
        first = 2;
    }
    for (int i = first; i < argc; ++i) {
        const std::string_view argument = argv[i];
        if (options_end || argument.empty() || argument.front() != '-' || argument == "-") {
            arguments.files.emplace_back(argument);
            continue;
        }
        // --option=value and --option value are both accepted.
        std::string_view option = argument;
        std::optional<std::string_view> attached;
        const std::string_view::size_type equals = argument.find('=');
        if (argument.rfind("--", 0) == 0 && equals != std::string_view::npos) {
            option = argument.substr(0, equals);
            attached = argument.substr(equals + 1);
        }
        auto value = [&]() -> std::string_view {
            if (attached) return *attached;
            if (i + 1 >= argc) throw UsageError(std::string(option) + " needs a value");
            return argv[++i];
        };
        auto no_value = [&]() {
            if (attached) throw UsageError(std::string(option) + " takes no value");
        };
        if (option == "--") {
            options_end = true;
        } else if (option == "-h" || option == "--help") {
            arguments.command = Command::kHelp;
        } else if (option == "--version") {
            arguments.command = Command::kVersion;
        } else if (option == "--json") {
            no_value();
            set_output(arguments, OutputFormat::kJson, output_set);
        } else if (option == "--urdf") {
            no_value();
            set_output(arguments, OutputFormat::kUrdf, output_set);
        } else if (option == "--sdf") {
            no_value();
            set_output(arguments, OutputFormat::kSdf, output_set);
        } else if (option == "--mjcf") {
            no_value();
            set_output(arguments, OutputFormat::kMjcf, output_set);
        } else if (option == "--density") {
            arguments.density = positive_number(option, value());
        } else if (option == "--mass") {
            arguments.mass = positive_number(option, value());
        } else if (option == "--scale") {
            arguments.scale = positive_number(option, value());
        } else if (option == "--units") {
            const std::string unit(value());
            double metres = 0.0;
            if (!metres_per_unit(unit, metres)) {
                throw UsageError("--units wants one of " + std::string(known_units()) + ", not '" +
                                 unit + "'");
            }
            arguments.metres_per_unit = metres;
        } else if (option == "--about") {
            const std::string_view about = value();
            if (about == "com") {
                arguments.about = About::kCenterOfMass;
            } else if (about == "origin") {
                arguments.about = About::kOrigin;
            } else {
                arguments.about = About::kPoint;
                arguments.point = parse_point(about);
            }
        } else if (option == "--format") {
            arguments.format = std::string(value());
        } else if (option == "--weld-tolerance") {
            const std::string_view text = value();
            double tolerance = -1.0;
            if (!parse_double(text, tolerance) || !(tolerance >= 0.0) ||
                tolerance > POLYMASS_MAX_WELD_TOLERANCE) {
                throw UsageError("--weld-tolerance wants a number in [0, " +
                                 std::to_string(POLYMASS_MAX_WELD_TOLERANCE) + "], not '" +
                                 std::string(text) + "'");
            }
            arguments.weld_tolerance = tolerance;
        } else if (option == "--planarity-tolerance") {
            const std::string_view text = value();
            double tolerance = -1.0;
            if (!parse_double(text, tolerance) || !(tolerance > 0.0 && tolerance < 1.0)) {
                throw UsageError("--planarity-tolerance wants a number in (0, 1), not '" +
                                 std::string(text) + "'");
            }
            arguments.planarity_tolerance = tolerance;
        } else if (option == "--triangulate") {
            no_value();
            arguments.triangulate = true;
        } else if (option == "--accept-inverted") {
            no_value();
            arguments.accept_inverted = true;
        } else if (option == "--no-check") {
            no_value();
            arguments.no_check = true;
        } else if (option == "--timings") {
            no_value();
            arguments.timings = true;
        } else {
            throw UsageError("unknown option '" + std::string(argument) +
                             "' (see polymass --help)");
        }
    }
    if (arguments.command == Command::kHelp || arguments.command == Command::kVersion) {
        return arguments;
    }
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
    return std::string(
               "polymass - mass properties of solid meshes: volume, mass, centre of mass,\n"
               "inertia tensor, principal moments and axes, surface area.\n"
               "\n"
               "Usage:\n"
               "  polymass [OPTIONS] FILE...        mass properties of each file\n"
               "  polymass check [--json] FILE...   is each file a valid closed solid? why not?\n"
               "  polymass --help | --version\n"
               "\n"
               "Formats (by extension, or --format NAME): ") +
           supported_formats() +
           ".\n"
           "Polygon faces are kept as they are; vertices at the same position are one vertex.\n"
           "A file with several objects/solids/nodes gives each part and the combined solid.\n"
           "\n"
           "Mass:\n"
           "  --density D        mass = D * volume (default 1: mass equals volume)\n"
           "  --mass M           density = M / volume\n"
           "Lengths:\n"
           "  --units U          the file's length unit, converted to metres: " +
           known_units() +
           "\n"
           "                     (e.g. a CAD STL in millimetres: --units mm --density 2700\n"
           "                     gives kg, m and kg*m^2)\n"
           "  --scale S          multiply every coordinate by S (after --units)\n"
           "Inertia:\n"
           "  --about com        about the centre of mass (default; always printed)\n"
           "  --about origin     also about the origin (0, 0, 0)\n"
           "  --about X,Y,Z      also about that point (in output units)\n"
           "Output (default: a table for people):\n"
           "  --json             JSON, every digit (schema in the README)\n"
           "  --urdf             URDF <inertial> (origin at the centre of mass)\n"
           "  --sdf              SDFormat <inertial> with <pose>\n"
           "  --mjcf             MuJoCo <inertial pos mass fullinertia>\n"
           "Checks:\n"
           "  --accept-inverted  an inside-out mesh is turned and reported, not refused\n"
           "  --no-check         skip the topology checks (trusted input; faster)\n"
           "  --weld-tolerance T vertices closer than T times the mesh size are one vertex\n"
           "                     (default 1e-9; 0: exact positions only)\n"
           "  --planarity-tolerance T\n"
           "                     how far (relative to its size) a polygon face's vertex may\n"
           "                     be off the face's plane (default 1e-6)\n"
           "  --triangulate      split polygon faces into fans of triangles from their first\n"
           "                     corner: a non-planar face then counts as that surface\n"
           "  --timings          print the time spent reading and computing to stderr\n"
           "\n"
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
           "  polymass check scan.ply\n";
}

}  // namespace polymass_cli
