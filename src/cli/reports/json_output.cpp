#include "reports/json_output.hpp"

#include <cmath>

#include "reports/report.hpp"

namespace polymass_cli {

Json json_number(double value) {
    if (!std::isfinite(value)) return nullptr;
    return value + 0.0;  // -0 + 0 is +0 in round-to-nearest
}

Json json_numbers(const double* values, size_t count) {
    Json array = Json::array();
    for (size_t i = 0; i < count; ++i) array.push_back(json_number(values[i]));
    return array;
}

Json json_tensor(const double* values) {
    const std::array<double, 9> symmetric = symmetric_tensor(values);
    Json rows = Json::array();
    for (int row = 0; row < 3; ++row) rows.push_back(json_numbers(symmetric.data() + 3 * row, 3));
    return rows;
}

void print_json(std::ostream& out, const Json& document) {
    out << document.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

}  // namespace polymass_cli
