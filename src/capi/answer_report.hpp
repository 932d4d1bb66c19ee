// A call's options as the core's settings, and the core's answer
// (core::answer_surface) in the C API's terms: the status and message of the
// chain of modes, the provenance.
#pragma once

#include <polymass/polymass.h>

#include "context.hpp"
#include "core/surface_answer.hpp"
#include "mesh_input.hpp"

namespace polymass::capi {

// The settings of one analysis with the call's (checked) options: the
// findings in full (a mesh being made) or stopping at the first problem.
core::AnswerSettings answer_settings(polymass_context* context, const polymass_options& options,
                                     bool findings);

// POLYMASS_OK when a mode answered; otherwise the first mode's status, with
// the message in the context: the solid's own when the chain is the solid
// alone, else each mode's reason.
int32_t report_answer(polymass_context* context, const MeshInput& input,
                      const polymass_options& options, const core::SurfaceAnswer& answer);

// The message of a mesh (polymass_mesh_message) to `out`: what is wrong with
// the surface as given (its verdict's message, "" for a valid solid), then,
// when no mode answered, each other mode's reason ("...; hull: ..."). Uses
// the context's message as scratch.
void mesh_message(polymass_context* context, const MeshInput& input,
                  const polymass_options& options, const core::SurfaceAnswer& answer,
                  char (&out)[sizeof(polymass_context::message)]);

// Which mode answered and what it did (the answer must have one).
polymass_provenance provenance_of(const core::SurfaceAnswer& answer,
                                  const polymass_options& options);

}  // namespace polymass::capi
