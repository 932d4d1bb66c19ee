// The tool's only contact with libpolymass: a context holding the options,
// and a part of a Model handed over as a polymass_mesh_desc (no copy) to
// compute its mass properties or to check it.
#pragma once

#include <polymass/polymass.h>

#include <string>
#include <vector>

#include "model/model.hpp"

namespace polymass_cli {

// A polymass_context with the given options, freed on destruction.
class Library {
public:
    explicit Library(const polymass_options& options);
    ~Library();
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;

    polymass_context* context() const { return context_; }
    std::string message() const { return polymass_context_message(context_); }

private:
    polymass_context* context_ = nullptr;
};

// A part of a model as the library reads it, in place (no copy).
polymass_mesh_desc describe(const Model& model, const Part& part);

struct SolidResult {
    int32_t status = POLYMASS_OK;
    // The context's message when status is an error, then which of the
    // tool's options would give an answer, if one would.
    std::string message;
    polymass_mass_properties properties{};
    polymass_provenance provenance{};  // which mode answered, and what it did
    // On failure: the option that would give an answer ("--repair", "--hull",
    // "--shell T"), if one would, and what that mode would do.
    std::string answering_option;
    polymass_provenance answering_provenance{};
};

// The part's mass properties by the library's options' chain of modes.
SolidResult compute_solid(const Library& library, const Model& model, const Part& part,
                          const polymass_mass_desc& mass);

struct CheckResult {
    polymass_diagnostics diagnostics{};
    std::string message;  // why the mesh is not a valid solid, if it is not
};

CheckResult check_solid(const Library& library, const Model& model, const Part& part);

// The shell (connected piece of surface, as the library welds it) of each
// face, numbered from 0; empty when the library cannot tell (indices out of
// range, non-finite coordinates: the check says which).
std::vector<uint32_t> shell_of_each_face(const Library& library, const Model& model,
                                         const Part& part);

// Each shell of a part as the library judges it (a solid, a cavity, inside
// out, overlapping, no volume); empty when the surface fails the checks that
// come before the shells (open, non-manifold, ...: the check says which).
// expected_count: how many shells the caller expects (shell_of_each_face
// tells), so that one call of the library, which checks the whole surface,
// usually does.
std::vector<polymass_shell> shell_list(const Library& library, const Model& model, const Part& part,
                                       uint64_t expected_count);

// The name of a polymass_shell.kind in the tool's reports.
const char* shell_kind_name(int32_t kind);

}  // namespace polymass_cli
