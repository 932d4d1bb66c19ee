#include "reports/number_format.hpp"

#include <charconv>
#include <cstdio>

namespace polymass_cli {

std::string exact_number(double value) {
    char text[32];
    // -0 + 0 is +0: a zero is printed without a sign.
    const std::to_chars_result result = std::to_chars(text, text + sizeof text, value + 0.0);
    return std::string(text, result.ptr);
}

std::string float_number(float value) {
    char text[32];
    const std::to_chars_result result = std::to_chars(text, text + sizeof text, value + 0.0f);
    return std::string(text, result.ptr);
}

std::string readable_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value + 0.0);  // -0 printed as 0
    return text;
}

}  // namespace polymass_cli
