// --urdf, --sdf, --mjcf: the <inertial> element of a link or body, about the
// centre of mass in axes parallel to the mesh's, written with pugixml. All
// three formats take the inertia tensor's elements (off-diagonals are the
// NEGATED products of inertia, Ixy = -integral rho x y dV), which is what the
// library returns:
//  - URDF: <inertia ixx ixy ixz iyy iyz izz>, "the 3x3 rotational inertia
//    matrix, represented in the inertia frame ... only 6 above-diagonal
//    elements of this matrix are specified" (wiki.ros.org/urdf/XML/link).
//  - SDFormat: <inertia><ixx>..</ixx><ixy>.. "the 3x3 rotational inertia
//    matrix", with <pose> the centre of mass in the link frame
//    (sdformat.org/spec, link -> inertial).
//  - MJCF: fullinertia="M(1,1) M(2,2) M(3,3) M(1,2) M(1,3) M(2,3)" of the
//    "full inertia matrix M" (mujoco.readthedocs.io, XML reference, inertial).
// The link frame is the file's frame moved to --origin (no rotation), so the
// inertial's origin is the centre of mass minus that point.
#include <polymass/polymass.h>

#include <pugixml.hpp>

#include "library/categories.hpp"
#include "reports/number_format.hpp"
#include "reports/provenance.hpp"
#include "reports/report.hpp"
#include "reports/utf8.hpp"
#include "xml_memory.hpp"

namespace polymass_cli {
namespace {

// The six distinct elements of the symmetric tensor, by name.
struct TensorElement {
    const char* name;
    int index;  // row-major in the 3x3 tensor
};
constexpr TensorElement kUpperTriangle[] = {{"ixx", 0}, {"ixy", 1}, {"ixz", 2},
                                            {"iyy", 4}, {"iyz", 5}, {"izz", 8}};

std::string xyz(const std::array<double, 3>& v) {
    return exact_number(v[0]) + " " + exact_number(v[1]) + " " + exact_number(v[2]);
}

void write_urdf(pugi::xml_node parent, const polymass_mass_properties& p,
                const std::array<double, 3>& origin, const std::array<double, 9>& inertia) {
    pugi::xml_node inertial = parent.append_child("inertial");
    pugi::xml_node pose = inertial.append_child("origin");
    pose.append_attribute("xyz") = xyz(origin).c_str();
    pose.append_attribute("rpy") = "0 0 0";
    inertial.append_child("mass").append_attribute("value") = exact_number(p.mass).c_str();
    pugi::xml_node tensor = inertial.append_child("inertia");
    for (const TensorElement& e : kUpperTriangle) {
        tensor.append_attribute(e.name) = exact_number(inertia[e.index]).c_str();
    }
}

void write_sdf(pugi::xml_node parent, const polymass_mass_properties& p,
               const std::array<double, 3>& origin, const std::array<double, 9>& inertia) {
    pugi::xml_node inertial = parent.append_child("inertial");
    inertial.append_child("pose").text() = (xyz(origin) + " 0 0 0").c_str();
    inertial.append_child("mass").text() = exact_number(p.mass).c_str();
    pugi::xml_node tensor = inertial.append_child("inertia");
    for (const TensorElement& e : kUpperTriangle) {
        tensor.append_child(e.name).text() = exact_number(inertia[e.index]).c_str();
    }
}

void write_mjcf(pugi::xml_node parent, const polymass_mass_properties& p,
                const std::array<double, 3>& origin, const std::array<double, 9>& inertia) {
    pugi::xml_node inertial = parent.append_child("inertial");
    inertial.append_attribute("pos") = xyz(origin).c_str();
    inertial.append_attribute("mass") = exact_number(p.mass).c_str();
    const std::string full = exact_number(inertia[0]) + " " + exact_number(inertia[4]) + " " +
                             exact_number(inertia[8]) + " " + exact_number(inertia[1]) + " " +
                             exact_number(inertia[2]) + " " + exact_number(inertia[5]);
    inertial.append_attribute("fullinertia") = full.c_str();
}

// A comment's text: XML forbids "--" inside a comment and a '-' at its end;
// pugixml writes comments as given.
void add_comment(pugi::xml_node parent, const std::string& text) {
    std::string safe = valid_utf8(text);
    for (std::string::size_type at = safe.find("--"); at != std::string::npos;
         at = safe.find("--", at)) {
        safe.replace(at, 2, "- -");
    }
    parent.append_child(pugi::node_comment).set_value((" " + safe + " ").c_str());
}

}  // namespace

void write_inertial_xml(std::ostream& out, const std::vector<FileReport>& files,
                        OutputFormat format, const OutputSettings& settings) {
    pugixml_allocates_with_new();
    pugi::xml_document document;
    for (const FileReport& file : files) {
        // With one valid file the output is its comments and the element,
        // ready to parse or paste; a failed one only has its error on stderr.
        const bool several = files.size() > 1;
        if (file.exit_code() != kExitOk) {
            if (several) {
                const std::string why =
                    file.readable ? std::string(category_of(file.solid.result.status)) + ": " +
                                        file.solid.result.message
                                  : std::string(kUnreadableCategory) + ": " + file.read_error;
                add_comment(document, file.path + ": no inertial, " + why);
            }
            continue;
        }
        const polymass_mass_properties& p = file.solid.result.properties;
        if (several) add_comment(document, file.path);
        if (p.warnings) add_comment(document, "warning: " + warning_text(p.warnings));
        add_comment(document, "provenance: " + provenance_text(file.solid.result.provenance));
        add_comment(document, "error bound: " + error_bound_text(p));
        for (const std::string& note : file.notes) add_comment(document, "note: " + note);
        if (!file.solid.material.empty())
            add_comment(document, "material: " + material_text(file.solid));
        if (length_unit_of(file, settings).empty()) add_comment(document, kFileUnitsNote);
        std::array<double, 3> origin{};
        for (int k = 0; k < 3; ++k) origin[k] = p.center_of_mass[k] - settings.link_origin[k];
        const std::array<double, 9> inertia = symmetric_tensor(p.inertia);
        if (format == OutputFormat::kUrdf) {
            write_urdf(document, p, origin, inertia);
        } else if (format == OutputFormat::kSdf) {
            write_sdf(document, p, origin, inertia);
        } else {
            write_mjcf(document, p, origin, inertia);
        }
    }
    document.save(out, "  ", pugi::format_indent | pugi::format_no_declaration,
                  pugi::encoding_utf8);
}

}  // namespace polymass_cli
