// Running a reader in a child process, so that a crash inside it is a
// ReadError, not the end of the tool.
//
// The readers built on other libraries (tinygltf, lib3mf; assimp, which the
// tool used before, aborted on a 3MF with a bad zip checksum) parse untrusted
// JSON, buffers and zip packages with code the project cannot fix. They run in
// a forked child that sends the Model back through a pipe; the parent turns a
// child killed by a signal into a ReadError saying so. The memory of a
// compressed file's reader is bounded by the file's size (see read_isolated),
// so that a zip bomb is an error, not the machine's memory.
#pragma once

#include <cstdint>
#include <functional>

#include "model/model.hpp"

namespace polymass_cli {

// Calls read() in a child process and returns its Model, or throws the
// ReadError it threw, or a ReadError when it crashed or ran out of its
// memory. For a compressed file (3MF), packed_size is its size and the
// memory 256 MiB and 64 bytes per byte of it beyond the address space the
// tool already had: a mesh's XML deflates 3 to 10 times, so only a zip bomb
// expands that far. 0: no bound (glTF and Collada are not compressed, and a
// glTF's buffers may be files of their own; their readers check each buffer
// against the bytes it has).
Model read_isolated(const std::function<Model()>& read, uint64_t packed_size = 0);

// That memory (beyond what the tool had) for a compressed file of packed_size bytes.
uint64_t packed_memory_budget(uint64_t packed_size);

}  // namespace polymass_cli
