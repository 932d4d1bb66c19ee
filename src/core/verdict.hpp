// The one place that decides whether a mesh is a valid solid.
//
// Every front door (the C API, and through it the tool, Python and Rust)
// reports this verdict as it is: the first defect in the order below, and the
// warnings about what the policy accepted. The checks that found them keep
// their counts and locations in MeshAnalysis; docs/validity.md explains each
// rule.
#pragma once

#include <cstdint>

namespace polymass::core {

// In the order they are judged: a defect hides the ones after it.
enum class Defect {
    none,
    face_too_small,      // a face has fewer than 3 vertices
    index_out_of_range,  // a face refers past the vertex array
    non_finite,          // a used coordinate is NaN or infinite
    extent_overflow,     // the bounding box's size does not fit in a double
    open,                // an edge is used by one face
    non_manifold,        // an edge is used by more than two faces (and not accepted)
    misoriented,         // an edge is traversed twice the same way
    non_planar,          // a polygon face is off its plane beyond the tolerance
    zero_volume,         // the signed volume is at rounding level
    integrals_overflow,  // a volume integral overflows
    volume_underflow,    // the volume is below the smallest normal double
    inverted,            // the whole surface is inside out (and not accepted)
    crossing,            // faces cross each other
    inverted_shell,      // a shell is inside out, outside every solid
    overlapping_shells,  // a shell lies in a solid of the same sense: counted twice
};

// What the policy accepted, as bits.
enum Warning : std::uint32_t {
    kWarningInverted = 1u << 0,     // an inside-out surface, taken turned
    kWarningDegenerate = 1u << 1,   // zero-area faces (harmless)
    kWarningUnchecked = 1u << 2,    // topology not checked (trusted input)
    kWarningNonManifold = 1u << 3,  // balanced non-manifold edges
    kWarningTouching = 1u << 4,     // faces touch without crossing
    // The intersection check did not run (skipped by name or with the
    // topology): faces may cross and regions count twice unseen.
    kWarningIntersectionsUnchecked = 1u << 8,
};

struct Verdict {
    Defect defect = Defect::none;
    std::uint32_t warnings = 0;  // Warning bits
    // +1, or -1 when the whole surface was accepted inside out.
    int outward = 1;

    bool valid() const { return defect == Defect::none; }
};

// What is accepted instead of refused.
struct Policy {
    bool accept_inverted = false;
    bool accept_balanced_non_manifold = false;
};

struct MeshAnalysis;
struct MeshScan;

// The defect that leaves a surface's coordinates unusable for any body:
// indices out of range, coordinates not finite, an extent beyond doubles.
Defect coordinates_defect(const MeshScan& scan);

// The verdict on what the analysis found so far (checks it did not run are
// not judged).
Verdict judge(const MeshAnalysis& analysis, const Policy& policy);

// The verdict on a piece of a surface (a range of its faces, integrated on
// its own): only what a piece can be judged on - its face sizes, indices,
// coordinates and planar faces. Whether the whole is closed and bounds a
// volume is the whole's question.
Verdict judge_piece(const MeshAnalysis& analysis);

}  // namespace polymass::core
