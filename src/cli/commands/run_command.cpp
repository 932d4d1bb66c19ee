// The command a parsed command line names, run: the one dispatch, shared by
// main and by the out-of-memory test (tests/cli/out_of_memory.cpp), so that
// the test drives every command exactly as the tool does.
#include <polymass/polymass.h>

#include <iostream>

#include "commands/commands.hpp"

namespace polymass_cli {

ExitCode run_command(const Arguments& arguments) {
    switch (arguments.command) {
        case Command::kHelp:
            std::cout << arguments.help;
            return kExitOk;
        case Command::kVersion:
            std::cout << "polymass " << polymass_version_string() << '\n';
            return kExitOk;
        case Command::kCheck:
            return run_check(arguments);
        case Command::kProperties:
            return run_properties(arguments);
        case Command::kAssembly:
            return run_assembly(arguments);
        case Command::kAudit:
            return run_audit(arguments);
    }
    return kExitInternal;
}

}  // namespace polymass_cli
