// How far an approximate answer (a thin sheet standing for a wall, a convex
// hull standing for a solid) can be from the body it stands for.
#pragma once

namespace polymass::core {

// Absolute bounds in the caller's units, for unit density (a density ρ
// multiplies the volume's mass counterpart and the inertia bound by ρ; the
// centre of mass is unchanged). Infinite when nothing useful can be said.
struct ApproximationBound {
    double volume = 0.0;
    double center_of_mass = 0.0;  // of each coordinate
    double inertia = 0.0;         // of each entry of the tensor about the centre of mass
};

// The bound for an answer computed from a body of volume `answer_volume`
// when the true body differs from it by a region of total volume at most
// `changed_volume` (added, removed, or counted twice), everything lying within
// `span` of everything else (a diameter). docs/approximations.md derives it.
ApproximationBound bound_of_changed_volume(double changed_volume, double answer_volume,
                                           double span);

}  // namespace polymass::core
