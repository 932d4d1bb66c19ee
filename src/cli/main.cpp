// polymass: mass properties of mesh files from the command line.
// Parses the arguments and hands over to the command; every failure ends in a
// message on stderr and a distinct exit status (exit_codes.hpp).
#include <iostream>
#include <new>
#include <stdexcept>
#ifdef __GLIBC__  // defined by the headers above
#include <malloc.h>
#endif

#include "arguments.hpp"
#include "commands/commands.hpp"
#include "exit_codes.hpp"
#include "out_of_memory.hpp"

int main(int argc, char** argv) {
    using namespace polymass_cli;
    end_out_of_memory_terminations_as_exit_4();
#ifdef __GLIBC__
    // Every buffer of 128 KiB or more in a mapping of its own, given back to
    // the system when freed. glibc's default raises that threshold to the
    // size of each large block freed (up to 32 MiB), so that the reader's and
    // the checks' later buffers come from the heap, where freed memory stays
    // resident: 14 MiB of a million-triangle STL's peak (113 MiB -> 97 MiB,
    // the file being 48 MiB), for a few page faults more.
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
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
