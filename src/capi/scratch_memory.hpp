// The scratch memory a context keeps between calls. The passes over a large
// mesh (the topology check's edge lists, the shells' tables) take blocks of
// megabytes and give them back at the end of the call; handed straight to
// the caller's allocator, such blocks are usually mapped fresh from the
// system and unmapped again on every call, and each page faults on its first
// touch. Kept here instead, the next call finds them mapped and warm.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <mutex>

namespace polymass::capi {

class ScratchMemoryResource final : public std::pmr::memory_resource {
public:
    explicit ScratchMemoryResource(std::pmr::memory_resource* upstream) : upstream_(upstream) {}
    ~ScratchMemoryResource() override { set_limit(0); }
    ScratchMemoryResource(const ScratchMemoryResource&) = delete;
    ScratchMemoryResource& operator=(const ScratchMemoryResource&) = delete;

    // Keeps at most `bytes` of freed blocks; those beyond go back upstream now.
    void set_limit(std::uint64_t bytes);

private:
    struct Block {
        void* pointer;
        std::size_t size;
    };

    void* do_allocate(std::size_t bytes, std::size_t alignment) override;
    void do_deallocate(void* pointer, std::size_t bytes, std::size_t alignment) override;
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
        return this == &other;
    }
    void give_back(const Block& block);  // to upstream, with mutex_ held

    std::pmr::memory_resource* upstream_;
    std::mutex mutex_;  // tasks of one call may allocate at the same time
    // Kept blocks in a fixed table (freeing must not allocate); a call's
    // large blocks are a handful.
    std::array<Block, 32> kept_{};
    std::size_t kept_count_ = 0;
    std::uint64_t kept_bytes_ = 0;
    std::uint64_t limit_ = UINT64_MAX;
};

}  // namespace polymass::capi
