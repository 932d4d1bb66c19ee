// An array of plain values taken from a memory resource and left unwritten,
// for scratch whose every element is written before it is read: a
// std::pmr::vector would first fill it with zeros, a pass over memory of its
// own (the topology check's edge list is 12 bytes a triangle).
#pragma once

#include <cstddef>
#include <memory_resource>
#include <type_traits>
#include <vector>

namespace polymass::core {

template <class T>
class ScratchBuffer {
    static_assert(std::is_trivial_v<T>, "elements are left unconstructed");

public:
    ScratchBuffer(std::size_t size, std::pmr::memory_resource* memory)
        : memory_(memory),
          size_(size),
          data_(size ? static_cast<T*>(memory->allocate(size * sizeof(T), alignof(T))) : nullptr) {}
    ~ScratchBuffer() {
        if (data_) memory_->deallocate(data_, size_ * sizeof(T), alignof(T));
    }
    ScratchBuffer(const ScratchBuffer&) = delete;
    ScratchBuffer& operator=(const ScratchBuffer&) = delete;

    T* data() { return data_; }
    T& operator[](std::size_t i) { return data_[i]; }

private:
    std::pmr::memory_resource* memory_;
    std::size_t size_;
    T* data_;
};

// Gives a vector's memory back now. Assigning {} empties a vector but keeps
// its memory, which at the checks' peaks (a tree's inputs, a search's lists)
// counts.
template <class T>
void let_go(std::pmr::vector<T>& items) {
    items.clear();
    items.shrink_to_fit();
}

}  // namespace polymass::core
