// Numbers as the tool prints them: every digit in machine-read output (JSON,
// XML), so a parser gets back the very double; fewer in the table for people.
#pragma once

#include <string>

namespace polymass_cli {

// The shortest decimal that reads back as exactly this double (0 for -0).
std::string exact_number(double value);

// The shortest decimal that reads back as exactly this float (0 for -0):
// what --usda writes for its 32-bit attributes.
std::string float_number(float value);

// Ten significant digits.
std::string readable_number(double value);

}  // namespace polymass_cli
