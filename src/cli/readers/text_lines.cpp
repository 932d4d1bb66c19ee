#include "readers/text_lines.hpp"

#include <charconv>
#include <cstdlib>
#include <string>

#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string printable(std::string_view token) {
    constexpr std::string_view::size_type kLongest = 40;
    std::string shown(token.substr(0, kLongest));
    for (char& c : shown) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    }
    return token.size() > kLongest ? shown + "..." : shown;
}

}  // namespace

bool parse_double(std::string_view token, double& value) {
    // from_chars takes no leading '+', which text formats allow.
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const std::from_chars_result result = std::from_chars(token.data(), end, value);
    if (result.ec == std::errc::result_out_of_range && result.ptr == end) {
        // from_chars says out of range for a magnitude too small for a double
        // as well as too large. strtod decides both as the C standard does:
        // the correctly rounded subnormal or zero, or +-HUGE_VAL (infinity),
        // which the library reports as a non-finite coordinate. The tool
        // never sets a locale, so strtod reads the same syntax as from_chars.
        const std::string terminated(token);
        char* parsed_end = nullptr;
        value = std::strtod(terminated.c_str(), &parsed_end);
        return parsed_end == terminated.c_str() + terminated.size();
    }
    return result.ec == std::errc() && result.ptr == end && !token.empty();
}

bool parse_integer(std::string_view token, int64_t& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const std::from_chars_result result = std::from_chars(token.data(), end, value);
    return result.ec == std::errc() && result.ptr == end && !token.empty();
}

bool TextLines::next_line(bool strip_comments) {
    if (next_line_ >= text_.size()) return false;
    std::string_view::size_type end = text_.find('\n', next_line_);
    if (end == std::string_view::npos) end = text_.size();
    line_ = text_.substr(next_line_, end - next_line_);
    next_line_ = end + 1;
    ++line_number_;
    if (strip_comments) {
        const std::string_view::size_type hash = line_.find('#');
        if (hash != std::string_view::npos) line_ = line_.substr(0, hash);
    }
    return true;
}

bool TextLines::next_token(std::string_view& token) {
    std::string_view::size_type begin = 0;
    while (begin < line_.size() && is_space(line_[begin])) ++begin;
    std::string_view::size_type end = begin;
    while (end < line_.size() && !is_space(line_[end])) ++end;
    token = line_.substr(begin, end - begin);
    line_.remove_prefix(end);
    return !token.empty();
}

std::string_view TextLines::expect_token(const char* what) {
    std::string_view token;
    if (!next_token(token)) fail(std::string("expected ") + what + ", found the end of the line");
    return token;
}

double TextLines::expect_double(const char* what) {
    const std::string_view token = expect_token(what);
    double value = 0.0;
    if (!parse_double(token, value)) {
        fail(std::string("expected ") + what + ", found '" + printable(token) + "'");
    }
    return value;
}

int64_t TextLines::expect_integer(const char* what) {
    const std::string_view token = expect_token(what);
    int64_t value = 0;
    if (!parse_integer(token, value)) {
        fail(std::string("expected ") + what + ", found '" + printable(token) + "'");
    }
    return value;
}

void TextLines::fail(const std::string& message) const {
    throw ReadError("line " + std::to_string(line_number_) + ": " + message);
}

}  // namespace polymass_cli
