// Out-of-memory injection into the polymass tool: every allocation of the
// tool after its command line is parsed (its readers, the libraries they use,
// the library's calls, its reports) made to fail in turn, for each command
// line given. For each N = 1, 2, ... the Nth allocation fails, until a run
// makes fewer than N allocations. An allocation is operator new's (which then
// calls the new handler or throws std::bad_alloc, as it does when memory runs
// out) and, in a build without a sanitizer (whose runtime owns malloc), also
// malloc's, calloc's and realloc's, which then return NULL: the C libraries
// under the readers (libzip, zlib, assimp's XML parser) allocate so.
//
// Every failing run must end as the tool ends on exhausted memory:
// std::bad_alloc reaching main ("polymass: out of memory", exit 4), or exit 4
// itself - never another category (a file "unreadable" or a mesh "not a
// solid" because memory ran out), a different answer, a crash, or (under
// ASan) a leak. Two exceptions, by design. A reader that runs under the
// file's memory budget (3MF, Collada: a zip or an element count can expand
// without end) reports a failed allocation as the file's: unreadable, with
// the budget's message. And a C library under such a reader reports a failed
// malloc as a file it cannot read ("Could not read ZIP file", "malformed
// XML"), which the tool cannot tell from one: in a reader's child process a
// failed C allocation may end as unreadable, with the library's message -
// under the budget, the category the tool gives a file that needs more. A run
// whose failed allocation was done without (a C library falling back, glibc
// reading /proc without a buffer) passes when its exit status and its whole
// output are those of the run without a failure.
//
// The readers of glTF, 3MF and Collada run in a forked child (isolated_reader):
// the count and the fact that an allocation failed are kept in shared memory,
// so a failure in the child is seen too. Their libraries catch std::bad_alloc
// and report a parse error of their own, or carry on; the child's new handler
// tells the tool that memory ran out all the same, and this program calls the
// new handler as the standard operator new does.
//
// A std::bad_alloc escaping a noexcept function (nlohmann-json's destructors
// allocate) calls std::terminate, where the tool's handler ends the process
// with exit 4 (src/cli/out_of_memory.hpp). So each command line runs in a
// worker process, with that handler; a worker so ended has passed its run,
// and another is forked to carry on from the next allocation.
//
//   polymass_out_of_memory ARGUMENT... [-- ARGUMENT...]...
//
// Each group of arguments (separated by --) is one command line of the tool,
// without "polymass": a mesh file, "audit robot.urdf", "assembly parts.json".
// OUT_OF_MEMORY_FROM=N skips the first N - 1 allocations (to debug the Nth).
#include <errno.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
#include "out_of_memory.hpp"

// Whether malloc can be replaced here: with glibc, which allows it ("Replacing
// malloc"), and not under a sanitizer, whose runtime owns malloc.
#include <cstddef>  // defines __GLIBC__ where glibc is the C library
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define INJECT_INTO_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define INJECT_INTO_MALLOC 0
#endif
#endif
#if !defined(INJECT_INTO_MALLOC)
#if defined(__GLIBC__)
#define INJECT_INTO_MALLOC 1
#else
#define INJECT_INTO_MALLOC 0
#endif
#endif

#if INJECT_INTO_MALLOC
// glibc's allocator under its own names, which replacing malloc leaves in place.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* memory, std::size_t size);
void __libc_free(void* memory);
}
#endif

namespace {

struct Injection {
    std::atomic<long> countdown{-1};  // allocations left before the one that fails; < 0: none
    std::atomic<int> failed{0};       // an allocation was made to fail
    std::atomic<int> failed_c_in_reader{0};  // ... a C one, in a reader's child process
    std::atomic<pid_t> worker{0};            // the process running the tool
};

// A command line's progress, kept by its worker process (work_through) where the
// supervisor finds it when the worker ends early.
struct Progress {
    long n;               // the allocation failing in the run under way (0-based)
    bool expected_done;   // the run without a failure is behind
    int expected_status;  // its exit status
    bool complete;        // a run made fewer than n + 1 allocations: the line is done
    long failures, over_budget, c_in_reader, done_without, terminated;
};

// In shared memory, so that a forked reader or worker counts on the same
// numbers.
template <typename T>
T* shared() {
    void* memory =
        mmap(nullptr, sizeof(T), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED) std::abort();
    return new (memory) T();
}

Injection* injection() {
    static Injection* const state = shared<Injection>();
    return state;
}

bool allocation_fails() {
    Injection* state = injection();
    if (state->countdown.load() < 0) return false;
    if (state->countdown.fetch_sub(1) != 0) return false;
    state->failed.store(1);
    return true;
}

// Memory from the system's allocator, counted by the caller only.
void* raw_allocate(std::size_t size) {
#if INJECT_INTO_MALLOC
    return __libc_malloc(size ? size : 1);
#else
    return std::malloc(size ? size : 1);
#endif
}

void* allocate(std::size_t size) {
    if (allocation_fails()) return nullptr;
    return raw_allocate(size);
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
    std::string output;  // stdout, as far as it fits the capture
    std::string errors;  // stderr, likewise
    bool over_budget;    // the tool said a reader ran out of the file's memory budget
};

// One run of the command line with the countdown armed at n (< 0: none): its
// exit status, with std::bad_alloc reaching main counted as main counts it,
// and its output. The command line is parsed before: CLI11 copies strings
// inside functions declared noexcept (App::_find_subcommand), where a failed
// allocation terminates - not the project's to fix, and a command line is a
// few short strings.
Run run_tool(const std::vector<std::string>& words, long n) {
    using namespace polymass_cli;
    std::vector<const char*> argv{"polymass"};
    for (const std::string& word : words) argv.push_back(word.c_str());
    const Arguments arguments = parse_arguments(static_cast<int>(argv.size()), argv.data());
    static Capture output, errors;  // too large for the stack of a sanitized build
    output.clear();
    errors.clear();
    std::streambuf* out = std::cout.rdbuf(&output);
    std::streambuf* err = std::cerr.rdbuf(&errors);
    int status;
    injection()->failed.store(0);
    injection()->failed_c_in_reader.store(0);
    injection()->countdown.store(n);
    try {
        status = run_command(arguments);
    } catch (const std::bad_alloc&) {
        status = kExitInternal;
    }
    injection()->countdown.store(-1);
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    // isolated_reader.cpp's message for a reader over the file's budget, in
    // the table (stdout) or after it (stderr).
    constexpr std::string_view over_budget = "the reader ran out of its memory";
    return {status, std::string(output.text()), std::string(errors.text()),
            output.text().find(over_budget) != std::string_view::npos ||
                errors.text().find(over_budget) != std::string_view::npos};
}

// Where a run's output parts from the expected one's, for the failure's
// message: a few lines of each from there, and the run's stderr.
std::string difference(const Run& expected, const Run& run) {
    std::size_t at = 0;
    while (at < expected.output.size() && at < run.output.size() &&
           expected.output[at] == run.output[at])
        ++at;
    const std::size_t from = expected.output.rfind('\n', at) == std::string::npos
                                 ? 0
                                 : expected.output.rfind('\n', at) + 1;
    auto excerpt = [from](const std::string& text) {
        return from >= text.size() ? std::string("(ends)") : text.substr(from, 300);
    };
    return "  stdout from byte " + std::to_string(from) + ", expected:\n" +
           excerpt(expected.output) + "\n  got:\n" + excerpt(run.output) +
           "\n  stderr: " + run.errors.substr(0, 300) + "\n";
}

// The command lines of the arguments: groups separated by "--".
std::vector<std::vector<std::string>> command_lines(int argc, char** argv) {
    std::vector<std::vector<std::string>> lines(1);
    for (int i = 1; i < argc; ++i) {
        if (std::string_view(argv[i]) == "--") {
            lines.emplace_back();
        } else {
            lines.back().push_back(argv[i]);
        }
    }
    std::vector<std::vector<std::string>> nonempty;
    for (auto& line : lines)
        if (!line.empty()) nonempty.push_back(std::move(line));
    return nonempty;
}

std::string joined(const std::vector<std::string>& words) {
    std::string line = "polymass";
    for (const std::string& word : words) line += " " + word;
    return line;
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

#if INJECT_INTO_MALLOC
// Replacing these four replaces the C allocator for every library of the
// process (glibc's "Replacing malloc"); the other entry points (memalign,
// posix_memalign, ...) stay glibc's and their memory is freed by __libc_free
// all the same. A failure is as the C standard has it: NULL and ENOMEM.
namespace {
void* failed_c_allocation() {
    if (getpid() != injection()->worker.load()) injection()->failed_c_in_reader.store(1);
    errno = ENOMEM;
    return nullptr;
}
}  // namespace

extern "C" void* malloc(std::size_t size) {
    if (allocation_fails()) return failed_c_allocation();
    return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t count, std::size_t size) {
    if (allocation_fails()) return failed_c_allocation();
    return __libc_calloc(count, size);
}
extern "C" void* realloc(void* memory, std::size_t size) {
    if (size != 0 && allocation_fails()) return failed_c_allocation();
    return __libc_realloc(memory, size);
}
extern "C" void free(void* memory) { __libc_free(memory); }
#endif

namespace {

// Runs the command line with each allocation failing in turn, from
// progress->n, keeping the counts in progress; ends the process (exit 0) when
// done. A run that ends in std::terminate ends the process there (exit 4,
// the tool's own handler) for the supervisor to carry on after it.
[[noreturn]] void work_through(const std::vector<std::string>& words, Progress* progress) {
    using polymass_cli::kExitInternal, polymass_cli::kExitUnreadable;
    polymass_cli::end_out_of_memory_terminations_as_exit_4();
    injection()->worker.store(getpid());
    const std::string line = joined(words);
    const Run expected = run_tool(words, -1);
    progress->expected_status = expected.status;
    progress->expected_done = true;
    for (;; ++progress->n) {
        const Run run = run_tool(words, progress->n);
        if (!injection()->failed.load()) {
            if (run.status != expected.status || run.output != expected.output) {
                std::printf("%s: exit %d without a failed allocation, %d expected\n%s",
                            line.c_str(), run.status, expected.status,
                            difference(expected, run).c_str());
                ++progress->failures;
            }
            progress->complete = true;
            break;
        }
        if (run.status == kExitInternal) continue;
        if (run.status == kExitUnreadable && run.over_budget) {
            ++progress->over_budget;
        } else if (run.status == kExitUnreadable && injection()->failed_c_in_reader.load()) {
            ++progress->c_in_reader;
        } else if (run.status == expected.status && run.output == expected.output) {
            ++progress->done_without;
        } else {
            std::printf("%s: allocation %ld failed: exit %d, not %d (out of memory)\n%s",
                        line.c_str(), progress->n + 1, run.status, int(kExitInternal),
                        difference(expected, run).c_str());
            ++progress->failures;
        }
        std::fflush(stdout);  // the next run may end the process
    }
    std::fflush(stdout);
    std::exit(0);  // not _exit: under ASan, LeakSanitizer checks the worker at its exit
}

}  // namespace

int main(int argc, char** argv) {
    using polymass_cli::kExitInternal;
    // OUT_OF_MEMORY_FROM=N starts at the Nth allocation, to debug a failure
    // (its breakpoint then comes first).
    const char* from = std::getenv("OUT_OF_MEMORY_FROM");
    const long first = from ? std::max(0L, std::atol(from) - 1) : 0;
    Progress* const progress = shared<Progress>();
    int failures = 0;
    // Each command line in a worker process, forked again after a run that
    // ended the worker: in std::terminate, as the tool does (exit 4, out of
    // memory, a pass), or otherwise (a crash or a leak, a failure).
    for (const std::vector<std::string>& words : command_lines(argc, argv)) {
        const std::string line = joined(words);
        *progress = Progress{};
        progress->n = first;
        while (!progress->complete) {
            std::fflush(stdout);
            const pid_t worker = fork();
            if (worker < 0) std::abort();
            if (worker == 0) work_through(words, progress);
            int status = 0;
            while (waitpid(worker, &status, 0) < 0 && errno == EINTR) {
            }
            if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && progress->complete) break;
            if (!progress->expected_done) {
                std::printf("%s: the run without a failed allocation ended the process (%d)\n",
                            line.c_str(), status);
                ++progress->failures;
                break;
            }
            if (WIFEXITED(status) && WEXITSTATUS(status) == kExitInternal) {
                ++progress->terminated;
            } else {
                std::printf("%s: allocation %ld failed: the process ended (%s %d)\n", line.c_str(),
                            progress->n + 1, WIFSIGNALED(status) ? "signal" : "exit",
                            WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
                ++progress->failures;
            }
            ++progress->n;
        }
        std::printf(
            "%s: exit %d; each of its %ld allocations failed in turn (%ld of them inside the "
            "file's memory budget, %ld C allocations in a reader's process reported as the "
            "file's, %ld done without, %ld ended in std::terminate as out of memory)\n",
            line.c_str(), progress->expected_status, progress->n, progress->over_budget,
            progress->c_in_reader, progress->done_without, progress->terminated);
        failures += progress->failures;
    }
    return failures == 0 ? 0 : 1;
}
