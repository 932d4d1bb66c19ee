// --urdf, --sdf, --mjcf: the <inertial> element of a link or body, about the
// centre of mass in axes parallel to the mesh's. All three formats take the
// inertia tensor's elements (off-diagonals are the NEGATED products of
// inertia, Ixy = -integral rho x y dV), which is what the library returns:
//  - URDF: <inertia ixx ixy ixz iyy iyz izz>, "the 3x3 rotational inertia
//    matrix, represented in the inertia frame ... only 6 above-diagonal
//    elements of this matrix are specified" (wiki.ros.org/urdf/XML/link).
//  - SDFormat: <inertia><ixx>..</ixx><ixy>.. "the 3x3 rotational inertia
//    matrix", with <pose> the centre of mass in the link frame
//    (sdformat.org/spec, link -> inertial).
//  - MJCF: fullinertia="M(1,1) M(2,2) M(3,3) M(1,2) M(1,3) M(2,3)" of the
//    "full inertia matrix M" (mujoco.readthedocs.io, XML reference, inertial).
#include <polymass/polymass.h>

#include "library/categories.hpp"
#include "reports/number_format.hpp"
#include "reports/report.hpp"
#include "reports/utf8.hpp"

namespace polymass_cli {
namespace {

std::string xyz(const double* v) {
    return exact_number(v[0]) + " " + exact_number(v[1]) + " " + exact_number(v[2]);
}

void write_urdf(std::ostream& out, const polymass_mass_properties& p) {
    const double* i = p.inertia;
    out << "<inertial>\n"
        << "  <origin xyz=\"" << xyz(p.center_of_mass) << "\" rpy=\"0 0 0\"/>\n"
        << "  <mass value=\"" << exact_number(p.mass) << "\"/>\n"
        << "  <inertia ixx=\"" << exact_number(i[0]) << "\" ixy=\"" << exact_number(i[1])
        << "\" ixz=\"" << exact_number(i[2]) << "\" iyy=\"" << exact_number(i[4]) << "\" iyz=\""
        << exact_number(i[5]) << "\" izz=\"" << exact_number(i[8]) << "\"/>\n"
        << "</inertial>\n";
}

void write_sdf(std::ostream& out, const polymass_mass_properties& p) {
    const double* i = p.inertia;
    out << "<inertial>\n"
        << "  <pose>" << xyz(p.center_of_mass) << " 0 0 0</pose>\n"
        << "  <mass>" << exact_number(p.mass) << "</mass>\n"
        << "  <inertia>\n";
    const struct {
        const char* name;
        int element;
    } kElements[] = {{"ixx", 0}, {"ixy", 1}, {"ixz", 2}, {"iyy", 4}, {"iyz", 5}, {"izz", 8}};
    for (const auto& e : kElements) {
        out << "    <" << e.name << ">" << exact_number(i[e.element]) << "</" << e.name << ">\n";
    }
    out << "  </inertia>\n"
        << "</inertial>\n";
}

void write_mjcf(std::ostream& out, const polymass_mass_properties& p) {
    const double* i = p.inertia;
    out << "<inertial pos=\"" << xyz(p.center_of_mass) << "\" mass=\"" << exact_number(p.mass)
        << "\" fullinertia=\"" << exact_number(i[0]) << " " << exact_number(i[4]) << " "
        << exact_number(i[8]) << " " << exact_number(i[1]) << " " << exact_number(i[2]) << " "
        << exact_number(i[5]) << "\"/>\n";
}

std::string comment_safe(std::string text) {
    for (std::string::size_type at = text.find("--"); at != std::string::npos;
         at = text.find("--", at)) {
        text.replace(at, 2, "- -");
    }
    return text;
}

}  // namespace

void write_inertial_xml(std::ostream& out, const std::vector<FileReport>& files,
                        OutputFormat format) {
    for (const FileReport& file : files) {
        // With one file the output is the element alone, ready to parse or paste.
        if (files.size() > 1) out << "<!-- " << comment_safe(valid_utf8(file.path)) << " -->\n";
        if (file.exit_code() != kExitOk) continue;  // the error went to stderr
        const polymass_mass_properties& p = file.solid.result.properties;
        if (format == OutputFormat::kUrdf) {
            write_urdf(out, p);
        } else if (format == OutputFormat::kSdf) {
            write_sdf(out, p);
        } else {
            write_mjcf(out, p);
        }
    }
}

}  // namespace polymass_cli
