// A surface analysed once by the library (a polymass_mesh): its verdict and
// message, what the checks found, its shells, which mode answered and the
// body's moments and mass properties are then read from the analysis
// without analysing again (polymass_mesh_*). polymass check reads its whole
// report from one; the parts of a file, the meshes of an assembly and of an
// audit are each analysed once.
#pragma once

#include <polymass/polymass.h>

#include <string>
#include <vector>

#include "library/solid.hpp"
#include "model/model.hpp"

namespace polymass_cli {

class SurfaceAnalysis {
public:
    // The part analysed with the given options (the library's, or a variant
    // of them). Throws std::bad_alloc when memory runs out.
    SurfaceAnalysis(const Library& library, const Model& model, const Part& part,
                    const polymass_options& options);
    ~SurfaceAnalysis();
    SurfaceAnalysis(SurfaceAnalysis&& other) noexcept;
    SurfaceAnalysis(const SurfaceAnalysis&) = delete;
    SurfaceAnalysis& operator=(const SurfaceAnalysis&) = delete;
    SurfaceAnalysis& operator=(SurfaceAnalysis&&) = delete;

    // The mesh's status: POLYMASS_OK when a mode of the chain answered.
    int32_t status() const { return status_; }
    bool valid() const { return status_ == POLYMASS_OK; }
    // Valid as given: not inside out and turned by --accept-inverted (a
    // cavity exported as a part of its own is inside out by itself).
    bool valid_as_given() const { return valid() && !(warnings_ & POLYMASS_WARNING_INVERTED); }
    // Why no mode answered (status and the library's message).
    SolidResult failure() const;
    // The answer with the given density or mass, its provenance and its
    // inertia about the library's point; failure() when no mode answered.
    SolidResult properties(const Library& library, const polymass_mass_desc& mass) const;
    // Its moments at unit density (valid() only).
    polymass_moments moments(const Library& library) const;

    // What the checks found, whatever answered: diagnostics.status is the
    // surface's own verdict as a solid.
    const polymass_diagnostics& diagnostics() const { return diagnostics_; }
    // The shells, as the library judges them (unjudged when the surface
    // fails a check that comes before the shells).
    std::vector<polymass_shell> shells(const Library& library) const;
    // The shell of each face, numbered as shells() numbers them; empty when
    // the faces are unreadable (indices out of range, non-finite
    // coordinates, faces of fewer than 3 vertices: the diagnostics say which).
    std::vector<uint32_t> shell_of_each_face(const Library& library) const;

private:
    polymass_mesh* mesh_ = nullptr;  // null only when the analysis could not run
    int32_t status_ = POLYMASS_OK;
    std::string message_;
    uint32_t warnings_ = 0;
    polymass_diagnostics diagnostics_{};
    uint64_t face_count_ = 0;
};

// The answer of the analysis of part, with the given density or mass, as
// compute_solid gives it: when no mode answered, which option would
// (suggest_option).
SolidResult answer_of(const Library& library, const SurfaceAnalysis& analysis, const Model& model,
                      const Part& part, const polymass_mass_desc& mass);

}  // namespace polymass_cli
