#include "reports/utf8.hpp"

#include "reports/json_output.hpp"

namespace polymass_cli {

std::string valid_utf8(const std::string& text) {
    // Dumped with replacement, the string is a valid JSON literal: parsing it
    // back gives its UTF-8 text.
    return Json::parse(Json(text).dump(-1, ' ', false, Json::error_handler_t::replace))
        .get<std::string>();
}

}  // namespace polymass_cli
