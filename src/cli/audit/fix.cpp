// The replacement <inertial> is written in the description's own format, at
// the centre of mass, its axes the link's (no rotation), every number in the
// fewest digits that read back as the same double. Its lines are indented as
// the element it replaces, children one step (two spaces, or a tab when the
// element is indented with tabs) further.
#include "audit/fix.hpp"

#include <algorithm>

#include "reports/number_format.hpp"
#include "text_streams.hpp"

namespace polymass_cli::audit {
namespace {

struct Written {
    double mass;
    Eigen::Vector3d center_of_mass;
    Eigen::Matrix3d inertia;
};

std::string triple(const Eigen::Vector3d& v) {
    return exact_number(v[0]) + " " + exact_number(v[1]) + " " + exact_number(v[2]);
}

std::string inertial_text(Format format, const Written& w, const std::string& indent) {
    const std::string step = indent.find('\t') != std::string::npos ? "\t" : "  ";
    const std::string inner = indent + step;
    const Eigen::Matrix3d& i = w.inertia;
    OutputText out;
    switch (format) {
        case Format::kUrdf:
            out << "<inertial>\n"
                << inner << "<origin xyz=\"" << triple(w.center_of_mass) << "\" rpy=\"0 0 0\"/>\n"
                << inner << "<mass value=\"" << exact_number(w.mass) << "\"/>\n"
                << inner << "<inertia ixx=\"" << exact_number(i(0, 0)) << "\" ixy=\""
                << exact_number(i(0, 1)) << "\" ixz=\"" << exact_number(i(0, 2)) << "\" iyy=\""
                << exact_number(i(1, 1)) << "\" iyz=\"" << exact_number(i(1, 2)) << "\" izz=\""
                << exact_number(i(2, 2)) << "\"/>\n"
                << indent << "</inertial>";
            break;
        case Format::kSdf: {
            out << "<inertial>\n"
                << inner << "<pose>" << triple(w.center_of_mass) << " 0 0 0</pose>\n"
                << inner << "<mass>" << exact_number(w.mass) << "</mass>\n"
                << inner << "<inertia>\n";
            const std::pair<const char*, double> entries[] = {{"ixx", i(0, 0)}, {"ixy", i(0, 1)},
                                                              {"ixz", i(0, 2)}, {"iyy", i(1, 1)},
                                                              {"iyz", i(1, 2)}, {"izz", i(2, 2)}};
            for (const auto& [name, value] : entries) {
                out << inner << step << "<" << name << ">" << exact_number(value) << "</" << name
                    << ">\n";
            }
            out << inner << "</inertia>\n" << indent << "</inertial>";
            break;
        }
        case Format::kMjcf:
            out << "<inertial pos=\"" << triple(w.center_of_mass) << "\" mass=\""
                << exact_number(w.mass) << "\" fullinertia=\"" << exact_number(i(0, 0)) << " "
                << exact_number(i(1, 1)) << " " << exact_number(i(2, 2)) << " "
                << exact_number(i(0, 1)) << " " << exact_number(i(0, 2)) << " "
                << exact_number(i(1, 2)) << "\"/>";
            break;
    }
    return out.str();
}

}  // namespace

FixResult fix_description(const FileAudit& audit, const FixSettings& settings) {
    struct Edit {
        TextRange range;
        std::string text;
    };
    std::vector<Edit> edits;
    FixResult result;
    for (const LinkAudit& link : audit.links) {
        if (!link.declared) continue;
        if (!link.computed) {
            result.left.push_back(link.name + ": no geometry measured");
            continue;
        }
        if (!link.declared->text) {
            result.left.push_back(link.name + ": its <inertial> is not in this file");
            continue;
        }
        // The geometry at the declared mass (for MJCF, before MuJoCo's
        // bounds and total mass, which it applies to the file's inertials
        // itself), else as computed.
        const Computed& c = link.at_declared_mass ? *link.at_declared_mass : *link.computed;
        const double mass = settings.density ? *settings.density * c.volume : c.mass;
        // At a fixed geometry the inertia is proportional to the mass;
        // symmetric from the computed tensor's upper triangle.
        Eigen::Matrix3d inertia = c.inertia.triangularView<Eigen::Upper>();
        inertia.triangularView<Eigen::StrictlyLower>() = inertia.transpose();
        const Written written{mass, c.center_of_mass, inertia * (mass / c.mass)};
        const TextRange& range = *link.declared->text;
        edits.push_back({range, inertial_text(audit.format, written, range.indent)});
    }
    std::sort(edits.begin(), edits.end(),
              [](const Edit& a, const Edit& b) { return a.range.begin > b.range.begin; });
    result.text = audit.text;
    for (const Edit& edit : edits) {
        result.text.replace(edit.range.begin, edit.range.end - edit.range.begin, edit.text);
        ++result.replaced;
    }
    return result;
}

}  // namespace polymass_cli::audit
