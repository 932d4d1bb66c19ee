#include "library/huge_page_memory.hpp"

#ifdef __linux__
#include <sys/mman.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace polymass_cli {
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;

// Every block is malloc's (so that the tool's out-of-memory test fails it in
// turn as any other), aligned inside it, with malloc's own pointer just
// before the block for deallocate, which is given no size.
void* allocate(void*, std::size_t size, std::size_t alignment) {
    const std::size_t align = std::max(size >= kHugePage ? kHugePage : alignof(void*), alignment);
    if (size > SIZE_MAX - align - sizeof(void*)) return nullptr;
    void* const raw = std::malloc(size + align + sizeof(void*));
    if (raw == nullptr) return nullptr;
    const std::uintptr_t after_raw = reinterpret_cast<std::uintptr_t>(raw) + sizeof(void*);
    void* const block = reinterpret_cast<void*>((after_raw + align - 1) / align * align);
    static_cast<void**>(block)[-1] = raw;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Only whole huge pages inside the block: the rest of malloc's chunk may
    // be another's. A kernel without them ignores the advice.
    if (size >= kHugePage) madvise(block, size / kHugePage * kHugePage, MADV_HUGEPAGE);
#endif
    return block;
}

void deallocate(void*, void* block) {
    if (block != nullptr) std::free(static_cast<void**>(block)[-1]);
}

}  // namespace

const polymass_allocator* huge_page_allocator() {
    static const polymass_allocator allocator = [] {
        polymass_allocator made{};
        polymass_allocator_init(&made, sizeof made);
        made.allocate = allocate;
        made.deallocate = deallocate;
        return made;
    }();
    return &allocator;
}

}  // namespace polymass_cli
