#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include "commands/commands.hpp"
#include "commands/part_materials.hpp"
#include "commands/parts_report.hpp"
#include "library/categories.hpp"
#include "readers/mesh_reader.hpp"
#include "reports/html_mesh.hpp"
#include "reports/html_page.hpp"
#include "reports/report.hpp"

namespace polymass_cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

PartReport solid_report(const Library& library, const Model& model, const Part& part,
                        const polymass_mass_desc& mass) {
    PartReport report;
    report.name = part.name;
    report.vertices = used_vertices(model, part);
    report.faces = part.face_count();
    report.computed = true;
    report.result = compute_solid(library, model, part, mass);
    return report;
}

// The file's report; model is the mesh as read (for the --html page).
FileReport process_file(const Library& library, const std::string& path, const Arguments& arguments,
                        const polymass_mass_desc& mass, Model& model) {
    FileReport report;
    report.path = path;
    const auto read_start = std::chrono::steady_clock::now();
    try {
        model = read_mesh_file(path, arguments.format);
    } catch (const ReadError& error) {
        report.read_error = error.what();
        return report;
    }
    prepare_model(model, arguments);
    report.readable = true;
    report.format = model.format;
    report.in_metres = !model.declared_unit.empty();
    report.notes = model.notes;
    for (const std::string& note : model.notes) {
        std::cerr << "polymass: " << path << ": note: " << note << '\n';
    }
    report.read_seconds = seconds_since(read_start);

    const auto compute_start = std::chrono::steady_clock::now();
    if (model.parts.size() > 1) {
        report_parts(library, path, model, arguments, mass, judge_parts(library, model), report);
        for (PartReport& part : report.parts) part.material = material_of(arguments, part.name);
        report.solid.material = common_material(report.parts);
    } else {
        // One part: --density/--mass/--material NAME=V may still name it.
        report.solid = solid_report(library, model, model.parts.front(),
                                    part_masses(arguments, path, model, mass).front());
        report.solid.material = material_of(arguments, report.solid.name);
    }
    report.compute_seconds = seconds_since(compute_start);
    return report;
}

// The holes a repair capped, each located by its lowest vertex: drawn on
// the --html page.
Located capped_holes(const polymass_provenance& provenance) {
    Located located;
    for (const uint64_t vertex : provenance.first_holes)
        if (vertex != POLYMASS_NONE) located.vertices.push_back(vertex);
    return located;
}

}  // namespace

void prepare_model(Model& model, const Arguments& arguments) {
    // A unit the file declares is its truth, applied by its reader: --units
    // is for the files that declare none, and never scales a length twice.
    double metres_per_unit = arguments.metres_per_unit.value_or(1.0);
    if (!model.declared_unit.empty() && arguments.metres_per_unit) {
        model.notes.push_back("--units not applied: the file declares its unit");
        metres_per_unit = 1.0;
    }
    scale_model(model, metres_per_unit * arguments.scale);
    if (arguments.triangulate) triangulate_model(model);
}

polymass_options options_for(const Arguments& arguments) {
    polymass_options options{};
    polymass_options_init(&options, sizeof options);
    // Files are welded: STL stores each triangle's corners, and OBJ/PLY
    // exporters often repeat positions per face or per material.
    options.flags = POLYMASS_OPTION_WELD_VERTICES;
    if (arguments.accept_inverted) options.flags |= POLYMASS_OPTION_ACCEPT_INVERTED;
    if (arguments.no_check) options.flags |= POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS;
    if (arguments.no_intersection_check) options.flags |= POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    options.weld_tolerance = arguments.weld_tolerance;
    options.planarity_tolerance = arguments.planarity_tolerance;
    std::copy(arguments.modes.begin(), arguments.modes.end(), options.modes);
    options.shell_thickness = arguments.shell_thickness;
    return options;
}

Library library_for(const Arguments& arguments) {
    const uint32_t cores = std::max(1u, std::thread::hardware_concurrency());
    const uint32_t threads =
        arguments.threads ? arguments.threads : std::min<uint32_t>(cores, POLYMASS_MAX_THREADS);
    return Library(options_for(arguments), threads, arguments.point);
}

ExitCode run_properties(const Arguments& arguments) {
    const Library library = library_for(arguments);
    polymass_mass_desc mass{};
    polymass_mass_desc_init(&mass, sizeof mass);
    mass.mass_mode = arguments.mass ? POLYMASS_MASS_FROM_TOTAL : POLYMASS_MASS_FROM_DENSITY;
    mass.density = arguments.density.value_or(1.0);
    mass.mass = arguments.mass.value_or(1.0);

    std::vector<FileReport> files;
    // --html: the page draws each mesh with what --json reports of it.
    HtmlPage page("properties");
    Json meshes = Json::array();
    for (const std::string& path : arguments.files) {
        Model model;
        files.push_back(process_file(library, path, arguments, mass, model));
        const FileReport& file = files.back();
        if (!arguments.html.empty())
            meshes.push_back(file.readable ? mesh_view(page, model, combined_part(model), {},
                                                       capped_holes(file.solid.result.provenance))
                                           : Json());
        if (arguments.timings && file.readable) {
            std::cerr << "polymass: " << path << ": read " << file.read_seconds << " s, compute "
                      << file.compute_seconds << " s\n";
        }
    }
    ExitCode worst = write_reports(files, arguments);
    if (!arguments.html.empty()) {
        page.data()["report"] = json_document(files, output_settings(files, arguments));
        page.data()["meshes"] = meshes;
        worst = std::max(worst, page.write(arguments.html));
    }
    return worst;
}

namespace {

bool in_metres(const FileReport& file) { return file.readable && file.in_metres; }

// Lengths are metres with --units, or when every file's are (each declares
// its unit).
bool lengths_in_metres(const std::vector<FileReport>& files, const Arguments& arguments) {
    return arguments.metres_per_unit || std::all_of(files.begin(), files.end(), in_metres);
}

}  // namespace

OutputSettings output_settings(const std::vector<FileReport>& files, const Arguments& arguments) {
    OutputSettings settings;
    settings.about = arguments.about;
    settings.point = arguments.point;
    if (lengths_in_metres(files, arguments)) settings.length_unit = "m";
    settings.link_origin = arguments.link_origin;
    return settings;
}

ExitCode write_reports(const std::vector<FileReport>& files, const Arguments& arguments) {
    ExitCode worst = kExitOk;
    for (const FileReport& file : files) {
        worst = std::max(worst, file.exit_code());
        const std::string& path = file.path;
        // The table shows errors itself; the machine formats keep stdout clean.
        if (arguments.output != OutputFormat::kTable && file.exit_code() != kExitOk) {
            std::cerr << "polymass: " << path << ": "
                      << (file.readable ? category_of(file.solid.result.status)
                                        : kUnreadableCategory)
                      << ": " << (file.readable ? file.solid.result.message : file.read_error)
                      << '\n';
        }
        // Warnings go to stderr whatever the output, where a script sees them.
        if (file.exit_code() == kExitOk && file.solid.result.properties.warnings) {
            std::cerr << "polymass: " << path
                      << ": warning: " << warning_text(file.solid.result.properties.warnings)
                      << '\n';
        }
    }
    // The table labels its lengths "(file units)"; the machine outputs carry
    // bare numbers, so say it once.
    if (!lengths_in_metres(files, arguments) && arguments.output != OutputFormat::kTable) {
        std::cerr << "polymass: note: " << kFileUnitsNote << " (give the file's unit with --units)"
                  << (std::any_of(files.begin(), files.end(), in_metres)
                          ? "; files that declare their unit (3MF, Collada) excepted: in "
                            "metres, that unit applied"
                          : "")
                  << "\n";
    }

    const OutputSettings settings = output_settings(files, arguments);
    switch (arguments.output) {
        case OutputFormat::kTable:
            write_table(std::cout, files, settings);
            break;
        case OutputFormat::kJson:
            write_json(std::cout, files, settings);
            break;
        case OutputFormat::kUsda:
            // A prim float cannot hold is a result the output cannot carry.
            if (!write_usda(std::cout, std::cerr, files, settings))
                worst = std::max(worst, exit_code_of(POLYMASS_ERROR_OVERFLOW));
            break;
        default:
            write_inertial_xml(std::cout, files, arguments.output, settings);
    }
    return worst;
}

}  // namespace polymass_cli
