#include "out_of_memory.hpp"

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <new>

#include "exit_codes.hpp"

namespace polymass_cli {
namespace {

std::terminate_handler default_handler = nullptr;

[[noreturn]] void on_terminate() {
    // The exception that called std::terminate is the handled one here.
    if (const std::exception_ptr in_flight = std::current_exception()) {
        try {
            std::rethrow_exception(in_flight);
        } catch (const std::bad_alloc&) {
            // Written without allocating, and without the output's buffers.
            static const char message[] = "polymass: out of memory\n";
            const ssize_t written = write(STDERR_FILENO, message, sizeof message - 1);
            (void)written;
            _exit(kExitInternal);
        } catch (...) {
        }
    }
    if (default_handler != nullptr) default_handler();
    std::abort();
}

}  // namespace

void throw_if_out_of_memory(const std::error_code& error) {
    if (error == std::errc::not_enough_memory) throw std::bad_alloc();
}

void end_out_of_memory_terminations_as_exit_4() {
    const std::terminate_handler previous = std::set_terminate(on_terminate);
    if (previous != on_terminate) default_handler = previous;
}

}  // namespace polymass_cli
