#include "struct_versions.hpp"

#include <algorithm>

namespace polymass::capi {

polymass_diagnostics StructVersions<polymass_diagnostics>::defaults() {
    polymass_diagnostics report = zeroed<polymass_diagnostics>();
    for (uint64_t* location :
         {&report.first_non_finite_vertices[0], &report.first_out_of_range_faces[0],
          &report.first_small_faces[0], &report.first_degenerate_faces[0],
          &report.first_non_planar_faces[0], &report.first_inverted_shells[0],
          &report.first_overlapping_shells[0]})
        std::fill_n(location, POLYMASS_DIAGNOSTIC_LOCATIONS, POLYMASS_NONE);
    for (uint64_t* pair :
         {&report.first_open_edges[0][0], &report.first_non_manifold_edges[0][0],
          &report.first_misoriented_edges[0][0], &report.first_intersecting_face_pairs[0][0],
          &report.first_touching_face_pairs[0][0]})
        std::fill_n(pair, 2 * POLYMASS_DIAGNOSTIC_LOCATIONS, POLYMASS_NONE);
    return report;
}

polymass_provenance StructVersions<polymass_provenance>::defaults() {
    polymass_provenance provenance = zeroed<polymass_provenance>();
    for (uint64_t* location :
         {&provenance.first_reoriented_faces[0], &provenance.first_turned_shells[0],
          &provenance.first_duplicate_faces[0], &provenance.first_degenerate_faces[0],
          &provenance.first_triangulated_faces[0], &provenance.first_holes[0]})
        std::fill_n(location, POLYMASS_DIAGNOSTIC_LOCATIONS, POLYMASS_NONE);
    std::fill_n(&provenance.first_split_edges[0][0], 2 * POLYMASS_DIAGNOSTIC_LOCATIONS,
                POLYMASS_NONE);
    return provenance;
}

}  // namespace polymass::capi
