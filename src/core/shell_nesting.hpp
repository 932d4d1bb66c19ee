// How the shells of a surface nest, once none crosses another.
//
// When nothing crosses, the shells' surfaces are disjoint or touch, and each
// shell lies inside a whole number of the others. The winding number of the
// rest of the surface at a vertex of a shell says how many (counted with
// their orientation): it is counted exactly, as the signed crossings of a
// segment from that vertex to a point outside everything, with exact
// predicates, of the faces of the shells whose boxes hold the vertex (no
// other shell winds around it; none, and no segment is needed); a segment
// that grazes an edge or a vertex of those, or starts on another shell, is
// replaced by another. Where shells touch, a shell may pass
// through another along its own edges, so each triangle touching another
// shell is also probed from a point inside it (symbolically perturbed), and
// a shell whose probes disagree is marked mixed. docs/validity.md has the
// reasoning.
#pragma once

#include <atomic>
#include <climits>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "indexed_surface.hpp"
#include "shells.hpp"
#include "surface_contacts.hpp"
#include "task_runner.hpp"

namespace polymass::core {

// A winding number that could not be counted (every probe was degenerate).
inline constexpr int kUnknownWinding = INT_MIN;
// Windings that differ between pieces of one shell: the shell passes
// through another's surface (where the two touch) and bounds some region
// twice, or less than once.
inline constexpr int kMixedWinding = INT_MAX;

// For each shell, the winding number of every other shell at a point of it
// (kUnknownWinding where it could not be counted, kMixedWinding where it
// differs between points). The surface must be indexed with its shells
// (IndexedSurface::shells, which boxes them), at least two, none crossing
// another; contacts are find_contacts' (surface_contacts.hpp): which shapes
// touch another shell. The probes run as tasks of `tasks`; the result is the
// same for every runner.
template <class Scalar, class Index>
std::pmr::vector<int> count_windings(const IndexedSurface<Scalar, Index>& surface,
                                     const SurfaceContacts& contacts, TaskRunner& tasks,
                                     std::pmr::memory_resource* memory);

}  // namespace polymass::core
