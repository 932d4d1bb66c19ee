// Text for outputs that must be UTF-8 (JSON, XML): names and paths from a
// file or a command line may be in any encoding.
#pragma once

#include <string>

namespace polymass_cli {

// text with its well-formed UTF-8 sequences kept and every other byte
// replaced by U+FFFD, the replacement character.
std::string valid_utf8(const std::string& text);

}  // namespace polymass_cli
