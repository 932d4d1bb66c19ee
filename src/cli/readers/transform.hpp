// The placement of a mesh instance in a scene file (glTF nodes, 3MF build
// items and components): a 3x4 affine matrix in double precision, composed
// from the root down and applied to each vertex as it is read.
#pragma once

#include <array>
#include <vector>

namespace polymass_cli {

// Rows of a 3x4 affine matrix: [R | t].
using Transform = std::array<double, 12>;
inline constexpr Transform kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// a * b: b applied first.
Transform compose(const Transform& a, const Transform& b);

// The determinant of the linear part: negative for a mirroring transform,
// which turns a solid's faces inside out.
double determinant(const Transform& t);

// Appends t * (x, y, z) to positions.
void append_transformed(std::vector<double>& positions, const Transform& t, double x, double y,
                        double z);

}  // namespace polymass_cli
