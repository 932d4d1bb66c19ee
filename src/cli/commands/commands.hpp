// The things the tool does, each returning the exit status.
#pragma once

#include <polymass/polymass.h>

#include "arguments.hpp"
#include "exit_codes.hpp"
#include "library/solid.hpp"
#include "model/model.hpp"
#include "reports/report.hpp"

namespace polymass_cli {

// The command the command line names (help and version printed here), run;
// returns the exit status. Exceptions escape to main: std::bad_alloc when
// memory runs out.
ExitCode run_command(const Arguments& arguments);

// polymass FILE...: mass properties in the chosen output format.
ExitCode run_properties(const Arguments& arguments);

// polymass check FILE...: the diagnostics of each file.
ExitCode run_check(const Arguments& arguments);

// polymass assembly FILE: each placed part of an assembly file and the whole.
ExitCode run_assembly(const Arguments& arguments);

// Writes the reports in the output format the command line chose, with
// errors, warnings and notes on stderr; returns the highest exit status.
ExitCode write_reports(const std::vector<FileReport>& files, const Arguments& arguments);

// How the reports label their numbers: from the command line, and metres
// when every file's lengths are (FileReport::in_metres).
OutputSettings output_settings(const std::vector<FileReport>& files, const Arguments& arguments);

// polymass audit FILE...: robot descriptions' inertials against their
// geometry (exit 0, or 1 when a finding reaches --fail-on).
ExitCode run_audit(const Arguments& arguments);

// The library options the command line asks for.
polymass_options options_for(const Arguments& arguments);

// The library as the command line asks for it: its options, the threads it
// may use (--threads; every core by default) and the --about point.
Library library_for(const Arguments& arguments);

// What the command line asks done to a model once read: --units (unless the
// file declares its unit: a note says so) and --scale, --triangulate.
void prepare_model(Model& model, const Arguments& arguments);

}  // namespace polymass_cli
