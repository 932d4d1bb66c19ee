#include "json_writer.hpp"

#include <cstddef>
#include <cstdio>

#include "number_format.hpp"

namespace polymass_cli {

namespace {

// The length of the well-formed UTF-8 sequence text[at...] starts (Unicode,
// table 3-7: no overlong forms, no surrogates, nothing above U+10FFFF), or 0.
size_t utf8_sequence_length(const std::string& text, size_t at) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    size_t length = 0;
    unsigned char low = 0x80;  // the range of the second byte
    unsigned char high = 0xbf;
    if (lead >= 0xc2 && lead <= 0xdf) {
        length = 2;
    } else if (lead >= 0xe0 && lead <= 0xef) {
        length = 3;
        if (lead == 0xe0) low = 0xa0;   // overlong below U+0800
        if (lead == 0xed) high = 0x9f;  // surrogates U+D800..U+DFFF
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        length = 4;
        if (lead == 0xf0) low = 0x90;   // overlong below U+10000
        if (lead == 0xf4) high = 0x8f;  // above U+10FFFF
    } else {
        return 0;
    }
    if (text.size() - at < length) return 0;
    if (byte(at + 1) < low || byte(at + 1) > high) return 0;
    for (size_t i = 2; i < length; ++i) {
        if (byte(at + i) < 0x80 || byte(at + i) > 0xbf) return 0;
    }
    return length;
}

}  // namespace

std::string json_escape(const std::string& text) {
    // JSON text is UTF-8: a name or path in another encoding (a Latin-1 OBJ
    // object name) keeps its valid sequences, and each byte that is not part
    // of one becomes U+FFFD, the replacement character.
    static constexpr const char* kReplacement = "\xEF\xBF\xBD";
    std::string escaped = "\"";
    for (size_t at = 0; at < text.size();) {
        const char c = text[at];
        if (static_cast<unsigned char>(c) >= 0x80) {
            const size_t length = utf8_sequence_length(text, at);
            if (length == 0) {
                escaped += kReplacement;
                ++at;
            } else {
                escaped.append(text, at, length);
                at += length;
            }
            continue;
        }
        ++at;
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
