// The tool's C allocator: glibc's own (__libc_malloc and its kin), with each
// failure noted before NULL is returned (note_failed_c_allocation), so that a
// reader's child that ran out of memory inside a C library says so rather
// than calling the file unreadable. Part of the executable only: replacing
// malloc is the program's choice, never a library's, and the out-of-memory
// test has its own. glibc allows the replacement ("Replacing malloc"): these
// four serve every library of the process; memalign and the other entry
// points stay glibc's, and their memory is freed by __libc_free all the same.
#include "c_allocation.hpp"

#include "readers/isolated_reader.hpp"

#if POLYMASS_REPLACES_MALLOC
extern "C" {

void* malloc(std::size_t size) {
    void* memory = __libc_malloc(size);
    if (memory == nullptr) polymass_cli::note_failed_c_allocation();
    return memory;
}

void* calloc(std::size_t count, std::size_t size) {
    void* memory = __libc_calloc(count, size);
    if (memory == nullptr) polymass_cli::note_failed_c_allocation();
    return memory;
}

void* realloc(void* memory, std::size_t size) {
    void* moved = __libc_realloc(memory, size);
    if (moved == nullptr && size != 0) polymass_cli::note_failed_c_allocation();
    return moved;
}

void free(void* memory) { __libc_free(memory); }

}  // extern "C"
#endif
