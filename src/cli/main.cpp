// polymass: mass properties of mesh files from the command line.
// Parses the arguments and hands over to the command; every failure ends in a
// message on stderr and a distinct exit status (exit_codes.hpp).
#include <iostream>
#include <new>
#include <stdexcept>

#include "arguments.hpp"
#include "commands/commands.hpp"
#include "exit_codes.hpp"
#include "out_of_memory.hpp"

int main(int argc, char** argv) {
    using namespace polymass_cli;
    end_out_of_memory_terminations_as_exit_4();
    try {
        return run_command(parse_arguments(argc, argv));
    } catch (const UsageError& error) {
        std::cerr << "polymass: " << error.what() << '\n';
        return kExitUsage;
    } catch (const std::invalid_argument& error) {
        // A setting the library refused (polymass_context_set_threads).
        std::cerr << "polymass: invalid option: " << error.what() << '\n';
        return kExitUsage;
    } catch (const std::bad_alloc&) {
        std::cerr << "polymass: out of memory\n";
        return kExitInternal;
    } catch (const std::exception& error) {
        std::cerr << "polymass: internal error: " << error.what() << '\n';
        return kExitInternal;
    }
}
