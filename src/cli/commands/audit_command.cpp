// polymass audit: each description read, its links measured and judged
// (audit/), the table or JSON printed, and with --fix the corrected
// description written.
#include <fstream>
#include <iostream>

#include "audit/audit.hpp"
#include "audit/fix.hpp"
#include "audit/report.hpp"
#include "commands/commands.hpp"

namespace polymass_cli {

ExitCode run_audit(const Arguments& arguments) {
    using namespace audit;
    const Library library = library_for(arguments);
    AuditSettings settings;
    settings.options = library.options();
    settings.from =
        arguments.audit.from_visual ? GeometrySource::kVisual : GeometrySource::kCollision;
    settings.density = arguments.density.value_or(settings.density);
    Severity fail_on = Severity::kError;
    severity_from_name(arguments.audit.fail_on, fail_on);

    std::vector<FileAudit> files;
    ExitCode worst = kExitOk;
    for (const std::string& path : arguments.files) {
        files.push_back(audit_file(library, path, settings));
        const FileAudit& file = files.back();
        if (!file.error.empty()) worst = std::max(worst, kExitUnreadable);
        for (const LinkAudit& link : file.links) {
            for (const Finding& finding : link.findings) {
                if (finding.severity >= fail_on) worst = std::max(worst, kExitInvalidMesh);
            }
        }
    }
    if (arguments.output == OutputFormat::kJson) {
        write_audit_json(std::cout, files);
    } else {
        write_audit_table(std::cout, files);
    }
    if (!arguments.html.empty()) worst = std::max(worst, write_audit_html(arguments.html, files));
    if (!arguments.audit.fix.empty() && files.front().error.empty()) {
        FixSettings fix;
        if (arguments.density || arguments.audit.mass_from_geometry) fix.density = settings.density;
        const FixResult result = fix_description(files.front(), fix);
        std::ofstream out(arguments.audit.fix, std::ios::binary);
        out << result.text;
        out.close();
        if (!out) {
            std::cerr << "polymass: cannot write " << arguments.audit.fix << '\n';
            return kExitUnreadable;
        }
        std::cerr << "polymass: " << arguments.audit.fix << ": " << result.replaced
                  << " inertial(s) replaced\n";
        for (const std::string& left : result.left) {
            std::cerr << "polymass: left as it is: " << left << '\n';
        }
    }
    return worst;
}

}  // namespace polymass_cli
