// What each shell of a closed surface is: a solid, a cavity in a solid, a
// shell turned inside out, or one whose region another shell covers too.
//
// The rule (docs/validity.md): a valid solid's surface bounds every point of
// space zero times or once. Seen from one shell, the rest of the surface must
// wind around it zero times when it encloses positive volume (a solid, or a
// part in a hollow) and once when negative (a cavity inside a solid). A
// negative shell that nothing winds around is inside out: it would subtract
// its volume from a solid it is not in. A shell wound around once already,
// positive, is inside another solid: its volume would count twice.
//
// Without the intersection check the winding is not counted; the rule is
// then applied with bounding boxes, which can prove a shell inside out (it is
// in no solid shell's box) but not that a cavity lies inside its solid.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "findings.hpp"
#include "mesh_scan.hpp"
#include "mesh_view.hpp"
#include "shells.hpp"

namespace polymass::core {

enum class ShellKind { solid, cavity, inverted, overlapping, no_volume };

struct ShellSummary {
    std::size_t face_count = 0;
    std::size_t first_face = 0;
    double signed_volume = 0;  // taken so that the whole surface's volume is positive
    double surface_area = 0;
    Eigen::AlignedBox3d bounds;
    ShellKind kind = ShellKind::solid;
};

struct ShellSurvey {
    Shells shells;
    std::pmr::vector<ShellSummary> summary;  // one per shell
    Finding inverted;                        // shells inside out, outside every solid
    Finding overlapping;                     // shells whose region is bounded twice
    bool nesting_counted = false;            // decided by winding numbers, not boxes

    explicit ShellSurvey(Shells found, std::pmr::memory_resource* memory)
        : shells(std::move(found)), summary(memory) {}
};

// Splits a closed, consistently oriented surface into shells, integrates each
// one's volume about `reference`, and classifies them by bounding boxes.
// outward is +1, or -1 for a surface taken inside out as a whole;
// whole_volume is the surface's signed volume and whole_encloses_no_volume
// its verdict (the one shell's, when it is in one piece: the common case
// costs no second pass over the faces). identities and vertex_sets as
// find_shells'.
template <class Scalar, class Index>
ShellSurvey survey_shells(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                          const VertexIdentities& identities,
                          std::pmr::vector<std::uint32_t> vertex_sets,
                          const Eigen::Vector3d& reference, int outward, double whole_volume,
                          bool whole_encloses_no_volume, TaskRunner& tasks,
                          std::pmr::memory_resource* memory);

// Classifies again by the winding numbers of find_overlaps (those it could
// count; the others keep their boxes' answer).
void classify_by_winding(ShellSurvey& survey, const std::pmr::vector<int>& winding_of_shell,
                         int outward);

}  // namespace polymass::core
