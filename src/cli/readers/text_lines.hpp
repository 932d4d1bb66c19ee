// Line-by-line, token-by-token reading of a text mesh file (OBJ, OFF, ASCII
// STL and PLY), with numbers parsed strictly: a token that is not entirely a
// number is an error naming the line, never a silent 0.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

namespace polymass_cli {

class TextLines {
public:
    explicit TextLines(std::string_view text, std::string_view::size_type start = 0)
        : text_(text), next_line_(start) {}

    // Moves to the next line (comments after '#' removed when strip_comments);
    // false at the end of the text.
    bool next_line(bool strip_comments);
    // The next whitespace-separated token of the current line; false if none.
    bool next_token(std::string_view& token);
    // Like next_token, but a missing token is an error saying what was expected.
    std::string_view expect_token(const char* what);
    double expect_double(const char* what);
    int64_t expect_integer(const char* what);
    uint64_t line_number() const { return line_number_; }
    // The bytes of the current line not yet read as tokens.
    std::string_view::size_type rest_of_line() const { return line_.size(); }
    // Where the next line starts (for a binary body after a text header).
    // At most the text's size: a last line without a newline ends there.
    std::string_view::size_type offset() const { return std::min(next_line_, text_.size()); }

    // Throws ReadError "line N: message".
    [[noreturn]] void fail(const std::string& message) const;

private:
    std::string_view text_;
    std::string_view line_;
    std::string_view::size_type next_line_;
    uint64_t line_number_ = 0;
};

// Strict parses of a whole token; false if it is not one. Doubles accept nan
// and inf (the library reports them as non-finite coordinates).
bool parse_double(std::string_view token, double& value);
bool parse_integer(std::string_view token, int64_t& value);

}  // namespace polymass_cli
