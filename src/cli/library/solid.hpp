// The tool's only contact with libpolymass: a context with the worker
// threads the command line allows, the options the command line asks for
// (given to every analysis: the library takes options per call), and a part
// of a Model handed over as a polymass_mesh_desc (no copy) to compute its
// mass properties.
#pragma once

#include <polymass/polymass.h>

#include <array>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace polymass_cli {

// A polymass_context with the given threads (1: no worker) that keeps no
// scratch memory between calls, freed on destruction; the options of the command line; and the
// point it reports inertia about (--about X,Y,Z; the origin otherwise).
class Library {
public:
    explicit Library(const polymass_options& options, uint32_t threads = 1,
                     const std::array<double, 3>& point = {0.0, 0.0, 0.0});
    ~Library();
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;

    polymass_context* context() const { return context_; }
    const polymass_options& options() const { return options_; }
    const std::array<double, 3>& point() const { return point_; }
    std::string message() const { return polymass_context_message(context_); }

private:
    polymass_context* context_ = nullptr;
    polymass_options options_{};
    std::array<double, 3> point_{};
};

// A part of a model as the library reads it, in place (no copy).
polymass_mesh_desc describe(const Model& model, const Part& part);

struct SolidResult {
    int32_t status = POLYMASS_OK;
    // The library's message when status is an error, then which of the
    // tool's options would give an answer, if one would.
    std::string message;
    polymass_mass_properties properties{};
    // The inertia tensor about the library's point (polymass_inertia_about).
    std::array<double, 9> inertia_point{};
    polymass_provenance provenance{};  // which mode answered, and what it did
    // On failure: the option that would give an answer ("--repair", "--hull",
    // "--shell T"), if one would, and what that mode would do.
    std::string answering_option;
    polymass_provenance answering_provenance{};
    bool options_tried = false;  // suggest_option ran: the above is all there is
};

// result.properties as the library answered them, completed: its inertia
// about the library's point (status OVERFLOW when that does not fit).
void add_inertia_point(const Library& library, SolidResult& result);

// The part's mass properties by the library's options' chain of modes, in
// one call (polymass_mass_properties_compute); when refused, which option
// would answer (suggest_option).
SolidResult compute_solid(const Library& library, const Model& model, const Part& part,
                          const polymass_mass_desc& mass);

// For a surface the library's chain refused with status: which option of
// the tool would answer it (--repair, then --hull, then --shell T for a flat
// surface, among the modes the chain lacks), in result.answering_option and
// answering_provenance, and said at the end of result.message. A status that
// rules every mode out (indices out of range, coordinates not finite) says
// it alone; otherwise the surface is analysed once more, with those modes.
void suggest_option(const Library& library, const polymass_mesh_desc& desc, int32_t status,
                    SolidResult& result);

// The name of a polymass_shell.kind in the tool's reports.
const char* shell_kind_name(int32_t kind);

}  // namespace polymass_cli
