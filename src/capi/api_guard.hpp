// The one place where C++ meets C: every exported function that can fail runs
// its body through guarded(), so no exception ever crosses the boundary.
#pragma once

#include <exception>
#include <new>

#include "context.hpp"

namespace polymass::capi {

template <class Body>
int32_t guarded(polymass_context* context, Body&& body) noexcept {
    if (!context) return POLYMASS_ERROR_INVALID_ARGUMENT;  // nowhere to put a message
    context->clear_message();
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return context->fail(POLYMASS_ERROR_OUT_OF_MEMORY,
                             "out of memory: the allocator could not provide working memory");
    } catch (const std::exception& error) {
        return context->fail(POLYMASS_ERROR_INTERNAL, "internal error: %s", error.what());
    } catch (...) {
        return context->fail(POLYMASS_ERROR_INTERNAL, "internal error: unknown exception");
    }
}

}  // namespace polymass::capi
