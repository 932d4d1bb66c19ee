// Out-of-memory injection into the polymass tool: every allocation of the
// tool after its command line is parsed (its readers, the libraries they use,
// the library's calls, its reports) made to fail in turn. For each file and
// each N = 1, 2, ... the Nth allocation fails (operator new calls the new
// handler or throws std::bad_alloc, as it does when memory runs out), until a
// run makes fewer than N allocations. Every failing run must end as the tool
// ends on exhausted memory: std::bad_alloc reaching main ("polymass: out of
// memory", exit 4), or exit 4 itself - never another category (a file
// "unreadable" or a mesh "not a solid" because memory ran out), a crash, or
// (under ASan) a leak. One exception, by design: a reader that runs under the
// file's memory budget (3MF, whose zip can inflate without end) reports a
// failed allocation as the file's - unreadable, with the budget's message.
//
// The readers of glTF, 3MF and Collada run in a forked child (isolated_reader):
// the count and the fact that an allocation failed are kept in shared memory,
// so a failure in the child is seen too. Their libraries catch std::bad_alloc
// and report a parse error of their own, or carry on; the child's new handler
// tells the tool that memory ran out all the same, and this program calls the
// new handler as the standard operator new does.
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
#include <string_view>
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

// As the standard operator new does when memory runs out: the new handler,
// if one is set (the isolated readers' children set one), else std::bad_alloc.
void* allocate_or_throw(std::size_t size) {
    for (;;) {
        if (void* memory = allocate(size)) return memory;
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

void* allocate_or_null(std::size_t size) noexcept {
    try {
        return allocate_or_throw(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}

// Output kept in a fixed buffer, without allocating (a string stream would
// allocate, and swallow the failure as a stream error); what does not fit is
// dropped.
class Capture : public std::streambuf {
public:
    Capture() { clear(); }
    Capture(const Capture&) = delete;
    Capture& operator=(const Capture&) = delete;
    void clear() { setp(buffer_, buffer_ + sizeof buffer_); }
    std::string_view text() const { return {pbase(), std::size_t(pptr() - pbase())}; }

protected:
    int_type overflow(int_type c) override { return traits_type::not_eof(c); }

private:
    char buffer_[1 << 14];
};

struct Run {
    int status;
    bool over_budget;  // the tool said a reader ran out of the file's memory budget
};

// One run of `polymass FILE` with the countdown armed at n (< 0: none),
// its output discarded: the exit status, with std::bad_alloc reaching main
// counted as main counts it. The command line is parsed before: CLI11 copies
// strings inside functions declared noexcept (App::_find_subcommand), where
// a failed allocation terminates - not the project's to fix, and a command
// line is a few short strings.
Run run_tool(const std::string& file, long n) {
    using namespace polymass_cli;
    const char* argv[] = {"polymass", file.c_str()};
    const Arguments arguments = parse_arguments(2, argv);
    static Capture output, errors;  // too large for the stack of a sanitized build
    output.clear();
    errors.clear();
    std::streambuf* out = std::cout.rdbuf(&output);
    std::streambuf* err = std::cerr.rdbuf(&errors);
    Run run;
    injection()->failed.store(0);
    injection()->countdown.store(n);
    try {
        run.status = run_properties(arguments);
    } catch (const std::bad_alloc&) {
        run.status = kExitInternal;
    }
    injection()->countdown.store(-1);
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    // isolated_reader.cpp's message for a reader over the file's budget, in
    // the table (stdout) or after it (stderr).
    constexpr std::string_view over_budget = "the reader ran out of its memory";
    run.over_budget = output.text().find(over_budget) != std::string_view::npos ||
                      errors.text().find(over_budget) != std::string_view::npos;
    return run;
}

}  // namespace

void* operator new(std::size_t size) { return allocate_or_throw(size); }
void* operator new[](std::size_t size) { return allocate_or_throw(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return allocate_or_null(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return allocate_or_null(size);
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }

int main(int argc, char** argv) {
    using polymass_cli::kExitInternal, polymass_cli::kExitUnreadable;
    int failures = 0;
    for (int f = 1; f < argc; ++f) {
        const std::string file = argv[f];
        const int expected = run_tool(file, -1).status;
        long n = 0, over_budget = 0;
        for (;; ++n) {
            const Run run = run_tool(file, n);
            if (!injection()->failed.load()) {
                if (run.status != expected) {
                    std::printf("%s: exit %d without a failed allocation, %d expected\n",
                                file.c_str(), run.status, expected);
                    ++failures;
                }
                break;
            }
            if (run.status == kExitUnreadable && run.over_budget) {
                ++over_budget;
            } else if (run.status != kExitInternal) {
                std::printf("%s: allocation %ld failed: exit %d, not %d (out of memory)\n",
                            file.c_str(), n + 1, run.status, int(kExitInternal));
                ++failures;
            }
        }
        std::printf(
            "%s: exit %d; each of its %ld allocations failed in turn (%ld of them inside the "
            "file's memory budget)\n",
            file.c_str(), expected, n, over_budget);
    }
    return failures == 0 ? 0 : 1;
}
