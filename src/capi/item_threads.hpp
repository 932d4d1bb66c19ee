// How the calls over many independent meshes (polymass_batch_compute,
// polymass_packed_compute) spread them over the context's threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "context.hpp"

namespace polymass::capi {

// Calls compute(i, item_context) once for each item i in [0, count): on the
// calling thread through `context` itself when it has one thread, else on
// its workers, each taking the next item not yet taken and computing it
// through its own batch context (each item needs its own message and
// scratch). Each item is computed whole on one thread, so which thread takes
// it changes none of its results. compute must not throw.
template <class Compute>
void for_each_item(polymass_context* context, uint64_t count, Compute&& compute) {
    const std::size_t threads = std::min<uint64_t>(context->threads(), count);
    if (threads <= 1) {
        for (uint64_t i = 0; i < count; ++i) compute(i, context);
        return;
    }
    for (std::size_t thread = 0; thread < threads; ++thread) context->batch_context(thread);
    std::atomic<uint64_t> next{0};
    context->tasks().run(threads, [&](std::size_t thread) {
        polymass_context* own = context->batch_context(thread);
        for (uint64_t i = next++; i < count; i = next++) compute(i, own);
    });
}

}  // namespace polymass::capi
