// A mesh file's bytes, mapped into memory rather than copied: the kernel
// reads the file as the reader walks it (at the speed of `cat`), nothing is
// allocated per byte, and the pages are given back as soon as the reader lets
// the file go. Only regular files are read: a device (/dev/zero), a pipe or a
// directory has no size to bound the reading by.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace polymass_cli {

class FileBytes {
public:
    // Maps path; throws ReadError when it cannot be opened, is not a regular
    // file, or is empty.
    explicit FileBytes(const std::string& path);
    ~FileBytes();
    FileBytes(FileBytes&& other) noexcept;
    FileBytes& operator=(FileBytes&&) = delete;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;

    std::string_view view() const { return {static_cast<const char*>(data_), size_}; }
    // Gives back the pages before offset that the reader is done with: a
    // reader walking a large file front to back keeps only a window of it in
    // memory (the file is mapped read-only, so a page touched again is read
    // again).
    void drop_before(std::size_t offset);
    // Unmaps the file now (view() is then empty): a reader that has decoded
    // what it needs frees the pages before building the rest.
    void release();

private:
    void* data_ = nullptr;
    std::size_t size_ = 0;
};

// The size of path after the checks of FileBytes, without the mapping, for a
// file another library opens itself (glTF, 3MF, Collada).
std::size_t regular_file_size(const std::string& path);

}  // namespace polymass_cli
