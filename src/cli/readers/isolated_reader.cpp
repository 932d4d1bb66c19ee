#include "readers/isolated_reader.hpp"

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>

#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

// The child's answer: a tag, then the Model or the error's message.
enum class Outcome : uint8_t { kModel = 0, kReadError = 1 };

class Writer {
public:
    void bytes(const void* data, size_t size) { out_.append(static_cast<const char*>(data), size); }
    template <class T>
    void value(T v) {
        bytes(&v, sizeof v);
    }
    template <class T>
    void array(const std::vector<T>& values) {
        value<uint64_t>(values.size());
        bytes(values.data(), values.size() * sizeof(T));
    }
    void text(const std::string& s) {
        value<uint64_t>(s.size());
        bytes(s.data(), s.size());
    }
    const std::string& data() const { return out_; }

private:
    std::string out_;
};

class Reader {
public:
    explicit Reader(const std::string& in) : in_(in) {}
    void bytes(void* data, size_t size) {
        if (size > in_.size() - at_) throw ReadError("the reader's child process sent too little");
        if (size == 0) return;  // an empty vector's data() may be null
        std::memcpy(data, in_.data() + at_, size);
        at_ += size;
    }
    template <class T>
    T value() {
        T v;
        bytes(&v, sizeof v);
        return v;
    }
    template <class T>
    std::vector<T> array() {
        const uint64_t count = value<uint64_t>();
        if (count > (in_.size() - at_) / sizeof(T))
            throw ReadError("the reader's child process sent too little");
        std::vector<T> values(count);
        bytes(values.data(), count * sizeof(T));
        return values;
    }
    std::string text() {
        const std::vector<char> chars = array<char>();
        return std::string(chars.begin(), chars.end());
    }

private:
    const std::string& in_;
    size_t at_ = 0;
};

// model by value: its positions are written as doubles (as_doubles).
std::string serialize(Model model) {
    Writer out;
    out.value(Outcome::kModel);
    out.text(model.format);
    out.text(model.declared_unit);
    out.array(model.positions.as_doubles());
    out.value<uint64_t>(model.parts.size());
    for (const Part& part : model.parts) {
        out.text(part.name);
        out.array(part.indices);
        out.array(part.face_sizes);
    }
    out.value<uint64_t>(model.notes.size());
    for (const std::string& note : model.notes) out.text(note);
    return out.data();
}

Model deserialize(const std::string& data) {
    Reader in(data);
    if (in.value<Outcome>() == Outcome::kReadError) throw ReadError(in.text());
    Model model;
    model.format = in.text();
    model.declared_unit = in.text();
    model.positions = Positions(in.array<double>());
    model.parts.resize(in.value<uint64_t>());
    for (Part& part : model.parts) {
        part.name = in.text();
        part.indices = in.array<uint32_t>();
        part.face_sizes = in.array<uint32_t>();
    }
    model.notes.resize(in.value<uint64_t>());
    for (std::string& note : model.notes) note = in.text();
    return model;
}

void write_all(int fd, const std::string& data) {
    for (size_t at = 0; at < data.size();) {
        const ssize_t written = write(fd, data.data() + at, data.size() - at);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return;  // the parent is gone: nothing to tell
        at += size_t(written);
    }
}

std::string read_all(int fd) {
    std::string data;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t got = read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return data;
        data.append(buffer, size_t(got));
    }
}

// What the child tells the parent besides its answer, in memory both share:
// whether an allocation failed in it, and whether it ran under a memory
// budget. The libraries behind these readers catch std::bad_alloc inside
// their parsers and report a parse error of their own, carry on with what
// they have, or let it escape a noexcept function and abort (tinygltf,
// assimp; libzip reports a failed malloc as an error of its own): however
// the child ends after an allocation failed, its answer says nothing about
// the file, and the parent reports the failed allocation instead.
struct ChildState {
    std::atomic<int> allocation_failed{0};
    std::atomic<int> budgeted{0};  // a failed allocation then means the file's, not the machine's
};

ChildState* child_state = nullptr;  // the child's view of the shared page

// The child's new handler: called by operator new when memory runs out.
void note_failed_allocation() {
    child_state->allocation_failed.store(1);
    throw std::bad_alloc();
}

// The bytes of address space the process has mapped (its libraries, stacks,
// heap), or 0 when /proc cannot tell.
uint64_t mapped_bytes() {
    FILE* statm = std::fopen("/proc/self/statm", "r");
    if (statm == nullptr) return 0;
    unsigned long long pages = 0;
    const int read = std::fscanf(statm, "%llu", &pages);
    std::fclose(statm);
    return read == 1 ? pages * uint64_t(sysconf(_SC_PAGESIZE)) : 0;
}

[[noreturn]] void run_child(int fd, uint64_t file_size, const std::function<Model()>& read,
                            ChildState* state) {
    child_state = state;
    std::set_new_handler(note_failed_allocation);
    // A small crafted file can make a reader work without end (3MF objects
    // whose components reuse each other expand into a full tree): two minutes
    // of CPU, far beyond any real file, then SIGXCPU - a crash the parent
    // reports.
    constexpr rlim_t kCpuSeconds = 120;
    const struct rlimit cpu = {kCpuSeconds, kCpuSeconds};
    setrlimit(RLIMIT_CPU, &cpu);
    // Memory: an allocation past the budget fails (std::bad_alloc). An
    // existing lower limit stays. Without /proc, no limit: the budget would
    // have nothing to add to.
    const uint64_t mapped = mapped_bytes();
    struct rlimit memory {};
    if (file_size > 0 && mapped > 0 && getrlimit(RLIMIT_AS, &memory) == 0 &&
        reader_memory_budget(file_size) < RLIM_INFINITY - mapped) {
        const rlim_t budget = mapped + reader_memory_budget(file_size);
        if (memory.rlim_cur == RLIM_INFINITY || budget < memory.rlim_cur) {
            memory.rlim_cur = budget;
            state->budgeted.store(setrlimit(RLIMIT_AS, &memory) == 0);
        }
    }
    std::string answer;
    try {
        answer = serialize(read());
    } catch (const ReadError& error) {
        Writer out;
        out.value(Outcome::kReadError);
        out.text(error.what());
        answer = out.data();
    } catch (const std::bad_alloc&) {
        state->allocation_failed.store(1);  // also when thrown without an allocation
        _exit(1);                           // the parent reads the shared state first
    } catch (...) {
        _exit(2);  // worse: the parent reports the exit status
    }
    write_all(fd, answer);
    _exit(0);
}

// The shared page of a child's state, unmapped when the parent is done with it.
class SharedChildState {
public:
    SharedChildState() {
        void* memory = mmap(nullptr, sizeof(ChildState), PROT_READ | PROT_WRITE,
                            MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (memory == MAP_FAILED) throw std::bad_alloc();
        state_ = new (memory) ChildState;
    }
    ~SharedChildState() { munmap(state_, sizeof(ChildState)); }
    SharedChildState(const SharedChildState&) = delete;
    SharedChildState& operator=(const SharedChildState&) = delete;
    ChildState* get() const { return state_; }

private:
    ChildState* state_;
};

}  // namespace

uint64_t reader_memory_budget(uint64_t file_size) {
    constexpr uint64_t kBase = uint64_t(256) << 20;
    constexpr uint64_t kBytesPerFileByte = 64;
    return file_size > (UINT64_MAX - kBase) / kBytesPerFileByte
               ? UINT64_MAX
               : kBase + kBytesPerFileByte * file_size;
}

Model read_isolated(const std::function<Model()>& read, uint64_t file_size) {
    const SharedChildState state;
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) throw ReadError(std::string("pipe: ") + std::strerror(errno));
    const pid_t child = fork();
    if (child < 0) {
        close(pipe_ends[0]);
        close(pipe_ends[1]);
        throw ReadError(std::string("fork: ") + std::strerror(errno));
    }
    if (child == 0) {
        close(pipe_ends[0]);
        run_child(pipe_ends[1], file_size, read, state.get());
    }
    close(pipe_ends[1]);
    const std::string answer = read_all(pipe_ends[0]);
    close(pipe_ends[0]);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (state.get()->allocation_failed.load()) {
        // Under the file's budget, the file asked for more than a mesh of its
        // size can; otherwise the machine's memory ran out: the tool's
        // out-of-memory ending, not a file that cannot be read.
        if (!state.get()->budgeted.load()) throw std::bad_alloc();
        throw ReadError("the reader ran out of its memory (" +
                        std::to_string(reader_memory_budget(file_size) >> 20) +
                        " MiB for a file of this size): it expands beyond what a mesh of its "
                        "size can hold (a zip bomb, an element count that lies), or is corrupt");
    }
    if (WIFSIGNALED(status))
        throw ReadError(std::string("the reader crashed on this file (") +
                        strsignal(WTERMSIG(status)) + "): it is corrupt or not of its format");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw ReadError("the reader failed (exit status " + std::to_string(WEXITSTATUS(status)) +
                        ")");
    return deserialize(answer);
}

}  // namespace polymass_cli
