// polymass: mass properties of mesh files from the command line.
// Parses the arguments and hands over to the command; every failure ends in a
// message on stderr and a distinct exit status (exit_codes.hpp).
#include <polymass/polymass.h>

#include <iostream>
#include <new>
#include <stdexcept>

#include "arguments.hpp"
#include "commands/commands.hpp"
#include "exit_codes.hpp"

int main(int argc, char** argv) {
    using namespace polymass_cli;
    try {
        const Arguments arguments = parse_arguments(argc, argv);
        switch (arguments.command) {
            case Command::kHelp:
                std::cout << help_text();
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
    } catch (const UsageError& error) {
        std::cerr << "polymass: " << error.what() << '\n';
        return kExitUsage;
    } catch (const std::invalid_argument& error) {
        // Options the library refused (polymass_context_set_options).
        std::cerr << "polymass: invalid option: " << error.what() << '\n';
        return kExitUsage;
    } catch (const std::bad_alloc&) {
        std::cerr << "polymass: out of memory\n";
        return kExitInternal;
    } catch (const std::exception& error) {
        std::cerr << "polymass: internal error: " << error.what() << '\n';
        return kExitInternal;
    }
    return kExitInternal;
}
