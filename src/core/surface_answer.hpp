// The one analysis of a surface and the answer of its chain of modes
// (docs/repair.md): every validity rule and every approximation bound the
// C API reports is decided here, for the mesh handle (the findings in full)
// and the one-call path (stopping at the first problem) alike.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <memory_resource>
#include <optional>

#include "approximation_bound.hpp"
#include "convex_hull.hpp"
#include "mesh_analysis.hpp"
#include "mesh_repair.hpp"
#include "mesh_view.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {

// How a surface is turned into a body; the values are the C API's
// POLYMASS_MODE_*.
enum class Mode { solid = 1, repair = 2, shell = 3, hull = 4 };

inline constexpr std::size_t kMaxModes = 4;

// What the body answered has: the exact solid's flags mark nothing else.
enum BodyWarning : std::uint32_t {
    kWarningRepaired = 1u << 5,  // a repaired surface
    kWarningShell = 1u << 6,     // a thin wall
    kWarningHull = 1u << 7,      // the convex hull
};

struct AnswerSettings {
    // The checks of the surface as a solid (check_intersections only with
    // check_topology); stop_at_first_problem false and list_shells true for
    // the findings in full.
    AnalysisSettings analysis;
    std::array<Mode, kMaxModes> modes{};
    std::size_t mode_count = 0;  // 0: the solid alone
    double shell_thickness = 0;  // > 0 when the chain holds shell
};

// The body a mode gave: its integrals and what is known of them.
struct Body {
    VolumeIntegrals integrals;  // about `reference`, outward-oriented
    IntegralBounds bounds;      // on their rounding errors
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    double surface_area = 0.0;
    std::uint32_t warnings = 0;  // Warning and BodyWarning bits
    // How far the body can be from the caller's solid when a mode other than
    // solid answered (zero otherwise), at unit density.
    ApproximationBound approximation;
};

// Why a mode gave no answer.
enum class Refusal {
    defect,                   // a verdict's defect (the surface's, or the repaired one's)
    nothing_left,             // repair dropped every face
    unbalanced_non_manifold,  // repair cannot split an edge into pairs
    non_orientable,           // repair cannot orient a shell
    no_area,                  // shell: the surface has no area to make a wall of
    hull_too_few_points,      // hull: fewer than 4 distinct used vertices
    hull_collinear,
    hull_coplanar,
    hull_beyond_exact_range,  // hull: the orientation tests beyond their exact range
};

struct ModeFailure {
    Mode mode = Mode::solid;
    Refusal refusal = Refusal::defect;
    // Refusal::defect: the defect, of the surface (SurfaceAnswer::surface
    // holds its findings) or, when of_own_surface, of the surface the mode
    // made (SurfaceAnswer::own_surface: the repaired one, or the hull, of
    // own_triangles triangles).
    Defect defect = Defect::none;
    bool of_own_surface = false;
    std::size_t own_triangles = 0;
    double area = 0.0;  // Refusal::no_area
};

struct SurfaceAnswer {
    // The surface judged as a solid: in full, or as far as the first problem,
    // or (when no mode of the chain can take a valid solid as its answer and
    // the findings are not wanted) its scan alone.
    MeshAnalysis surface;
    // The analysis of a surface a mode made (repaired, or a hull) whose
    // verdict refused it.
    std::optional<MeshAnalysis> own_surface;

    std::optional<Mode> answered;                                // the mode that answered, if any
    Body body;                                                   // when one did
    RepairReport repairs;                                        // Mode::repair: what was fixed
    double shell_area = 0.0;                                     // Mode::shell
    std::size_t hull_vertex_count = 0, hull_triangle_count = 0;  // Mode::hull
    double hull_volume = 0.0;

    // The modes that failed, in the order tried: the solid's verdict once
    // (however often the chain asks for it), then each other mode's.
    std::array<ModeFailure, kMaxModes + 1> failures{};
    std::size_t failure_count = 0;

    explicit SurfaceAnswer(MeshAnalysis analysed) : surface(std::move(analysed)) {}
};

template <class Scalar, class Index>
SurfaceAnswer answer_surface(const MeshView<Scalar, Index>& mesh, const AnswerSettings& settings,
                             std::pmr::memory_resource* memory);

}  // namespace polymass::core
