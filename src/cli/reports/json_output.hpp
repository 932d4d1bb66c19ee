// JSON through nlohmann-json: the documents are built as values and printed
// once, with every double in the fewest digits that parse back to the same
// bits, and any byte of a name or path that is not UTF-8 replaced.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <ostream>

namespace polymass_cli {

// Objects keep their keys in the order they are set: the README's order.
// Objects are made with Json::object(), never by indexing a null value:
// nlohmann-json 3.11.2's operator[] marks a null value an object before it
// allocates the object, and when that allocation fails, the value's
// destructor follows a null pointer (found by tests/cli/out_of_memory.cpp).
using Json = nlohmann::ordered_json;

// A number as the outputs write it: -0 is 0 (a zero has no sign worth
// printing), NaN and infinities become null (JSON has no word for them).
Json json_number(double value);
Json json_numbers(const double* values, size_t count);  // [a, b, c]
// A symmetric tensor (row-major 3x3) from its upper triangle, so that [i][j]
// and [j][i] are the same double.
Json json_tensor(const double* values);

// The document, two-space indented, then a newline. Strings are written as
// UTF-8 with each maximal ill-formed subsequence replaced by U+FFFD (Unicode
// 15, section 3.9, "U+FFFD Substitution of Maximal Subparts").
void print_json(std::ostream& out, const Json& document);

}  // namespace polymass_cli
