// The audit's outputs: a table for people, JSON for continuous integration
// (schema in the README: one object per file, an array under "files" with a
// summary when several files are given).
#pragma once

#include <ostream>
#include <vector>

#include "audit/audit.hpp"

namespace polymass_cli::audit {

void write_audit_table(std::ostream& out, const std::vector<FileAudit>& files);
void write_audit_json(std::ostream& out, const std::vector<FileAudit>& files);

}  // namespace polymass_cli::audit
