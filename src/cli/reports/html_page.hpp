// --html: one self-contained page (reports/html/page.html) that draws what a
// command found. The page's data is one JSON object; large arrays (vertex
// positions, triangles) travel beside it as little-endian binary, base64 in
// the page, which the page's script reads by id.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "reports/json_output.hpp"

namespace polymass_cli {

class HtmlPage {
public:
    // kind: which view the page shows: "check", "properties" or "audit".
    explicit HtmlPage(const std::string& kind);

    // The page's data: "kind", "generator", then what the command adds.
    Json& data() { return data_; }

    // An array the data names by the returned id.
    std::string add_floats(const std::vector<float>& values);
    std::string add_uint32s(const std::vector<uint32_t>& values);

    // Writes the page: kExitOk, or kExitUnreadable (said on stderr) when
    // the file cannot be written.
    ExitCode write(const std::string& path) const;

private:
    std::string add_blob(std::string bytes);

    Json data_ = Json::object();
    std::vector<std::string> blobs_;  // base64
};

}  // namespace polymass_cli
