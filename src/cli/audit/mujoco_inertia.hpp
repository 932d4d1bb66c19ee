// MuJoCo's rules for the inertial its compiler infers from a body's geoms
// (docs/audit.md, "MJCF: what MuJoCo computes"): which geoms it weighs, the
// mass of each, and what <compiler> then does to each body and to the whole.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "audit/description.hpp"

namespace polymass_cli::audit {

// Whether MuJoCo weighs the geom: its group within inertiagrouprange,
// whatever its contype and conaffinity.
bool weighed_by_mujoco(const Weighing& weighing, const MujocoCompiler& compiler);

// The geom's mass as MuJoCo gives it, amount being its volume (its area for
// a surface): its mass attribute, else density * amount; 0 when it weighs
// nothing (mass or density 0, or a mass on a geom of no volume), which
// MuJoCo then leaves out.
double mujoco_geom_mass(const Weighing& weighing, double amount);

// The inertial rebuilt around a new tensor (about the same centre of mass):
// principal moments and axes, and the tensor about the link origin.
void set_inertia(Computed& computed, const Eigen::Matrix3d& inertia);

// boundmass, boundinertia (on the principal moments), then balanceinertia,
// as MuJoCo applies them to each body; each that changes something is
// added to computed.rules.
void apply_body_rules(const MujocoCompiler& compiler, Computed& computed);

// How far MuJoCo's legacy figure is from the exact one (mass, principal
// moments, centre of mass): a finding when they differ beyond rounding, a
// warning from 5 %.
std::optional<Finding> judge_legacy(const Computed& exact, const Computed& legacy);

// Which inertial MuJoCo uses for the link ("declared", "computed", or
// "none": no inertial and inertiafromgeom false, or nothing weighed).
const char* mujoco_uses(const MujocoCompiler& compiler, const LinkAudit& link);

// The file-wide rules: settotalmass (every body's mass and inertia scaled
// so that the masses MuJoCo uses add up to it), and moving bodies whose
// mass MuJoCo finds zero (it refuses the model).
void apply_model_rules(const Description& description, FileAudit& audit);

}  // namespace polymass_cli::audit
