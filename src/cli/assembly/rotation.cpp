#include "assembly/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace polymass_cli {
namespace {

// How far a quaternion's length may be from 1: decimals written to seven
// digits (0.7071068) are accepted, a quaternion meant otherwise is not.
constexpr double kQuaternionTolerance = 1e-6;
// What polymass_moments_transform accepts: R R^T within 1e-12 of the identity.
constexpr double kOrthonormalTolerance = 1e-12;

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

}  // namespace

std::array<double, 9> quaternion_matrix(double w, double x, double y, double z,
                                        std::string& error) {
    const double norm = std::sqrt(w * w + x * x + y * y + z * z);
    if (!(std::abs(norm - 1.0) <= kQuaternionTolerance)) {
        error = "not a unit quaternion: its length is " + number(norm) +
                " (a rotation's is 1, to within 1e-6)";
        return {1, 0, 0, 0, 1, 0, 0, 0, 1};
    }
    w /= norm, x /= norm, y /= norm, z /= norm;
    return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
            2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

std::string rotation_problem(const std::array<double, 9>& m, bool mirror) {
    double off = 0.0;  // the largest element of R R^T - I
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double dot = 0.0;
            for (int k = 0; k < 3; ++k) dot += m[3 * i + k] * m[3 * j + k];
            off = std::max(off, std::abs(dot - (i == j ? 1.0 : 0.0)));
        }
    }
    if (!(off <= kOrthonormalTolerance)) {
        return "not orthonormal: R R^T differs from the identity by " + number(off) +
               " (at most 1e-12): write its elements to 16 digits, or give a quaternion";
    }
    const double determinant = m[0] * (m[4] * m[8] - m[5] * m[7]) -
                               m[1] * (m[3] * m[8] - m[5] * m[6]) +
                               m[2] * (m[3] * m[7] - m[4] * m[6]);
    if (determinant < 0 && !mirror) {
        return "a mirror (determinant -1), not a rotation: add \"mirror\": true to the part "
               "if it is mirrored on purpose";
    }
    if (determinant > 0 && mirror) {
        return "a rotation (determinant +1), but the part says \"mirror\": true";
    }
    return {};
}

}  // namespace polymass_cli
