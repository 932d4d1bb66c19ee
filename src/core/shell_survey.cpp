#include "shell_survey.hpp"

#include <cmath>
#include <limits>

#include "surface_overlaps.hpp"

namespace polymass::core {
namespace {

// Rounding level of a shell's signed volume, as for the whole surface
// (mesh_integration.hpp): |V| below it cannot be told from zero.
bool encloses_no_volume(const ShellSummary& shell) {
    constexpr double slack = 1024.0 * std::numeric_limits<double>::epsilon();
    const double size = shell.bounds.isEmpty() ? 0.0 : shell.bounds.diagonal().stableNorm();
    return !(std::abs(shell.signed_volume) > slack * shell.surface_area * size);
}

void record_kinds(ShellSurvey& survey) {
    survey.inverted = {};
    survey.overlapping = {};
    for (std::size_t shell = 0; shell < survey.summary.size(); ++shell) {
        if (survey.summary[shell].kind == ShellKind::inverted) survey.inverted.record(shell);
        if (survey.summary[shell].kind == ShellKind::overlapping) survey.overlapping.record(shell);
    }
}

}  // namespace

template <class Scalar, class Index>
ShellSurvey survey_shells(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                          const VertexIdentities& identities,
                          std::pmr::vector<std::uint32_t> vertex_sets,
                          const Eigen::Vector3d& reference, int outward, double whole_volume,
                          bool whole_encloses_no_volume, TaskRunner& tasks,
                          std::pmr::memory_resource* memory) {
    ShellSurvey survey(find_shells(mesh, scan, identities, std::move(vertex_sets), tasks, memory),
                       memory);
    survey.summary.resize(survey.shells.count);
    // One shell is the whole surface, whose volume the caller has judged:
    // nothing to compare it with.
    if (survey.shells.count == 1) {
        ShellSummary& whole = survey.summary[0];
        whole.face_count = mesh.face_count;
        whole.signed_volume = outward * whole_volume;
        whole.kind = whole_encloses_no_volume  ? ShellKind::no_volume
                     : whole.signed_volume > 0 ? ShellKind::solid
                                               : ShellKind::inverted;
        record_kinds(survey);
        return survey;
    }
    // Each face's cone from the reference point: a fan of tetrahedra, exact
    // for planar faces; its area from the same fan.
    for_each_face(mesh, [&](std::size_t face, std::size_t first, std::size_t size) {
        ShellSummary& shell = survey.summary[survey.shells.of_face[face]];
        if (shell.face_count++ == 0) shell.first_face = face;
        const Eigen::Vector3d a = mesh.positions[mesh.indices[first]] - reference;
        Eigen::Vector3d b = mesh.positions[mesh.indices[first + 1]] - reference;
        Eigen::Vector3d area = Eigen::Vector3d::Zero();
        shell.bounds.extend(a + reference);
        shell.bounds.extend(b + reference);
        for (std::size_t i = 2; i < size; ++i) {
            const Eigen::Vector3d c = mesh.positions[mesh.indices[first + i]] - reference;
            shell.signed_volume += outward * a.dot(b.cross(c)) / 6.0;
            area += (b - a).cross(c - a);
            shell.bounds.extend(c + reference);
            b = c;
        }
        shell.surface_area += 0.5 * area.norm();
    });
    for (ShellSummary& shell : survey.summary) {
        if (encloses_no_volume(shell)) {
            shell.kind = ShellKind::no_volume;
        } else if (shell.signed_volume > 0) {
            shell.kind = ShellKind::solid;
        } else {
            shell.kind = ShellKind::inverted;
            for (const ShellSummary& other : survey.summary)
                if (other.signed_volume > 0 && other.bounds.contains(shell.bounds))
                    shell.kind = ShellKind::cavity;
        }
    }
    record_kinds(survey);
    return survey;
}

void classify_by_winding(ShellSurvey& survey, const std::pmr::vector<int>& winding_of_shell,
                         int outward) {
    for (std::size_t shell = 0; shell < survey.summary.size(); ++shell) {
        ShellSummary& summary = survey.summary[shell];
        if (winding_of_shell[shell] == kUnknownWinding || summary.kind == ShellKind::no_volume)
            continue;
        if (winding_of_shell[shell] == kMixedWinding) {
            summary.kind = ShellKind::overlapping;
            continue;
        }
        const int around = outward * winding_of_shell[shell];
        if (summary.signed_volume > 0)
            summary.kind = around == 0 ? ShellKind::solid : ShellKind::overlapping;
        else
            summary.kind = around == 1   ? ShellKind::cavity
                           : around == 0 ? ShellKind::inverted
                                         : ShellKind::overlapping;
    }
    survey.nesting_counted = true;
    record_kinds(survey);
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                      \
    template ShellSurvey survey_shells<Scalar, Index>(                                           \
        const MeshView<Scalar, Index>&, const MeshScan&, const VertexIdentities&,                \
        std::pmr::vector<std::uint32_t>, const Eigen::Vector3d&, int, double, bool, TaskRunner&, \
        std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
