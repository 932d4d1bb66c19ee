// What the tool does when memory runs out where std::bad_alloc would not
// reach main by itself: in a function that may not throw, in a function that
// reports it as an error code.
#pragma once

#include <system_error>

namespace polymass_cli {

// A std::bad_alloc escaping a function declared noexcept calls
// std::terminate, by default an abort - a crash. The libraries do it:
// nlohmann-json's destructors allocate (to take nested values apart without
// recursion), and an ordered object copies its members as it grows; CLI11
// copies strings inside noexcept functions. Installed, the handler ends the
// tool as memory running out anywhere else does: "polymass: out of memory"
// on stderr, exit 4. It does not unwind (a noexcept frame cannot be) and
// does not flush the output, which would be cut short. Any other exception,
// or none, keeps the default ending.
void end_out_of_memory_terminations_as_exit_4();

// Throws std::bad_alloc when error says memory ran out (errc::not_enough_memory,
// as std::filesystem's error-code functions report it): it would otherwise
// pass for a file that does not exist, a package not found.
void throw_if_out_of_memory(const std::error_code& error);

}  // namespace polymass_cli
