// polymass check: every finding of polymass_mesh_check with its count and
// first location (vertex numbers are 0-based positions in the file's vertex
// list, shown with their coordinates), plus the shell count.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "categories.hpp"
#include "commands.hpp"
#include "json_writer.hpp"
#include "mesh_reader.hpp"
#include "number_format.hpp"
#include "shells.hpp"
#include "solid.hpp"

namespace polymass_cli {
namespace {

struct Finding {
    const char* key;    // JSON key
    const char* label;  // table label
    uint64_t count;
    uint64_t first[2];  // a face (first[1] unused) or an edge's two vertices
    bool is_edge;
};

std::vector<Finding> findings_of(const polymass_diagnostics& d) {
    return {
        {"open_edges",
         "open edges",
         d.open_edges,
         {d.first_open_edge[0], d.first_open_edge[1]},
         true},
        {"non_manifold_edges",
         "non-manifold edges",
         d.non_manifold_edges,
         {d.first_non_manifold_edge[0], d.first_non_manifold_edge[1]},
         true},
        {"misoriented_edges",
         "misoriented edges",
         d.misoriented_edges,
         {d.first_misoriented_edge[0], d.first_misoriented_edge[1]},
         true},
        {"non_planar_faces",
         "non-planar faces",
         d.non_planar_faces,
         {d.first_non_planar_face, POLYMASS_NONE},
         false},
        {"degenerate_faces",
         "degenerate faces",
         d.degenerate_faces,
         {d.first_degenerate_face, POLYMASS_NONE},
         false},
        {"small_faces",
         "faces < 3 vertices",
         d.small_faces,
         {d.first_small_face, POLYMASS_NONE},
         false},
        {"out_of_range_indices",
         "bad vertex indices",
         d.out_of_range_indices,
         {d.first_out_of_range_face, POLYMASS_NONE},
         false},
        {"non_finite_vertices",
         "non-finite vertices",
         d.non_finite_vertices,
         {d.first_non_finite_vertex, POLYMASS_NONE},
         false},
    };
}

std::string vertex_text(const Model& model, uint64_t v) {
    if (v >= model.vertex_count()) return "vertex " + std::to_string(v);
    const double* p = &model.positions[3 * v];
    return "vertex " + std::to_string(v) + " (" + readable_number(p[0]) + ", " +
           readable_number(p[1]) + ", " + readable_number(p[2]) + ")";
}

std::string location_text(const Model& model, const Finding& finding) {
    if (finding.count == 0 || finding.first[0] == POLYMASS_NONE) return "";
    if (finding.is_edge) {
        return "first: " + vertex_text(model, finding.first[0]) + " - " +
               vertex_text(model, finding.first[1]);
    }
    if (std::string(finding.key) == "non_finite_vertices") {
        return "first: vertex " + std::to_string(finding.first[0]);
    }
    return "first: face " + std::to_string(finding.first[0]);
}

void write_text(std::ostream& out, const std::string& path, const Model& model,
                const CheckResult& check, uint64_t shells) {
    const polymass_diagnostics& d = check.diagnostics;
    out << path << " (" << model.format << "): ";
    if (d.status == POLYMASS_OK) {
        out << "a valid closed solid\n";
    } else {
        out << "NOT A VALID SOLID: " << category_of(d.status) << ": " << check.message << '\n';
    }
    out << "  faces " << d.face_count << ", vertices used " << d.used_vertex_count << ", edges "
        << d.edge_count << ", shells " << shells << '\n';
    for (const Finding& finding : findings_of(d)) {
        char line[64];
        std::snprintf(line, sizeof line, "  %-22s%8llu  ", finding.label,
                      static_cast<unsigned long long>(finding.count));
        out << line << location_text(model, finding) << '\n';
    }
    out << "  max non-planarity     " << readable_number(d.max_non_planarity) << '\n';
    out << "  signed volume         " << readable_number(d.signed_volume)
        << (d.signed_volume < 0 ? "  (inverted: the faces are inside out)" : "") << '\n';
}

void write_json_report(JsonWriter& json, const std::string& path, const Model& model,
                       const CheckResult& check, uint64_t shells) {
    const polymass_diagnostics& d = check.diagnostics;
    json.begin_object();
    json.key("file").value(path);
    json.key("format").value(model.format);
    json.key("valid").value(std::string(d.status == POLYMASS_OK ? "yes" : "no"));
    json.key("category").value(std::string(category_of(d.status)));
    json.key("message").value(check.message);
    json.key("faces").value(d.face_count);
    json.key("used_vertices").value(d.used_vertex_count);
    json.key("edges").value(d.edge_count);
    json.key("shells").value(shells);
    for (const Finding& finding : findings_of(d)) {
        json.key(finding.key).begin_object();
        json.key("count").value(finding.count);
        if (finding.count > 0 && finding.first[0] != POLYMASS_NONE) {
            json.key(finding.is_edge                                     ? "first_edge"
                     : std::string(finding.key) == "non_finite_vertices" ? "first_vertex"
                                                                         : "first_face");
            if (finding.is_edge) {
                json.begin_array();
                json.value(finding.first[0]);
                json.value(finding.first[1]);
                json.end_array();
            } else {
                json.value(finding.first[0]);
            }
        }
        json.end_object();
    }
    json.key("max_non_planarity").value(d.max_non_planarity);
    if (d.signed_volume == d.signed_volume) json.key("signed_volume").value(d.signed_volume);
    json.end_object();
}

}  // namespace

ExitCode run_check(const Arguments& arguments) {
    const Library library(options_for(arguments));
    const bool as_json = arguments.output == OutputFormat::kJson;
    std::ostringstream body;
    JsonWriter json(body);
    if (as_json && arguments.files.size() > 1) json.begin_array();
    ExitCode worst = kExitOk;
    for (const std::string& path : arguments.files) {
        Model model;
        try {
            model = read_mesh_file(path, arguments.format);
        } catch (const ReadError& error) {
            worst = std::max(worst, kExitUnreadable);
            std::cerr << "polymass: " << path << ": " << kUnreadableCategory << ": " << error.what()
                      << '\n';
            if (as_json) {
                json.begin_object();
                json.key("file").value(path);
                json.key("error").begin_object();
                json.key("category").value(std::string(kUnreadableCategory));
                json.key("message").value(std::string(error.what()));
                json.end_object();
                json.end_object();
            }
            continue;
        }
        scale_model(model, length_factor(arguments));
        const Part all = combined_part(model);
        const CheckResult check = check_solid(library, model, all);
        const uint64_t shells = count_shells(model, all);
        worst = std::max(worst, exit_code_of(check.diagnostics.status));
        if (as_json) {
            write_json_report(json, path, model, check, shells);
        } else {
            write_text(body, path, model, check, shells);
        }
    }
    if (as_json && arguments.files.size() > 1) json.end_array();
    std::cout << body.str();
    return worst;
}

}  // namespace polymass_cli
