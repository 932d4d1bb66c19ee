// The context behind polymass_context: what belongs to the caller - its
// allocator (as a std::pmr::memory_resource for core/, keeping scratch blocks
// between calls), the library's workers, and the last detailed error message.
// Options are per call, never the context's.
#pragma once

#include <polymass/polymass.h>

#include <cstdint>
#include <memory_resource>
#include <mutex>
#include <new>
#include <optional>
#include <utility>

#include "core/task_runner.hpp"
#include "core/worker_pool.hpp"
#include "scratch_memory.hpp"

namespace polymass::capi {

// Routes every allocation of core/ through the caller's polymass_allocator;
// a NULL from it becomes std::bad_alloc, which the API guard reports. The
// library's threads may allocate at the same time: the caller's functions are
// called from one thread at a time.
class HookMemoryResource final : public std::pmr::memory_resource {
public:
    explicit HookMemoryResource(const polymass_allocator& allocator) : allocator_(allocator) {}

private:
    void* do_allocate(std::size_t bytes, std::size_t alignment) override;
    void do_deallocate(void* pointer, std::size_t, std::size_t) override;
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
        return this == &other;
    }

    polymass_allocator allocator_;
    std::mutex mutex_;
};

// The allocator to use: the caller's, or malloc-backed when NULL.
polymass_allocator allocator_or_default(const polymass_allocator* allocator);

// Library objects (context, mesh) live in memory from the caller's allocator
// and keep a copy of it, their `allocator` member, to be freed with.
template <class Object, class... Arguments>
Object* create_object(const polymass_allocator& allocator, Arguments&&... arguments) {
    void* memory = allocator.allocate(allocator.user_data, sizeof(Object), alignof(Object));
    return memory ? new (memory) Object(std::forward<Arguments>(arguments)...) : nullptr;
}

template <class Object>
void destroy_object(Object* object) {
    if (!object) return;
    const polymass_allocator allocator = object->allocator;
    object->~Object();
    allocator.deallocate(allocator.user_data, object);
}

// Checks the options of one call (NULL: the defaults, every check and SOLID
// alone) and writes them, tolerances resolved (0: the default), to `out`; or
// returns the status with the message in the context. `out` is written only
// on success.
int32_t read_options(polymass_context* context, const polymass_options* options,
                     polymass_options& out);

}  // namespace polymass::capi

struct polymass_context {
    // A batch's context allocates through its parent's hook (`shared`), so
    // that the caller's allocator sees one thread at a time.
    explicit polymass_context(const polymass_allocator& hook,
                              polymass::capi::HookMemoryResource* shared = nullptr)
        : allocator(hook),
          hook_memory(hook),
          memory(shared ? shared : &hook_memory),
          batch_contexts(&hook_memory) {}
    ~polymass_context();

    polymass_allocator allocator;
    polymass::capi::HookMemoryResource hook_memory;
    polymass::capi::ScratchMemoryResource memory;  // what core/ allocates from
    char message[512] = "";

    void clear_message() { message[0] = '\0'; }
    // Formats the message and returns status, so that `return fail(...)` reads naturally.
    int32_t fail(int32_t status, const char* format, ...) __attribute__((format(printf, 3, 4)));

    // What runs the pieces of a call: the calling thread alone, or the
    // context's workers, started on first use.
    polymass::core::TaskRunner& tasks();
    // How many threads a call may use (polymass_context_set_threads).
    std::size_t threads() const { return serial_only_ ? 1 : threads_; }
    void set_threads(uint32_t threads) { threads_ = threads; }
    // One context per thread of a batch (each item needs its own message and
    // scratch), created on first use and kept; their own calls run serially.
    polymass_context* batch_context(std::size_t thread);
    // Bounds the scratch memory kept between calls, the batch's contexts' too.
    void set_scratch_limit(uint64_t bytes);

private:
    polymass::core::SerialTaskRunner serial_;
    std::optional<polymass::core::WorkerPool> workers_;
    std::pmr::vector<polymass_context*> batch_contexts;
    uint64_t scratch_limit_ = UINT64_MAX;
    std::size_t threads_ = 1;
    bool serial_only_ = false;  // a batch's context: its thread is one of the workers
};
