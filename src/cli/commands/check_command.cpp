// polymass check: every finding of the library's analysis of a file
// (polymass_mesh_diagnostics) with its count and first few locations
// (vertex numbers are 0-based positions in the file's vertex list, shown
// with their coordinates; face pairs with the shells the faces are in), and
// the shells as the library judges them: a solid, a cavity, inside out,
// overlapping another, or without volume. A file of several parts is judged
// part by part, as polymass FILE judges it. Each file (each part, and the
// parts together, for a file of several) is analysed once: the findings,
// the shells and which mode answers are read from that one analysis.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "commands/commands.hpp"
#include "commands/parts_report.hpp"
#include "library/categories.hpp"
#include "library/solid.hpp"
#include "library/surface_analysis.hpp"
#include "readers/mesh_reader.hpp"
#include "reports/html_mesh.hpp"
#include "reports/html_page.hpp"
#include "reports/json_output.hpp"
#include "reports/number_format.hpp"
#include "reports/provenance.hpp"
#include "text_streams.hpp"

namespace polymass_cli {
namespace {

enum class Where { kEdge, kFace, kVertex, kFacePair, kShell };

struct Finding {
    const char* key;    // JSON key
    const char* label;  // table label
    uint64_t count;
    Where where;
    std::vector<std::array<uint64_t, 2>> locations;  // the first few; [1] for edges and pairs
};

Finding face_finding(const char* key, const char* label, uint64_t count,
                     const uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS], Where where) {
    Finding finding{key, label, count, where, {}};
    for (const uint64_t location : first) {
        if (location != POLYMASS_NONE) finding.locations.push_back({location, POLYMASS_NONE});
    }
    return finding;
}

Finding pair_finding(const char* key, const char* label, uint64_t count,
                     const uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS][2],
                     Where where = Where::kEdge) {
    Finding finding{key, label, count, where, {}};
    for (const auto& edge : first) {
        if (edge[0] != POLYMASS_NONE) finding.locations.push_back({edge[0], edge[1]});
    }
    return finding;
}

std::vector<Finding> findings_of(const polymass_diagnostics& d) {
    return {
        pair_finding("open_edges", "open edges", d.open_edges, d.first_open_edges),
        pair_finding("non_manifold_edges", "non-manifold edges", d.non_manifold_edges,
                     d.first_non_manifold_edges),
        pair_finding("misoriented_edges", "misoriented edges", d.misoriented_edges,
                     d.first_misoriented_edges),
        face_finding("non_planar_faces", "non-planar faces", d.non_planar_faces,
                     d.first_non_planar_faces, Where::kFace),
        face_finding("degenerate_faces", "degenerate faces", d.degenerate_faces,
                     d.first_degenerate_faces, Where::kFace),
        face_finding("small_faces", "faces < 3 vertices", d.small_faces, d.first_small_faces,
                     Where::kFace),
        face_finding("out_of_range_indices", "bad vertex indices", d.out_of_range_indices,
                     d.first_out_of_range_faces, Where::kFace),
        face_finding("non_finite_vertices", "non-finite vertices", d.non_finite_vertices,
                     d.first_non_finite_vertices, Where::kVertex),
        pair_finding("intersecting_face_pairs", "crossing face pairs", d.intersecting_face_pairs,
                     d.first_intersecting_face_pairs, Where::kFacePair),
        pair_finding("touching_face_pairs", "touching face pairs", d.touching_face_pairs,
                     d.first_touching_face_pairs, Where::kFacePair),
        face_finding("inverted_shells", "inside-out shells", d.inverted_shells,
                     d.first_inverted_shells, Where::kShell),
        face_finding("overlapping_shells", "overlapping shells", d.overlapping_shells,
                     d.first_overlapping_shells, Where::kShell),
    };
}

// What check needs besides the library's report: each face's shell (to say
// which shells a pair of faces belongs to) and the shells' descriptions.
struct ShellView {
    std::vector<uint32_t> of_face;
    std::vector<polymass_shell> list;
};

std::string face_text(const ShellView& shells, uint64_t face) {
    std::string text = "face " + std::to_string(face);
    if (face < shells.of_face.size())
        text += " (shell " + std::to_string(shells.of_face[face]) + ")";
    return text;
}

std::string vertex_text(const Model& model, uint64_t v) {
    if (v >= model.vertex_count()) return "vertex " + std::to_string(v);
    const std::array<double, 3> p = model.positions.vertex(v);
    return "vertex " + std::to_string(v) + " (" + readable_number(p[0]) + ", " +
           readable_number(p[1]) + ", " + readable_number(p[2]) + ")";
}

std::string location_text(const Model& model, const ShellView& shells, const Finding& finding,
                          const std::array<uint64_t, 2>& location) {
    switch (finding.where) {
        case Where::kEdge:
            return "edge " + vertex_text(model, location[0]) + " - " +
                   vertex_text(model, location[1]);
        case Where::kVertex:
            return vertex_text(model, location[0]);
        case Where::kFacePair:
            return face_text(shells, location[0]) + " and " + face_text(shells, location[1]);
        case Where::kShell:
            return "shell " + std::to_string(location[0]);
        case Where::kFace:
            break;
    }
    return "face " + std::to_string(location[0]);
}

std::string shells_summary(const polymass_diagnostics& d, const ShellView& shells) {
    std::string text = std::to_string(shells.list.empty() ? d.shell_count : shells.list.size());
    std::string kinds;
    for (const int32_t kind : {POLYMASS_SHELL_SOLID, POLYMASS_SHELL_CAVITY, POLYMASS_SHELL_INVERTED,
                               POLYMASS_SHELL_OVERLAPPING, POLYMASS_SHELL_NO_VOLUME}) {
        const auto count =
            std::count_if(shells.list.begin(), shells.list.end(),
                          [&](const polymass_shell& shell) { return shell.kind == kind; });
        if (count > 0)
            kinds +=
                (kinds.empty() ? "" : ", ") + std::to_string(count) + " " + shell_kind_name(kind);
    }
    return kinds.empty() ? text : text + " (" + kinds + ")";
}

void write_text(std::ostream& out, const std::string& path, const Model& model,
                const SurfaceAnalysis& check, const ShellView& shells) {
    const polymass_diagnostics& d = check.diagnostics();
    out << path << " (" << model.format << "): ";
    if (d.status == POLYMASS_OK) {
        out << "a valid closed solid\n";
    } else {
        const std::string message = check.failure().message;
        out << "NOT A VALID SOLID: " << category_of(d.status)
            << (message.empty() ? "" : ": " + message) << '\n';
    }
    out << "  faces " << d.face_count << ", vertices used " << d.used_vertex_count << ", edges "
        << d.edge_count << ", shells " << shells_summary(d, shells) << '\n';
    for (const Finding& finding : findings_of(d)) {
        char line[64];
        std::snprintf(line, sizeof line, "  %-22s%8llu  ", finding.label,
                      static_cast<unsigned long long>(finding.count));
        out << line;
        for (size_t i = 0; i < finding.locations.size(); ++i) {
            out << (i == 0 ? "" : "                                  ")
                << location_text(model, shells, finding, finding.locations[i]) << '\n';
        }
        if (finding.locations.empty()) out << '\n';
        if (finding.count > finding.locations.size()) {
            out << "                                  ... and "
                << finding.count - finding.locations.size() << " more\n";
        }
    }
    for (size_t i = 0; i < shells.list.size() && shells.list.size() > 1; ++i) {
        const polymass_shell& shell = shells.list[i];
        out << "  shell " << i << ": " << shell.face_count << " faces from face "
            << shell.first_face << ", signed volume " << readable_number(shell.signed_volume)
            << " (" << shell_kind_name(shell.kind) << ")\n";
    }
    out << "  max non-planarity     " << readable_number(d.max_non_planarity) << '\n';
    out << "  signed volume         " << readable_number(d.signed_volume)
        << (d.signed_volume < 0 ? "  (inverted: the faces are inside out)" : "") << '\n';
}

Json json_report(const std::string& path, const Model& model, const SurfaceAnalysis& check,
                 const ShellView& shells) {
    const polymass_diagnostics& d = check.diagnostics();
    Json report = Json::object();
    report["file"] = path;
    report["format"] = model.format;
    report["valid"] = d.status == POLYMASS_OK;
    report["category"] = category_of(d.status);
    report["message"] = check.failure().message;
    report["faces"] = d.face_count;
    report["used_vertices"] = d.used_vertex_count;
    report["edges"] = d.edge_count;
    report["shells"] = shells.list.empty() ? d.shell_count : uint64_t(shells.list.size());
    Json shell_list = Json::array();
    for (const polymass_shell& shell : shells.list) {
        Json entry = Json::object();
        entry["faces"] = shell.face_count;
        entry["first_face"] = shell.first_face;
        entry["signed_volume"] = json_number(shell.signed_volume);
        entry["kind"] = shell_kind_name(shell.kind);
        shell_list.push_back(entry);
    }
    report["shell_list"] = shell_list;
    for (const Finding& finding : findings_of(d)) {
        Json locations = Json::array();
        for (const auto& location : finding.locations) {
            if (finding.where == Where::kEdge || finding.where == Where::kFacePair) {
                locations.push_back({location[0], location[1]});
            } else {
                locations.push_back(location[0]);
            }
        }
        const char* list = finding.where == Where::kEdge       ? "first_edges"
                           : finding.where == Where::kVertex   ? "first_vertices"
                           : finding.where == Where::kFacePair ? "first_pairs"
                           : finding.where == Where::kShell    ? "first_shells"
                                                               : "first_faces";
        report[finding.key] = {{"count", finding.count}, {list, locations}};
        if (finding.where == Where::kFacePair) {
            Json pair_shells = Json::array();
            for (const auto& location : finding.locations) {
                if (location[1] < shells.of_face.size())
                    pair_shells.push_back(
                        {shells.of_face[location[0]], shells.of_face[location[1]]});
            }
            report[finding.key]["first_pair_shells"] = pair_shells;
        }
    }
    report["max_non_planarity"] = json_number(d.max_non_planarity);
    if (!std::isnan(d.signed_volume)) report["signed_volume"] = json_number(d.signed_volume);
    return report;
}

// The surface check reports on, analysed once: a file of one part as it is,
// with the options; a file of several as judge_parts judged it: its parts
// apart against each other when every part is a solid by itself (analysed
// here when the options skip that check, which judge_parts then leaves
// out), else the file as one welded surface. own holds an analysis made here.
const SurfaceAnalysis& checked_surface(const Library& library, const Model& model, const Part& all,
                                       const std::optional<JudgedParts>& parts,
                                       std::optional<SurfaceAnalysis>& own) {
    if (parts && parts->apart) {
        if (parts->between) return *parts->between;
        return own.emplace(analyse_between(library, *parts->apart));
    }
    if (parts) return *parts->whole;
    return own.emplace(library, model, all, library.options());
}

// The shells of the checked surface, listed when the library judged them
// (when the surface fails a check that comes before the shells, only their
// count is told).
ShellView shell_view(const Library& library, const SurfaceAnalysis& check) {
    ShellView shells{check.shell_of_each_face(library), check.shells(library)};
    if (std::any_of(shells.list.begin(), shells.list.end(), [](const polymass_shell& shell) {
            return shell.kind == POLYMASS_SHELL_UNJUDGED;
        }))
        shells.list.clear();
    return shells;
}

// Which mode answers the file, as polymass FILE answers it (a file of
// several parts part by part): the options' chain (the solid alone by
// default), or else the option that would. A file of one part is answered
// by the analysis check reports on.
SolidResult answer_of(const Library& library, const std::string& path, const Model& model,
                      const Part& all, const Arguments& arguments,
                      const std::optional<JudgedParts>& parts, const SurfaceAnalysis& check) {
    polymass_mass_desc unit{};
    polymass_mass_desc_init(&unit, sizeof unit);
    if (!parts) return answer_of(library, check, model, all, unit);
    FileReport report;
    report_parts(library, path, model, arguments, unit, *parts, report);
    SolidResult answer = report.solid.result;
    if (answer.status == POLYMASS_OK || answer.options_tried) return answer;
    // Refused: a chain of modes would answer the whole as one surface
    // (parts_report), so that surface says which option would answer.
    suggest_option(library, describe(model, all), answer.status, answer);
    return answer;
}

std::string answer_text(const SolidResult& answer) {
    if (answer.status == POLYMASS_OK) return "answered as " + provenance_text(answer.provenance);
    if (answer.answering_option.empty()) return "no mode gives an answer";
    // The probe's thickness is arbitrary: only the area is the surface's.
    if (answer.answering_provenance.mode == POLYMASS_MODE_SHELL)
        return answer.answering_option + " would give an answer: a thin wall over the surface's " +
               "area " + readable_number(answer.answering_provenance.shell_area);
    return answer.answering_option +
           " would give an answer: " + provenance_text(answer.answering_provenance);
}

Json answer_json(const SolidResult& answer) {
    if (answer.status == POLYMASS_OK) return {{"mode", answer_mode_name(answer.provenance.mode)}};
    if (answer.answering_option.empty()) return {{"mode", nullptr}};
    return {{"mode", answer_mode_name(answer.answering_provenance.mode)},
            {"option", answer.answering_option}};
}

// The edges' vertices and the faces the findings name, which the --html
// page draws exactly.
Located located_by(const polymass_diagnostics& d) {
    Located located;
    for (const Finding& finding : findings_of(d)) {
        std::vector<uint64_t>& list =
            finding.where == Where::kEdge ? located.vertices : located.faces;
        if (finding.where != Where::kEdge && finding.where != Where::kFace &&
            finding.where != Where::kFacePair)
            continue;
        for (const auto& location : finding.locations) {
            list.push_back(location[0]);
            if (finding.where != Where::kFace) list.push_back(location[1]);
        }
    }
    return located;
}

}  // namespace

ExitCode run_check(const Arguments& arguments) {
    const Library library = library_for(arguments);
    const bool as_json = arguments.output == OutputFormat::kJson;
    // --html: the page draws each file's mesh beside what --json reports.
    const bool html = !arguments.html.empty();
    HtmlPage page("check");
    Json meshes = Json::array();
    OutputText body;
    Json reports = Json::array();
    ExitCode worst = kExitOk;
    for (const std::string& path : arguments.files) {
        Model model;
        try {
            model = read_mesh_file(path, arguments.format);
        } catch (const ReadError& error) {
            worst = std::max(worst, kExitUnreadable);
            std::cerr << "polymass: " << path << ": " << kUnreadableCategory << ": " << error.what()
                      << '\n';
            if (as_json || html) {
                Json failure = Json::object();
                failure["file"] = path;
                failure["error"] = {{"category", kUnreadableCategory}, {"message", error.what()}};
                reports.push_back(failure);
                meshes.push_back(nullptr);
            }
            continue;
        }
        prepare_model(model, arguments);
        // The file's solid: its one part as read (a copy would add 4 bytes a
        // corner to the check's peak), or every part's faces in one.
        const Part combined = model.parts.size() > 1 ? combined_part(model) : Part{};
        const Part& all = model.parts.size() > 1 ? combined : model.parts.front();
        // A file of several parts is judged as polymass FILE judges it, once
        // for both the findings and the answer: when every part is a solid by
        // itself, its parts apart (each welded by itself, none sharing a
        // vertex with another) against each other, so that parts resting on
        // each other touch and are not non-manifold; else as one welded
        // surface. The parts apart keep the file's faces, in its order; as
        // each part is a solid by itself, their check names faces and shells
        // only (crossing, touching, nested), never an edge or a vertex, whose
        // numbers the copies do not keep.
        std::optional<JudgedParts> parts;
        if (model.parts.size() > 1) parts.emplace(judge_parts(library, model));
        std::optional<SurfaceAnalysis> own;
        const SurfaceAnalysis& check = checked_surface(library, model, all, parts, own);
        const ShellView shells = shell_view(library, check);
        const uint64_t shell_count = check.diagnostics().shell_count;
        const SolidResult answer = answer_of(library, path, model, all, arguments, parts, check);
        worst = std::max(worst, exit_code_of(check.diagnostics().status));
        if (as_json || html) {
            reports.push_back(json_report(path, model, check, shells));
            reports.back()["answer"] = answer_json(answer);
        }
        if (html) {
            // Each face's shell only when there are several to tell apart.
            meshes.push_back(mesh_view(page, model, all,
                                       shell_count > 1 ? shells.of_face : std::vector<uint32_t>(),
                                       located_by(check.diagnostics())));
        }
        if (!as_json) {
            write_text(body, path, model, check, shells);
            body << "  " << answer_text(answer) << '\n';
        }
    }
    if (!as_json) std::cout << body.str();
    if (!as_json && !html) return worst;
    // One file: its object; several: an array of them.
    const Json& document = arguments.files.size() == 1 ? reports.front() : reports;
    if (as_json) print_json(std::cout, document);
    if (html) {
        page.data()["report"] = document;
        page.data()["meshes"] = meshes;
        worst = std::max(worst, page.write(arguments.html));
    }
    return worst;
}

}  // namespace polymass_cli
