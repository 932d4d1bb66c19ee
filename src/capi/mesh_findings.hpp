// What the checks of core/ found in a mesh, in the C API's terms: the status
// and message of the first problem (with what the options accept as warnings),
// or the whole polymass_diagnostics report.
#pragma once

#include <cstdint>

#include "context.hpp"
#include "core/mesh_analysis.hpp"
#include "mesh_input.hpp"

namespace polymass::capi {

// Runs core::analyse_mesh with the call's options; full_report runs every
// check (topology even when the options skip it) without stopping early.
core::MeshAnalysis analyse(polymass_context* context, const MeshInput& input,
                           const polymass_options& options, bool full_report);

// The status of what the scan found (indices out of range, non-finite or
// overflowing coordinates), with its message in the context.
int32_t judge_scan(polymass_context* context, const MeshInput& input, const core::MeshScan& scan);

// POLYMASS_ERROR_NON_PLANAR_FACE, with its message in the context, when the
// integration found polygon faces off their planes by more than the tolerance.
int32_t judge_planarity(polymass_context* context, const core::IntegrationResult& integration,
                        const polymass_options& options);

// The status of the first problem, in the order the checks run, with its
// message in the context; what the options accept instead is added to warnings.
int32_t judge(polymass_context* context, const MeshInput& input, const polymass_options& options,
              const core::MeshAnalysis& analysis, uint32_t& warnings);

// The report of what the arguments (and, when given, the analysis) show.
void fill_report(polymass_diagnostics& report, const MeshInput& input,
                 const core::MeshAnalysis* analysis);

}  // namespace polymass::capi
