// The rules that turn declared and computed inertials into findings, each in
// one function; the thresholds are the README's.
#pragma once

#include <string>
#include <vector>

#include "audit/audit.hpp"

namespace polymass_cli::audit {

// A fraction as a percentage in three significant digits (whole numbers from
// 100 %): enough to read a difference by.
std::string percent(double fraction);

// Findings about the declared inertial alone: a mass that is not positive, a
// tensor that is not positive definite or breaks a triangle inequality; or
// that it is all zero (a static link), which is said and not judged further.
std::vector<Finding> judge_declared(const Inertial& declared);

// Findings from comparing the declared inertial with the computed one (at
// the declared mass): implied density (a mesh's units suspected only when
// the geometry has a mesh), principal moments and axes, centre of mass.
std::vector<Finding> judge_against_geometry(const Inertial& declared, const Computed& computed,
                                            bool has_mesh);

}  // namespace polymass_cli::audit
