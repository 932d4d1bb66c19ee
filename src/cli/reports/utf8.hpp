// Text for outputs that must be UTF-8 (XML): names and paths from a file or a
// command line may be in any encoding.
#pragma once

#include <string>

namespace polymass_cli {

// text with its well-formed UTF-8 kept and each maximal ill-formed
// subsequence replaced by U+FFFD, as the JSON output writes it (pugixml
// writes the bytes it is given, nlohmann-json replaces: this borrows the
// latter, so both outputs agree).
std::string valid_utf8(const std::string& text);

}  // namespace polymass_cli
