// A small streaming JSON writer: two-space indentation, numbers with every
// digit, arrays of numbers kept on one line.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace polymass_cli {

class JsonWriter {
public:
    explicit JsonWriter(std::ostream& out) : out_(out) {}

    void begin_object();
    void end_object();
    void begin_array();
    void end_array();
    // The key of the next value in the current object.
    JsonWriter& key(const std::string& name);
    void value(double number);
    void value(uint64_t number);
    void value(const std::string& text);
    // true or false (not an overload of value: a string literal would pick it).
    void boolean(bool truth);
    void numbers(const double* values, size_t count);  // [a, b, c] on one line
    void matrix(const double values[9]);               // [[...], [...], [...]]

private:
    void before_value();
    void newline();
    std::ostream& out_;
    std::vector<bool> first_in_level_;  // per open object/array: nothing written yet
    bool after_key_ = false;
};

// text as a JSON string literal, quotes included. Bytes that are not valid
// UTF-8 become U+FFFD, so the output is valid JSON whatever the input.
std::string json_escape(const std::string& text);

}  // namespace polymass_cli
