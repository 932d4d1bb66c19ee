// Whether the tool's executable replaces malloc (c_allocation.cpp): with
// glibc, which allows it, and not under a sanitizer, whose runtime owns
// malloc. The out-of-memory test (tests/cli/out_of_memory.cpp) injects
// failures into malloc exactly when the tool replaces it.
#pragma once

#include <cstddef>  // defines __GLIBC__ where glibc is the C library

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define POLYMASS_REPLACES_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define POLYMASS_REPLACES_MALLOC 0
#endif
#endif
#if !defined(POLYMASS_REPLACES_MALLOC)
#if defined(__GLIBC__)
#define POLYMASS_REPLACES_MALLOC 1
#else
#define POLYMASS_REPLACES_MALLOC 0
#endif
#endif

#if POLYMASS_REPLACES_MALLOC
// glibc's allocator under its own names, which a replaced malloc calls.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* memory, std::size_t size);
void __libc_free(void* memory);
}
#endif
