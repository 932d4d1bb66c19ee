// Mirror pairs: links whose names mark them left and right (left_/right_,
// l_/r_, _L/_R, FL/FR, LF/RF, ...) and whose geometries are mirror images
// (a reflection across a link-frame plane maps one computed inertial onto
// the other) should declare mirrored inertials. A declared product of
// inertia whose sign breaks that mirror passes every test of the tensor
// alone; this finds it.
#pragma once

#include <optional>
#include <string>

#include "audit/audit.hpp"

namespace polymass_cli::audit {

// The name with its side taken out ("left_hip" -> "{side}_hip"), and the
// side ('L' or 'R'); nothing when the name marks no side, or more than one.
struct Sided {
    std::string key;
    char side = 0;
};
std::optional<Sided> sided_name(const std::string& name);

// Adds a mirror_sign finding to a link of each mirror pair whose declared
// products of inertia break the mirror of their geometry.
void judge_mirror_pairs(FileAudit& audit);

}  // namespace polymass_cli::audit
