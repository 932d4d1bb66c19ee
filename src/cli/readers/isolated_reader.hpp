// Running a reader in a child process, so that a crash inside it is a
// ReadError, not the end of the tool.
//
// The readers built on other libraries (tinygltf, assimp; the 3MF reader's
// libzip and pugixml) parse untrusted JSON, buffers and zip packages with
// code the project cannot fix (assimp, which once read 3MF, aborted on a bad
// zip checksum). They run in
// a forked child that sends the Model back through a pipe; the parent turns a
// child killed by a signal into a ReadError saying so. The memory of a 3MF or
// Collada reader is bounded by the file's size (see read_isolated), so that a
// zip bomb or a lying element count is an error, not the machine's memory.
#pragma once

#include <cstdint>
#include <functional>

#include "model/model.hpp"

namespace polymass_cli {

// Calls read() in a child process and returns its Model, or throws the
// ReadError it threw, or a ReadError when it crashed or ran out of its
// memory. For a file that a crafted copy can make its reader expand without
// end - a 3MF's zip, a Collada accessor whose count is missing or lies -
// file_size is its size and the child's memory 256 MiB and 64 bytes per
// byte of it beyond the address space the tool already had: a mesh's XML
// deflates 3 to 10 times, and a reader holds a few times its text, so only
// a hostile file asks for that much. 0: no bound (a glTF's buffers may be
// files of their own; its reader checks each buffer against the bytes it
// has).
Model read_isolated(const std::function<Model()>& read, uint64_t file_size = 0);

// That memory (beyond what the tool had) for a file of file_size bytes.
uint64_t reader_memory_budget(uint64_t file_size);

}  // namespace polymass_cli
