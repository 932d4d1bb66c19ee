// Library statuses as the names the tool prints (JSON "category") and as exit
// statuses.
#pragma once

#include <cstdint>

#include "exit_codes.hpp"

namespace polymass_cli {

// The category of a failure to read a file.
inline constexpr const char* kUnreadableCategory = "unreadable";

// "open", "non_manifold", "inverted", ... for a library status.
const char* category_of(int32_t status);

ExitCode exit_code_of(int32_t status);

}  // namespace polymass_cli
