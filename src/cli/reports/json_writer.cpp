#include "reports/json_writer.hpp"

#include <cstddef>
#include <cstdio>

#include "reports/number_format.hpp"
#include "reports/utf8.hpp"

namespace polymass_cli {

std::string json_escape(const std::string& raw) {
    // JSON text is UTF-8: a name or path in another encoding (a Latin-1 OBJ
    // object name) keeps its valid sequences, the other bytes become U+FFFD.
    const std::string text = valid_utf8(raw);
    std::string escaped = "\"";
    for (const char c : text) {
        switch (c) {
            case '"':
                escaped += "\\\"";
                break;
            case '\\':
                escaped += "\\\\";
                break;
            case '\n':
                escaped += "\\n";
                break;
            case '\t':
                escaped += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char code[8];
                    std::snprintf(code, sizeof code, "\\u%04x", static_cast<unsigned>(c));
                    escaped += code;
                } else {
                    escaped += c;
                }
        }
    }
    return escaped + "\"";
}

void JsonWriter::newline() { out_ << '\n' << std::string(2 * first_in_level_.size(), ' '); }

void JsonWriter::before_value() {
    if (after_key_) {
        after_key_ = false;
        return;
    }
    if (first_in_level_.empty()) return;
    if (!first_in_level_.back()) out_ << ',';
    first_in_level_.back() = false;
    newline();
}

void JsonWriter::begin_object() {
    before_value();
    out_ << '{';
    first_in_level_.push_back(true);
}

void JsonWriter::end_object() {
    const bool empty = first_in_level_.back();
    first_in_level_.pop_back();
    if (!empty) newline();
    out_ << '}';
    if (first_in_level_.empty()) out_ << '\n';
}

void JsonWriter::begin_array() {
    before_value();
    out_ << '[';
    first_in_level_.push_back(true);
}

void JsonWriter::end_array() {
    const bool empty = first_in_level_.back();
    first_in_level_.pop_back();
    if (!empty) newline();
    out_ << ']';
    if (first_in_level_.empty()) out_ << '\n';
}

JsonWriter& JsonWriter::key(const std::string& name) {
    before_value();
    out_ << json_escape(name) << ": ";
    after_key_ = true;
    return *this;
}

void JsonWriter::value(double number) {
    before_value();
    out_ << exact_number(number);
}

void JsonWriter::value(uint64_t number) {
    before_value();
    out_ << number;
}

void JsonWriter::boolean(bool truth) {
    before_value();
    out_ << (truth ? "true" : "false");
}

void JsonWriter::value(const std::string& text) {
    before_value();
    out_ << json_escape(text);
}

void JsonWriter::numbers(const double* values, size_t count) {
    before_value();
    out_ << '[';
    for (size_t i = 0; i < count; ++i) out_ << (i ? ", " : "") << exact_number(values[i]);
    out_ << ']';
}

void JsonWriter::matrix(const double values[9]) {
    before_value();
    out_ << '[';
    for (int row = 0; row < 3; ++row) {
        out_ << (row ? ", [" : "[");
        for (int column = 0; column < 3; ++column) {
            out_ << (column ? ", " : "") << exact_number(values[3 * row + column]);
        }
        out_ << ']';
    }
    out_ << ']';
}

}  // namespace polymass_cli
