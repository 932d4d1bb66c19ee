#include "readers/transform.hpp"

namespace polymass_cli {

Transform compose(const Transform& a, const Transform& b) {
    Transform result{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 4; ++column) {
            double sum = column == 3 ? a[4 * row + 3] : 0.0;
            for (int k = 0; k < 3; ++k) sum += a[4 * row + k] * b[4 * k + column];
            result[4 * row + column] = sum;
        }
    }
    return result;
}

double determinant(const Transform& t) {
    return t[0] * (t[5] * t[10] - t[6] * t[9]) - t[1] * (t[4] * t[10] - t[6] * t[8]) +
           t[2] * (t[4] * t[9] - t[5] * t[8]);
}

void append_transformed(std::vector<double>& positions, const Transform& t, double x, double y,
                        double z) {
    for (int row = 0; row < 3; ++row) {
        positions.push_back(t[4 * row] * x + t[4 * row + 1] * y + t[4 * row + 2] * z +
                            t[4 * row + 3]);
    }
}

}  // namespace polymass_cli
