// The core's analysis and verdict in the C API's terms: the status and
// message of the defect (with the warnings the policy accepted), or the whole
// polymass_diagnostics report. Nothing here judges: core::judge does.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <vector>

#include "context.hpp"
#include "core/mesh_analysis.hpp"
#include "mesh_input.hpp"

namespace polymass::capi {

// Runs core::analyse_mesh with the call's options: every check the options
// do not skip; with full_report, each to its end (every finding counted, not
// only the first) and the shells listed even when they are not judged.
core::MeshAnalysis analyse(polymass_context* context, const MeshInput& input,
                           const polymass_options& options, bool full_report);

// POLYMASS_ERROR_FACE_TOO_SMALL with its message when the input has faces
// of fewer than 3 vertices, else POLYMASS_OK.
int32_t report_small_faces(polymass_context* context, const MeshInput& input);

// The status of the analysis's verdict, with its message in the context; the
// warnings it accepted, as POLYMASS_WARNING_* bits, in `warnings`. options
// are the call's (the message quotes the planarity tolerance).
int32_t report_verdict(polymass_context* context, const MeshInput& input,
                       const polymass_options& options, const core::MeshAnalysis& analysis,
                       uint32_t& warnings);

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

// The report of what the arguments (and, when given, the analysis) show;
// its status is the caller's to set.
void fill_report(polymass_diagnostics& report, const MeshInput& input,
                 const core::MeshAnalysis* analysis);

// The analysis's shells (judged, or listed unjudged) and the shell of each
// face; both left empty when the analysis has none (faces unreadable).
void list_shells(const core::MeshAnalysis& analysis, std::pmr::vector<polymass_shell>& shells,
                 std::pmr::vector<uint32_t>& shell_of_face);

}  // namespace polymass::capi
