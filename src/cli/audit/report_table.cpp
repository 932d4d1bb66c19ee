// The table: per file, per link, the declared and computed mass, centre of
// mass and principal moments on two lines, then each finding.
#include <Eigen/Eigenvalues>
#include <iomanip>

#include "audit/report.hpp"
#include "reports/number_format.hpp"

namespace polymass_cli::audit {
namespace {

std::string triple(const Eigen::Vector3d& v) {
    return readable_number(v[0]) + " " + readable_number(v[1]) + " " + readable_number(v[2]);
}

void write_row(std::ostream& out, const char* label, double mass, const Eigen::Vector3d& com,
               const Eigen::Vector3d& moments) {
    out << "    " << std::left << std::setw(9) << label << " mass " << std::setw(12)
        << readable_number(mass) << " com " << std::setw(36) << triple(com) << " moments "
        << triple(moments) << '\n';
}

}  // namespace

void write_audit_table(std::ostream& out, const std::vector<FileAudit>& files) {
    for (const FileAudit& file : files) {
        out << file.path;
        if (!file.error.empty()) {
            out << ": cannot be read: " << file.error << "\n\n";
            continue;
        }
        out << " (" << format_name(file.format) << ", " << file.links.size()
            << (file.links.size() == 1 ? " link)\n" : " links)\n");
        for (const LinkAudit& link : file.links) {
            out << "  " << link.name << " [" << link.geometry << "]\n";
            if (link.declared) {
                const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(link.declared->inertia,
                                                                           Eigen::EigenvaluesOnly);
                write_row(out, "declared", link.declared->mass, link.declared->center_of_mass,
                          eigen.eigenvalues());
            }
            if (link.computed) {
                write_row(out, "computed", link.computed->mass, link.computed->center_of_mass,
                          link.computed->principal_moments);
            }
            if (link.mujoco_legacy) {
                write_row(out, "legacy", link.mujoco_legacy->mass,
                          link.mujoco_legacy->center_of_mass,
                          link.mujoco_legacy->principal_moments);
            }
            for (const Finding& finding : link.findings) {
                out << "    " << severity_name(finding.severity) << ": " << finding.kind << ": "
                    << finding.message << '\n';
            }
        }
        out << '\n';
    }
}

}  // namespace polymass_cli::audit
