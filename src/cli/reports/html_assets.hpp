// The --html report page's template, built into the tool
// (reports/html/embed_page.cmake): its markup, style, script and three.js
// before the report's data, and what follows the data.
#pragma once

#include <string_view>

namespace polymass_cli {

std::string_view html_page_head();
std::string_view html_page_tail();

}  // namespace polymass_cli
