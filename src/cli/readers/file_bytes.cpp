#include "readers/file_bytes.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

// An open descriptor, closed on every way out. Opened without blocking: a
// pipe opened for reading waits for a writer, forever if none comes; opened
// so, it is then refused as not a regular file (regular files ignore the flag).
class Descriptor {
public:
    explicit Descriptor(const std::string& path)
        : fd_(open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)) {
        if (fd_ < 0) throw ReadError("cannot open the file");
    }
    ~Descriptor() { close(fd_); }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int fd() const { return fd_; }

private:
    int fd_;
};

// The size of a regular, non-empty file; anything else is a ReadError.
std::size_t size_of_open_file(int fd) {
    struct stat status {};
    if (fstat(fd, &status) != 0)
        throw ReadError(std::string("cannot read the file: ") + std::strerror(errno));
    if (!S_ISREG(status.st_mode))
        throw ReadError(S_ISDIR(status.st_mode)
                            ? "it is a directory, not a file"
                            : "not a regular file (a device or a pipe): it has no size to read "
                              "it by");
    if (status.st_size == 0) throw ReadError("the file is empty");
    return std::size_t(status.st_size);
}

}  // namespace

FileBytes::FileBytes(const std::string& path) {
    const Descriptor file(path);
    const std::size_t size = size_of_open_file(file.fd());
    void* data = mmap(nullptr, size, PROT_READ, MAP_PRIVATE, file.fd(), 0);
    if (data == MAP_FAILED)
        throw ReadError(std::string("cannot read the file: ") + std::strerror(errno));
    // Read front to back: the kernel reads ahead and drops what was read.
    madvise(data, size, MADV_SEQUENTIAL);
    data_ = data;
    size_ = size;
}

FileBytes::FileBytes(FileBytes&& other) noexcept : data_(other.data_), size_(other.size_) {
    other.data_ = nullptr;
    other.size_ = 0;
}

FileBytes::~FileBytes() { release(); }

void FileBytes::drop_before(std::size_t offset) {
    const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
    const std::size_t whole_pages = std::min(offset, size_) / page * page;
    if (whole_pages > 0) madvise(data_, whole_pages, MADV_DONTNEED);
}

void FileBytes::release() {
    if (data_ != nullptr) munmap(data_, size_);
    data_ = nullptr;
    size_ = 0;
}

std::size_t regular_file_size(const std::string& path) {
    const Descriptor file(path);
    return size_of_open_file(file.fd());
}

}  // namespace polymass_cli
