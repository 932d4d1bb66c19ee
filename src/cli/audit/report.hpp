// The audit's outputs: a table for people, JSON for continuous integration
// (schema in the README: one object per file, an array under "files" with a
// summary when several files are given).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "exit_codes.hpp"
#include "reports/json_output.hpp"

namespace polymass_cli::audit {

void write_audit_table(std::ostream& out, const std::vector<FileAudit>& files);
void write_audit_json(std::ostream& out, const std::vector<FileAudit>& files);
// The document write_audit_json prints.
Json audit_json_document(const std::vector<FileAudit>& files);

// --html: the page drawing each robot in its zero pose: each link's measured
// geometry (settings.from, as the audit measured it) and its declared and
// computed inertials, beside the findings. kExitUnreadable when the page
// cannot be written.
ExitCode write_audit_html(const std::string& path, const std::vector<FileAudit>& files);

}  // namespace polymass_cli::audit
