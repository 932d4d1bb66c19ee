// A part's rotation as an assembly file gives it: a 3x3 matrix, or a unit
// quaternion in an order the file names. What is accepted, and why, is in
// the README (the assembly file's schema).
#pragma once

#include <array>
#include <string>

namespace polymass_cli {

// The rotation matrix (row-major) of the quaternion q = w + x i + y j + z k
// (Hamilton's convention, turning points: p' = q p q*). q must be within
// 1e-6 of unit length and is normalised; otherwise `error` says why and the
// result is the identity.
std::array<double, 9> quaternion_matrix(double w, double x, double y, double z, std::string& error);

// Empty when matrix is orthonormal to 1e-12 (what the library accepts) and a
// proper rotation, or a mirror (determinant -1) when mirror is true; else why
// not.
std::string rotation_problem(const std::array<double, 9>& matrix, bool mirror);

}  // namespace polymass_cli
