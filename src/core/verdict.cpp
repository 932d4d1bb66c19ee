#include "verdict.hpp"

#include <cfloat>
#include <cmath>

#include "mesh_analysis.hpp"

namespace polymass::core {
namespace {

bool integrals_finite(const IntegrationResult& integration) {
    const VolumeIntegrals& integrals = integration.integrals;
    return std::isfinite(integration.surface_area) && std::isfinite(integrals.volume) &&
           integrals.first.allFinite() && integrals.second.allFinite() &&
           integrals.products.allFinite();
}

// The defect of the faces' sizes and the scan, if any: the first thing every
// verdict judges.
Defect scan_defect(const MeshAnalysis& analysis) {
    if (analysis.small_faces.count > 0) return Defect::face_too_small;
    return coordinates_defect(analysis.scan);
}

}  // namespace

Defect coordinates_defect(const MeshScan& scan) {
    if (scan.out_of_range_indices > 0) return Defect::index_out_of_range;
    if (scan.non_finite.count > 0) return Defect::non_finite;
    if (!std::isfinite(scan.diagonal())) return Defect::extent_overflow;
    return Defect::none;
}

Verdict judge_piece(const MeshAnalysis& analysis) {
    Verdict verdict;
    verdict.defect = scan_defect(analysis);
    if (verdict.valid() && analysis.integration && analysis.integration->non_planar_faces.count > 0)
        verdict.defect = Defect::non_planar;
    return verdict;
}

Verdict judge(const MeshAnalysis& analysis, const Policy& policy) {
    Verdict verdict;
    auto refuse = [&](Defect defect) {
        verdict.defect = defect;
        return verdict;
    };
    if (const Defect defect = scan_defect(analysis); defect != Defect::none) return refuse(defect);

    if (const auto& topology = analysis.topology) {
        if (topology->open.count > 0) return refuse(Defect::open);
        if (topology->non_manifold.count > 0) {
            if (!(policy.accept_balanced_non_manifold && topology->non_manifold_balanced))
                return refuse(Defect::non_manifold);
            verdict.warnings |= kWarningNonManifold;
        }
        if (topology->misoriented.count > 0) return refuse(Defect::misoriented);
    } else {
        verdict.warnings |= kWarningUnchecked;
    }

    const auto& integration = analysis.integration;
    if (!integration) return verdict;
    if (integration->non_planar_faces.count > 0) return refuse(Defect::non_planar);
    if (integration->degenerate_faces.count > 0) verdict.warnings |= kWarningDegenerate;
    if (integration->encloses_no_volume) return refuse(Defect::zero_volume);
    if (!integrals_finite(*integration)) return refuse(Defect::integrals_overflow);
    // A solid too small for a double: its volume (size^3) underflowed. The
    // inertia (size^5 x density) can underflow too, but that depends on the
    // density: the mass properties say so.
    const double volume = integration->integrals.volume;
    if (!(std::abs(volume) >= DBL_MIN)) return refuse(Defect::volume_underflow);
    if (volume < 0) {
        if (!policy.accept_inverted) return refuse(Defect::inverted);
        verdict.warnings |= kWarningInverted;
        verdict.outward = -1;
    }

    // A shell inside out by the boxes is known before the faces are compared
    // (the analysis stops there when asked to), so it comes first; with
    // faces crossing, the kinds are still the boxes', as nesting is not
    // counted then, and every caller gets the same verdict.
    const auto& shells = analysis.shells;
    if (shells && shells->inverted.count > 0) return refuse(Defect::inverted_shell);
    if (const auto& overlaps = analysis.overlaps) {
        if (overlaps->crossing.count > 0) return refuse(Defect::crossing);
        if (overlaps->touching.count > 0) verdict.warnings |= kWarningTouching;
    } else {
        verdict.warnings |= kWarningIntersectionsUnchecked;
    }
    if (shells && shells->overlapping.count > 0) return refuse(Defect::overlapping_shells);
    return verdict;
}

}  // namespace polymass::core
