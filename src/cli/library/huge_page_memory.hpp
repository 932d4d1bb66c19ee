// The memory the tool's library contexts allocate from (polymass_allocator).
// A million-triangle STL's check takes a few hundred megabytes of buffers of
// megabytes each in turn, each freshly mapped (main.cpp: freed ones go back to
// the system, to keep the peak low); at 4 KiB a page, their first touches were
// 67,500 page faults, about a sixth of the run's CPU time in the kernel. A
// block of 2 MiB or more is therefore laid on 2 MiB boundaries and asked of
// the kernel as transparent huge pages (madvise MADV_HUGEPAGE, honoured under
// the kernel's policies "madvise" and "always"; "never" ignores it): 512 times
// fewer faults over its whole huge pages (its tail stays in small ones: a
// huge page is resident whole once touched). Smaller blocks
// are malloc's as before. The tool's own largest buffer, a binary STL's
// corners, comes from the same memory (HugePageArray). Figures:
// docs/tool-end-to-end.md, "Page faults".
#pragma once

#include <polymass/polymass.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>

namespace polymass_cli {

// For polymass_context_create; valid for the whole run.
const polymass_allocator* huge_page_allocator();

// count T's from that memory, left uninitialised (a vector would write zeros
// over every page before its writer fills it), freed on destruction. Throws
// std::bad_alloc.
template <class T>
class HugePageArray {
    static_assert(std::is_trivial_v<T>, "its elements are never constructed");

public:
    explicit HugePageArray(std::size_t count) : count_(count) {
        const polymass_allocator* memory = huge_page_allocator();
        if (count > SIZE_MAX / sizeof(T)) throw std::bad_alloc();
        data_ = static_cast<T*>(memory->allocate(memory->user_data, count * sizeof(T), alignof(T)));
        if (data_ == nullptr) throw std::bad_alloc();
    }
    ~HugePageArray() { huge_page_allocator()->deallocate(huge_page_allocator()->user_data, data_); }
    HugePageArray(const HugePageArray&) = delete;
    HugePageArray& operator=(const HugePageArray&) = delete;

    T* data() { return data_; }
    const T* data() const { return data_; }
    std::size_t size() const { return count_; }

private:
    T* data_ = nullptr;
    std::size_t count_;
};

}  // namespace polymass_cli
