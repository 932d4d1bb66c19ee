// The core's analysis in the C API's terms: the status and message of a
// defect, the polymass_diagnostics report, the shells. Nothing here judges:
// core::judge does.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <vector>

#include "context.hpp"
#include "core/mesh_analysis.hpp"
#include "mesh_input.hpp"

namespace polymass::capi {

// The status of a defect.
int32_t status_of(core::Defect defect);

// The status of a defect the analysis found, with its message (quoting the
// analysis's findings) in the context. input and options are the call's (the
// message quotes a face's size, the vertex count, the planarity tolerance).
int32_t report_verdict(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, const core::MeshAnalysis& analysis,
                       core::Defect defect);

// A finding's count and its first locations (the rest left as they are).
void copy_finding(const core::Finding& found, uint64_t& count,
                  uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS]);
template <class EdgeOrPairFinding>
void copy_finding(const EdgeOrPairFinding& found, uint64_t& count,
                  uint64_t (&first)[POLYMASS_DIAGNOSTIC_LOCATIONS][2]) {
    count = found.count;
    for (std::size_t i = 0; i < found.kept(); ++i) {
        first[i][0] = found.lowest[i][0];
        first[i][1] = found.lowest[i][1];
    }
}

// The report of what the analysis of the input found; its status is the
// caller's to set.
void fill_report(polymass_diagnostics& report, const MeshInput& input,
                 const core::MeshAnalysis& analysis);

// The analysis's shells (judged, or listed unjudged) and the shell of each
// face; both left empty when the analysis has none (faces unreadable).
void list_shells(const core::MeshAnalysis& analysis, std::pmr::vector<polymass_shell>& shells,
                 std::pmr::vector<uint32_t>& shell_of_face);

}  // namespace polymass::capi
