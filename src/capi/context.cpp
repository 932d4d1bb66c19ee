#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "api_guard.hpp"
#include "struct_io.hpp"

namespace polymass::capi {
namespace {

void* default_allocate(void*, std::size_t size, std::size_t alignment) {
    if (alignment <= alignof(std::max_align_t)) return std::malloc(size);
    // aligned_alloc wants a size that is a multiple of the alignment.
    return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}

void default_deallocate(void*, void* pointer) { std::free(pointer); }

}  // namespace

void* HookMemoryResource::do_allocate(std::size_t bytes, std::size_t alignment) {
    std::lock_guard<std::mutex> lock(mutex_);
    void* pointer = allocator_.allocate(allocator_.user_data, bytes, alignment);
    if (!pointer && bytes > 0) throw std::bad_alloc();
    return pointer;
}

void HookMemoryResource::do_deallocate(void* pointer, std::size_t, std::size_t) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pointer) allocator_.deallocate(allocator_.user_data, pointer);
}

polymass_allocator allocator_or_default(const polymass_allocator* allocator) {
    polymass_allocator malloc_backed = StructVersions<polymass_allocator>::defaults();
    if (allocator && allocator->allocate) return read_struct(*allocator, malloc_backed);
    malloc_backed.allocate = default_allocate;
    malloc_backed.deallocate = default_deallocate;
    return malloc_backed;
}

int32_t read_options(polymass_context* context, const polymass_options* options,
                     polymass_options& out) {
    if (!options) {
        out = StructVersions<polymass_options>::defaults();
        out.planarity_tolerance = POLYMASS_DEFAULT_PLANARITY_TOLERANCE;
        return POLYMASS_OK;
    }
    if (const int32_t status = check_struct(context, options, "options")) return status;
    const polymass_options read =
        read_struct(*options, StructVersions<polymass_options>::defaults());
    constexpr uint32_t known_flags =
        POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS | POLYMASS_OPTION_ACCEPT_INVERTED |
        POLYMASS_OPTION_WELD_VERTICES | POLYMASS_OPTION_ACCEPT_NON_MANIFOLD |
        POLYMASS_OPTION_SKIP_INTERSECTION_CHECK;
    if (read.flags & ~known_flags)
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "options->flags has unknown bits 0x%x",
                             unsigned(read.flags & ~known_flags));
    const double tolerance = read.planarity_tolerance;
    if (!(tolerance >= 0.0 && tolerance < 1.0))  // also rejects NaN
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "options->planarity_tolerance is %g; it must be in [0, 1) "
                             "(0 selects the default %g)",
                             tolerance, POLYMASS_DEFAULT_PLANARITY_TOLERANCE);
    const double weld = read.weld_tolerance;
    if (!(weld >= 0.0 && weld <= POLYMASS_MAX_WELD_TOLERANCE))  // also rejects NaN
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "options->weld_tolerance is %g; it must be in [0, %g]", weld,
                             POLYMASS_MAX_WELD_TOLERANCE);
    bool shell = false;
    for (int i = 0; i < POLYMASS_MAX_MODES; ++i) {
        const uint32_t mode = read.modes[i];
        if (mode > POLYMASS_MODE_HULL)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "options->modes[%d] is %u; the modes are POLYMASS_MODE_SOLID (1), "
                                 "REPAIR (2), SHELL (3) and HULL (4), ended by POLYMASS_MODE_NONE "
                                 "(0)",
                                 i, unsigned(mode));
        shell |= mode == POLYMASS_MODE_SHELL;
    }
    const double thickness = read.shell_thickness;
    if (!(thickness >= 0.0 && std::isfinite(thickness)) || (shell && thickness == 0.0))
        return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                             "options->shell_thickness is %g; it must be finite, and positive "
                             "when the modes hold POLYMASS_MODE_SHELL",
                             thickness);
    out = read;
    if (tolerance == 0.0) out.planarity_tolerance = POLYMASS_DEFAULT_PLANARITY_TOLERANCE;
    return POLYMASS_OK;
}

}  // namespace polymass::capi

polymass_context::~polymass_context() {
    for (polymass_context* batch : batch_contexts) polymass::capi::destroy_object(batch);
}

polymass::core::TaskRunner& polymass_context::tasks() {
    if (threads() == 1) return serial_;
    if (!workers_ || workers_->thread_count() != threads()) {
        workers_.reset();
        workers_.emplace(threads(), &hook_memory);
    }
    return *workers_;
}

void polymass_context::set_scratch_limit(uint64_t bytes) {
    scratch_limit_ = bytes;
    memory.set_limit(bytes);
    for (polymass_context* batch : batch_contexts) batch->set_scratch_limit(bytes);
}

polymass_context* polymass_context::batch_context(std::size_t thread) {
    batch_contexts.reserve(thread + 1);  // push_back below cannot throw
    while (batch_contexts.size() <= thread) {
        polymass_context* batch =
            polymass::capi::create_object<polymass_context>(allocator, allocator, &hook_memory);
        if (!batch) throw std::bad_alloc();
        batch->serial_only_ = true;
        batch->set_scratch_limit(scratch_limit_);
        batch_contexts.push_back(batch);
    }
    return batch_contexts[thread];
}

int32_t polymass_context::fail(int32_t status, const char* format, ...) {
    va_list arguments;
    va_start(arguments, format);
    std::vsnprintf(message, sizeof message, format, arguments);
    va_end(arguments);
    return status;
}

using namespace polymass::capi;

extern "C" {

POLYMASS_API int32_t polymass_context_create(polymass_context** out_context,
                                             const polymass_allocator* allocator) {
    if (!out_context) return POLYMASS_ERROR_INVALID_ARGUMENT;
    *out_context = nullptr;
    // No context yet to hold a message: a wrong allocator is only a status.
    if (allocator && (!is_known_size<polymass_allocator>(allocator->struct_size) ||
                      allocator->reserved != 0 || !allocator->allocate != !allocator->deallocate))
        return POLYMASS_ERROR_INVALID_ARGUMENT;
    const polymass_allocator hook = allocator_or_default(allocator);
    *out_context = create_object<polymass_context>(hook, hook);
    return *out_context ? POLYMASS_OK : POLYMASS_ERROR_OUT_OF_MEMORY;
}

POLYMASS_API void polymass_context_destroy(polymass_context* context) { destroy_object(context); }

POLYMASS_API int32_t polymass_context_set_threads(polymass_context* context, uint32_t threads) {
    return guarded(context, [&] {
        if (threads < 1 || threads > POLYMASS_MAX_THREADS)
            return context->fail(POLYMASS_ERROR_INVALID_ARGUMENT,
                                 "threads is %u; it must be in [1, %u]", unsigned(threads),
                                 unsigned(POLYMASS_MAX_THREADS));
        context->set_threads(threads);
        return int32_t(POLYMASS_OK);
    });
}

POLYMASS_API int32_t polymass_context_set_scratch_limit(polymass_context* context,
                                                        uint64_t max_kept_bytes) {
    return guarded(context, [&] {
        context->set_scratch_limit(max_kept_bytes);
        return int32_t(POLYMASS_OK);
    });
}

POLYMASS_API const char* polymass_context_message(const polymass_context* context) {
    return context ? context->message : "context is NULL";
}

}  // extern "C"
