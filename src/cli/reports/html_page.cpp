#include "reports/html_page.hpp"

#include <polymass/polymass.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>

#include "reports/html_assets.hpp"

namespace polymass_cli {
namespace {

void append_little_endian(std::string& bytes, uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(char((value >> shift) & 0xffu));
}

// RFC 4648 base64 with padding: what the page's atob-free decoder reads.
std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t group = 0;
        for (size_t k = 0; k < 3; ++k) group = group << 8 | (k < n ? uint8_t(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k)
            text.push_back(k <= n ? kDigits[(group >> (18 - 6 * k)) & 63u] : '=');
    }
    return text;
}

// JSON inside <script>: every '<' (only ever inside a string) is written
// \u003c, the same string to a JSON reader, so that no name or path can end
// the element or open a comment in it.
std::string script_safe(const std::string& json) {
    std::string safe;
    safe.reserve(json.size());
    for (const char c : json) {
        if (c == '<') {
            safe += "\\u003c";
        } else {
            safe.push_back(c);
        }
    }
    return safe;
}

}  // namespace

HtmlPage::HtmlPage(const std::string& kind) {
    data_["kind"] = kind;
    data_["generator"] = std::string("polymass ") + polymass_version_string();
}

std::string HtmlPage::add_floats(const std::vector<float>& values) {
    std::string bytes;
    bytes.reserve(4 * values.size());
    for (const float value : values) {
        uint32_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        append_little_endian(bytes, bits);
    }
    return add_blob(std::move(bytes));
}

std::string HtmlPage::add_uint32s(const std::vector<uint32_t>& values) {
    std::string bytes;
    bytes.reserve(4 * values.size());
    for (const uint32_t value : values) append_little_endian(bytes, value);
    return add_blob(std::move(bytes));
}

std::string HtmlPage::add_blob(std::string bytes) {
    blobs_.push_back(base64(bytes));
    return "polymass-blob-" + std::to_string(blobs_.size() - 1);
}

ExitCode HtmlPage::write(const std::string& path) const {
    std::ofstream out(path, std::ios::binary);
    out << html_page_head();
    out << "<script id=\"polymass-data\" type=\"application/json\">"
        << script_safe(data_.dump(-1, ' ', false, Json::error_handler_t::replace)) << "</script>\n";
    for (size_t i = 0; i < blobs_.size(); ++i) {
        out << "<script id=\"polymass-blob-" << i << "\" type=\"application/octet-stream\">"
            << blobs_[i] << "</script>\n";
    }
    out << html_page_tail();
    out.close();
    if (out) return kExitOk;
    std::cerr << "polymass: cannot write " << path << '\n';
    return kExitUnreadable;
}

}  // namespace polymass_cli
