#include "scratch_memory.hpp"

#include <algorithm>

namespace polymass::capi {
namespace {

// Smaller blocks come and go through the allocator's own free lists without
// touching the system: keeping them would only add a lock.
constexpr std::size_t kept_from_bytes = std::size_t{64} << 10;
// Every kept block is aligned for any request up to this, and starts with a
// header of this size holding its size: a kept block may serve a smaller
// request than the one it was made for.
constexpr std::size_t block_alignment = 64;

bool keepable(std::size_t bytes, std::size_t alignment) {
    return bytes >= kept_from_bytes && alignment <= block_alignment;
}

}  // namespace

void ScratchMemoryResource::set_limit(std::uint64_t bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    limit_ = bytes;
    // The largest go first: they are the ones a limit is about.
    Block* const kept = kept_.data();
    std::sort(kept, kept + kept_count_,
              [](const Block& a, const Block& b) { return a.size < b.size; });
    while (kept_bytes_ > bytes) give_back(kept[--kept_count_]);
}

void ScratchMemoryResource::give_back(const Block& block) {
    kept_bytes_ -= block.size;
    upstream_->deallocate(static_cast<unsigned char*>(block.pointer) - block_alignment,
                          block_alignment + block.size, block_alignment);
}

void* ScratchMemoryResource::do_allocate(std::size_t bytes, std::size_t alignment) {
    if (!keepable(bytes, alignment)) return upstream_->allocate(bytes, alignment);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        // The smallest kept block that fits: a call makes the same requests
        // as the one before it on the same mesh, so they find the blocks they
        // had, and what is kept stays what the largest call had at once.
        Block* const kept = kept_.data();
        Block* const end = kept + kept_count_;
        Block* best = end;
        for (Block* block = kept; block != end; ++block)
            if (block->size >= bytes && (best == end || block->size < best->size)) best = block;
        if (best != end) {
            void* pointer = best->pointer;
            kept_bytes_ -= best->size;
            *best = kept[--kept_count_];
            return pointer;
        }
        // None fits: the calls are growing, and the smaller kept blocks are
        // the past's; they go back rather than pile up.
        std::size_t still_kept = 0;
        for (Block* block = kept; block != end; ++block)
            if (block->size < bytes)
                give_back(*block);
            else
                kept[still_kept++] = *block;
        kept_count_ = still_kept;
    }
    auto* start =
        static_cast<unsigned char*>(upstream_->allocate(block_alignment + bytes, block_alignment));
    *reinterpret_cast<std::size_t*>(start) = bytes;
    return start + block_alignment;
}

void ScratchMemoryResource::do_deallocate(void* pointer, std::size_t bytes, std::size_t alignment) {
    if (!keepable(bytes, alignment)) return upstream_->deallocate(pointer, bytes, alignment);
    const Block block{pointer, *reinterpret_cast<const std::size_t*>(
                                   static_cast<unsigned char*>(pointer) - block_alignment)};
    std::lock_guard<std::mutex> lock(mutex_);
    kept_bytes_ += block.size;
    if (kept_count_ == kept_.size() || kept_bytes_ > limit_) return give_back(block);
    kept_[kept_count_++] = block;
}

}  // namespace polymass::capi
