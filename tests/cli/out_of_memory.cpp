// Out-of-memory injection into the polymass tool: every allocation of the
// tool after its command line is parsed (its readers, the libraries they use,
// its reports; the library's own allocations are test_allocator.c's) made to
// fail in turn. For each file and
// each N = 1, 2, ... the Nth allocation fails (operator new throws
// std::bad_alloc, as it does when memory runs out), until a run makes fewer
// than N allocations. Every failing run must end as the tool ends on
// exhausted memory: std::bad_alloc reaching main ("polymass: out of memory",
// exit 4), or exit 4 itself - never another category (a file "unreadable"
// because memory ran out), a crash, or (under ASan) a leak.
//
// The readers of glTF, 3MF and Collada run in a forked child (isolated_reader):
// the count and the fact that an allocation failed are kept in shared memory,
// so a failure in the child is seen too.
//
//   polymass_out_of_memory FILE...
#include <sys/mman.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <streambuf>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "commands/commands.hpp"
#include "exit_codes.hpp"

namespace {

struct Injection {
    std::atomic<long> countdown;  // allocations left before the one that fails; < 0: none fails
    std::atomic<int> failed;      // an allocation was made to fail
};

// In shared memory, so that a forked reader counts on the same numbers.
Injection* injection() {
    static Injection* shared = [] {
        void* memory = mmap(nullptr, sizeof(Injection), PROT_READ | PROT_WRITE,
                            MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (memory == MAP_FAILED) std::abort();
        return new (memory) Injection{{-1}, {0}};
    }();
    return shared;
}

bool allocation_fails() {
    Injection* state = injection();
    if (state->countdown.load() < 0) return false;
    if (state->countdown.fetch_sub(1) != 0) return false;
    state->failed.store(1);
    return true;
}

void* allocate(std::size_t size) {
    if (allocation_fails()) return nullptr;
    return std::malloc(size ? size : 1);
}

void* allocate_or_throw(std::size_t size) {
    void* memory = allocate(size);
    if (!memory) throw std::bad_alloc();
    return memory;
}

// Output thrown away without allocating (a string stream would allocate,
// and swallow the failure as a stream error).
class Discard : public std::streambuf {
protected:
    int_type overflow(int_type c) override { return traits_type::not_eof(c); }
};

// One run of `polymass FILE` with the countdown armed at n (< 0: none),
// its output discarded: the exit status, with std::bad_alloc reaching main
// counted as main counts it. The command line is parsed before: CLI11 copies
// strings inside functions declared noexcept (App::_find_subcommand), where
// a failed allocation terminates - not the project's to fix, and a command
// line is a few short strings.
int run_tool(const std::string& file, long n) {
    using namespace polymass_cli;
    const char* argv[] = {"polymass", file.c_str()};
    const Arguments arguments = parse_arguments(2, argv);
    Discard discarded;
    std::streambuf* out = std::cout.rdbuf(&discarded);
    std::streambuf* err = std::cerr.rdbuf(&discarded);
    int status;
    injection()->failed.store(0);
    injection()->countdown.store(n);
    try {
        status = run_properties(arguments);
    } catch (const std::bad_alloc&) {
        status = kExitInternal;
    }
    injection()->countdown.store(-1);
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    return status;
}

}  // namespace

void* operator new(std::size_t size) { return allocate_or_throw(size); }
void* operator new[](std::size_t size) { return allocate_or_throw(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }

int main(int argc, char** argv) {
    int failures = 0;
    for (int f = 1; f < argc; ++f) {
        const std::string file = argv[f];
        const int expected = run_tool(file, -1);
        long n = 0;
        for (;; ++n) {
            const int status = run_tool(file, n);
            if (!injection()->failed.load()) {
                if (status != expected) {
                    std::printf("%s: exit %d without a failed allocation, %d expected\n",
                                file.c_str(), status, expected);
                    ++failures;
                }
                break;
            }
            if (status != polymass_cli::kExitInternal) {
                std::printf("%s: allocation %ld failed: exit %d, not %d (out of memory)\n",
                            file.c_str(), n + 1, status, int(polymass_cli::kExitInternal));
                ++failures;
            }
        }
        std::printf("%s: exit %d; each of its %ld allocations failed in turn\n", file.c_str(),
                    expected, n);
    }
    return failures == 0 ? 0 : 1;
}
